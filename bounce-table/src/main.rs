//! `bounce-table`: predicted bounce and debounce windows for the typical switches of
//! physics.md sec. 7 (the built-in catalogue), with every tier of the model side by side; and
//! `bounce-table eval`, the JSON Lines interface to the model and the exact reference.
//!
//! Usage: `bounce-table [--sample-period SECONDS]` (default 1e-4 s), or
//! `bounce-table eval [--method exact|map|averaged|closed|auto] [--tolerance X]
//! [--precision f32|f64] [--nodes N] < scenes.jsonl`.

mod eval;
mod scene_input;

use std::process::ExitCode;

use contact_bounce::{
    catalogue, Margin, Method, Nodes, Prediction, Tolerance, Window, DEFAULT_MAX_IMPACTS,
};

fn usage() -> &'static str {
    "usage: bounce-table [--sample-period SECONDS]\n\
     \x20      bounce-table eval [--method exact|map|averaged|closed|auto] [--tolerance X]\n\
     \x20                        [--precision f32|f64] [--nodes N] < scenes.jsonl\n\
     Prints predicted bounce times and debounce windows for the built-in catalogue of typical\n\
     switches (physics.md sec. 7). The parameters are typical values, not a datasheet."
}

fn parse_args() -> Result<f64, String> {
    let mut period = 1e-4;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--sample-period" => {
                let value = args
                    .next()
                    .ok_or("--sample-period needs a value in seconds")?;
                period = value
                    .parse::<f64>()
                    .ok()
                    .filter(|p| p.is_finite() && *p > 0.0)
                    .ok_or_else(|| {
                        format!("--sample-period: '{value}' is not a positive number of seconds")
                    })?;
            }
            "-h" | "--help" => return Err(String::new()),
            other => return Err(format!("unknown argument '{other}'")),
        }
    }
    Ok(period)
}

fn seconds(t: Option<f64>) -> String {
    match t {
        None => "endless".to_owned(),
        Some(t) if t < 1e-3 => format!("{:.3} us", t * 1e6),
        Some(t) if t < 1.0 => format!("{:.3} ms", t * 1e3),
        Some(t) => format!("{t:.3} s"),
    }
}

fn error(p: &Prediction<f64>) -> String {
    p.expected_error
        .map_or_else(|| "unknown".to_owned(), |e| format!("{:.1} %", e * 100.0))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().is_some_and(|a| a == "eval") {
        let options = match eval::options(args.get(1..).unwrap_or_default()) {
            Ok(o) => o,
            Err(message) => {
                eprintln!("bounce-table: {message}\n{}", usage());
                return ExitCode::from(2);
            }
        };
        return match eval::run(&options) {
            Ok(true) => ExitCode::SUCCESS,
            Ok(false) => ExitCode::FAILURE,
            Err(e) => {
                eprintln!("bounce-table eval: {e}");
                ExitCode::FAILURE
            }
        };
    }
    let period = match parse_args() {
        Ok(p) => p,
        Err(message) => {
            if !message.is_empty() {
                eprintln!("bounce-table: {message}");
            }
            eprintln!("{}", usage());
            return if message.is_empty() {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(2)
            };
        }
    };
    println!(
        "Typical switches of physics.md sec. 7: assumed, typical parameters, not a datasheet."
    );
    println!("Bounce = accumulation time of the preloaded contact (impacts above no threshold).");
    println!(
        "Window = Auto tier at 10 % tolerance, widened by its expected error, in ticks of {}.",
        seconds(Some(period))
    );
    println!();
    println!(
        "{:<22} {:>6} {:>13} {:>13} {:>13} {:>13} {:>10} {:>8}",
        "switch", "j0", "closed", "averaged N8", "map", "auto 10 %", "expected", "window"
    );
    let mut failed = false;
    let tolerance = Tolerance::new(0.1).ok();
    for typical in catalogue::ALL {
        let scene = match typical.scene::<f64>() {
            Ok(s) => s,
            Err(e) => {
                eprintln!("bounce-table: {}: {e}", typical.name);
                failed = true;
                continue;
            }
        };
        let closed = scene.predict(Method::Closed);
        let averaged = scene.predict(Method::Averaged(Nodes::N8));
        let map = scene.predict(Method::Map {
            max_impacts: DEFAULT_MAX_IMPACTS,
        });
        let auto = tolerance.map_or(closed, |t| scene.predict(Method::Auto(t)));
        let window =
            Window::from_prediction(&auto, &Margin::none().with_expected_error(&auto), period)
                .map_or_else(|e| e.to_string(), |w| w.ticks().to_string());
        println!(
            "{:<22} {:>6.2} {:>13} {:>13} {:>13} {:>13} {:>10} {:>8}",
            typical.name,
            scene.dimensionless_impulse().unwrap_or(f64::NAN),
            seconds(closed.bounce_time()),
            seconds(averaged.bounce_time()),
            seconds(map.bounce_time()),
            seconds(auto.bounce_time()),
            error(&auto),
            window,
        );
    }
    if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

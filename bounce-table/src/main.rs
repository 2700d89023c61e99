//! `bounce-table`: debounce windows for switches, from physics.
//!
//! ```text
//! bounce-table [OPTIONS] [SCENE_FILE]      the catalogue of typical switches, or your switches
//! bounce-table eval [OPTIONS] < scenes.jsonl
//! bounce-table calibrate [OPTIONS] CAPTURE   describe a capture of a real switch
//! ```

use bounce_table::capture::EdgeName;
use std::process::ExitCode;

use bounce_table::cli::{self, Invocation};
use bounce_table::commands::replay::taps;
use bounce_table::commands::{calibrate, eval, replay, table};
use bounce_table::render::output::{identifier, render_to};
use bounce_table::render::plot;
use bounce_table::scene::file::{open, Entries};
use bounce_table::support::strict::printable;
use bounce_table::{capture, stats};

/// Writes to standard output. A reader that stopped early (`bounce-table ... | head`) ends the
/// run quietly with success, as it does for other command-line tools; any other failure to
/// write is an error (exit status 1), never a panic.
fn emit(text: &str) {
    use std::io::Write;
    let mut stdout = std::io::stdout().lock();
    if let Err(e) = stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("bounce-table: standard output: {e}");
        std::process::exit(1);
    }
}

/// `print!` through [`emit`].
macro_rules! out {
    ($($arg:tt)*) => { emit(&format!($($arg)*)) };
}

/// `println!` through [`emit`].
macro_rules! outln {
    ($($arg:tt)*) => { emit(&format!("{}\n", format!($($arg)*))) };
}

/// The scene file's entries (else the catalogue's); `None` when the file cannot be opened or
/// parsed as a whole (each fault reported).
fn open_entries(file: Option<&str>) -> Option<Entries> {
    match file {
        None => Some(Entries::catalogue()),
        Some(path) => open(path)
            .inspect_err(|errors| {
                for e in errors {
                    eprintln!("bounce-table: {e}");
                }
            })
            .ok(),
    }
}

/// Writes `text` to `path` completely or not at all (a temporary file, then a rename).
fn write_atomically(path: &str, text: &str) -> std::io::Result<()> {
    write_atomically_with(path, |w| w.write_all(text.as_bytes()))
}

/// Writes what `write` writes to `path` completely or not at all: into a temporary file beside
/// it, renamed over it once complete.
fn write_atomically_with(
    path: &str,
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let target = std::path::Path::new(path);
    let tmp = target.with_extension(format!("tmp-{}", std::process::id()));
    // A failed write (a full disk, an error while rendering) or rename leaves no temporary
    // file behind.
    std::fs::File::create(&tmp)
        .and_then(|file| {
            let mut w = std::io::BufWriter::new(file);
            write(&mut w)?;
            w.into_inner()
                .map_err(std::io::IntoInnerError::into_error)?
                .sync_all()
        })
        .and_then(|()| std::fs::rename(&tmp, target))
        .inspect_err(|_| {
            let _ = std::fs::remove_file(&tmp);
        })
}

/// `bounce-table replay --taps`.
fn taps_main(
    request: &replay::Request,
    t: &taps::TapSettings,
    events: &[bounce_table::capture::Event],
) -> ExitCode {
    if request.output == replay::Output::Curve {
        eprintln!("bounce-table replay: --format curve is the isolated replay's learning curve; with --taps, give table or json");
        return ExitCode::from(2);
    }
    let lines = match taps::run(events, &request.calibration, &request.settings, t) {
        Ok(lines) => lines,
        Err(e) => {
            eprintln!("bounce-table replay: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(dir) = &request.plot {
        if let Err(code) = write_plots(dir, taps::plots(&lines)) {
            return code;
        }
    }
    match request.output {
        replay::Output::Json => out!("{}", taps::json(&lines)),
        _ => out!("{}", taps::markdown(&lines, t)),
    }
    ExitCode::SUCCESS
}

/// Writes `replay --plot DIR`'s plots (named files of SVG) into `dir`.
fn write_plots(dir: &str, plots: Vec<(String, String)>) -> Result<(), ExitCode> {
    for (file, svg) in plots {
        let name = format!("{dir}/{file}");
        if let Err(e) = std::fs::create_dir_all(dir).and_then(|()| write_atomically(&name, &svg)) {
            eprintln!("bounce-table replay: {name}: {e}");
            return Err(ExitCode::FAILURE);
        }
    }
    Ok(())
}

/// `bounce-table replay`.
fn replay_main(request: &replay::Request) -> ExitCode {
    let capture::Loaded {
        events,
        skipped,
        analog,
    } = match capture::load(&request.capture) {
        Ok(x) => x,
        Err(e) => {
            eprintln!("bounce-table replay: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(t) = &request.taps {
        return taps_main(request, t, &events);
    }
    if request.output == replay::Output::Curve {
        return match replay::learning_curves(&events, &request.settings) {
            Ok(curves) => {
                out!("{}", replay::curve_csv(&curves));
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("bounce-table replay: {e}");
                ExitCode::from(2)
            }
        };
    }
    let lines = match replay::run(&events, &request.calibration, &request.settings) {
        Ok(lines) => lines,
        Err(e) => {
            eprintln!("bounce-table replay: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(dir) = &request.plot {
        if let Err(code) = write_plots(dir, replay::plots(&lines)) {
            return code;
        }
    }
    match request.output {
        replay::Output::Json => out!("{}", replay::json(&lines)),
        replay::Output::Curve => {}
        replay::Output::Markdown => {
            let loaded = capture::Loaded {
                events,
                skipped,
                analog,
            };
            out!(
                "{}",
                replay::report(&loaded, request.capture.event_gap, &lines)
            );
        }
    }
    ExitCode::SUCCESS
}

/// The arguments after the program's name; `None` (reported) where one is not UTF-8.
fn arguments() -> Option<Vec<String>> {
    let mut args = Vec::new();
    for arg in std::env::args_os().skip(1) {
        match arg.into_string() {
            Ok(a) => args.push(a),
            Err(raw) => {
                eprintln!(
                    "bounce-table: the argument '{}' is not UTF-8",
                    printable(&raw.to_string_lossy())
                );
                return None;
            }
        }
    }
    Some(args)
}

fn main() -> ExitCode {
    let Some(args) = arguments() else {
        return ExitCode::from(2);
    };
    match cli::parse(args) {
        Ok(Invocation::Help(text)) => {
            out!("{}\n", text.trim_end());
            ExitCode::SUCCESS
        }
        Ok(Invocation::Version) => {
            outln!("bounce-table {}", env!("CARGO_PKG_VERSION"));
            ExitCode::SUCCESS
        }
        Ok(Invocation::Eval(options)) => eval_main(&options),
        Ok(Invocation::Replay(request)) => replay_main(&request),
        Ok(Invocation::Calibrate(options)) => calibrate_main(&options),
        Ok(Invocation::Table(options)) => table_main(&options),
        Err(refusal) => {
            eprintln!("{refusal}");
            ExitCode::from(2)
        }
    }
}

/// `bounce-table eval`.
fn eval_main(options: &eval::Options) -> ExitCode {
    let input = match eval::input(options) {
        Ok(input) => input,
        Err(e) => {
            eprintln!("bounce-table eval: {e}");
            return ExitCode::from(2);
        }
    };
    match eval::run(options, input) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("bounce-table eval: {e}");
            ExitCode::FAILURE
        }
    }
}

/// `bounce-table calibrate`.
fn calibrate_main(request: &calibrate::Request) -> ExitCode {
    let c = &request.calibration;
    if let Some(output) = &request.output {
        let same = std::fs::canonicalize(&request.capture.file)
            .ok()
            .zip(std::fs::canonicalize(output).ok())
            .is_some_and(|(a, b)| a == b);
        if same {
            eprintln!(
                "bounce-table calibrate: --output {} is the capture itself: refusing to overwrite it",
                printable(output)
            );
            return ExitCode::from(2);
        }
    }
    let capture::Loaded {
        events,
        skipped,
        analog,
    } = match capture::load(&request.capture) {
        Ok(x) => x,
        Err(e) => {
            eprintln!("bounce-table calibrate: {e}");
            return ExitCode::from(2);
        }
    };
    let loaded = capture::Loaded {
        events,
        skipped,
        analog,
    };
    // The plots are files of their own; the text is what the library writes.
    if let (Some(dir), calibrate::Written::Report) = (&request.plot, request.written) {
        let groups = stats::group(&loaded.events, c.resolution, c.burst_gap);
        for ((switch, kind), d) in &groups {
            let name = format!(
                "{dir}/{}-{}.svg",
                identifier(switch).to_lowercase(),
                kind.name()
            );
            let svg = calibrate::plot(switch, *kind, d, c.percentile);
            if let Err(e) =
                std::fs::create_dir_all(dir).and_then(|()| write_atomically(&name, &svg))
            {
                eprintln!("bounce-table calibrate: {name}: {e}");
                return ExitCode::FAILURE;
            }
        }
    }
    let text = match calibrate::written(request, &loaded, || taps::window_costs(&loaded.events, c))
    {
        Ok(text) => text,
        Err(e) => {
            eprintln!("bounce-table calibrate: {}", printable(&e));
            return ExitCode::from(2);
        }
    };
    match &request.output {
        Some(path) => match write_atomically(path, &text) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!(
                    "bounce-table calibrate: {}: cannot write it: {e}",
                    printable(path)
                );
                ExitCode::FAILURE
            }
        },
        None => {
            out!("{text}");
            ExitCode::SUCCESS
        }
    }
}

/// The table mode.
fn table_main(options: &cli::Options) -> ExitCode {
    let typical = options.file.is_none();
    let source = options
        .file
        .clone()
        .unwrap_or_else(|| "catalogue".to_owned());
    if let (Some(input), Some(output)) = (&options.file, &options.output) {
        let same = std::fs::canonicalize(input)
            .ok()
            .zip(std::fs::canonicalize(output).ok())
            .is_some_and(|(a, b)| a == b);
        if same {
            eprintln!("bounce-table: --output {output} is the scene file itself: refusing to overwrite it");
            return ExitCode::from(2);
        }
    }
    let Some(entries) = open_entries(options.file.as_deref()) else {
        return ExitCode::from(2);
    };
    let Some((mut analyses, layout)) = table::analyse_all(
        entries,
        &options.settings,
        options.format,
        &source,
        &mut |message| eprintln!("bounce-table: {}", printable(&message)),
    ) else {
        // Nothing is written when any switch failed.
        return ExitCode::from(2);
    };
    let (format, settings) = (options.format, &options.settings);
    let mut render = |w: &mut dyn std::io::Write| {
        render_to(
            w,
            format,
            &mut analyses,
            settings,
            typical,
            &source,
            Some(layout),
        )
    };
    let written = match &options.output {
        Some(path) => write_atomically_with(path, render),
        None => {
            let mut stdout = std::io::BufWriter::new(std::io::stdout().lock());
            render(&mut stdout)
                .and_then(|()| std::io::Write::flush(&mut stdout))
                .inspect_err(|e| {
                    // A reader that stopped early ends the run quietly (see `emit`).
                    if e.kind() == std::io::ErrorKind::BrokenPipe {
                        std::process::exit(0);
                    }
                })
        }
    };
    if let Err(e) = written {
        let path = options.output.as_deref().unwrap_or("standard output");
        eprintln!("bounce-table: {path}: cannot write it: {e}");
        return ExitCode::FAILURE;
    }
    if let Some(dir) = &options.plot {
        if let Err(e) = std::fs::create_dir_all(dir) {
            eprintln!("bounce-table: {dir}: {e}");
            return ExitCode::FAILURE;
        }
        let Some(entries) = open_entries(options.file.as_deref()) else {
            return ExitCode::FAILURE;
        };
        let rows = match analyses.rows() {
            Ok(rows) => rows,
            Err(e) => {
                eprintln!("bounce-table: {e}");
                return ExitCode::FAILURE;
            }
        };
        for (entry, a) in entries.zip(rows) {
            let (Ok(entry), Ok(a)) = (entry, a) else {
                continue;
            };
            let input = entry.template.nominal();
            match plot::plots(input, &a, settings.percentile) {
                Ok((envelope, motion)) => {
                    let stem = identifier(&entry.name).to_lowercase();
                    for (suffix, svg) in [("envelope", envelope), ("motion", motion)] {
                        let path = format!("{dir}/{stem}-{suffix}.svg");
                        if let Err(e) = write_atomically(&path, &svg) {
                            eprintln!("bounce-table: {path}: {e}");
                            return ExitCode::FAILURE;
                        }
                    }
                }
                Err(e) => eprintln!(
                    "bounce-table: {}: plot: {}: {}",
                    printable(&entry.name),
                    e.field,
                    e.message
                ),
            }
        }
    }
    ExitCode::SUCCESS
}

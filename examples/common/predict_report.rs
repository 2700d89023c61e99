// The lines `examples/predict.rs` prints, the same on the host and on every target: integers
// only (formatting floats would pull ~30 KB of core::fmt into the firmware).

use contact_bounce::{
    catalogue, tiers::DEFAULT_MAX_IMPACTS, window::window_ticks, Float, Margin, Method, Nodes,
    Tolerance, Window,
};
use core::fmt::Write;

/// The tactile dome's window at compile time: t_b1 widened by its worst atan error (8 % at
/// j0 <= 1, x/atan(x) - 1 with x = j0/2 = 0.175: 1 %) and 50 %, in 10 us ticks.
const DOME_TICKS: u32 =
    match contact_bounce::window::preload_bounce_time(5e-5, 5000.0, 1.0, 0.5, 0.7) {
        Ok(t) => match window_ticks(t.seconds, 1.5, 10e-6) {
            Ok(ticks) => ticks,
            Err(_) => panic!("window does not fit"),
        },
        Err(_) => panic!("bad switch parameters"),
    };

pub fn run(out: &mut impl Write) -> core::fmt::Result {
    let switches = [
        catalogue::REED,
        catalogue::TACTILE_DOME,
        catalogue::SIGNAL_RELAY,
        catalogue::CONTACTOR,
    ];
    for switch in switches {
        let Ok(scene) = switch.scene::<f32>() else {
            writeln!(out, "{}: invalid", switch.name)?;
            continue;
        };
        let auto = Tolerance::new(0.1f32).map(Method::Auto);
        for (tag, method) in [
            (
                "map",
                Ok(Method::Map {
                    max_impacts: DEFAULT_MAX_IMPACTS,
                }),
            ),
            ("averaged", Ok(Method::Averaged(Nodes::N8))),
            ("auto", auto),
        ] {
            let Ok(method) = method else { continue };
            let p = scene.predict(method);
            let nanoseconds = p.bounce_time().and_then(|t| (t * 1e9).ceil_u32());
            let margin = Margin::none().with_expected_error(&p);
            let ticks = Window::from_prediction(&p, &margin, 10e-6).map(|w| w.ticks());
            match (nanoseconds, ticks) {
                (Some(ns), Ok(ticks)) => writeln!(
                    out,
                    "{} {tag}: bounce {ns} ns, window {ticks} x 10 us",
                    switch.name
                )?,
                _ => writeln!(out, "{} {tag}: no finite window", switch.name)?,
            }
        }
    }
    writeln!(out, "tactile dome const: window {DOME_TICKS} x 10 us")
}

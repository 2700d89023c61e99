// The lines `examples/predict.rs` prints, the same on the host and on every target: integers
// only (formatting floats would pull ~30 KB of core::fmt into the firmware).

use contact_bounce::{
    scene::catalogue, tiers::DEFAULT_MAX_IMPACTS, Float, Margin, Method, Nodes, Tolerance, Window,
};
use core::fmt::Write;

#[path = "dome_window.rs"]
mod dome_window;
use dome_window::DOME_TICKS;

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

// The lines `examples/uno.rs` prints (on the Uno and on the host): for two switches, the map's
// impacts walked one by one with `MapImpacts` and its Zeno tail (the map tier's end time, with
// none of the averaged model linked), and a compile-time window. The full `predict` report
// (three tiers) needs more AVR flash than the Uno's 32 KB (`uno_cost_closed_map` in
// docs/reports/cost-report.md).

use contact_bounce::{scene::catalogue, tiers::MapImpacts, tiers::DEFAULT_MAX_IMPACTS, Float};
use core::fmt::Write;

#[path = "dome_window.rs"]
mod dome_window;
use dome_window::DOME_TICKS;

pub fn run(out: &mut impl Write) -> core::fmt::Result {
    for switch in [catalogue::TACTILE_DOME, catalogue::SIGNAL_RELAY] {
        let Ok(scene) = switch.scene::<f32>() else {
            writeln!(out, "{}: invalid", switch.name)?;
            continue;
        };
        let mut impacts = MapImpacts::new(&scene, DEFAULT_MAX_IMPACTS);
        let (mut count, mut last) = (0_u32, 0.0_f32);
        for impact in impacts.by_ref() {
            count = count.saturating_add(1);
            last = impact.time;
        }
        let end = impacts.zeno_tail_time().map(|tail| last + tail);
        // A 1.5x margin, in 10 us ticks, rounded up.
        match end
            .and_then(|t| (t * 1e9).ceil_u32())
            .zip(end.and_then(|t| (t * 1.5 / 10e-6).ceil_u32()))
        {
            Some((ns, ticks)) => writeln!(
                out,
                "{}: {count} impacts, then Zeno: bounce {ns} ns, window {ticks} x 10 us",
                switch.name
            )?,
            None => writeln!(out, "{}: {count} impacts, no Zeno end", switch.name)?,
        }
    }
    writeln!(out, "tactile dome const: window {DOME_TICKS} x 10 us")
}

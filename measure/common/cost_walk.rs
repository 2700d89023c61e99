// Measured on the Uno: scene validation, the map's impacts walked with `MapImpacts` and its
// Zeno tail (what fits the Uno: the map's full prediction links the averaged hand-over), then
// 1000 debouncer samples, ours and debouncr's (16-sample), and the sample loop alone.

use contact_bounce::{scene::catalogue, tiers::MapImpacts, tiers::DEFAULT_MAX_IMPACTS};
use core::hint::black_box;

pub fn run(mark: extern "C" fn(u8)) {
    let switch = black_box(catalogue::TACTILE_DOME);
    mark(0);
    let scene = switch.scene::<f32>();
    mark(1);
    if let Ok(scene) = scene {
        let scene = black_box(scene);
        let mut impacts = MapImpacts::new(&scene, DEFAULT_MAX_IMPACTS);
        let mut last = 0.0_f32;
        for impact in impacts.by_ref() {
            last = impact.time;
        }
        black_box(impacts.zeno_tail_time().map(|tail| last + tail));
        mark(2);
    }
    super::debouncers::run(|id| mark(id), 3);
}

// Measured on the Uno: scene validation, the map's impacts walked with `MapImpacts` and its
// Zeno tail (what fits the Uno: the map's full prediction links the averaged hand-over), then
// 1000 debouncer samples, ours and debouncr's (16-sample), and the sample loop alone.

use contact_bounce::{catalogue, MapImpacts, Mode, State, Windows, DEFAULT_MAX_IMPACTS};
use core::hint::black_box;

fn samples(mut seed: u32) -> impl Iterator<Item = bool> {
    (0..1000).map(move |_| {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        seed & 0x7 != 0
    })
}

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
    if let Ok(windows) = Windows::new(black_box(12), black_box(12), Mode::Confirm) {
        let mut state = State::new(false);
        mark(3);
        for s in samples(black_box(0x1234_5678)) {
            black_box(state.update(black_box(s), &windows));
        }
        mark(4);
    }
    let mut theirs = debouncr::debounce_16(false);
    mark(5);
    for s in samples(black_box(0x1234_5678)) {
        black_box(theirs.update(black_box(s)));
    }
    mark(6);
    for s in samples(black_box(0x1234_5678)) {
        black_box(s);
    }
    mark(7);
}

// Measured on the Uno: scene validation, the closed and map tiers, then 1000 debouncer samples,
// ours and debouncr's (16-sample), and the sample loop alone.

use contact_bounce::{catalogue, Method, Mode, State, Windows, DEFAULT_MAX_IMPACTS};
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
        black_box(scene.predict(black_box(Method::Closed)));
        mark(2);
        black_box(scene.predict(black_box(Method::Map {
            max_impacts: DEFAULT_MAX_IMPACTS,
        })));
        mark(3);
    }
    if let Ok(windows) = Windows::new(black_box(12), black_box(12), Mode::Confirm) {
        let mut state = State::new(false);
        mark(4);
        for s in samples(black_box(0x1234_5678)) {
            black_box(state.update(black_box(s), &windows));
        }
        mark(5);
    }
    let mut theirs = debouncr::debounce_16(false);
    mark(6);
    for s in samples(black_box(0x1234_5678)) {
        black_box(theirs.update(black_box(s)));
    }
    mark(7);
    for s in samples(black_box(0x1234_5678)) {
        black_box(s);
    }
    mark(8);
}

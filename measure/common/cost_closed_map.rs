// Measured on the Uno: scene validation, the closed and map tiers, then 1000 debouncer samples,
// ours and debouncr's (16-sample), and the sample loop alone.

use contact_bounce::{scene::catalogue, tiers::DEFAULT_MAX_IMPACTS, Method};
use core::hint::black_box;

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
    super::debouncers::run(|id| mark(id), 4);
}

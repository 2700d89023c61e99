// Measured on the Uno: scene validation, then the exact tier (the method is a constant, so
// only the exact tier is linked).

use contact_bounce::{scene::catalogue, tiers::EXACT_MAX_IMPACTS, Method};
use core::hint::black_box;

pub fn run(mark: extern "C" fn(u8)) {
    let switch = black_box(catalogue::TACTILE_DOME);
    mark(0);
    let scene = switch.scene::<f32>();
    mark(1);
    if let Ok(scene) = scene {
        let scene = black_box(scene);
        black_box(scene.predict(Method::Exact {
            max_impacts: EXACT_MAX_IMPACTS,
        }));
        mark(2);
    }
}

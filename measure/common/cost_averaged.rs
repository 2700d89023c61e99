// Measured on the Uno: scene validation, then the averaged tier with 4 and with 8 nodes.

use contact_bounce::{scene::catalogue, Method, Nodes};
use core::hint::black_box;

pub fn run(mark: extern "C" fn(u8)) {
    let switch = black_box(catalogue::TACTILE_DOME);
    mark(0);
    let scene = switch.scene::<f32>();
    mark(1);
    if let Ok(scene) = scene {
        let scene = black_box(scene);
        black_box(scene.predict(black_box(Method::Averaged(Nodes::N4))));
        mark(2);
        black_box(scene.predict(black_box(Method::Averaged(Nodes::N8))));
        mark(3);
    }
}

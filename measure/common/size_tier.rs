// The body of the per-tier size firmware: the tactile dome (viscous, f32) predicted with one
// tier, inputs hidden from the optimiser. `METHOD` comes from the example including this.

use contact_bounce::{scene::catalogue, Margin, Window};
use core::hint::black_box;

pub fn run(method: contact_bounce::Method<f32>) -> u32 {
    match black_box(catalogue::TACTILE_DOME).scene::<f32>() {
        Ok(scene) => {
            // The method stays visible to the optimiser: only its tier is linked.
            let prediction = scene.predict(method);
            Window::from_prediction(&prediction, &Margin::none(), black_box(1e-6))
                .map_or(0, |w| w.ticks())
        }
        Err(_) => u32::MAX,
    }
}

//! Flash cost of the averaged tier for a hereditary scene (`Scene<f32, Hereditary<f32>>`).
//!
//! Built by `scripts/size-report.sh` beside `size_restitution`: the difference is what an
//! exponential relaxation kernel costs (its harmonic sum needs atan, no sin). On the host it is an empty
//! program.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
mod firmware {
    use contact_bounce::{
        Contact, Frequency, Hereditary, Margin, Method, Nodes, Offset, Restitution, Scene,
        Threshold, Window,
    };
    use core::hint::black_box;
    use cortex_m as _;
    use panic_halt as _;

    #[cortex_m_rt::entry]
    fn main() -> ! {
        // The tactile dome of docs/physics.md sec. 7, opaque to the optimiser.
        let contact = Contact {
            frequency: Frequency::MassStiffness {
                mass: black_box(5e-5_f32),
                stiffness: black_box(5000.0),
            },
            offset: Offset::PreloadForce(black_box(1.0)),
            restitution: Restitution::Coefficient(black_box(0.7)),
            closing_speed: black_box(0.5),
            threshold: Threshold::None,
        };
        let ticks = match Hereditary::exponential(black_box(1e9), black_box(1e-5))
            .and_then(|kernel| Scene::new(contact, kernel))
        {
            Ok(scene) => {
                let prediction = scene.predict(Method::Averaged(Nodes::N8));
                Window::from_prediction(&prediction, &Margin::none(), black_box(1e-6))
                    .map_or(0, |w| w.ticks())
            }
            Err(_) => u32::MAX,
        };
        black_box(ticks);
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {}

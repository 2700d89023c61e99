//! What each tier, and Auto, costs on each switch of the catalogue on a Cortex-M4F:
//! `scripts/cost-report.sh` runs this under QEMU with an instruction trace and counts the
//! instructions between calls of `cost_mark`. In f32: the eight catalogue switches, the tactile
//! dome with R = 0.9 and 0.95 (more impacts), and the dome with a relaxation kernel instead of
//! viscous damping (five kernels and restitutions). Per scene: validation, then closed, averaged
//! N8, the map, the exact tier, Auto at 10 % and at 1 %. `Method::Auto` weighs the tiers by
//! costs measured here (`src/tiers/method.rs`, `src/tiers/exact/mod.rs`). On the host it does nothing.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
mod firmware {
    use contact_bounce::{
        scene::catalogue, tiers::DEFAULT_MAX_IMPACTS, tiers::EXACT_MAX_IMPACTS, Contact, Frequency,
        Hereditary, Method, Nodes, Offset, Restitution, Scene, Threshold, Tolerance, Viscous,
    };
    use core::hint::black_box;
    use cortex_m as _;
    use cortex_m_semihosting::debug;
    use panic_halt as _;

    /// The marker: the instructions between two calls are one measurement.
    #[inline(never)]
    #[no_mangle]
    pub extern "C" fn cost_mark(id: u32) {
        black_box(id);
    }

    /// The tiers, in the report's column order, each followed by a mark.
    fn tiers<D: contact_bounce::scene::Dissipation<f32>, S: contact_bounce::scene::OffsetSign>(
        scene: &Scene<f32, D, S>,
    ) {
        let scene = black_box(scene);
        let (Ok(ten), Ok(one)) = (Tolerance::new(0.1f32), Tolerance::new(0.01f32)) else {
            return;
        };
        let methods = [
            Method::Closed,
            Method::Averaged(Nodes::N8),
            Method::Map {
                max_impacts: DEFAULT_MAX_IMPACTS,
            },
            Method::Exact {
                max_impacts: EXACT_MAX_IMPACTS,
            },
            Method::Auto(ten),
            Method::Auto(one),
        ];
        for method in methods {
            black_box(scene.predict(black_box(method)));
            cost_mark(2);
        }
    }

    /// The tactile dome's contact with restitution `r`.
    fn dome(r: f32) -> Contact<f32> {
        Contact {
            frequency: Frequency::MassStiffness {
                mass: black_box(5e-5),
                stiffness: black_box(5000.0),
            },
            offset: Offset::PreloadForce(black_box(1.0)),
            restitution: Restitution::Coefficient(black_box(r)),
            closing_speed: black_box(0.5),
            threshold: Threshold::None,
        }
    }

    #[cortex_m_rt::entry]
    fn main() -> ! {
        cost_mark(0);
        for switch in &catalogue::ALL {
            let scene = black_box(switch).scene::<f32>();
            cost_mark(1);
            if let Ok(scene) = scene {
                tiers(&scene);
            }
        }
        for r in [0.9, 0.95] {
            let scene = Viscous::new(black_box(0.03)).and_then(|v| Scene::new_preload(dome(r), v));
            cost_mark(1);
            if let Ok(scene) = scene {
                tiers(&scene);
            }
        }
        for (kappa, tau, r) in [
            (1e9, 1e-5, 0.7),
            (3e8, 3e-4, 0.7),
            (1e9, 1e-5, 0.9),
            (1e9, 1e-5, 0.5),
            (3e9, 1e-6, 0.7),
        ] {
            let scene = Hereditary::exponential(black_box(kappa), black_box(tau))
                .and_then(|k| Scene::new_preload(dome(r), k));
            cost_mark(1);
            if let Ok(scene) = scene {
                tiers(&scene);
            }
        }
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {}

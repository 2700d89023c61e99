//! What each tier costs on a Cortex-M: `scripts/cost-report.sh` runs this under QEMU with an
//! instruction trace and counts the instructions between calls of `cost_mark`. The tactile dome
//! of docs/physics.md sec. 7 in f32, each tier once; then 1000 debouncer samples, ours and
//! debouncr's (its 16-sample debouncer), on the same pseudo-random input. On the host it does
//! nothing.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
#[path = "common/debouncer_cost.rs"]
#[allow(dead_code)] // `run_learner` is cost_learner's
mod debouncers;

#[cfg(target_os = "none")]
mod firmware {
    use contact_bounce::{
        scene::catalogue, tiers::DEFAULT_MAX_IMPACTS, tiers::EXACT_MAX_IMPACTS, Method, Nodes,
        Tolerance,
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

    #[cortex_m_rt::entry]
    fn main() -> ! {
        let switch = black_box(catalogue::TACTILE_DOME);
        cost_mark(0);
        let scene = switch.scene::<f32>();
        cost_mark(1); // 0 -> 1: validating the scene
        if let Ok(scene) = scene {
            let scene = black_box(scene);
            let tolerance = Tolerance::new(black_box(0.1f32));
            for method in [
                Method::Closed,
                Method::Averaged(Nodes::N4),
                Method::Averaged(Nodes::N8),
                Method::Map {
                    max_impacts: DEFAULT_MAX_IMPACTS,
                },
                Method::Exact {
                    max_impacts: EXACT_MAX_IMPACTS,
                },
            ] {
                black_box(scene.predict(black_box(method)));
                cost_mark(2);
            }
            if let Ok(t) = tolerance {
                black_box(scene.predict(Method::Auto(t)));
            }
            cost_mark(3);
        }
        super::debouncers::run(|id| cost_mark(u32::from(id)), 4);
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {}

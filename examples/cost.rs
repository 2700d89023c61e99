//! What each tier costs on a Cortex-M: `scripts/cost-report.sh` runs this under QEMU with an
//! instruction trace and counts the instructions between calls of `cost_mark`. The tactile dome
//! of physics.md sec. 7 in f32, each tier once; then 1000 debouncer samples, ours and
//! debouncr's (its 16-sample debouncer), on the same pseudo-random input. On the host it does
//! nothing.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
mod firmware {
    use contact_bounce::{
        catalogue, Method, Mode, Nodes, State, Tolerance, Windows, DEFAULT_MAX_IMPACTS,
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

    /// 1000 samples of a bouncing input (a 32-bit LFSR, biased to runs).
    fn samples(mut seed: u32) -> impl Iterator<Item = bool> {
        (0..1000).map(move |_| {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed & 0x7 != 0
        })
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
            ] {
                black_box(scene.predict(black_box(method)));
                cost_mark(2);
            }
            if let Ok(t) = tolerance {
                black_box(scene.predict(Method::Auto(t)));
            }
            cost_mark(3);
        }
        if let Ok(windows) = Windows::new(black_box(12), black_box(12), Mode::Confirm) {
            let mut state = State::new(false);
            cost_mark(4);
            for s in samples(black_box(0x1234_5678)) {
                black_box(state.update(black_box(s), &windows));
            }
            cost_mark(5);
        }
        let mut theirs = debouncr::debounce_16(false);
        cost_mark(6);
        for s in samples(black_box(0x1234_5678)) {
            black_box(theirs.update(black_box(s)));
        }
        cost_mark(7);
        // The loop alone: the samples without a debouncer.
        for s in samples(black_box(0x1234_5678)) {
            black_box(s);
        }
        cost_mark(8);
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {}

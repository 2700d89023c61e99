//! What the learning debouncer costs on a Cortex-M: `scripts/cost-report.sh` runs this under
//! QEMU with an instruction trace and counts the instructions between calls of `cost_mark`:
//! the learner on a bouncing input, and the idle path (a settled contact) through our
//! debouncer and the learner (`common/debouncer_cost.rs`). Apart from `cost.rs`, so that each
//! debouncer is measured as a firmware that uses it alone would inline it. On the host it does
//! nothing.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
#[path = "common/debouncer_cost.rs"]
#[allow(dead_code)] // `run` is cost's
mod debouncers;

#[cfg(target_os = "none")]
mod firmware {
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
        cost_mark(0);
        super::debouncers::run_learner(|id| cost_mark(u32::from(id)), 1);
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {}

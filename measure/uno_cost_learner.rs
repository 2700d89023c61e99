//! What the learning debouncer costs on the Arduino Uno: `scripts/cost-report.sh` runs this in
//! libsimavr and counts the exact cycles between calls of `cost_mark` (tools/simavr-cycles.c):
//! the learner on a bouncing input, and the idle path (a settled contact) through our
//! debouncer and the learner (`common/debouncer_cost.rs`). On the host it does nothing.
#![cfg_attr(target_arch = "avr", no_std, no_main, feature(asm_experimental_arch))]

#[cfg(target_arch = "avr")]
#[path = "../examples/common/avr.rs"]
#[allow(dead_code)] // the UART is not used here
mod avr;

#[cfg(target_arch = "avr")]
#[path = "common/debouncer_cost.rs"]
#[allow(dead_code)] // `run` is uno_cost's
mod debouncers;

#[cfg(target_arch = "avr")]
mod firmware {
    /// The marker: the cycles between two calls are one measurement.
    #[inline(never)]
    #[no_mangle]
    pub extern "C" fn cost_mark(id: u8) {
        core::hint::black_box(id);
    }

    #[no_mangle]
    pub extern "C" fn main() -> ! {
        cost_mark(0);
        super::debouncers::run_learner(|id| cost_mark(id), 1);
        super::avr::halt()
    }
}

#[cfg(not(target_arch = "avr"))]
fn main() {}

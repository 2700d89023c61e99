//! What the model costs on the Arduino Uno: `scripts/cost-report.sh` runs this in libsimavr
//! and counts the exact cycles between calls of `cost_mark` (tools/simavr-cycles.c): the
//! tactile dome of docs/physics.md sec. 7 in f32, walked with `MapImpacts`, and the debouncers. On
//! the host it does nothing.
#![cfg_attr(target_arch = "avr", no_std, no_main, feature(asm_experimental_arch))]

#[cfg(target_arch = "avr")]
#[path = "../examples/common/avr.rs"]
#[allow(dead_code)] // the UART is not used here
mod avr;

#[cfg(target_arch = "avr")]
#[path = "common/cost_walk.rs"]
mod measured;

#[cfg(target_arch = "avr")]
#[path = "common/debouncer_cost.rs"]
#[allow(dead_code)] // `run_learner` is uno_cost_learner's
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
        super::measured::run(cost_mark);
        super::avr::halt()
    }
}

#[cfg(not(target_arch = "avr"))]
fn main() {}

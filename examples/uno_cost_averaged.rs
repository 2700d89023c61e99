//! Does the averaged tier fit the Arduino Uno? `scripts/cost-report.sh` builds this for the Uno and
//! reports how much flash it needs (the linker says by how much it overflows the 32 KB); in
//! f32, for the tactile dome of docs/physics.md sec. 7, between calls of `cost_mark`. On the host it
//! does nothing.
#![cfg_attr(target_arch = "avr", no_std, no_main, feature(asm_experimental_arch))]

#[cfg(target_arch = "avr")]
#[path = "common/avr.rs"]
#[allow(dead_code)] // the UART is not used here
mod avr;

#[cfg(target_arch = "avr")]
#[path = "common/cost_averaged.rs"]
mod measured;

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

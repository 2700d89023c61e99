//! `Method::Auto` and the debouncer on an Arduino Uno (ATmega328P), printed over the UART: the
//! signal relay modelled with restitution only (a `Scene<f32, Undamped>`, so none of the damped
//! code is linked), Auto at 10 %, its window, and a recorded press of the relay through the
//! debouncer in both modes (`common/trace_report.rs`, the lines `debounce_trace` prints for the
//! relay with its damping). Auto on a damped scene links every damped tier and does not fit
//! the Uno's 32 KB (`auto` in docs/reports/cost-report.md).
//!
//! Build with the nightly toolchain for `avr-none` (`scripts/uno.sh` does it and runs it in
//! simavr); on the host it prints the same lines, which is what CI compares.
#![cfg_attr(target_arch = "avr", no_std, no_main, feature(asm_experimental_arch))]

#[path = "common/trace_report.rs"]
mod report;

#[cfg(target_arch = "avr")]
#[path = "common/avr.rs"]
mod avr;

#[cfg(target_arch = "avr")]
mod firmware {
    use super::avr::{halt, Uart};
    use core::fmt::Write;

    #[no_mangle]
    pub extern "C" fn main() -> ! {
        let mut uart = Uart::init();
        if super::report::run_restitution_only(&mut uart).is_err() {
            let _ = uart.write_str("report failed\n");
        }
        let _ = uart.write_str("done\n");
        halt()
    }
}

#[cfg(not(target_arch = "avr"))]
fn main() {
    let mut out = String::new();
    if report::run_restitution_only(&mut out).is_err() {
        std::process::exit(1);
    }
    println!("{out}done");
}

//! Predictions on an Arduino Uno (ATmega328P), printed over the UART: the map tier for two
//! switches of docs/physics.md sec. 7 and a compile-time window (`common/uno_report.rs`).
//!
//! Build with the nightly toolchain for `avr-none` (`scripts/uno.sh` does it and runs it in
//! simavr); on the host it prints the same lines, which is what CI compares.
#![cfg_attr(target_arch = "avr", no_std, no_main, feature(asm_experimental_arch))]

#[path = "common/uno_report.rs"]
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
        if super::report::run(&mut uart).is_err() {
            let _ = uart.write_str("report failed\n");
        }
        let _ = uart.write_str("done\n");
        halt()
    }
}

#[cfg(not(target_arch = "avr"))]
fn main() {
    let mut out = String::new();
    if report::run(&mut out).is_err() {
        std::process::exit(1);
    }
    println!("{out}done");
}

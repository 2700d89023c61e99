//! The learning debouncer on an Arduino Uno (ATmega328P), printed over the UART: a recorded
//! relay press, pressed and released 12 times from a prior (`common/learn_report.rs`, the lines
//! `debounce_trace` prints after its own under QEMU).
//!
//! Build with the nightly toolchain for `avr-none` (`scripts/uno.sh` does it and runs it in
//! simavr); on the host it prints the same lines, which is what CI compares.
#![cfg_attr(target_arch = "avr", no_std, no_main, feature(asm_experimental_arch))]

#[path = "common/learn_report.rs"]
mod learn;

#[path = "data/relay_press.rs"]
#[allow(dead_code)]
mod data;

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
        if super::learn::run(&mut uart, &super::data::BITS, super::data::SAMPLES).is_err() {
            let _ = uart.write_str("report failed\n");
        }
        let _ = uart.write_str("done\n");
        halt()
    }
}

#[cfg(not(target_arch = "avr"))]
fn main() {
    let mut out = String::new();
    if learn::run(&mut out, &data::BITS, data::SAMPLES).is_err() {
        std::process::exit(1);
    }
    println!("{out}done");
}

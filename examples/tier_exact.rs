//! Cost firmware: the exact tier. Built by `scripts/cost-report.sh` for thumbv6m, thumbv7em and the
//! Uno (the skeleton is `common/tier_firmware.rs`); on the host it is an empty program.
#![cfg_attr(any(target_os = "none", target_arch = "avr"), no_std, no_main)]
#![cfg_attr(target_arch = "avr", feature(asm_experimental_arch))]

#[cfg(target_arch = "avr")]
#[path = "common/avr.rs"]
#[allow(dead_code)] // the UART is not used here
mod avr;

#[cfg(any(target_os = "none", target_arch = "avr"))]
#[path = "common/tier_firmware.rs"]
mod firmware;

#[cfg(any(target_os = "none", target_arch = "avr"))]
fn work() {
    firmware::measure(|scene| {
        firmware::window_of(
            scene,
            contact_bounce::Method::Exact {
                max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
            },
        )
    });
}

#[cfg(not(any(target_os = "none", target_arch = "avr")))]
fn main() {}

//! Cost firmware: the lean closed form `preload_viscous_bounce_seconds` (t_b1v: restitution and viscous damping, no `Scene`, no expected error) and its window, nothing else. Built by `scripts/cost-report.sh` for thumbv6m, thumbv7em and the
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
    firmware::measure_without_scene(|| {
        // The dome as f32 constants, hidden from the optimiser.
        let d = core::hint::black_box(firmware::DOME);
        contact_bounce::tiers::preload_viscous_bounce_seconds(&d)
            .and_then(|time| {
                contact_bounce::Window::from_seconds(
                    time,
                    &contact_bounce::Margin::none(),
                    core::hint::black_box(1e-5),
                )
            })
            .map_or(0, |w| w.ticks())
    });
}

#[cfg(not(any(target_os = "none", target_arch = "avr")))]
fn main() {}

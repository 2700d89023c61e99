//! Cost firmware: Auto at 1 % on the dome without its damping: a restitution-only scene, whose type links no damping (every tier Auto may choose is linked, each for restitution only). Built by `scripts/cost-report.sh` for thumbv6m, thumbv7em and the
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
    firmware::measure_undamped(|scene| {
        contact_bounce::Tolerance::new(core::hint::black_box(0.01_f32)).map_or(u32::MAX, |t| {
            firmware::window(&scene.predict(contact_bounce::Method::Auto(t)))
        })
    });
}

#[cfg(not(any(target_os = "none", target_arch = "avr")))]
fn main() {}

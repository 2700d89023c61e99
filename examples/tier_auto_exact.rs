//! Cost firmware: Auto at 1 % among the closed forms and the exact tier alone
//! (`Scene::predict_auto_among::<{ AutoTiers::EXACT }>`: no map, no averaged quadrature linked). Built by `scripts/cost-report.sh` for thumbv6m, thumbv7em and the
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
        contact_bounce::Tolerance::new(core::hint::black_box(0.01_f32)).map_or(u32::MAX, |t| {
            firmware::window(
                &scene.predict_auto_among::<{ contact_bounce::tiers::AutoTiers::EXACT }>(t),
            )
        })
    });
}

#[cfg(not(any(target_os = "none", target_arch = "avr")))]
fn main() {}

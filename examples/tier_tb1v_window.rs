//! Cost firmware: the lean closed form `preload_viscous_bounce_time` (t_b1v: restitution and viscous damping, no `Scene`) and its window, nothing else. Built by `scripts/cost-report.sh` for thumbv6m, thumbv7em and the
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
    // The dome's values as f32 constants (as firmware would write them), hidden from the
    // optimiser: no f64 catalogue and no conversion in the firmware.
    const D: contact_bounce::catalogue::Typical = contact_bounce::catalogue::TACTILE_DOME;
    #[allow(clippy::cast_possible_truncation)]
    const INPUTS: [f32; 6] = [
        D.mass as f32,
        D.stiffness as f32,
        D.preload_force as f32,
        D.closing_speed as f32,
        D.restitution as f32,
        D.damping_ratio as f32,
    ];
    firmware::measure_without_scene(|| {
        let [m, k, f, v, r, z] = core::hint::black_box(INPUTS);
        contact_bounce::tiers::preload_viscous_bounce_time(m, k, f, v, r, z)
            .and_then(|e| {
                contact_bounce::Window::from_seconds(
                    e.time,
                    &contact_bounce::Margin::none(),
                    core::hint::black_box(1e-5),
                )
            })
            .map_or(0, |w| w.ticks())
    });
}

#[cfg(not(any(target_os = "none", target_arch = "avr")))]
fn main() {}

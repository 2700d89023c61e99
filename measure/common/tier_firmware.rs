// The skeleton of the per-tier cost firmware (`measure/tier_*.rs`): the tactile dome of
// docs/physics.md sec. 7 written as f32 constants (as firmware writes its switch: no f64
// catalogue converted at run time), its inputs hidden from the optimiser; `cost_mark(0)`, the scene
// validated, typed as the preload it is (`Preloaded::scene`, `Scene::new_preload`: no gap's code
// is linked), `cost_mark(1)`, the example's `work` (one tier, named as a constant, so only that
// tier is linked), `cost_mark(2)`, its result stored to a volatile. `scripts/cost-report.sh`
// counts instructions (QEMU) or cycles (simavr) between the marks, and takes the crate's share
// of flash as this firmware's text minus `tier_empty`'s (the same skeleton, no crate code).

use contact_bounce::scene::{Dissipation, OffsetSign, Preload};
use contact_bounce::{
    scene::catalogue, Margin, Method, Prediction, Preloaded, Scene, Undamped, Viscous, Window,
};
use core::hint::black_box;

/// The tactile dome's six numbers, rounded to f32 when the firmware is compiled.
#[allow(clippy::cast_possible_truncation)]
pub const DOME: Preloaded<f32> = {
    let d = catalogue::TACTILE_DOME;
    Preloaded {
        mass: d.mass as f32,
        stiffness: d.stiffness as f32,
        preload_force: d.preload_force as f32,
        closing_speed: d.closing_speed as f32,
        restitution: d.restitution as f32,
        damping_ratio: d.damping_ratio as f32,
    }
};

/// The marker: the instructions (cycles) between two calls are one measurement.
#[inline(never)]
#[no_mangle]
pub extern "C" fn cost_mark(id: u8) {
    black_box(id);
}

/// The window of a prediction at 10 us samples, no margin (0 where it has no end).
#[allow(dead_code)] // not every tier firmware asks a prediction
pub fn window(prediction: &Prediction<f32>) -> u32 {
    Window::from_prediction(prediction, &Margin::none(), black_box(1e-5)).map_or(0, |w| w.ticks())
}

/// The window of a scene's bounce time by one method at 10 us samples, no margin (0 where it
/// has no end): `Window::from_scene`, which links no counts and no expected error.
#[allow(dead_code)] // not every tier firmware asks for it
pub fn window_of<D: Dissipation<f32>, S: OffsetSign>(
    scene: &Scene<f32, D, S>,
    method: Method<f32>,
) -> u32 {
    Window::from_scene(scene, method, &Margin::none(), black_box(1e-5)).map_or(0, |w| w.ticks())
}

/// The marks around `work`, with no scene (`tier_empty`, and the lean closed form).
#[allow(dead_code)]
pub fn measure_without_scene(work: impl FnOnce() -> u32) {
    cost_mark(0);
    cost_mark(1);
    let ticks = work();
    cost_mark(2);
    let mut out = 0_u32;
    // SAFETY: a valid, aligned local.
    unsafe { core::ptr::write_volatile(&mut out, ticks) };
}

/// Validates the dome and runs `work` on it between the marks.
#[allow(dead_code)]
pub fn measure(work: impl FnOnce(&Scene<f32, Viscous<f32>, Preload>) -> u32) {
    let switch = black_box(DOME);
    cost_mark(0);
    let scene = switch.scene();
    cost_mark(1);
    finish(scene.map(|scene| work(&black_box(scene))));
}

/// Validates the dome without its damping (a `Scene<f32, Undamped, Preload>`, whose type links
/// no damping and no gap) and runs `work` on it between the marks.
#[allow(dead_code)]
pub fn measure_undamped(work: impl FnOnce(&Scene<f32, Undamped, Preload>) -> u32) {
    let switch = black_box(DOME);
    cost_mark(0);
    let scene = Scene::new_preload(switch.contact(), Undamped);
    cost_mark(1);
    finish(scene.map(|scene| work(&black_box(scene))));
}

/// The last mark, and the result (`u32::MAX` for an invalid scene) stored to a volatile.
fn finish<E>(ticks: Result<u32, E>) {
    let ticks = ticks.unwrap_or(u32::MAX);
    cost_mark(2);
    let mut out = 0_u32;
    // SAFETY: a valid, aligned local.
    unsafe { core::ptr::write_volatile(&mut out, ticks) };
}

#[cfg(target_arch = "arm")]
mod entry {
    use cortex_m as _;
    use cortex_m_semihosting::debug;
    use panic_halt as _;

    #[cortex_m_rt::entry]
    fn main() -> ! {
        crate::work();
        debug::exit(debug::EXIT_SUCCESS);
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(target_arch = "avr")]
mod entry {
    #[no_mangle]
    pub extern "C" fn main() -> ! {
        crate::work();
        crate::avr::halt()
    }
}

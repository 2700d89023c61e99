// The lines `examples/debounce_trace.rs` (and, for the relay without its damping,
// `examples/uno_auto.rs`) print, the same on the host and on every target.

#[path = "../data/relay_press.rs"]
#[allow(dead_code)]
pub mod data;

use contact_bounce::scene::OffsetSign;
use contact_bounce::{
    debounce::Polarity, scene::catalogue, scene::Dissipation, Debouncer, Float, Margin, Method,
    Mode, Scene, Tolerance, Undamped, Window, Windows,
};
use core::convert::Infallible;
use core::fmt::Write;
use embedded_hal::digital::{ErrorType, InputPin};

/// An active-low pin replaying the recorded samples (closed reads low), then staying closed.
struct Replay {
    next: usize,
}

impl ErrorType for Replay {
    type Error = Infallible;
}

impl InputPin for Replay {
    fn is_high(&mut self) -> Result<bool, Infallible> {
        let k = self.next;
        self.next += 1;
        let closed = match data::BITS.get(k / 32) {
            Some(word) if k < data::SAMPLES => word >> (k % 32) & 1 == 1,
            _ => true,
        };
        Ok(!closed)
    }
    fn is_low(&mut self) -> Result<bool, Infallible> {
        self.is_high().map(|high| !high)
    }
}

fn run_one(out: &mut impl Write, label: &str, windows: Windows) -> core::fmt::Result {
    let Ok(mut button) = Debouncer::new(Replay { next: 0 }, windows, Polarity::ActiveLow);
    write!(out, "{label} ({} samples):", windows.press())?;
    for k in 1..data::SAMPLES + 400 {
        let Ok(edge) = button.update();
        if let Some(edge) = edge {
            write!(out, " {edge:?}@{k}")?;
        }
    }
    writeln!(out)
}

/// The signal relay as the catalogue gives it (restitution and viscous damping).
#[allow(dead_code)] // each example runs one of the two
pub fn run(out: &mut impl Write) -> core::fmt::Result {
    match catalogue::SIGNAL_RELAY.scene::<f32>() {
        Ok(scene) => run_scene(out, &scene),
        Err(_) => writeln!(out, "invalid scene"),
    }
}

/// The signal relay with restitution only (`Scene<f32, Undamped>`: none of the damped code is
/// linked). Leaving damping out only lengthens a preload's predicted bounce, so its window
/// still covers the recorded (damped) press.
#[allow(dead_code)] // each example runs one of the two
pub fn run_restitution_only(out: &mut impl Write) -> core::fmt::Result {
    match Scene::new(
        catalogue::SIGNAL_RELAY.preloaded::<f32>().contact(),
        Undamped,
    ) {
        Ok(scene) => run_scene(out, &scene),
        Err(_) => writeln!(out, "invalid scene"),
    }
}

/// Auto at 10 % on `scene`, its window at the trace's sampling period widened by the
/// expected error, and the recorded press through the debouncer in both modes, beside a guessed
/// short hold-off.
fn run_scene<D: Dissipation<f32>, S: OffsetSign>(
    out: &mut impl Write,
    scene: &Scene<f32, D, S>,
) -> core::fmt::Result {
    let period = f32::from(u16::try_from(data::PERIOD_NS).unwrap_or(u16::MAX)) * 1e-9;
    let Ok(tolerance) = Tolerance::new(0.1f32) else {
        return writeln!(out, "invalid tolerance");
    };
    let p = scene.predict(Method::Auto(tolerance));
    let margin = Margin::none().with_expected_error(&p);
    let Ok(window) = Window::from_prediction(&p, &margin, period) else {
        return writeln!(out, "no finite window");
    };
    // The bounce in whole nanoseconds, and the expected error in parts per million.
    let ns = p.bounce_time().and_then(|t| (t * 1e9).ceil_u32());
    let ppm = p.expected_error.and_then(|e| (e * 1e6).ceil_u32());
    write!(out, "auto 10 %: {} ({}), ", p.tier.name(), p.regime.name())?;
    match ns {
        Some(ns) => write!(out, "bounce {ns} ns")?,
        None => write!(out, "bounce beyond 2^32 ns")?,
    }
    match ppm {
        Some(ppm) => writeln!(out, ", expected error {ppm} ppm")?,
        None => writeln!(out, ", no expected error")?,
    }
    for (label, ticks, mode) in [
        ("physics confirm", window, Mode::Confirm),
        ("physics hold-off", window, Mode::HoldOff),
        (
            "fixed 0.2 ms hold-off",
            Window::from_ticks(20),
            Mode::HoldOff,
        ),
    ] {
        match Windows::from_windows(ticks, ticks, mode) {
            Ok(windows) => run_one(out, label, windows)?,
            Err(_) => writeln!(out, "{label}: window out of range")?,
        }
    }
    Ok(())
}

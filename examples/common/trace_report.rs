// The lines `examples/debounce_trace.rs` prints, the same on the host and on every target.

#[path = "../data/relay_press.rs"]
#[allow(dead_code)]
pub mod data;

use contact_bounce::{
    catalogue, debounce::Polarity, Debouncer, Margin, Method, Mode, Tolerance, Window, Windows,
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

pub fn run(out: &mut impl Write) -> core::fmt::Result {
    let period = f32::from(u16::try_from(data::PERIOD_NS).unwrap_or(u16::MAX)) * 1e-9;
    let Ok(scene) = catalogue::SIGNAL_RELAY.scene::<f32>() else {
        return writeln!(out, "invalid scene");
    };
    let Ok(tolerance) = Tolerance::new(0.1f32) else {
        return writeln!(out, "invalid tolerance");
    };
    let p = scene.predict(Method::Auto(tolerance));
    let margin = Margin::none().with_expected_error(&p);
    let Ok(window) = Window::from_prediction(&p, &margin, period) else {
        return writeln!(out, "no finite window");
    };
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

//! Bounce traces from the exact reference, sampled and debounced: the checks of the debouncer
//! on physics windows, and the comparison with fixed windows.
//!
//! A press: the contact is open before t = 0; each impact closes it for a dwell (Newton
//! impacts last no time: [`Dwell::None`]; [`Dwell::FractionOfFlight`] is a stand-in for a real
//! contact's finite impact); it is open during flights, and closed from the end of the bounce
//! (the Zeno accumulation) on. Release bounce is not modelled (the physics covers the make).

use contact_bounce::{Edge, Mode, State, Windows};

use crate::reference::{simulate_observed, Failure, OneBody, DEFAULT_BUDGET};

/// How long the contact conducts at each impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Dwell {
    /// Not at all (Newton impacts).
    None,
    /// This fraction of the flight that follows.
    FractionOfFlight(f64),
}

/// A press, as the contact's closed intervals.
#[derive(Debug, Clone)]
pub struct Trace {
    /// Closed intervals [start, end) during the bounce, in time order.
    pub closed: Vec<(f64, f64)>,
    /// The end of the bounce: closed from here on.
    pub end: f64,
}

impl Trace {
    /// A press of `scene` (a preload) by the exact reference.
    ///
    /// # Errors
    /// The reference's failure; [`Failure::Invalid`] when the bounce has no end.
    pub fn press(scene: &OneBody, dwell: Dwell) -> Result<Self, Failure> {
        let mut times = Vec::new();
        let out = simulate_observed(scene, DEFAULT_BUDGET, |t, _| times.push(t))?;
        let end = out
            .end_time
            .ok_or(Failure::Invalid("an endless bounce has no press trace"))?;
        times.push(end);
        let closed = times
            .windows(2)
            .filter_map(|w| match dwell {
                Dwell::None => None,
                Dwell::FractionOfFlight(f) => Some((w[0], w[0] + f * (w[1] - w[0]))),
            })
            .collect();
        Ok(Self { closed, end })
    }

    /// The contact reads closed at time `t`.
    #[must_use]
    pub fn is_closed(&self, t: f64) -> bool {
        if t >= self.end {
            return true;
        }
        let i = self.closed.partition_point(|&(start, _)| start <= t);
        i > 0 && t < self.closed[i - 1].1
    }
}

/// What a debouncer made of a press.
#[derive(Debug, Clone, PartialEq)]
pub struct Debounced {
    /// Edges reported, with their sample times.
    pub edges: Vec<(f64, Edge)>,
    /// Edges beyond the one press a press should give.
    pub false_edges: usize,
    /// When the debounced state became closed for good, after the end of the bounce (s;
    /// negative if before).
    pub settle: f64,
}

/// Samples `trace` every `period` from `phase` (in [0, period)) before t = 0 until well after
/// the bounce and the window, and runs a debouncer with `windows` on it.
#[must_use]
pub fn debounce(trace: &Trace, period: f64, phase: f64, windows: Windows) -> Debounced {
    let mut state = State::new(false);
    let longest = f64::from(windows.press().max(windows.release()) + 2) * period;
    let start = -2.0 * period + phase;
    let stop = trace.end + 2.0 * longest + 4.0 * period;
    let mut edges = Vec::new();
    let mut k = 0_u64;
    loop {
        #[allow(clippy::cast_precision_loss)]
        let t = start + k as f64 * period;
        if t > stop {
            break;
        }
        if let Some(edge) = state.update(trace.is_closed(t), &windows) {
            edges.push((t, edge));
        }
        k += 1;
    }
    let settle = match edges.last() {
        Some(&(t, Edge::Press)) => t - trace.end,
        _ => f64::INFINITY,
    };
    let false_edges = edges.len().saturating_sub(1)
        + usize::from(!matches!(edges.last(), Some((_, Edge::Press))));
    Debounced {
        edges,
        false_edges,
        settle,
    }
}

/// Windows of `seconds` for press and release, at `period`, rounded up.
///
/// # Panics
/// If the window exceeds the debouncer's range (test helper).
#[must_use]
pub fn windows(seconds: f64, period: f64, mode: Mode) -> Windows {
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let ticks = (seconds / period).ceil().max(0.0) as u16;
    Windows::new(ticks, ticks, mode).expect("window in range")
}

//! The debounce windows a capture gives.

use super::fit::BounceModel;
use crate::capture;

/// How events are timed and windows fitted to them: what `calibrate` and `replay` share.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Calibration {
    /// Intervals shorter than this are unresolved (s; `--resolution`).
    pub resolution: f64,
    /// A quiet interval at least this long ends a burst (s; `--burst-gap`).
    pub burst_gap: f64,
    /// The windows' percentile (0..1; `--percentile` divided by 100).
    pub percentile: f64,
    /// The random held-out split's seed (`--seed`).
    pub seed: u64,
    /// No real tap is shorter than this (s): windows are capped at it (`--min-tap`).
    pub min_tap: Option<f64>,
}

/// A debounce window from a capture: the fitted model's predictive percentile, never below
/// the largest bounce observed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CaptureWindow {
    /// The largest bounce observed (s; 0 with no events).
    pub observed: f64,
    /// The percentile of the fitted model's posterior predictive (s): the bounce of the next
    /// event, with the uncertainty of a fit to this many events (`None` when no part has a
    /// spread to fit).
    pub predictive: Option<f64>,
    /// Bouncing events behind the fit (timed ones: a bounce shorter than the resolution counts
    /// as clean).
    pub bouncing: usize,
    /// Events of the switch and kind, clean or not.
    pub events: usize,
}

/// Fewer events of a switch and kind than this give no window to recommend. Below it the
/// uncertainty of the fit itself sets the tail: the 99th percentile of the Student t the
/// predictive uses is 2.82 at 10 events (1.21 times the normal's 2.33), 3.75 at 5 and 31.8 at
/// 2, where two releases 250 times apart gave a "window" of 1e26 s.
pub const MIN_EVENTS: usize = 10;

/// Beyond this multiple of the largest bounce observed, a window says why.
pub const FAR_BEYOND: f64 = 2.0;

/// From this many bouncing events on, a far window is not blamed on their number.
const MANY_EVENTS: usize = 100;

impl CaptureWindow {
    /// The window: the predictive percentile, or the largest bounce observed if that is
    /// longer (a window below a bounce already seen is wrong whatever the model says).
    #[must_use]
    pub fn recommended(&self) -> f64 {
        self.predictive
            .map_or(self.observed, |p| p.max(self.observed))
    }

    /// Too few events to recommend a window ([`MIN_EVENTS`]).
    #[must_use]
    pub fn too_few(&self) -> bool {
        self.events < MIN_EVENTS
    }

    /// Why the window is far beyond every observed bounce (more than [`FAR_BEYOND`] times the
    /// largest), or why it is only the largest observed; `None` otherwise.
    #[must_use]
    pub fn reason(&self) -> Option<String> {
        match self.predictive {
            None if self.observed > 0.0 => Some(format!(
                "only the largest observed: {} bouncing events give no spread to extrapolate",
                self.bouncing
            )),
            Some(p) if p > FAR_BEYOND * self.observed => {
                let times = p / self.observed;
                let times = if times < 1e6 {
                    format!("{times:.1}")
                } else {
                    format!("{times:.1e}")
                };
                // (The cause depends on the count: a few events give a wide fit; many that
                // the model's shape does not follow, a tail beyond them. A 10 MB capture of
                // 1,040 bouncing releases was called "so few".)
                let why = if self.bouncing < MANY_EVENTS {
                    "and the tail of a fit to so few reaches far"
                } else {
                    "and the fitted model's tail reaches far beyond them"
                };
                Some(format!(
                    "{times} times the largest observed: {} bouncing events spread widely, {why}",
                    self.bouncing
                ))
            }
            _ => None,
        }
    }
}

/// The window of one switch and kind at `percentile` of the fitted model's predictive.
#[must_use]
pub fn window(d: &[&capture::Description], percentile: f64) -> CaptureWindow {
    let model = BounceModel::fit(d);
    CaptureWindow {
        observed: d.iter().map(|x| x.bounce).fold(0.0, f64::max),
        predictive: model.predictive.as_ref().map(|p| p.quantile(percentile)),
        bouncing: d.iter().filter(|x| super::fit::bounces(x)).count(),
        events: d.len(),
    }
}

/// The chronological held-out check of a window, fitted on the earlier `fraction` of a switch
/// and kind's events (in capture order) and judged on the later ones.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cover {
    /// The window fitted on the earlier events.
    pub window: CaptureWindow,
    /// Later events whose bounce it covers.
    pub covered: usize,
    /// Later events.
    pub later: usize,
    /// The largest later bounce (s).
    pub later_max: f64,
}

/// How many of `n` events in capture order are the earlier `fraction` (rounded down).
#[must_use]
pub fn earlier_count(n: usize, fraction: f64) -> usize {
    #[allow(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        clippy::cast_precision_loss
    )]
    let k = (n as f64 * fraction).floor() as usize;
    k.min(n)
}

/// The chronological held-out check of [`window`] on `d` (see [`Cover`]).
#[must_use]
pub fn chronological_cover(d: &[&capture::Description], percentile: f64, fraction: f64) -> Cover {
    let (earlier, later) = d.split_at(earlier_count(d.len(), fraction));
    let w = window(earlier, percentile);
    Cover {
        window: w,
        covered: later.iter().filter(|x| x.bounce <= w.recommended()).count(),
        later: later.len(),
        later_max: later.iter().map(|x| x.bounce).fold(0.0, f64::max),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_far_window_is_blamed_on_few_events_only_when_they_are_few() {
        let far = |bouncing| CaptureWindow {
            observed: 1e-3,
            predictive: Some(2.3e-3),
            bouncing,
            events: bouncing,
        };
        let few = far(12).reason().unwrap_or_default();
        let many = far(1040).reason().unwrap_or_default();
        assert!(
            few.starts_with("2.3 times") && few.contains("so few"),
            "{few}"
        );
        assert!(
            many.starts_with("2.3 times") && !many.contains("so few"),
            "{many}"
        );
        assert_eq!(
            CaptureWindow {
                predictive: Some(1.5e-3),
                ..far(1040)
            }
            .reason(),
            None
        );
    }
}

//! The debounce windows a capture gives.

use super::fit::BounceModel;
use super::heldout::{Ratios, Validation, VALIDATION_QUANTILES};
use super::sorted;
use crate::capture;
use host_tests::stats::nearest_rank;

/// A debounce window from a capture, two ways, and the one recommended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Window {
    /// The percentile of the observed bounce, widened by the worst held-out under-prediction
    /// of the empirical quantiles at the nearest checked quantile (s).
    pub empirical: Option<f64>,
    /// The percentile of the [`BounceModel`] fitted to every event, widened by the model's
    /// worst held-out under-prediction at the nearest checked quantile (s).
    pub fitted: Option<f64>,
}

impl Window {
    /// The larger of the two: a window must cover the bounce, and each estimate has only the
    /// capture's events behind it.
    #[must_use]
    pub fn recommended(&self) -> Option<f64> {
        match (self.empirical, self.fitted) {
            (Some(a), Some(b)) => Some(a.max(b)),
            (a, b) => a.or(b),
        }
    }
}

/// The worst under-prediction (observed / predicted, at least 1) among `ratios` at the checked
/// quantile nearest `percentile`.
fn worst(checks: &[Validation], percentile: f64, ratios: Ratios) -> f64 {
    let nearest = VALIDATION_QUANTILES
        .iter()
        .enumerate()
        .min_by(|a, b| {
            (a.1 - percentile)
                .abs()
                .total_cmp(&(b.1 - percentile).abs())
        })
        .map_or(0, |(i, _)| i);
    checks
        .iter()
        .filter_map(|v| ratios(v)[nearest])
        .fold(1.0_f64, |w, r| if r > 0.0 { w.max(1.0 / r) } else { w })
}

/// The windows of one switch and kind at `percentile`, from its events and their held-out
/// checks.
#[must_use]
pub fn window(d: &[&capture::Description], percentile: f64, checks: &[Validation]) -> Window {
    let all = sorted(d.iter().map(|x| x.bounce).collect());
    Window {
        empirical: nearest_rank(&all, percentile)
            .map(|b| b * worst(checks, percentile, |v| &v.empirical)),
        fitted: BounceModel::fit(d)
            .quantile(percentile)
            .map(|b| b * worst(checks, percentile, |v| &v.fitted)),
    }
}

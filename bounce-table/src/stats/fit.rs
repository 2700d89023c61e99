//! The fits: what the impact model takes from a capture's timing ([`ImpactFit`]), log-normal
//! parts ([`LogNormal`]) and the bounce model with empirical terms ([`BounceModel`]).

use super::groups::sorted;
use super::predictive::{Predictive, MIN_FIT};
use crate::capture;
use contact_bounce_reference::stats::nearest_rank;

/// Whether an event counts as bouncing in the fits: a bounce the instrument timed. One shorter
/// than the resolution is fitted with the clean events: its duration is the instrument's
/// sampling, not the contact's, and spread in ln t over a decade of sampling noise it would set
/// the tail of the whole fit (any window at least the resolution covers it, and a window is
/// never below the largest bounce observed).
pub fn bounces(d: &capture::Description) -> bool {
    d.bounce > 0.0 && d.timed
}

/// The resolved flights of an event's first burst: the impact model describes one closing, so
/// a later burst's flights (and the quiet interval before it) are not its flights.
fn first_burst(d: &capture::Description) -> &[f64] {
    d.flights.get(..d.first_burst_flights).unwrap_or(&d.flights)
}

/// What the impact model can take from a capture's timing: the restitution coefficient from
/// the ratio of successive resolved flights (each flight lasts in proportion to the speed that
/// starts it, for small j: `t_f = 2 R v / (Omega^2 |Delta|)`, so successive flights shrink by
/// R), and the scale `v0 / (Omega^2 |Delta|) = t_f1 / (2 R)` from the first flight. Omega,
/// Delta and v0 cannot be separated by timing alone: that needs the closing speed, the preload
/// force or the contact's resonance measured apart.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactFit {
    /// Successive resolved flight pairs seen.
    pub pairs: usize,
    /// The median ratio of successive flights: the estimate of R.
    pub restitution: Option<f64>,
    /// The ratios' quartiles.
    pub quartiles: Option<(f64, f64)>,
    /// The share of ratios below 1 (all of them, if the impact model held).
    pub shrinking: f64,
    /// The median first resolved flight (s).
    pub first_flight: Option<f64>,
}

impl ImpactFit {
    /// The fit from described events.
    #[must_use]
    pub fn new(d: &[&capture::Description]) -> Self {
        let ratios = sorted(
            d.iter()
                .flat_map(|x| first_burst(x).windows(2).map(|w| w[1] / w[0]))
                .collect(),
        );
        let firsts = sorted(
            d.iter()
                .filter_map(|x| first_burst(x).first().copied())
                .collect(),
        );
        #[allow(clippy::cast_precision_loss)]
        let shrinking = if ratios.is_empty() {
            0.0
        } else {
            ratios.iter().filter(|&&r| r < 1.0).count() as f64 / ratios.len() as f64
        };
        Self {
            pairs: ratios.len(),
            restitution: nearest_rank(&ratios, 0.5),
            quartiles: nearest_rank(&ratios, 0.25).zip(nearest_rank(&ratios, 0.75)),
            shrinking,
            first_flight: nearest_rank(&firsts, 0.5),
        }
    }

    /// Whether the flights decay as the impact model says: at least 5 pairs, at least 80 % of
    /// ratios below 1 and the upper quartile below 1. (A label, not a test: it says whether the
    /// model's parameters mean anything for this switch.)
    #[must_use]
    pub fn holds(&self) -> bool {
        self.pairs >= 5 && self.shrinking >= 0.8 && self.quartiles.is_some_and(|(_, q3)| q3 < 1.0)
    }

    /// The impact model's bounce for one event: its first resolved flight over 1 - R (the
    /// geometric sum of the flights); 0 without a resolved flight; `None` when R >= 1.
    #[must_use]
    pub fn bounce(&self, d: &capture::Description) -> Option<f64> {
        let r = self.restitution.filter(|r| *r < 1.0)?;
        Some(first_burst(d).first().map_or(0.0, |f| f / (1.0 - r)))
    }
}

/// A log-normal distribution fitted to durations above a known floor: `mu` the mean of the
/// logarithms of their excess over the floor (the maximum-likelihood estimate) and `sigma`
/// their sample standard deviation (n - 1). Bounce durations are positive and spread over
/// decades, which is what a log-normal describes; whether it describes a given capture is for
/// the held-out check to say. The floor is 0 for a burst; a late burst's bounce holds a quiet
/// interval of at least the burst gap, so it is never shorter than the gap, and its log-normal
/// is that of the excess over it (the three-parameter log-normal with its threshold known, not
/// fitted).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogNormal {
    /// Mean of ln (t - floor) (t in seconds).
    pub mu: f64,
    /// Standard deviation of ln (t - floor) (0 when every duration is the same).
    pub sigma: f64,
    /// No duration is shorter (s).
    pub floor: f64,
    /// Durations fitted.
    pub n: usize,
}

impl LogNormal {
    /// The fit to `t`; `None` with fewer than [`MIN_FIT`] durations or any not positive and
    /// finite.
    #[must_use]
    pub fn fit(t: &[f64]) -> Option<Self> {
        Self::fit_above(t, 0.0)
    }

    /// The fit to `t` above `floor` (s); `None` with fewer than [`MIN_FIT`] durations, any
    /// not finite or not above the floor, or a floor not finite and non-negative.
    #[must_use]
    pub fn fit_above(t: &[f64], floor: f64) -> Option<Self> {
        if t.len() < MIN_FIT
            || !(floor.is_finite() && floor >= 0.0)
            || t.iter().any(|x| !(x.is_finite() && *x > floor))
        {
            return None;
        }
        #[allow(clippy::cast_precision_loss)]
        let n = t.len() as f64;
        let mu = t.iter().map(|x| (x - floor).ln()).sum::<f64>() / n;
        let var = t
            .iter()
            .map(|x| ((x - floor).ln() - mu).powi(2))
            .sum::<f64>()
            / (n - 1.0);
        Some(Self {
            mu,
            sigma: var.sqrt(),
            floor,
            n: t.len(),
        })
    }

    /// P(duration <= t).
    #[must_use]
    pub fn cdf(&self, t: f64) -> f64 {
        if t <= self.floor {
            return 0.0;
        }
        let x = (t - self.floor).ln() - self.mu;
        if self.sigma <= 0.0 {
            return if x >= 0.0 { 1.0 } else { 0.0 };
        }
        0.5 * libm::erfc(-x / (self.sigma * core::f64::consts::SQRT_2))
    }

    /// The median, floor + e^mu (s).
    #[must_use]
    pub fn median(&self) -> f64 {
        self.floor + self.mu.exp()
    }
}

/// ln(floor + e^x) without overflow (`floor` >= 0).
fn ln_add_exp(floor: f64, x: f64) -> f64 {
    if floor <= 0.0 {
        return x;
    }
    let a = floor.ln();
    let m = a.max(x);
    m + ((a - m).exp() + (x - m).exp()).ln()
}

/// Maximum log-likelihood of a normal fitted to `x` (its spread floored at 1e-3 in ln t, a
/// tenth of a percent, so identical durations do not give an infinite likelihood).
fn normal_log_likelihood(x: &[f64]) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let n = x.len() as f64;
    let mean = x.iter().sum::<f64>() / n;
    let var = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).max(1e-6);
    -0.5 * n * ((2.0 * core::f64::consts::PI * var).ln() + 1.0)
}

/// -2 ln L + parameters ln n of labelled log-normal parts (each part's share and its
/// log-normal), over all their durations; `extra` parameters are added (a threshold chosen).
fn information(parts: &[&[f64]], extra: f64) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let n = parts.iter().map(|p| p.len()).sum::<usize>() as f64;
    let mut likelihood = 0.0;
    for p in parts.iter().filter(|p| !p.is_empty()) {
        #[allow(clippy::cast_precision_loss)]
        let k = p.len() as f64;
        let logs: Vec<f64> = p.iter().map(|t| t.ln()).collect();
        likelihood += k * (k / n).ln() + normal_log_likelihood(&logs);
    }
    #[allow(clippy::cast_precision_loss)]
    let params = 3.0 * parts.len() as f64 - 1.0 + extra;
    -2.0 * likelihood + params * n.ln()
}

/// Whether a one-burst event reopens at `threshold` (its hold's share of the longest flight at
/// least the threshold; never without a threshold or a hold).
#[must_use]
pub fn reopens(d: &capture::Description, threshold: Option<f64>) -> bool {
    matches!((d.hold, threshold), (Some(h), Some(c)) if h.share >= c)
}

/// The bounces of one-burst events that reopen (their hold at least `threshold`) and of the
/// others.
fn split_at(one_burst: &[&capture::Description], threshold: Option<f64>) -> (Vec<f64>, Vec<f64>) {
    let (mut reopen, mut plain) = (Vec::new(), Vec::new());
    for x in one_burst {
        if reopens(x, threshold) {
            reopen.push(x.bounce);
        } else {
            plain.push(x.bounce);
        }
    }
    (reopen, plain)
}

/// The threshold on [`capture::Hold::share`] that splits one-burst presses into plain and
/// reopening parts, when the data ask for it: among the shares observed, the one whose split
/// has the lowest Bayesian information criterion (a share, two log-normals and the threshold:
/// 6 parameters), if that is lower than one log-normal's (2) and both parts have at least
/// [`MIN_FIT`] events. `None` otherwise.
#[must_use]
pub fn reopening_threshold(one_burst: &[&capture::Description]) -> Option<f64> {
    if one_burst
        .iter()
        .any(|x| !(x.bounce.is_finite() && x.bounce > 0.0))
    {
        return None;
    }
    let all: Vec<f64> = one_burst.iter().map(|x| x.bounce).collect();
    let mut best = (information(&[&all], 0.0), None);
    for c in one_burst.iter().filter_map(|x| x.hold.map(|h| h.share)) {
        let (reopen, plain) = split_at(one_burst, Some(c));
        if plain.len() < MIN_FIT || reopen.len() < MIN_FIT {
            continue;
        }
        let bic = information(&[&plain, &reopen], 1.0);
        if bic < best.0 {
            best = (bic, Some(c));
        }
    }
    best.1
}

/// The fitted bounce model of one switch and kind: the impact model where it holds, and
/// empirical terms for what it does not produce. Each event is one of three kinds:
///
/// - clean (no bounce), with the share observed;
/// - one burst: log-normal in its duration. Where the impact model holds, each event's burst
///   is its first resolved flight over 1 - R (the flights the model sums), times 1 + the
///   closed share (the median of dwell and chatter time over flight time: a Newton impact has
///   no contact time, a real contact dwells and chatters between flights); elsewhere the
///   observed burst durations;
/// - a late burst (the contact bounced again after settling for at least the burst gap):
///   log-normal in the event's whole bounce over the burst gap (which it holds, so is never
///   shorter than), with the share observed.
///
/// One-burst presses that reopen (a closed dwell comparable to the flights, then more bounce:
/// the stuck pair of two bodies with unequal partial frequencies, [`capture::Hold`]) are a part
/// of their own, log-normal in their whole bounce, when the data ask for it
/// ([`reopening_threshold`]: the hold's share of the longest flight that best splits them,
/// if the split lowers the Bayesian information criterion and leaves both parts at least
/// [`MIN_FIT`] events). A stuck pair's
/// reopening adds a dwell and a second burst to the first, so such a capture's bounces are
/// bimodal; one log-normal over both modes is wide and its tail reaches far past either.
///
/// The model's quantiles are those of that mixture; with few events its log-normal tails go
/// past the largest event observed, which a window wants.
#[derive(Debug, Clone, PartialEq)]
pub struct BounceModel {
    /// Events fitted.
    pub events: usize,
    /// Share of events with no bounce.
    pub clean: f64,
    /// Share with one burst.
    pub single: f64,
    /// Share with a late burst.
    pub late: f64,
    /// The one-burst events' bounce.
    pub burst: Option<LogNormal>,
    /// The late-burst events' bounce.
    pub late_bounce: Option<LogNormal>,
    /// Share of one-burst events that reopen, when they are a part of their own (else 0, and
    /// they are in `single`).
    pub reopened: f64,
    /// The reopening events' bounce, when they are a part of their own.
    pub reopened_bounce: Option<LogNormal>,
    /// The median dwell before a reopening, over the one-burst events that reopen (s).
    pub reopening_dwell: Option<f64>,
    /// The threshold on the hold's share of the longest flight that makes a reopening, when
    /// reopenings are a part of their own ([`reopening_threshold`]).
    pub reopening: Option<f64>,
    /// Whether the burst term is the impact model's (else the observed bursts').
    pub impact: bool,
    /// Median (dwell + chatter time) / flight time over the one-burst events with a resolved
    /// flight.
    pub closed_share: Option<f64>,
    /// The same parts' posterior predictive: the bounce of the next event, with the
    /// uncertainty of shares and spreads fitted to few events (`None` with nothing to spread).
    pub predictive: Option<Predictive>,
}

impl BounceModel {
    /// The model fitted to described events.
    #[must_use]
    pub fn fit(d: &[&capture::Description]) -> Self {
        let fit = ImpactFit::new(d);
        let clean: Vec<_> = d.iter().filter(|x| !bounces(x)).collect();
        let one_burst: Vec<&capture::Description> = d
            .iter()
            .copied()
            .filter(|x| bounces(x) && x.bursts <= 1)
            .collect();
        let reopening = reopening_threshold(&one_burst);
        let reopening_dwell = nearest_rank(
            &sorted(
                one_burst
                    .iter()
                    .filter(|x| reopens(x, reopening))
                    .filter_map(|x| x.hold.map(|h| h.dwell))
                    .collect(),
            ),
            0.5,
        );
        let (reopened, _) = split_at(&one_burst, reopening);
        let single: Vec<_> = one_burst
            .iter()
            .filter(|x| !reopens(x, reopening))
            .collect();
        let late_events: Vec<_> = d.iter().filter(|x| bounces(x) && x.bursts > 1).collect();
        let late: Vec<f64> = late_events.iter().map(|x| x.bounce).collect();
        // The late bursts' floor: the least burst gap they were described at (one gap for
        // all, as `calibrate` describes them). A late burst whose bounce is the gap itself (two
        // changes exactly a gap apart, in a capture whose clock ticks divide the gap) has no
        // excess to take the logarithm of: then the part is the whole bounce's log-normal.
        let gap = late_events
            .iter()
            .map(|x| x.burst_gap)
            .fold(f64::INFINITY, f64::min);
        let late_floor = if gap.is_finite() && late.iter().all(|t| *t > gap) {
            gap
        } else {
            0.0
        };
        let closed_share = nearest_rank(
            &sorted(
                single
                    .iter()
                    .filter_map(|x| {
                        let flying: f64 = x.flights.iter().sum();
                        let closed: f64 = x.dwells.iter().sum::<f64>() + x.chatter_time;
                        (flying > 0.0).then(|| closed / flying)
                    })
                    .collect(),
            ),
            0.5,
        );
        let impact = fit.holds();
        let burst: Vec<f64> = single
            .iter()
            .map(|x| match (impact, fit.bounce(x)) {
                (true, Some(b)) if b > 0.0 => b * (1.0 + closed_share.unwrap_or(0.0)),
                _ => x.bounce,
            })
            .collect();
        #[allow(clippy::cast_precision_loss)]
        let share = |k: usize| {
            if d.is_empty() {
                0.0
            } else {
                k as f64 / d.len() as f64
            }
        };
        Self {
            events: d.len(),
            clean: share(clean.len()),
            single: share(single.len()),
            late: share(late.len()),
            burst: LogNormal::fit(&burst),
            late_bounce: LogNormal::fit_above(&late, late_floor),
            reopened: share(reopened.len()),
            reopened_bounce: LogNormal::fit(&reopened),
            reopening_dwell,
            reopening,
            impact,
            closed_share,
            predictive: Predictive::fit(
                clean.len(),
                &[(&burst, 0.0), (&reopened, 0.0), (&late, late_floor)],
            ),
        }
    }

    /// The bouncing parts with their shares; `None` if a part that occurs could not be fitted.
    fn parts(&self) -> Option<Vec<(f64, LogNormal)>> {
        [
            (self.single, self.burst),
            (self.reopened, self.reopened_bounce),
            (self.late, self.late_bounce),
        ]
        .into_iter()
        .filter(|(w, _)| *w > 0.0)
        .map(|(w, l)| l.map(|l| (w, l)))
        .collect()
    }

    /// P(bounce <= t); `None` if a part that occurs could not be fitted.
    #[must_use]
    pub fn cdf(&self, t: f64) -> Option<f64> {
        let parts = self.parts()?;
        Some(self.clean + parts.iter().map(|(w, l)| w * l.cdf(t)).sum::<f64>())
    }

    /// The `q` quantile of the bounce (s, 0 if at least a share `q` is clean): the least t
    /// with P(bounce <= t) >= q, by bisection in ln t to 1e-12 relative (q = 1: where the
    /// distribution reaches 1 in f64, about 8 standard deviations past the last median). `None`
    /// if a part that occurs could not be fitted, or if there are no events.
    #[must_use]
    pub fn quantile(&self, q: f64) -> Option<f64> {
        if self.events == 0 {
            return None;
        }
        let parts = self.parts()?;
        if q <= self.clean || parts.is_empty() {
            return Some(0.0);
        }
        // The cdf reaches its total (1 up to rounding) 40 standard deviations past the
        // largest median; q is asked to the total so rounding cannot leave it unreachable.
        let total = self.clean + parts.iter().map(|(w, _)| w).sum::<f64>();
        let q = q.min(total);
        let spread = parts.iter().map(|(_, l)| l.sigma).fold(0.0, f64::max) * 40.0 + 1.0;
        let mut lo = parts
            .iter()
            .map(|(_, l)| l.mu)
            .fold(f64::INFINITY, f64::min)
            - spread;
        let mut hi = parts
            .iter()
            .map(|(_, l)| ln_add_exp(l.floor, l.mu + spread))
            .fold(f64::NEG_INFINITY, f64::max);
        let at = |x: f64| self.clean + parts.iter().map(|(w, l)| w * l.cdf(x.exp())).sum::<f64>();
        for _ in 0..200 {
            if hi - lo <= 1e-12 * hi.abs().max(1.0) {
                break;
            }
            let mid = 0.5 * (lo + hi);
            if at(mid) >= q {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        Some(hi.exp())
    }
}

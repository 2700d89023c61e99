//! The bounce of the next events, with the uncertainty of a fit to few: the posterior
//! predictive of the [`super::BounceModel`]'s mixture.
//!
//! A window fitted to a few dozen events and then used on the next few dozen must carry two
//! uncertainties the fitted distribution alone does not: that of its parameters (a log-normal's
//! mean and spread from 5 or 25 durations) and that of its shares (1 late burst in 27 events
//! says little about the next 27). So:
//!
//! - each part's log-duration (over its floor: the burst gap for a late burst, which holds a
//!   quiet interval that long; 0 for the others) is the Student t posterior predictive of a
//!   normal sample with unknown mean and variance (non-informative prior): centre the sample
//!   mean, scale `s sqrt(1 + 1/n)`, `n - 1` degrees of freedom;
//! - a part with fewer than [`MIN_FIT`] events has no spread of its own: it takes the pooled
//!   within-part spread of the switch and kind's other parts (their degrees of freedom);
//! - the shares of clean, one-burst and late-burst events are the posterior mean under a
//!   uniform Dirichlet prior, `(k + 1) / (n + 3)`: a part seen once is not taken to be rare.
//!
//! Quantiles are found by bisection in ln t.

use statrs::distribution::{ContinuousCDF, StudentsT};

/// Fewer durations than this give no log-normal: two points fix a spread but say nothing of
/// its shape.
pub const MIN_FIT: usize = 3;

/// One part of the predictive mixture: its share and the t distribution of its ln duration
/// over its floor.
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// No duration of the part is shorter (s): the t is that of ln (t - floor).
    pub floor: f64,
    /// Posterior mean share.
    pub share: f64,
    /// Centre of ln (t - floor) (s).
    pub centre: f64,
    /// Scale of ln (t - floor) (the sample spread times `sqrt(1 + 1/n)`).
    pub scale: f64,
    /// Degrees of freedom.
    pub freedom: f64,
    /// Durations behind it.
    pub n: usize,
    /// Whether the spread is pooled from the other parts (fewer than [`MIN_FIT`] events).
    pub pooled: bool,
}

/// The posterior predictive bounce of the next event.
#[derive(Debug, Clone, PartialEq)]
pub struct Predictive {
    /// Posterior mean share of clean events.
    pub clean: f64,
    /// The bouncing parts.
    pub parts: Vec<Part>,
}

fn mean_and_squares(v: &[f64]) -> (f64, f64) {
    #[allow(clippy::cast_precision_loss)]
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    (mean, v.iter().map(|x| (x - mean).powi(2)).sum())
}

impl Predictive {
    /// The predictive of `clean` clean events and the bouncing parts: each its durations (s)
    /// and its floor (s, no duration shorter). `None` when no part with events has a spread to
    /// use: no part has 2 distinct durations (then nothing says how far the next event may
    /// go), a floor is not finite and non-negative, or a duration is not finite and above its
    /// part's floor.
    #[must_use]
    pub fn fit(clean: usize, parts: &[(&[f64], f64)]) -> Option<Self> {
        if parts.iter().any(|(p, floor)| {
            !(floor.is_finite() && *floor >= 0.0) || p.iter().any(|t| !(t.is_finite() && t > floor))
        }) {
            return None;
        }
        let logs: Vec<(Vec<f64>, f64)> = parts
            .iter()
            .map(|(p, floor)| (p.iter().map(|t| (t - floor).ln()).collect(), *floor))
            .collect();
        let (squares, freedom) = logs
            .iter()
            .map(|(l, _)| l)
            .filter(|l| l.len() >= 2)
            .fold((0.0, 0usize), |(s, f), l| {
                (s + mean_and_squares(l).1, f + l.len() - 1)
            });
        #[allow(clippy::cast_precision_loss)]
        let pooled = (freedom > 0).then(|| ((squares / freedom as f64).sqrt(), freedom as f64));
        let events = clean + parts.iter().map(|(p, _)| p.len()).sum::<usize>();
        #[allow(clippy::cast_precision_loss)]
        let share = |k: usize| (k as f64 + 1.0) / (events as f64 + parts.len() as f64 + 1.0);
        let mut fitted = Vec::new();
        for (l, floor) in logs.iter().filter(|(l, _)| !l.is_empty()) {
            let (centre, squares) = mean_and_squares(l);
            let own = l.len() >= MIN_FIT;
            #[allow(clippy::cast_precision_loss)]
            let (spread, freedom) = if own {
                (
                    (squares / (l.len() - 1) as f64).sqrt(),
                    (l.len() - 1) as f64,
                )
            } else {
                pooled?
            };
            #[allow(clippy::cast_precision_loss)]
            let scale = spread * (1.0 + 1.0 / l.len() as f64).sqrt();
            if scale.is_nan() || scale <= 0.0 {
                return None;
            }
            fitted.push(Part {
                floor: *floor,
                share: share(l.len()),
                centre,
                scale,
                freedom,
                n: l.len(),
                pooled: !own,
            });
        }
        // The shares of parts that never occurred go to no duration: renormalise over those
        // that did (and the clean share).
        let total = share(clean) + fitted.iter().map(|p| p.share).sum::<f64>();
        for p in &mut fitted {
            p.share /= total;
        }
        if fitted.is_empty() {
            return None;
        }
        Some(Self {
            clean: share(clean) / total,
            parts: fitted,
        })
    }

    /// P(bounce <= t).
    #[must_use]
    pub fn cdf(&self, t: f64) -> f64 {
        if t <= 0.0 {
            return self.clean;
        }
        self.clean
            + self
                .parts
                .iter()
                .filter(|p| t > p.floor)
                .map(|p| {
                    let x = (t - p.floor).ln();
                    StudentsT::new(0.0, 1.0, p.freedom)
                        .map_or(0.0, |d| p.share * d.cdf((x - p.centre) / p.scale))
                })
                .sum::<f64>()
    }

    /// The least t with P(bounce <= t) >= q, to 1e-9 in ln t; 0 when the clean share alone
    /// reaches q. `q` is clamped to [0, 1 - 1e-12] (the t tails reach 1 only at infinity).
    #[must_use]
    pub fn quantile(&self, q: f64) -> f64 {
        let q = q.clamp(0.0, 1.0 - 1e-12);
        if q <= self.clean {
            return 0.0;
        }
        crate::support::inverse(|t| self.cdf(t), q)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_late_part_is_the_excess_over_its_floor() {
        // Late bursts 5 ms + 2, 4, 8 ms: their part is the t of ln(t - 5 ms), centred on
        // ln 4 ms, and no late burst is predicted shorter than the floor (below it, only the
        // clean share: 1/5 under the uniform prior).
        let late = [7e-3, 9e-3, 13e-3];
        let p = Predictive::fit(0, &[(&late, 5e-3)]).unwrap();
        let part = &p.parts[0];
        assert_eq!(part.floor, 5e-3);
        assert!((part.centre - 4e-3_f64.ln()).abs() < 1e-12);
        assert_eq!(p.cdf(5e-3), p.clean);
        assert!(p.cdf(5.001e-3) > p.clean);
        let median = |p: &Predictive| p.quantile(p.clean + 0.5 * p.parts[0].share);
        assert!((median(&p) - 9e-3).abs() < 1e-9);
        // The same durations without their floor: the geometric mean is the median, and late
        // bursts shorter than the gap they hold get a share.
        let whole = Predictive::fit(0, &[(&late, 0.0)]).unwrap();
        assert!((median(&whole) - 819e-9_f64.cbrt()).abs() < 1e-9);
        assert!(whole.cdf(5e-3) > whole.clean);
    }

    #[test]
    fn many_events_of_one_part_give_the_log_normal_quantile() {
        // 2001 durations whose logs are evenly spread normal scores: the predictive is a t with
        // 2000 degrees of freedom, within 1e-3 of the normal.
        let n = 2001;
        let logs: Vec<f64> = (1..=n)
            .map(|i| {
                let p = f64::from(i) / f64::from(n + 1);
                statrs::distribution::Normal::standard().inverse_cdf(p)
            })
            .collect();
        let t: Vec<f64> = logs.iter().map(|z| (-7.0 + 0.5 * z).exp()).collect();
        let p = Predictive::fit(0, &[(&t, 0.0)]).unwrap();
        let q = p.quantile(0.99);
        let want = (-7.0_f64 + 0.5 * 2.326_347_874).exp();
        assert!((q / want - 1.0).abs() < 2e-2, "{q} vs {want}");
    }

    #[test]
    fn few_events_widen_the_tail_and_a_single_late_one_borrows_the_spread() {
        let bursts = [1e-4, 2e-4, 3e-4, 4e-4];
        let many: Vec<f64> = bursts.iter().cycle().take(40).copied().collect();
        let few = Predictive::fit(0, &[(&bursts, 0.0)]).unwrap();
        let lots = Predictive::fit(0, &[(&many, 0.0)]).unwrap();
        assert!(few.quantile(0.99) > lots.quantile(0.99));
        // One late burst: its part exists, with the bursts' spread, and a share of 2/8.
        let p = Predictive::fit(2, &[(&bursts, 0.0), (&[3e-2], 0.0)]).unwrap();
        assert_eq!(p.parts.len(), 2);
        assert!(p.parts[1].pooled && !p.parts[0].pooled);
        assert!((p.parts[1].share - 2.0 / 10.0).abs() < 1e-12);
        assert!((p.clean - 3.0 / 10.0).abs() < 1e-12);
        assert!(p.quantile(0.9) > 3e-2);
        // Every event clean up to q: no bounce.
        assert_eq!(p.quantile(0.25), 0.0);
    }

    #[test]
    fn nothing_to_spread_gives_none() {
        assert_eq!(Predictive::fit(5, &[(&[1e-3], 0.0)]), None);
        assert_eq!(Predictive::fit(5, &[(&[], 0.0)]), None);
        assert_eq!(Predictive::fit(0, &[(&[1e-3, 1e-3, 1e-3], 0.0)]), None);
        assert_eq!(Predictive::fit(0, &[(&[1e-3, -1.0, 2e-3], 0.0)]), None);
        // A duration not above its part's floor, or a floor that is not one.
        assert_eq!(Predictive::fit(0, &[(&[6e-3, 5e-3, 8e-3], 5e-3)]), None);
        assert_eq!(Predictive::fit(0, &[(&[6e-3, 7e-3], f64::NAN)]), None);
        assert_eq!(Predictive::fit(0, &[(&[6e-3, 7e-3], -1e-3)]), None);
    }

    #[test]
    fn cdf_and_quantile_agree() {
        let p = Predictive::fit(
            3,
            &[
                (&[1e-4, 3e-4, 2e-4, 5e-4], 0.0),
                (&[2e-2, 5e-2, 3e-2], 5e-3),
            ],
        )
        .unwrap();
        assert_eq!(p.quantile(0.3), 0.0); // the clean share is 4 / 10
        for q in [0.5, 0.9, 0.99, 0.999] {
            let t = p.quantile(q);
            assert!(p.cdf(t) >= q - 1e-9 && p.cdf(t * (1.0 - 1e-6)) < q, "{q}");
        }
    }
}

//! Held-out checks: fit on one part of a capture, predict the other part's bounce quantiles.

use super::fit::{BounceModel, ImpactFit};
use super::groups::sorted;
use crate::capture;
use contact_bounce_reference::stats::nearest_rank;

/// Picks one predictor's ratios out of a [`Validation`].
pub(super) type Ratios = fn(&Validation) -> &[Option<f64>; 3];

/// How many random halvings the report's spread of held-out ratios draws.
pub const RANDOM_SPLITS: usize = 200;

/// The quantiles the validation compares.
pub const VALIDATION_QUANTILES: [f64; 3] = [0.5, 0.9, 0.99];

/// A held-out check: fit on one part, predict the other part's bounce quantiles.
#[derive(Debug, Clone, PartialEq)]
pub struct Validation {
    /// How the events were split.
    pub split: &'static str,
    /// Events fitted on / checked on.
    pub sizes: (usize, usize),
    /// Per quantile of [`VALIDATION_QUANTILES`]: the held-out part's observed bounce.
    pub observed: [Option<f64>; 3],
    /// Predicted / observed with the empirical part (the fitted part's own quantiles).
    pub empirical: [Option<f64>; 3],
    /// Predicted / observed with the impact model (`None` where it predicts nothing).
    pub model: [Option<f64>; 3],
    /// Predicted / observed with the fitted [`BounceModel`].
    pub fitted: [Option<f64>; 3],
}

pub(crate) fn ratio(p: Option<f64>, o: Option<f64>) -> Option<f64> {
    match (p, o) {
        (Some(p), Some(o)) if o > 0.0 => Some(p / o),
        (Some(0.0), Some(_)) => Some(1.0),
        _ => None,
    }
}

/// Checks both predictors on a split of `d` into `fit` and `check`.
fn validate(
    split: &'static str,
    fit: &[&capture::Description],
    check: &[&capture::Description],
) -> Validation {
    let model = ImpactFit::new(fit);
    let fitted = BounceModel::fit(fit);
    let observed = sorted(check.iter().map(|x| x.bounce).collect());
    let train = sorted(fit.iter().map(|x| x.bounce).collect());
    let modelled: Option<Vec<f64>> = fit.iter().map(|x| model.bounce(x)).collect();
    let modelled = modelled.map(sorted);
    let at = |v: &[f64], q| nearest_rank(v, q);
    Validation {
        split,
        sizes: (fit.len(), check.len()),
        observed: VALIDATION_QUANTILES.map(|q| at(&observed, q)),
        empirical: VALIDATION_QUANTILES.map(|q| ratio(at(&train, q), at(&observed, q))),
        model: VALIDATION_QUANTILES
            .map(|q| ratio(modelled.as_deref().and_then(|m| at(m, q)), at(&observed, q))),
        fitted: VALIDATION_QUANTILES.map(|q| ratio(fitted.quantile(q), at(&observed, q))),
    }
}

/// `d` shuffled (Fisher-Yates, `rng`) and cut in two halves.
pub(super) fn random_halves<'a>(
    d: &[&'a capture::Description],
    rng: &mut crate::scene::spreads::SplitMix,
) -> (Vec<&'a capture::Description>, Vec<&'a capture::Description>) {
    let mut shuffled = d.to_vec();
    for i in (1..shuffled.len()).rev() {
        let j = usize::try_from(rng.next_u64() % (i as u64 + 1)).unwrap_or(0);
        shuffled.swap(i, j);
    }
    let rest = shuffled.split_off(d.len() / 2);
    (shuffled, rest)
}

/// The two held-out checks of one switch and kind: a seeded random half (the same split for
/// the same seed everywhere), and the first half in capture order against the second.
#[must_use]
pub fn validations(d: &[&capture::Description], seed: u64) -> [Validation; 2] {
    let (first, second) = d.split_at(d.len() / 2);
    let (a, b) = random_halves(d, &mut crate::scene::spreads::SplitMix(seed));
    [
        validate("random halves", &a, &b),
        validate("chronological halves", first, second),
    ]
}

/// How far one predictor's held-out ratio moves over many random halvings, at one quantile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RatioSpread {
    /// Halvings in which the predictor predicted (and the held-out half had the quantile).
    pub predicted: usize,
    /// 10th, 50th and 90th percentile of predicted / observed over those halvings.
    pub p10: f64,
    /// The median ratio.
    pub p50: f64,
    /// The 90th percentile.
    pub p90: f64,
}

/// The held-out ratios of the empirical quantiles, the impact model and the fitted model over
/// `splits` random halvings (seeded; the first is the one of [`validations`]): per predictor,
/// per quantile of [`VALIDATION_QUANTILES`], `None` where it never predicted.
#[must_use]
pub fn random_splits(
    d: &[&capture::Description],
    seed: u64,
    splits: usize,
) -> [[Option<RatioSpread>; 3]; 3] {
    let mut rng = crate::scene::spreads::SplitMix(seed);
    let checks: Vec<Validation> = (0..splits)
        .map(|_| {
            let (a, b) = random_halves(d, &mut rng);
            validate("random halves", &a, &b)
        })
        .collect();
    let pick: [Ratios; 3] = [|v| &v.empirical, |v| &v.model, |v| &v.fitted];
    pick.map(|f| {
        [0, 1, 2].map(|k| {
            let r = sorted(checks.iter().filter_map(|v| f(v)[k]).collect());
            Some(RatioSpread {
                predicted: r.len(),
                p10: nearest_rank(&r, 0.1)?,
                p50: nearest_rank(&r, 0.5)?,
                p90: nearest_rank(&r, 0.9)?,
            })
        })
    })
}

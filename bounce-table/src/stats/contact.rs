//! Real-contact models fitted to a capture's press bounces: the paper's two bodies (Eq. 1,
//! whose stuck pair can reopen) and a compliant contact (a spring and dashpot at the stop,
//! which dwells at each impact). Each is simulated exactly by the reference
//! (`contact_bounce_reference::{two_body, compliant}`), over closing speeds spread log-normally
//! from press to press, and its parameters are those whose bounce durations best match the
//! capture's (distribution functions and the share that reopens: [`ContactFit::misfit`]), by
//! Nelder-Mead from the best of a seeded random search. What the models are worth is their held-out prediction, beside the empirical
//! quantiles'.
//!
//! Timing alone fixes only ratios: a preload and the closing speeds scale together, so the
//! preload is fixed at 10 um and the speeds are fitted; the masses enter by their ratio.

use contact_bounce_reference::compliant::{self, Compliant};
use contact_bounce_reference::stats::nearest_rank;
use contact_bounce_reference::two_body::{self, TwoBodies};
use statrs::distribution::{ContinuousCDF, Normal};

use super::groups::sorted;
use crate::scene::spreads::SplitMix;

/// The preload both models are simulated at (m): a scale that the fitted speeds absorb.
const PRELOAD: f64 = -1e-5;
/// Closing speeds per model evaluation while fitting, and when predicting.
const FIT_SPEEDS: usize = 40;
const PREDICT_SPEEDS: usize = 200;
/// Random starts, and Nelder-Mead steps from each of the best few.
const SEARCH: usize = 300;
const STARTS: usize = 3;
const STEPS: usize = 400;

/// A real-contact model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactModel {
    /// Two bodies with unequal partial frequencies (the paper's Eq. 1).
    TwoBody,
    /// One body against a compliant stop.
    Compliant,
}

impl ContactModel {
    /// Its name in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            ContactModel::TwoBody => "two bodies",
            ContactModel::Compliant => "compliant contact",
        }
    }

    /// (lower, upper) of each parameter, in the coordinates searched (logarithms for scales).
    fn bounds(self, scale: f64) -> Vec<(f64, f64)> {
        // `scale`: the capture's median bounce (s); frequencies around its inverse.
        let f = (1.0 / scale).ln();
        match self {
            // ln f1 (Hz), ln(w2 / w1), ln(m2 / m1), zeta, R, ln j, ln sigma
            ContactModel::TwoBody => vec![
                (f - 2.0, f + 3.0),
                (0.2_f64.ln(), 5.0_f64.ln()),
                (0.1_f64.ln(), 10.0_f64.ln()),
                (0.005, 0.3),
                (0.2, 0.9),
                (0.03_f64.ln(), 10.0_f64.ln()),
                (0.02_f64.ln(), 1.5_f64.ln()),
            ],
            // ln f (Hz), ln(kappa / Omega), zeta_c, ln j, ln sigma
            ContactModel::Compliant => vec![
                (f - 2.0, f + 3.0),
                (2.0_f64.ln(), 1000.0_f64.ln()),
                (0.01, 0.9),
                (0.03_f64.ln(), 10.0_f64.ln()),
                (0.02_f64.ln(), 1.5_f64.ln()),
            ],
        }
    }
}

/// A fitted real-contact model.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactFit {
    /// Which model.
    pub kind: ContactModel,
    /// Its parameters in the searched coordinates (see [`ContactFit::describe`]).
    pub params: Vec<f64>,
    /// The misfit on the fitted durations: the mean squared difference of the distribution
    /// functions at the observed durations, plus the squared difference of the shares that
    /// reopen.
    pub misfit: f64,
}

/// The standard normal scores of `n` evenly spread probabilities.
fn scores(n: usize) -> Vec<f64> {
    let normal = Normal::standard();
    #[allow(clippy::cast_precision_loss)]
    (0..n)
        .map(|i| normal.inverse_cdf((i as f64 + 0.5) / n as f64))
        .collect()
}

/// The closing speeds (m/s) of `n` presses: ln j normal with mean `spread[0]` and standard
/// deviation e^`spread[1]`, at evenly spread probabilities; j = v0 / (Omega |Delta|) with
/// Omega = 2 pi e^`ln_f`.
fn speeds(spread: &[f64], ln_f: f64, n: usize) -> Vec<f64> {
    let omega = 2.0 * std::f64::consts::PI * ln_f.exp();
    scores(n)
        .into_iter()
        .map(|z| (spread[0] + spread[1].exp() * z).exp() * omega * PRELOAD.abs())
        .collect()
}

/// The two bodies of parameters `p` (see [`ContactModel::bounds`]) closing at `v0`.
fn two_bodies(p: &[f64], v0: f64) -> TwoBodies {
    let w1 = 2.0 * std::f64::consts::PI * p[0].exp();
    let w2 = w1 * p[1].exp();
    let (m1, m2) = (1e-3, 1e-3 * p[2].exp());
    TwoBodies {
        m: [m1, m2],
        c: [m1 * w1 * w1, m2 * w2 * w2],
        d: [2.0 * p[3] * w1 * m1, 2.0 * p[3] * w2 * m2],
        delta: PRELOAD,
        restitution: p[4],
        closing_speed: v0,
        x2: 0.0,
        v2: 0.0,
        threshold: None,
    }
}

/// The model's bounce for each of `n` closing speeds (sorted) and the share of them that
/// reopen after sticking, or `None` where a simulation fails (the parameters are then out of
/// the model's reach).
fn bounces(kind: ContactModel, p: &[f64], n: usize) -> Option<(Vec<f64>, f64)> {
    let mut out = Vec::with_capacity(n);
    let mut reopen = 0usize;
    match kind {
        ContactModel::TwoBody => {
            for v0 in speeds(&p[5..7], p[0], n) {
                let mut separated = false;
                let o = two_body::simulate_traced(&two_bodies(p, v0), 20_000, |c| {
                    separated |= matches!(c, two_body::Contact::Separate(_));
                })
                .ok()?;
                out.push(o.end_time?);
                reopen += usize::from(separated);
            }
        }
        ContactModel::Compliant => {
            for v0 in speeds(&p[3..5], p[0], n) {
                let omega = 2.0 * std::f64::consts::PI * p[0].exp();
                let s = Compliant {
                    omega,
                    zeta: 0.0,
                    delta: PRELOAD,
                    kappa: omega * p[1].exp(),
                    zeta_contact: p[2],
                    closing_speed: v0,
                };
                out.push(compliant::simulate(&s, 20_000).ok()?.last()?.start);
            }
        }
    }
    if out.iter().any(|t| !(t.is_finite() && *t >= 0.0)) {
        return None;
    }
    #[allow(clippy::cast_precision_loss)]
    Some((sorted(out), reopen as f64 / n as f64))
}

/// The model's distribution against the observed one: the mean over the observed durations of
/// the squared difference between the model's distribution function there and the observed
/// one's (a Cramér-von Mises distance, in probability: stable where the bounce is multimodal and
/// a decile would jump between modes), plus the squared difference of the shares that reopen.
fn misfit(model: &[f64], observed: &[f64], reopening: (f64, f64)) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let (m, n) = (model.len() as f64, observed.len() as f64);
    #[allow(clippy::cast_precision_loss)]
    let distance = observed
        .iter()
        .enumerate()
        .map(|(i, x)| {
            let below = model.partition_point(|t| t <= x) as f64 / m;
            (below - (i as f64 + 0.5) / n).powi(2)
        })
        .sum::<f64>()
        / n;
    distance + (reopening.0 - reopening.1).powi(2)
}

/// Nelder-Mead on `f` from `start`, kept inside `bounds` (a point outside costs infinity).
fn nelder_mead(
    f: &impl Fn(&[f64]) -> f64,
    start: &[f64],
    bounds: &[(f64, f64)],
    steps: usize,
) -> (Vec<f64>, f64) {
    let n = start.len();
    let inside = |x: &[f64]| x.iter().zip(bounds).all(|(v, (lo, hi))| v >= lo && v <= hi);
    let cost = |x: &[f64]| if inside(x) { f(x) } else { f64::INFINITY };
    let mut simplex: Vec<(Vec<f64>, f64)> = vec![(start.to_vec(), cost(start))];
    for i in 0..n {
        let mut x = start.to_vec();
        let (lo, hi) = bounds[i];
        let step = 0.1 * (hi - lo);
        x[i] = if x[i] + step <= hi {
            x[i] + step
        } else {
            x[i] - step
        };
        let c = cost(&x);
        simplex.push((x, c));
    }
    for _ in 0..steps {
        simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
        #[allow(clippy::cast_precision_loss)]
        let centroid: Vec<f64> = (0..n)
            .map(|k| simplex[..n].iter().map(|p| p.0[k]).sum::<f64>() / n as f64)
            .collect();
        let along = |t: f64| -> Vec<f64> {
            centroid
                .iter()
                .zip(&simplex[n].0)
                .map(|(c, w)| c + t * (w - c))
                .collect()
        };
        let reflected = along(-1.0);
        let r = cost(&reflected);
        if r < simplex[0].1 {
            let expanded = along(-2.0);
            let e = cost(&expanded);
            simplex[n] = if e < r { (expanded, e) } else { (reflected, r) };
        } else if r < simplex[n - 1].1 {
            simplex[n] = (reflected, r);
        } else {
            let contracted = along(0.5);
            let c = cost(&contracted);
            if c < simplex[n].1 {
                simplex[n] = (contracted, c);
            } else {
                let best = simplex[0].0.clone();
                for p in simplex.iter_mut().skip(1) {
                    p.0 = best
                        .iter()
                        .zip(&p.0)
                        .map(|(b, x)| b + 0.5 * (x - b))
                        .collect();
                    p.1 = cost(&p.0);
                }
            }
        }
    }
    simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
    simplex.swap_remove(0)
}

impl ContactFit {
    /// The model fitted to bounce durations (s; the bouncing presses') and the share of them
    /// that reopen, from `seed`. `None` with fewer than 3 positive durations, or when no
    /// parameters inside the searched box reproduce any (every simulation failed).
    #[must_use]
    pub fn fit(kind: ContactModel, durations: &[f64], reopening: f64, seed: u64) -> Option<Self> {
        let observed = sorted(
            durations
                .iter()
                .copied()
                .filter(|t| t.is_finite() && *t > 0.0)
                .collect(),
        );
        if observed.len() < 3 {
            return None;
        }
        let scale = nearest_rank(&observed, 0.5)?;
        let bounds = kind.bounds(scale);
        let f = |p: &[f64]| {
            bounces(kind, p, FIT_SPEEDS).map_or(f64::INFINITY, |(m, r)| {
                misfit(&m, &observed, (r, reopening))
            })
        };
        let mut rng = SplitMix(seed);
        let mut tried: Vec<(Vec<f64>, f64)> = (0..SEARCH)
            .map(|_| {
                let p: Vec<f64> = bounds
                    .iter()
                    .map(|(lo, hi)| lo + (hi - lo) * rng.unit())
                    .collect();
                let c = f(&p);
                (p, c)
            })
            .collect();
        tried.sort_by(|a, b| a.1.total_cmp(&b.1));
        let best = tried
            .iter()
            .take(STARTS)
            .filter(|t| t.1.is_finite())
            .map(|(p, _)| nelder_mead(&f, p, &bounds, STEPS))
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        best.1.is_finite().then_some(Self {
            kind,
            params: best.0,
            misfit: best.1,
        })
    }

    /// The fitted model's bounce quantile `q` (s), over 200 closing speeds.
    #[must_use]
    pub fn quantiles(&self, q: &[f64]) -> Option<Vec<f64>> {
        let (b, _) = bounces(self.kind, &self.params, PREDICT_SPEEDS)?;
        q.iter().map(|&q| nearest_rank(&b, q)).collect()
    }

    /// The share of presses, over 200 closing speeds, in which the stuck pair
    /// separates again (two bodies; a compliant contact holds for good once it holds: 0).
    #[must_use]
    pub fn reopening(&self) -> Option<f64> {
        bounces(self.kind, &self.params, PREDICT_SPEEDS).map(|(_, r)| r)
    }

    /// The parameters in physical units.
    #[must_use]
    pub fn describe(&self) -> String {
        let p = &self.params;
        match self.kind {
            ContactModel::TwoBody => format!(
                "f1 {:.0} Hz, f2/f1 {:.2}, m2/m1 {:.2}, zeta {:.3}, R {:.2}, j {:.2} x/ {:.2}",
                p[0].exp(),
                p[1].exp(),
                p[2].exp(),
                p[3],
                p[4],
                p[5].exp(),
                p[6].exp().exp()
            ),
            ContactModel::Compliant => format!(
                "f {:.0} Hz, kappa/Omega {:.1}, zeta_c {:.2} (R {:.2}), j {:.2} x/ {:.2}",
                p[0].exp(),
                p[1].exp(),
                p[2],
                (-p[2] * std::f64::consts::PI / (1.0 - p[2] * p[2]).sqrt()).exp(),
                p[3].exp(),
                p[4].exp().exp()
            ),
        }
    }
}

/// The `q` quantile over all events of a model of the bouncing ones, with `clean` the share
/// of clean events: 0 up to `clean`, then the model's quantile `(q - clean) / (1 - clean)`.
fn with_clean(fit: &ContactFit, clean: f64, q: f64) -> Option<f64> {
    if q <= clean {
        return Some(0.0);
    }
    fit.quantiles(&[(q - clean) / (1.0 - clean)])
        .and_then(|v| v.first().copied())
}

/// The real-contact models' held-out check on each switch's presses, as a Markdown section:
/// each model fitted on the earlier half (capture order) and on a seeded random half, and
/// its P50 / P90 / P99 over the other half's, beside the empirical quantiles' and the fitted
/// bounce model's.
#[must_use]
pub fn report(groups: &super::Groups, seed: u64) -> String {
    use super::heldout::{random_halves, ratio, VALIDATION_QUANTILES};
    use super::BounceModel;
    let mut out = String::from(
        "\n## Real-contact models\n\nEach model is simulated exactly over closing speeds spread log-normally from \
         press to press, and its parameters are those whose bounce deciles best match the fitted half's bouncing \
         presses (the mean squared difference of the distribution functions at the observed durations, plus the squared \
         difference of the shares that reopen: the misfit; the clean share is the half's own). Two bodies: the paper's Eq. 1, a \
         moving contact (f1) on a fixed one (f2), Newton impacts (R), sticking once the impacts accumulate and \
         reopening when the stuck pair's contact force turns tensile. Compliant contact: one body, a spring and \
         dashpot at the stop (kappa, zeta_c), a dwell at each impact and no reopening. j = v0 / (Omega |Delta|) \
         at a 10 um preload (timing fixes only ratios). Predicted / observed P50 / P90 / P99 of the other half.\n\n\
         | switch | split | predictor | parameters (fitted half) | misfit | predicted / observed P50 / P90 / P99 |\n\
         |---|---|---|---|---:|---:|\n",
    );
    let three = |v: [Option<f64>; 3]| {
        v.iter()
            .map(|x| x.map_or_else(|| "-".to_owned(), |x| format!("{x:.2}")))
            .collect::<Vec<_>>()
            .join(" / ")
    };
    let mut tasks = Vec::new();
    for ((switch, kind), d) in groups {
        if *kind != crate::capture::Edge::Press {
            continue;
        }
        let refs: Vec<&crate::capture::Description> = d.iter().collect();
        let (first, second) = refs.split_at(refs.len() / 2);
        let (a, b) = random_halves(&refs, &mut SplitMix(seed));
        tasks.push((
            *switch,
            "chronological halves",
            first.to_vec(),
            second.to_vec(),
        ));
        tasks.push((*switch, "random halves", a, b));
    }
    // Every split's rows on a thread of its own (each fit takes seconds).
    let rows = |(switch, split, fit, check): &(
        &str,
        &str,
        Vec<&crate::capture::Description>,
        Vec<&crate::capture::Description>,
    )| {
        let mut out = String::new();
        let observed = sorted(check.iter().map(|x| x.bounce).collect());
        let train = sorted(fit.iter().map(|x| x.bounce).collect());
        let at = |v: &[f64], q| nearest_rank(v, q);
        let empirical = VALIDATION_QUANTILES.map(|q| ratio(at(&train, q), at(&observed, q)));
        out.push_str(&format!(
            "| {switch} | {split} | empirical | - | - | {} |\n",
            three(empirical)
        ));
        let model = BounceModel::fit(fit);
        let parts = model.reopening.map_or_else(
            || "no reopening part".to_owned(),
            |c| {
                format!(
                    "reopens {:.0} % (a hold of at least {c:.2} of the longest flight)",
                    model.reopened * 100.0
                )
            },
        );
        out.push_str(&format!(
            "| {switch} | {split} | fitted bounce model | {parts} | - | {} |\n",
            three(VALIDATION_QUANTILES.map(|q| ratio(model.quantile(q), at(&observed, q))))
        ));
        // Clean as the fitted bounce model counts it: a bounce shorter than the resolution is
        // the instrument's sampling, fitted with the clean events, not a contact's to match.
        #[allow(clippy::cast_precision_loss)]
        let clean =
            fit.iter().filter(|x| !super::fit::bounces(x)).count() as f64 / fit.len() as f64;
        let bouncing: Vec<f64> = fit
            .iter()
            .filter(|x| super::fit::bounces(x))
            .map(|x| x.bounce)
            .collect();
        // The share of the bouncing presses that reopen, as the fitted bounce model sorts them.
        let reopening = if model.clean < 1.0 {
            model.reopened / (1.0 - model.clean)
        } else {
            0.0
        };
        let kinds = [ContactModel::TwoBody, ContactModel::Compliant];
        let fits = crate::support::workers::each(kinds.len(), &|i| {
            kinds
                .get(i)
                .and_then(|&k| ContactFit::fit(k, &bouncing, reopening, seed))
        });
        for (k, c) in kinds.into_iter().zip(fits.into_iter().map(Option::flatten)) {
            match c {
                Some(c) => out.push_str(&format!(
                    "| {switch} | {split} | {} | {}; reopens {} | {:.4} | {} |\n",
                    k.name(),
                    c.describe(),
                    c.reopening()
                        .map_or_else(|| "-".to_owned(), |r| format!("{:.0} %", r * 100.0)),
                    c.misfit,
                    three(
                        VALIDATION_QUANTILES
                            .map(|q| ratio(with_clean(&c, clean, q), at(&observed, q)))
                    )
                )),
                None => out.push_str(&format!(
                    "| {switch} | {split} | {} | no fit | - | - |\n",
                    k.name()
                )),
            }
        }
        out
    };
    let sections: Vec<String> = crate::support::workers::each(tasks.len(), &|i| {
        tasks.get(i).map(&rows).unwrap_or_default()
    })
    .into_iter()
    .map(|s| s.unwrap_or_else(|| "| a fit failed |\n".to_owned()))
    .collect();
    out.push_str(&sections.concat());
    out
}

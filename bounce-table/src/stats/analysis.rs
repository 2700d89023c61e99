//! What the desk tool computes for one switch: the nominal prediction (the cheapest tier
//! meeting the tolerance, else the exact reference: this is the host), the window it implies,
//! and with ranges a seeded Monte Carlo (parallel) for the window at a percentile and the
//! sensitivity of the bounce to each ranged parameter.

use std::borrow::Cow;
use std::sync::atomic::{AtomicU64, Ordering};

use contact_bounce::{Method, Nodes, Prediction, Tolerance};
use contact_bounce_reference::stats::nearest_rank_unsorted;

use crate::scene::input::{FieldError, Placement, SceneInput};
use crate::scene::reference::outcome;
use crate::scene::spreads::{Range, Template};

/// How to analyse.
#[derive(Debug, Clone, Copy)]
pub struct Settings {
    /// Sampling (tick) period of the windows (s).
    pub period: f64,
    /// Relative tolerance asked of the model (else the exact reference is used).
    pub tolerance: f64,
    /// Percentile of the Monte Carlo windows (e.g. 99.9).
    pub percentile: f64,
    /// Monte Carlo samples for scenes with ranges.
    pub samples: u64,
    /// Seed of the Monte Carlo.
    pub seed: u64,
    /// Threads (at least 1).
    pub threads: usize,
    /// Show a progress bar on stderr for long runs.
    pub progress: bool,
    /// Safety factor on the window (at least 1): the window is this times the bound (the
    /// Monte Carlo's percentile, or the nominal upper bound); 1 is none.
    pub margin: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            period: 1e-4,
            tolerance: 0.1,
            percentile: 99.9,
            samples: 4000,
            seed: 1,
            threads: std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get),
            progress: false,
            margin: 1.0,
        }
    }
}

/// One bounce estimate: the time, an upper bound (widened by its expected error), and how.
#[derive(Debug, Clone, PartialEq)]
pub struct BounceEstimate {
    /// Bounce time (s): the end, else the last impact above the threshold.
    pub bounce: f64,
    /// Bounce time widened by the expected error (the exact reference: the time itself).
    pub upper: f64,
    /// The regime (its name: static where the estimate made it, no allocation a row).
    pub regime: Cow<'static, str>,
    /// Impacts (above the threshold, or in all), if finite.
    pub impacts: Option<f64>,
    /// The tier ("closed (Tb1v)", "averaged N8", "map", "exact reference").
    pub tier: Cow<'static, str>,
    /// Its expected error (0 for the exact reference).
    pub expected_error: f64,
}

fn endless() -> FieldError {
    FieldError {
        field: "threshold".to_owned(),
        message: "the bounce never ends and never drops below a threshold".to_owned(),
    }
}

/// The model's prediction where it promises the tolerance, else the exact reference's.
enum Answer {
    Model(Prediction<f64>),
    Exact(contact_bounce_reference::Outcome),
}

/// `f` of Auto's prediction where it promises `tolerance` (read where it was made: a Monte
/// Carlo sample keeps only its bounds), `None` where the exact reference must answer.
fn promised<R>(
    input: &SceneInput,
    tolerance: Tolerance<f64>,
    f: impl FnOnce(&Prediction<f64>) -> R,
) -> Result<Option<R>, FieldError> {
    input.with_core::<f64, _>(|scene| {
        let p = scene.predict(Method::Auto(tolerance));
        p.promises(tolerance).then(|| f(&p))
    })
}

fn answer(input: &SceneInput, tolerance: Tolerance<f64>) -> Result<Answer, FieldError> {
    Ok(match promised(input, tolerance, |p| *p)? {
        Some(p) => Answer::Model(p),
        None => Answer::Exact(outcome(input)?),
    })
}

impl Answer {
    /// The bounce time, its upper bound, and whether the exact reference gave it.
    fn bounds(&self) -> Result<(f64, f64, bool), FieldError> {
        match self {
            Self::Model(p) => model_bounds(p),
            Self::Exact(out) => exact_bounds(out),
        }
    }
}

fn model_bounds(p: &Prediction<f64>) -> Result<(f64, f64, bool), FieldError> {
    let bounce = p.bounce_time().ok_or_else(endless)?;
    Ok((
        bounce,
        bounce * (1.0 + p.expected_error.unwrap_or(0.0)),
        false,
    ))
}

fn exact_bounds(out: &contact_bounce_reference::Outcome) -> Result<(f64, f64, bool), FieldError> {
    let bounce = out.end_time.or(out.last_above_time).ok_or_else(endless)?;
    Ok((bounce, bounce, true))
}

/// [`Answer::bounds`] of the scene's answer, without keeping the answer: a Monte Carlo sample's
/// path.
fn answer_bounds(
    input: &SceneInput,
    tolerance: Tolerance<f64>,
) -> Result<(f64, f64, bool), FieldError> {
    match promised(input, tolerance, model_bounds)? {
        Some(bounds) => bounds,
        None => exact_bounds(&outcome(input)?),
    }
}

/// The bounce of one concrete scene: the model where it promises `tolerance`, else the exact
/// reference.
///
/// # Errors
/// The scene's invalid field, or an endless bounce (no threshold time either).
pub fn estimate(input: &SceneInput, tolerance: f64) -> Result<BounceEstimate, FieldError> {
    let answer = answer(input, Tolerance::new(tolerance)?)?;
    let (bounce, upper, _) = answer.bounds()?;
    Ok(match answer {
        Answer::Model(p) => BounceEstimate {
            bounce,
            upper,
            regime: Cow::Borrowed(p.regime.name()),
            impacts: p.impacts_above.value(),
            tier: Cow::Borrowed(p.tier.name()),
            expected_error: p.expected_error.unwrap_or(0.0),
        },
        Answer::Exact(out) => {
            let regime = out.regime.name();
            #[allow(clippy::cast_precision_loss)]
            let impacts = out.impacts_above.map(|n| n as f64);
            BounceEstimate {
                bounce,
                upper,
                regime: Cow::Borrowed(regime),
                impacts,
                tier: Cow::Borrowed("exact reference"),
                expected_error: 0.0,
            }
        }
    })
}

/// The Monte Carlo over a scene's ranges.
#[derive(Debug, Clone, PartialEq)]
pub struct MonteCarlo {
    /// Samples drawn.
    pub samples: u64,
    /// Median bounce (s).
    pub p50: f64,
    /// The window (s): the upper bound at the percentile.
    pub window: f64,
    /// The largest upper bound drawn (s).
    pub max: f64,
    /// Samples the model gave to the exact reference (it could not promise the tolerance).
    pub exact: u64,
}

/// How much each ranged parameter moves the bounce.
#[derive(Debug, Clone, PartialEq)]
pub struct Sensitivity {
    /// The parameter (a scene key, `kernel.tau` for nested ones).
    pub parameter: String,
    /// d ln(bounce) / d ln(parameter) at the nominal scene.
    pub elasticity: f64,
    /// |elasticity| times the parameter's relative half-width: its share of the spread.
    pub contribution: f64,
}

/// Everything about one switch.
#[derive(Debug, Clone, PartialEq)]
pub struct Analysis {
    /// Name.
    pub name: String,
    /// The nominal scene's estimate.
    pub nominal: BounceEstimate,
    /// The window (s): the Monte Carlo's percentile when there are ranges, else the
    /// nominal upper bound.
    pub window: f64,
    /// The window in ticks of the period, rounded up.
    pub ticks: u32,
    /// The Monte Carlo, with ranges.
    pub monte_carlo: Option<MonteCarlo>,
    /// Sensitivities, largest contribution first (with ranges).
    pub sensitivity: Vec<Sensitivity>,
    /// What the user should know before using the window: a scene whose contacts do not stay
    /// closed (a gap), where a window means little.
    pub warning: Option<String>,
}

/// The warning of a scene whose spring does not press the contacts together at rest (a gap,
/// or grazing): after its last impact the contacts are apart, or touch without force, so its
/// bounce time is not the time to a closed contact, and a window from it means little (a
/// datasheet's contact gap entered as `gap` gives a bounce of 0 and a window of 0 ticks).
#[must_use]
pub fn open_contact_warning(input: &SceneInput) -> Option<String> {
    match input.placement {
        Placement::Gap(d) if d > 0.0 => Some(format!(
            "the contacts do not stay closed: with gap = {d:e} m (> 0) the spring holds them apart \
             at rest, so the bounce ends with them open. A switch that closes and stays closed \
             presses its contacts together: give preload_force instead (a datasheet's contact \
             gap is how far the contacts open, not this gap; docs/parameters.md)"
        )),
        Placement::Gap(0.0) => Some(
            "the contacts touch without force at rest (gap = 0, grazing), so nothing holds them \
             closed after the bounce: a switch that stays closed presses its contacts together: \
             give preload_force (docs/parameters.md)"
                .to_owned(),
        ),
        // A negative gap is a preload: the spring presses the contacts together.
        Placement::Gap(_) | Placement::PreloadForce(_) => None,
    }
}

/// Draws the Monte Carlo samples in parallel; sample `i` is the same whatever the threads.
/// Samples a Monte Carlo worker draws between two updates of the shared progress count.
const PUBLISHED: u64 = 256;

fn monte_carlo(template: &Template, settings: &Settings) -> Result<MonteCarlo, FieldError> {
    let n = settings.samples.max(1);
    let threads = u64::try_from(settings.threads.max(1)).unwrap_or(1).min(n);
    let done = AtomicU64::new(0);
    let tolerance = Tolerance::new(settings.tolerance)?;
    // Each worker: its samples' bounces and upper bounds, and how many the exact reference
    // gave. One scene per worker, every ranged parameter drawn over it for each sample.
    let work = |k: usize| -> Result<(Vec<f64>, Vec<f64>, u64), FieldError> {
        // Reserved up front, but never more than a million (a library caller may ask for
        // any count; the CLI caps it).
        let share = usize::try_from(n / threads + 1).unwrap_or(0).min(1 << 20);
        let (mut bounces, mut uppers, mut exact) =
            (Vec::with_capacity(share), Vec::with_capacity(share), 0);
        let mut scene = template.nominal().clone();
        let mut i = u64::try_from(k).unwrap_or(u64::MAX);
        // Progress is published every PUBLISHED samples: with an atomic add a sample, two
        // threads fought over its cache line (the example file's Monte Carlo on two threads
        // took 1.23 times as long; on one, 1.03).
        let mut unpublished = 0;
        while i < n {
            template.sample_into(settings.seed, i, &mut scene);
            let (bounce, upper, by_reference) = answer_bounds(&scene, tolerance)?;
            bounces.push(bounce);
            uppers.push(upper);
            exact += u64::from(by_reference);
            unpublished += 1;
            if unpublished == PUBLISHED {
                done.fetch_add(unpublished, Ordering::Relaxed);
                unpublished = 0;
            }
            i += threads;
        }
        done.fetch_add(unpublished, Ordering::Relaxed);
        Ok((bounces, uppers, exact))
    };
    let results: Vec<Result<_, FieldError>> = std::thread::scope(|scope| {
        let jobs = crate::support::workers::spawn_each(
            scope,
            usize::try_from(threads).unwrap_or(1),
            &work,
        );
        if settings.progress {
            progress(&done, n, &jobs);
        }
        jobs.into_iter()
            .enumerate()
            // A worker that panicked (a thread that could not start): its share again, here.
            .map(|(k, job)| job.join(&work).unwrap_or_else(|| work(k)))
            .collect()
    });
    let all = usize::try_from(n).unwrap_or(0).min(1 << 20);
    let (mut bounces, mut uppers, mut exact) =
        (Vec::with_capacity(all), Vec::with_capacity(all), 0);
    for r in results {
        let (b, u, e) = r.map_err(|e| FieldError {
            field: e.field,
            message: format!(
                "a Monte Carlo sample is invalid: {} (narrow the range)",
                e.message
            ),
        })?;
        bounces.extend(b);
        uppers.extend(u);
        exact += e;
    }
    // Order statistics in linear time (a sort was a quarter of a run's time).
    let none = || FieldError {
        field: String::new(),
        message: "no Monte Carlo sample".to_owned(),
    };
    let max = uppers
        .iter()
        .copied()
        .max_by(f64::total_cmp)
        .ok_or_else(none)?;
    Ok(MonteCarlo {
        samples: n,
        p50: nearest_rank_unsorted(&mut bounces, 0.5).ok_or_else(none)?,
        window: nearest_rank_unsorted(&mut uppers, settings.percentile / 100.0).ok_or_else(none)?,
        max,
        exact,
    })
}

fn progress<T>(done: &AtomicU64, total: u64, handles: &[crate::support::workers::Job<'_, T>]) {
    use std::io::Write;
    let start = std::time::Instant::now();
    let mut shown = false;
    while handles.iter().any(|h| !h.is_finished()) {
        // Polled often at first, so a short Monte Carlo is not held up by the bar it never
        // shows (a poll of 200 ms cost every ranged switch 200 ms on a terminal).
        if start.elapsed().as_secs_f64() < 1.0 {
            std::thread::sleep(std::time::Duration::from_millis(2));
            continue;
        }
        std::thread::sleep(std::time::Duration::from_millis(200));
        let d = done.load(Ordering::Relaxed);
        #[allow(
            clippy::cast_precision_loss,
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss
        )]
        let filled = (40.0 * d as f64 / total as f64) as usize;
        eprint!(
            "\r[{}{}] {d}/{total} samples",
            "#".repeat(filled),
            " ".repeat(40 - filled.min(40))
        );
        let _ = std::io::stderr().flush();
        shown = true;
    }
    if shown {
        eprintln!();
    }
}

fn sensitivities(template: &Template, tolerance: f64) -> Result<Vec<Sensitivity>, FieldError> {
    let mut out = Vec::new();
    for (k, Range { field, dist, .. }) in template.params().iter().enumerate() {
        if dist.nominal() == 0.0 || dist.relative_half_width() == 0.0 {
            continue;
        }
        // A 1 % step, but never out of the range the user gave (which the Monte Carlo has
        // already sampled: R within (0.99, 0.995) must not be stepped to 1.002).
        let h = 0.01_f64.min(dist.relative_half_width());
        let up = estimate(&template.scaled(k, 1.0 + h), tolerance)?.bounce;
        let down = estimate(&template.scaled(k, 1.0 - h), tolerance)?.bounce;
        let elasticity = (up.ln() - down.ln()) / ((1.0 + h).ln() - (1.0 - h).ln());
        out.push(Sensitivity {
            parameter: field.clone(),
            elasticity,
            contribution: elasticity.abs() * dist.relative_half_width(),
        });
    }
    out.sort_by(|a, b| b.contribution.total_cmp(&a.contribution));
    Ok(out)
}

/// Analyses one switch.
///
/// # Errors
/// The invalid field (of the nominal scene, or of a sample: the range reaches outside the
/// model), or a window that does not fit in ticks.
pub fn analyse(
    name: &str,
    template: &Template,
    settings: &Settings,
) -> Result<Analysis, FieldError> {
    let nominal = estimate(template.nominal(), settings.tolerance)?;
    let (monte_carlo, sensitivity) = if template.params().is_empty() {
        (None, Vec::new())
    } else {
        let mc = monte_carlo(template, settings)?;
        let s = sensitivities(template, settings.tolerance)?;
        (Some(mc), s)
    };
    let bound = monte_carlo.as_ref().map_or(nominal.upper, |m| m.window);
    let margin = contact_bounce::Margin::new(settings.margin, 0.0).map_err(|e| FieldError {
        field: "margin".to_owned(),
        message: e.to_string(),
    })?;
    let window = settings.margin * bound;
    let ticks = contact_bounce::Window::from_seconds(bound, &margin, settings.period)
        .map_err(|e| FieldError {
            field: "period".to_owned(),
            message: e.to_string(),
        })?
        .ticks();
    Ok(Analysis {
        name: name.to_owned(),
        nominal,
        window,
        ticks,
        monte_carlo,
        sensitivity,
        warning: open_contact_warning(template.nominal()),
    })
}

/// The nodes the averaged envelope of the plots uses.
pub const PLOT_NODES: Nodes = Nodes::N8;

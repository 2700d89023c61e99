//! `bounce-table calibrate`: read a capture of a real switch and describe its bounce, per switch
//! and per kind (press, release), at the instrument's resolution.

use std::collections::BTreeMap;

use crate::capture::{self, CaptureError, Event, Kind, Polarity};
use crate::output::time;
use host_tests::stats::nearest_rank;

/// The capture's format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// JSON Lines of the bouncy-button capture.
    Jsonl,
    /// `time,level` rows.
    Csv,
    /// Value Change Dump.
    Vcd,
}

/// What `calibrate` was asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// The capture file.
    pub file: String,
    /// Its format (from the extension unless given).
    pub format: Format,
    /// Intervals shorter than this are unresolved (s).
    pub resolution: f64,
    /// A quiet interval at least this long ends a burst (s).
    pub burst_gap: f64,
    /// A change more than this after the previous one starts a new event (s); streams only.
    pub quiet: f64,
    /// The VCD signal.
    pub signal: Option<String>,
    /// High = closed.
    pub polarity: Polarity,
    /// JSON Lines sections to leave out.
    pub skip_sections: Vec<String>,
    /// The windows' percentile (0..1).
    pub percentile: f64,
    /// The random split's seed.
    pub seed: u64,
    /// Print the windows as C (`Some(false)`) or Rust (`Some(true)`) instead of the report.
    pub export: Option<bool>,
    /// Write one SVG per switch and kind there.
    pub plot: Option<String>,
    /// Print every event's description (CSV) instead of the report.
    pub events: bool,
}

fn seconds(name: &str, v: &str) -> Result<f64, String> {
    v.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite() && *x > 0.0)
        .ok_or(format!("{name}: '{v}' is not a positive number of seconds"))
}

/// Parses the arguments after `calibrate`.
///
/// # Errors
/// An unknown option, a missing or bad value, no file or two files.
pub fn options(args: &[String]) -> Result<Options, String> {
    let mut file: Option<String> = None;
    let mut format = None;
    let mut resolution = 3e-6;
    let mut burst_gap = 5e-3;
    let mut quiet = 0.2;
    let mut signal = None;
    let mut polarity = Polarity::ActiveLow;
    let mut skip_sections = Vec::new();
    let mut percentile = 0.99;
    let mut seed = 1;
    let mut export = None;
    let mut plot = None;
    let mut events = false;
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().cloned().ok_or(format!("{name} needs a value"));
        match arg.as_str() {
            "--format" => {
                format = Some(match value("--format")?.as_str() {
                    "jsonl" => Format::Jsonl,
                    "csv" => Format::Csv,
                    "vcd" => Format::Vcd,
                    other => return Err(format!("--format: '{other}' is not jsonl, csv or vcd")),
                });
            }
            "--resolution" => resolution = seconds("--resolution", &value("--resolution")?)?,
            "--burst-gap" => burst_gap = seconds("--burst-gap", &value("--burst-gap")?)?,
            "--quiet" => quiet = seconds("--quiet", &value("--quiet")?)?,
            "--signal" => signal = Some(value("--signal")?),
            "--active-high" => polarity = Polarity::ActiveHigh,
            "--skip-section" => skip_sections.push(value("--skip-section")?),
            "--percentile" => {
                let v = value("--percentile")?;
                percentile = v
                    .parse::<f64>()
                    .ok()
                    .filter(|p| *p > 0.0 && *p <= 100.0)
                    .ok_or(format!("--percentile: '{v}' is not in (0, 100]"))?
                    / 100.0;
            }
            "--seed" => {
                let v = value("--seed")?;
                seed = v
                    .parse()
                    .map_err(|_| format!("--seed: '{v}' is not a whole number"))?;
            }
            "--plot" => plot = Some(value("--plot")?),
            "--events" => events = true,
            "--export" => {
                export = Some(match value("--export")?.as_str() {
                    "c" => false,
                    "rust" => true,
                    other => return Err(format!("--export: '{other}' is not c or rust")),
                });
            }
            other if other.starts_with('-') => return Err(format!("unknown option {other}")),
            path => {
                if file.replace(path.to_owned()).is_some() {
                    return Err("give one capture file".to_owned());
                }
            }
        }
    }
    let file = file.ok_or("calibrate needs a capture file")?;
    let format = match format {
        Some(f) => f,
        None => match file.rsplit('.').next() {
            Some("jsonl") => Format::Jsonl,
            Some("csv") => Format::Csv,
            Some("vcd") => Format::Vcd,
            _ => return Err(format!("{file}: say --format jsonl|csv|vcd")),
        },
    };
    Ok(Options {
        file,
        format,
        resolution,
        burst_gap,
        quiet,
        signal,
        polarity,
        skip_sections,
        percentile,
        seed,
        export,
        plot,
        events,
    })
}

/// Reads the capture into events; the count of tests skipped (sections marked invalid or
/// named by `--skip-section`).
///
/// # Errors
/// The file cannot be read, or its content is malformed (named file and line).
pub fn load(o: &Options) -> Result<(Vec<Event>, usize), CaptureError> {
    let text = std::fs::read_to_string(&o.file).map_err(|e| CaptureError {
        file: o.file.clone(),
        line: 0,
        reason: e.to_string(),
    })?;
    let name = std::path::Path::new(&o.file)
        .file_stem()
        .map_or_else(|| o.file.clone(), |s| s.to_string_lossy().into_owned());
    match o.format {
        Format::Jsonl => capture::read_jsonl(&o.file, &text, &o.skip_sections),
        Format::Csv => Ok((
            capture::read_csv(&o.file, &text, o.polarity)?.segment(&name, o.quiet),
            0,
        )),
        Format::Vcd => Ok((
            capture::read_vcd(&o.file, &text, o.signal.as_deref(), o.polarity)?
                .segment(&name, o.quiet),
            0,
        )),
    }
}

fn sorted(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v
}

fn q(v: &[f64], p: f64, show: impl Fn(f64) -> String) -> String {
    nearest_rank(v, p).map_or_else(|| "-".to_owned(), show)
}

/// Every event described, one CSV row each, in capture order: where it is in the capture, its
/// bounce, transitions, resolved flights and dwells (count, longest), unresolved chatter
/// (count, time) and bursts.
#[must_use]
pub fn events_csv(events: &[Event], resolution: f64, burst_gap: f64) -> String {
    let mut out = String::from(
        "switch,origin,kind,bounce_s,transitions,flights,longest_flight_s,dwells,longest_dwell_s,chatter,chatter_time_s,bursts\n",
    );
    let quote = |s: &str| format!("\"{}\"", s.replace('"', "\"\""));
    let longest = |v: &[f64]| {
        v.iter()
            .copied()
            .reduce(f64::max)
            .map_or_else(String::new, |x| format!("{x:e}"))
    };
    for e in events {
        let d = e.describe(resolution, burst_gap);
        out.push_str(&format!(
            "{},{},{},{:e},{},{},{},{},{},{},{:e},{}\n",
            quote(&e.switch),
            quote(&e.origin),
            e.kind.name(),
            d.bounce,
            d.transitions,
            d.flights.len(),
            longest(&d.flights),
            d.dwells.len(),
            longest(&d.dwells),
            d.chatter,
            d.chatter_time,
            d.bursts,
        ));
    }
    out
}

/// The events described, per switch and kind, in capture order.
pub type Groups<'a> = BTreeMap<(&'a str, Kind), Vec<capture::Description>>;

/// Describes every event at `resolution` (a quiet interval of `burst_gap` ending a burst) and
/// groups them per switch and kind.
#[must_use]
pub fn group(events: &[Event], resolution: f64, burst_gap: f64) -> Groups<'_> {
    let mut groups: Groups<'_> = BTreeMap::new();
    for e in events {
        groups
            .entry((e.switch.as_str(), e.kind))
            .or_default()
            .push(e.describe(resolution, burst_gap));
    }
    groups
}

/// The description table (markdown): per switch and kind, the events, the share of clean edges
/// (one change), the bounce's P50/P90/P99/max, transitions, resolved flights and dwells, and
/// unresolved intervals (chatter).
#[must_use]
pub fn describe(groups: &Groups<'_>, resolution: f64) -> String {
    let mut out = String::new();
    out.push_str(&format!(
        "Resolution {}: shorter intervals are counted as chatter, not timed.\n\n",
        time(resolution)
    ));
    out.push_str("| switch | kind | events | clean | bounce P50 | P90 | P99 | max | transitions P50 / P90 / max | flights per event (P50) | longest flight P50 / P90 | dwells per event (P50) | chatter per event P50 / P90 |\n");
    out.push_str("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for ((switch, kind), d) in groups {
        #[allow(clippy::cast_precision_loss)]
        let count = |f: &dyn Fn(&capture::Description) -> usize| {
            sorted(d.iter().map(|x| f(x) as f64).collect())
        };
        let bounce = sorted(d.iter().map(|x| x.bounce).collect());
        let transitions = count(&|x| x.transitions);
        let flights = count(&|x| x.flights.len());
        let dwells = count(&|x| x.dwells.len());
        let chatter = count(&|x| x.chatter);
        let longest = sorted(
            d.iter()
                .filter_map(|x| x.flights.iter().copied().reduce(f64::max))
                .collect(),
        );
        let clean = d.iter().filter(|x| x.transitions <= 1).count();
        let n = |x: f64| format!("{x:.0}");
        out.push_str(&format!(
            "| {switch} | {} | {} | {clean} | {} | {} | {} | {} | {} / {} / {} | {} | {} / {} | {} | {} / {} |\n",
            kind.name(),
            d.len(),
            q(&bounce, 0.5, time),
            q(&bounce, 0.9, time),
            q(&bounce, 0.99, time),
            q(&bounce, 1.0, time),
            q(&transitions, 0.5, n),
            q(&transitions, 0.9, n),
            q(&transitions, 1.0, n),
            q(&flights, 0.5, n),
            q(&longest, 0.5, time),
            q(&longest, 0.9, time),
            q(&dwells, 0.5, n),
            q(&chatter, 0.5, n),
            q(&chatter, 0.9, n),
        ));
    }
    out
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

/// A log-normal distribution fitted to positive durations: `mu` the mean of their logarithms
/// (the maximum-likelihood estimate) and `sigma` their sample standard deviation (n - 1). Bounce durations are positive and spread over decades, which is what a log-normal
/// describes; whether it describes a given capture is for the held-out check to say.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogNormal {
    /// Mean of ln t (t in seconds).
    pub mu: f64,
    /// Standard deviation of ln t (0 when every duration is the same).
    pub sigma: f64,
    /// Durations fitted.
    pub n: usize,
}

/// Fewer durations than this give no log-normal: two points fix a spread but say nothing of
/// its shape.
pub const MIN_FIT: usize = 3;

impl LogNormal {
    /// The fit to `t`; `None` with fewer than [`MIN_FIT`] durations or any not positive and
    /// finite.
    #[must_use]
    pub fn fit(t: &[f64]) -> Option<Self> {
        if t.len() < MIN_FIT || t.iter().any(|x| !(x.is_finite() && *x > 0.0)) {
            return None;
        }
        #[allow(clippy::cast_precision_loss)]
        let n = t.len() as f64;
        let mu = t.iter().map(|x| x.ln()).sum::<f64>() / n;
        let var = t.iter().map(|x| (x.ln() - mu).powi(2)).sum::<f64>() / (n - 1.0);
        Some(Self {
            mu,
            sigma: var.sqrt(),
            n: t.len(),
        })
    }

    /// P(duration <= t).
    #[must_use]
    pub fn cdf(&self, t: f64) -> f64 {
        if t <= 0.0 {
            return 0.0;
        }
        let x = t.ln() - self.mu;
        if self.sigma <= 0.0 {
            return if x >= 0.0 { 1.0 } else { 0.0 };
        }
        0.5 * libm::erfc(-x / (self.sigma * core::f64::consts::SQRT_2))
    }

    /// The median, e^mu (s).
    #[must_use]
    pub fn median(&self) -> f64 {
        self.mu.exp()
    }
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
///   log-normal in the event's whole bounce, with the share observed.
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
    /// Whether the burst term is the impact model's (else the observed bursts').
    pub impact: bool,
    /// Median (dwell + chatter time) / flight time over the one-burst events with a resolved
    /// flight.
    pub closed_share: Option<f64>,
}

impl BounceModel {
    /// The model fitted to described events.
    #[must_use]
    pub fn fit(d: &[&capture::Description]) -> Self {
        let fit = ImpactFit::new(d);
        let clean: Vec<_> = d.iter().filter(|x| x.bounce <= 0.0).collect();
        let single: Vec<_> = d
            .iter()
            .filter(|x| x.bounce > 0.0 && x.bursts <= 1)
            .collect();
        let late: Vec<f64> = d
            .iter()
            .filter(|x| x.bounce > 0.0 && x.bursts > 1)
            .map(|x| x.bounce)
            .collect();
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
            late_bounce: LogNormal::fit(&late),
            impact,
            closed_share,
        }
    }

    /// The bouncing parts with their shares; `None` if a part that occurs could not be fitted.
    fn parts(&self) -> Option<Vec<(f64, LogNormal)>> {
        [(self.single, self.burst), (self.late, self.late_bounce)]
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
            .map(|(_, l)| l.mu)
            .fold(f64::NEG_INFINITY, f64::max)
            + spread;
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

/// Picks one predictor's ratios out of a [`Validation`].
type Ratios = fn(&Validation) -> &[Option<f64>; 3];

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

fn ratio(p: Option<f64>, o: Option<f64>) -> Option<f64> {
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
fn random_halves<'a>(
    d: &[&'a capture::Description],
    rng: &mut crate::spreads::SplitMix,
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
    let (a, b) = random_halves(d, &mut crate::spreads::SplitMix(seed));
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
    let mut rng = crate::spreads::SplitMix(seed);
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

fn ratio_text(r: Option<f64>) -> String {
    match r {
        None => "-".to_owned(),
        Some(r) if r >= 1000.0 => format!("{r:.1e}"),
        Some(r) => format!("{r:.2}"),
    }
}

fn three(r: &[Option<f64>; 3]) -> String {
    r.iter()
        .map(|x| ratio_text(*x))
        .collect::<Vec<_>>()
        .join(" / ")
}

fn lognormal_text(l: Option<LogNormal>) -> String {
    l.map_or_else(
        || "-".to_owned(),
        |l| format!("{} x/ {:.2}", time(l.median()), l.sigma.exp()),
    )
}

/// The fit, the held-out checks and the windows (markdown), after the description.
#[must_use]
pub fn assess(groups: &Groups<'_>, percentile: f64, seed: u64) -> String {
    let mut out = String::from(
        "\n## Impact-model fit\n\nR: the median ratio of successive resolved flights of the first burst (quartiles beside it); \
         the model holds when at least 5 pairs exist, 80 % of ratios are below 1 and the upper quartile too. \
         Scale v0 / (Omega^2 |Delta|) = first flight / (2 R); Omega, Delta and v0 apart need the closing \
         speed, the preload force or the resonance measured separately.\n\n\
         | switch | kind | flight pairs | R (median) | quartiles | ratios below 1 | first flight P50 | v0 / (Omega^2 \\|Delta\\|) | impact model holds |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let mut model = String::from(
        "\n## Fitted bounce model\n\nEach event is clean, one burst, or bounces again after a quiet interval of at \
         least the burst gap (a late burst). Bursts and late-burst bounces are log-normal (median x/ geometric \
         spread). The burst term is the impact model's (first flight / (1 - R), times 1 + the closed share: \
         the dwell and chatter a Newton impact does not have) where it holds, else the observed bursts'. \
         Last column: the model's quantiles over the capture's, on every event.\n\n\
         | switch | kind | events | clean | one burst | burst bounce | closed share | late burst | late bounce | burst term | model / observed P50 / P90 / P99 |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---|---:|\n",
    );
    let mut checks = String::from(
        "\n## Held-out check\n\nFit on one half, predict the other half's bounce P50 / P90 / P99: \
         predicted / observed, by the empirical part alone (the fitted half's own quantiles), by the \
         impact model alone (each event's first flight / (1 - R); `-` where R >= 1 or nothing is observed), \
         and by the fitted bounce model (`-` where a part that occurs has fewer than 3 events to fit).\n\n\
         | switch | kind | split | events | observed P50 / P90 / P99 | empirical | impact model | fitted model |\n\
         |---|---|---|---:|---:|---:|---:|---:|\n",
    );
    let mut spread = format!(
        "\n## Held-out over {RANDOM_SPLITS} random halvings\n\nThe held-out ratio (predicted / observed) over \
         {RANDOM_SPLITS} seeded random halvings: median and, in brackets, the 10th to 90th percentile; \
         \"splits\": how many halvings the predictor could predict in.\n\n\
         | switch | kind | predictor | splits | P50 | P90 | P99 |\n|---|---|---|---:|---:|---:|---:|\n"
    );
    let mut windows = format!(
        "\n## Windows\n\nP{p} of the observed bounce, and P{p} of the fitted model, each widened by its own worst \
         under-prediction in the held-out checks at that quantile; the window is the larger.\n\n\
         | switch | kind | empirical | fitted model | window | explained by |\n|---|---|---:|---:|---:|---|\n",
        p = percentile * 100.0
    );
    let pct = |x: f64| format!("{:.0} %", x * 100.0);
    for ((switch, kind), d) in groups {
        let refs: Vec<&capture::Description> = d.iter().collect();
        let fit = ImpactFit::new(&refs);
        let scale = fit
            .first_flight
            .zip(fit.restitution)
            .map(|(f, r)| f / (2.0 * r));
        out.push_str(&format!(
            "| {switch} | {} | {} | {} | {} | {:.0} % | {} | {} | {} |\n",
            kind.name(),
            fit.pairs,
            ratio_text(fit.restitution),
            fit.quartiles
                .map_or_else(|| "-".to_owned(), |(a, b)| format!("{a:.2} - {b:.2}")),
            fit.shrinking * 100.0,
            fit.first_flight.map_or_else(|| "-".to_owned(), time),
            scale.map_or_else(|| "-".to_owned(), |s| format!("{s:.3e} s")),
            if fit.holds() { "yes" } else { "no" },
        ));
        let m = BounceModel::fit(&refs);
        let all = sorted(refs.iter().map(|x| x.bounce).collect());
        let in_sample = VALIDATION_QUANTILES.map(|q| ratio(m.quantile(q), nearest_rank(&all, q)));
        model.push_str(&format!(
            "| {switch} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            kind.name(),
            m.events,
            pct(m.clean),
            pct(m.single),
            lognormal_text(m.burst),
            m.closed_share
                .map_or_else(|| "-".to_owned(), |c| format!("{c:.2}")),
            pct(m.late),
            lognormal_text(m.late_bounce),
            if m.impact { "impact model" } else { "observed" },
            three(&in_sample),
        ));
        let v = validations(&refs, seed);
        for c in &v {
            let observed = c
                .observed
                .iter()
                .map(|x| x.map_or_else(|| "-".to_owned(), time))
                .collect::<Vec<_>>()
                .join(" / ");
            checks.push_str(&format!(
                "| {switch} | {} | {} | {} + {} | {observed} | {} | {} | {} |\n",
                kind.name(),
                c.split,
                c.sizes.0,
                c.sizes.1,
                three(&c.empirical),
                three(&c.model),
                three(&c.fitted),
            ));
        }
        for (name, r) in ["empirical", "impact model", "fitted model"]
            .iter()
            .zip(random_splits(&refs, seed, RANDOM_SPLITS))
        {
            let cell = |x: Option<RatioSpread>| {
                x.map_or_else(
                    || "-".to_owned(),
                    |x| {
                        format!(
                            "{} ({} - {})",
                            ratio_text(Some(x.p50)),
                            ratio_text(Some(x.p10)),
                            ratio_text(Some(x.p90))
                        )
                    },
                )
            };
            spread.push_str(&format!(
                "| {switch} | {} | {name} | {} | {} | {} | {} |\n",
                kind.name(),
                r.iter().flatten().map(|x| x.predicted).max().unwrap_or(0),
                cell(r[0]),
                cell(r[1]),
                cell(r[2]),
            ));
        }
        let explained = if fit.holds() {
            "impact model and empirical terms"
        } else {
            "empirical terms only"
        };
        let w = window(&refs, percentile, &v);
        let show = |x: Option<f64>| x.map_or_else(|| "-".to_owned(), time);
        windows.push_str(&format!(
            "| {switch} | {} | {} | {} | {} | {explained} |\n",
            kind.name(),
            show(w.empirical),
            show(w.fitted),
            show(w.recommended()),
        ));
    }
    out + &model + &checks + &spread + &windows
}

/// The windows as C `#define`s or Rust constants (nanoseconds, rounded up).
#[must_use]
pub fn export(groups: &Groups<'_>, percentile: f64, seed: u64, rust: bool) -> String {
    let mut out = String::new();
    let guard = "BOUNCE_CALIBRATED_H";
    if rust {
        out.push_str(&format!(
            "// Debounce windows from a capture (bounce-table calibrate, P{}).\n\n",
            percentile * 100.0
        ));
    } else {
        out.push_str(&format!(
            "/* Debounce windows from a capture (bounce-table calibrate, P{}). */\n#ifndef {guard}\n#define {guard}\n\n",
            percentile * 100.0
        ));
    }
    for ((switch, kind), d) in groups {
        let refs: Vec<&capture::Description> = d.iter().collect();
        let v = validations(&refs, seed);
        let Some(w) = window(&refs, percentile, &v).recommended() else {
            continue;
        };
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let ns = (w * 1e9).ceil() as u64;
        let id = crate::output::identifier(&format!("{switch} {}", kind.name()));
        if rust {
            out.push_str(&format!("pub const {id}_WINDOW_NS: u64 = {ns};\n"));
        } else {
            out.push_str(&format!("#define {id}_WINDOW_NS {ns}ull\n"));
        }
    }
    if !rust {
        out.push_str(&format!("\n#endif /* {guard} */\n"));
    }
    out
}

/// The SVG of one switch and kind: the observed bounce's cumulative distribution against the
/// fitted [`BounceModel`]'s and, where it holds, the impact model's alone (each event's first
/// flight / (1 - R), fitted on all events), on a log10 time axis. Clean edges (no bounce) are left out and counted in the title.
#[must_use]
pub fn plot(switch: &str, kind: Kind, d: &[capture::Description]) -> String {
    let refs: Vec<&capture::Description> = d.iter().collect();
    let fit = ImpactFit::new(&refs);
    let cdf = |v: Vec<f64>| -> Vec<(f64, f64)> {
        let v = sorted(v.into_iter().filter(|t| *t > 0.0).collect());
        #[allow(clippy::cast_precision_loss)]
        let n = v.len() as f64;
        v.iter()
            .enumerate()
            .map(|(i, t)| {
                #[allow(clippy::cast_precision_loss)]
                let rank = (i + 1) as f64;
                (t.log10(), rank / n)
            })
            .collect()
    };
    let observed = cdf(d.iter().map(|x| x.bounce).collect());
    let clean = d.len() - observed.len();
    // The fitted model's distribution of the bouncing events, over the observed decades and
    // one more each side.
    let fitted = BounceModel::fit(&refs);
    let span = observed
        .first()
        .zip(observed.last())
        .map(|(a, b)| (a.0 - 1.0, b.0 + 1.0));
    let curve: Option<Vec<(f64, f64)>> = span.and_then(|(a, b)| {
        (0..=200)
            .map(|i| {
                let x = a + (b - a) * f64::from(i) / 200.0;
                let p = fitted.cdf(10f64.powf(x))?;
                Some((x, (p - fitted.clean) / (1.0 - fitted.clean)))
            })
            .collect()
    });
    let mut series = vec![crate::plot::Series {
        label: "observed",
        colour: "#1f77b4",
        points: observed,
        dots: true,
    }];
    // Where the flights do not shrink, R near 1 sends the impact model's sums off by decades:
    // drawn, it would only squash the axis.
    let modelled: Option<Vec<f64>> = refs.iter().map(|x| fit.bounce(x)).collect();
    if let Some(m) = modelled.filter(|_| fit.holds()) {
        series.push(crate::plot::Series {
            label: "impact model",
            colour: "#d62728",
            points: cdf(m),
            dots: false,
        });
    }
    if let Some(points) = curve {
        series.push(crate::plot::Series {
            label: "fitted model",
            colour: "#2ca02c",
            points,
            dots: false,
        });
    }
    crate::plot::svg(
        &format!(
            "{switch} {}: bounce CDF ({clean}/{} clean left out)",
            kind.name(),
            d.len()
        ),
        "log10 bounce (s)",
        "fraction of bouncing events",
        &series,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(a: &[&str]) -> Vec<String> {
        a.iter().map(|s| (*s).to_owned()).collect()
    }

    #[test]
    fn options_have_stated_defaults_and_name_the_bad_one() {
        let o = options(&args(&["capture.vcd"])).unwrap();
        assert_eq!(o.format, Format::Vcd);
        assert_eq!(
            (o.resolution, o.burst_gap, o.quiet, o.percentile),
            (3e-6, 5e-3, 0.2, 0.99)
        );
        let o = options(&args(&[
            "--burst-gap",
            "2e-2",
            "--percentile",
            "99.9",
            "c.csv",
        ]))
        .unwrap();
        assert_eq!((o.burst_gap, o.format), (2e-2, Format::Csv));
        assert!((o.percentile - 0.999).abs() < 1e-15);
        for (bad, named) in [
            (&["--burst-gap", "0", "c.csv"][..], "--burst-gap"),
            (&["--burst-gap", "NaN", "c.csv"], "--burst-gap"),
            (&["--burst-gap"], "--burst-gap"),
            (&["--resolution", "-1", "c.csv"], "--resolution"),
            (&["--percentile", "0", "c.csv"], "--percentile"),
            (&["--export", "java", "c.csv"], "--export"),
            (&["--frobnicate", "c.csv"], "--frobnicate"),
            (&["capture.bin"], "--format"),
            (&["a.csv", "b.csv"], "one capture"),
            (&[], "capture file"),
        ] {
            let e = options(&args(bad)).unwrap_err();
            assert!(e.contains(named), "{bad:?}: {e}");
        }
    }

    #[test]
    fn events_csv_has_one_row_per_event_quoted() {
        let events = [
            Event {
                switch: "a \"b\", c".into(),
                origin: "line 3".into(),
                kind: Kind::Press,
                // closed 10 us, open 1 us (chatter), closed 20 us, open 9 ms (quiet: a second
                // burst), closed 30 us.
                changes: vec![0.0, 10e-6, 11e-6, 31e-6, 9.031e-3, 9.061e-3],
            },
            Event {
                switch: "x".into(),
                origin: String::new(),
                kind: Kind::Release,
                changes: vec![1.0],
            },
        ];
        let csv = events_csv(&events, 3e-6, 5e-3);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 3, "{csv}");
        let rest = lines[1]
            .strip_prefix("\"a \"\"b\"\", c\",\"line 3\",press,")
            .unwrap();
        let f: Vec<f64> = rest.split(',').map(|x| x.parse().unwrap()).collect();
        let want = [9.061e-3, 6.0, 1.0, 9e-3, 3.0, 3e-5, 1.0, 1e-6, 2.0];
        assert_eq!(f.len(), want.len(), "{rest}");
        for (got, want) in f.iter().zip(want) {
            assert!((got - want).abs() <= 1e-12, "{rest}");
        }
        assert_eq!(lines[2], "\"x\",\"\",release,0e0,1,0,,0,,0,0e0,1");
    }
}

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
    let mut quiet = 0.2;
    let mut signal = None;
    let mut polarity = Polarity::ActiveLow;
    let mut skip_sections = Vec::new();
    let mut percentile = 0.99;
    let mut seed = 1;
    let mut export = None;
    let mut plot = None;
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
        quiet,
        signal,
        polarity,
        skip_sections,
        percentile,
        seed,
        export,
        plot,
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

/// The events described, per switch and kind, in capture order.
pub type Groups<'a> = BTreeMap<(&'a str, Kind), Vec<capture::Description>>;

/// Describes every event at `resolution` and groups them per switch and kind.
#[must_use]
pub fn group(events: &[Event], resolution: f64) -> Groups<'_> {
    let mut groups: Groups<'_> = BTreeMap::new();
    for e in events {
        groups
            .entry((e.switch.as_str(), e.kind))
            .or_default()
            .push(e.describe(resolution));
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
                .flat_map(|x| x.flights.windows(2).map(|w| w[1] / w[0]))
                .collect(),
        );
        let firsts = sorted(
            d.iter()
                .filter_map(|x| x.flights.first().copied())
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
        Some(d.flights.first().map_or(0.0, |f| f / (1.0 - r)))
    }
}

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
    }
}

/// The two held-out checks of one switch and kind: a seeded random half, and the first half in
/// capture order against the second.
#[must_use]
pub fn validations(d: &[&capture::Description], seed: u64) -> [Validation; 2] {
    let half = d.len() / 2;
    let (first, second) = d.split_at(half);
    let mut shuffled = d.to_vec();
    // Fisher-Yates with xorshift64*: the same split for the same seed everywhere.
    let mut state = seed | 1;
    for i in (1..shuffled.len()).rev() {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        let r = state.wrapping_mul(0x2545_F491_4F6C_DD1D);
        let j = usize::try_from(r % (i as u64 + 1)).unwrap_or(0);
        shuffled.swap(i, j);
    }
    let (a, b) = shuffled.split_at(half);
    [
        validate("random halves", a, b),
        validate("chronological halves", first, second),
    ]
}

/// A debounce window from a capture: the `percentile` of the observed bounce, widened by the
/// worst under-prediction of the held-out checks at the nearest checked quantile.
#[must_use]
pub fn window(d: &[&capture::Description], percentile: f64, checks: &[Validation]) -> Option<f64> {
    let all = sorted(d.iter().map(|x| x.bounce).collect());
    let base = nearest_rank(&all, percentile)?;
    let nearest = VALIDATION_QUANTILES
        .iter()
        .enumerate()
        .min_by(|a, b| {
            (a.1 - percentile)
                .abs()
                .total_cmp(&(b.1 - percentile).abs())
        })
        .map_or(0, |(i, _)| i);
    let worst = checks
        .iter()
        .filter_map(|v| v.empirical[nearest])
        .fold(1.0_f64, |w, r| if r > 0.0 { w.max(1.0 / r) } else { w });
    Some(base * worst)
}

fn ratio_text(r: Option<f64>) -> String {
    match r {
        None => "-".to_owned(),
        Some(r) if r >= 1000.0 => format!("{r:.1e}"),
        Some(r) => format!("{r:.2}"),
    }
}

/// The fit, the held-out checks and the windows (markdown), after the description.
#[must_use]
pub fn assess(groups: &Groups<'_>, percentile: f64, seed: u64) -> String {
    let mut out = String::from(
        "\n## Impact-model fit\n\nR: the median ratio of successive resolved flights (quartiles beside it); \
         the model holds when at least 5 pairs exist, 80 % of ratios are below 1 and the upper quartile too. \
         Scale v0 / (Omega^2 |Delta|) = first flight / (2 R); Omega, Delta and v0 apart need the closing \
         speed, the preload force or the resonance measured separately.\n\n\
         | switch | kind | flight pairs | R (median) | quartiles | ratios below 1 | first flight P50 | v0 / (Omega^2 \\|Delta\\|) | impact model holds |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let mut checks = String::from(
        "\n## Held-out check\n\nFit on one half, predict the other half's bounce P50 / P90 / P99: \
         predicted / observed, by the empirical part (the fitted half's own quantiles) and by the \
         impact model (each event's first flight / (1 - R); `-` where R >= 1 or nothing is observed).\n\n\
         | switch | kind | split | events | observed P50 / P90 / P99 | empirical | impact model |\n\
         |---|---|---|---:|---:|---:|---:|\n",
    );
    let mut windows = format!(
        "\n## Windows\n\nP{} of the observed bounce, widened by the worst under-prediction of the \
         held-out checks at that quantile.\n\n| switch | kind | window | explained by |\n|---|---|---:|---|\n",
        percentile * 100.0
    );
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
        let v = validations(&refs, seed);
        for c in &v {
            let three = |r: &[Option<f64>; 3]| {
                r.iter()
                    .map(|x| ratio_text(*x))
                    .collect::<Vec<_>>()
                    .join(" / ")
            };
            let observed = c
                .observed
                .iter()
                .map(|x| x.map_or_else(|| "-".to_owned(), time))
                .collect::<Vec<_>>()
                .join(" / ");
            checks.push_str(&format!(
                "| {switch} | {} | {} | {} + {} | {observed} | {} | {} |\n",
                kind.name(),
                c.split,
                c.sizes.0,
                c.sizes.1,
                three(&c.empirical),
                three(&c.model),
            ));
        }
        let explained = if fit.holds() {
            "impact model and empirical"
        } else {
            "empirical only"
        };
        windows.push_str(&format!(
            "| {switch} | {} | {} | {explained} |\n",
            kind.name(),
            window(&refs, percentile, &v).map_or_else(|| "-".to_owned(), time),
        ));
    }
    out + &checks + &windows
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
        let Some(w) = window(&refs, percentile, &v) else {
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
/// impact model's (each event's first flight / (1 - R), fitted on all events; absent when R >= 1),
/// on a log10 time axis. Clean edges (no bounce) are left out and counted in the title.
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
    let mut series = vec![crate::plot::Series {
        label: "observed",
        colour: "#1f77b4",
        points: observed,
        dots: true,
    }];
    let modelled: Option<Vec<f64>> = refs.iter().map(|x| fit.bounce(x)).collect();
    if let Some(m) = modelled {
        series.push(crate::plot::Series {
            label: "impact model",
            colour: "#d62728",
            points: cdf(m),
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

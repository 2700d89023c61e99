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

/// The description table (markdown): per switch and kind, the events, the share of clean edges
/// (one change), the bounce's P50/P90/P99/max, transitions, resolved flights and dwells, and
/// unresolved intervals (chatter).
#[must_use]
pub fn describe(events: &[Event], resolution: f64) -> String {
    let mut groups: BTreeMap<(&str, Kind), Vec<capture::Description>> = BTreeMap::new();
    for e in events {
        groups
            .entry((e.switch.as_str(), e.kind))
            .or_default()
            .push(e.describe(resolution));
    }
    let mut out = String::new();
    out.push_str(&format!(
        "Resolution {}: shorter intervals are counted as chatter, not timed.\n\n",
        time(resolution)
    ));
    out.push_str("| switch | kind | events | clean | bounce P50 | P90 | P99 | max | transitions P50 / P90 / max | flights per event (P50) | longest flight P50 / P90 | dwells per event (P50) | chatter per event P50 / P90 |\n");
    out.push_str("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for ((switch, kind), d) in &groups {
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

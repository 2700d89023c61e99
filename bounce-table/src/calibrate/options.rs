//! What `calibrate` is asked for: its options and the capture they name.

use crate::capture::{self, CaptureError, Event, Polarity};

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
    /// A change more than this after the previous one starts a new event in a stream (s); a
    /// JSON Lines event with a quiet interval this long inside holds several presses.
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
    /// Print the windows as C (`Some(false)`) or Rust (`Some(true)`) instead of the report
    /// (`--format c|rust`).
    pub export: Option<bool>,
    /// Write the output there, completely or not at all (else standard output).
    pub output: Option<String>,
    /// Write one SVG per switch and kind there.
    pub plot: Option<String>,
    /// Print every event's description (CSV) instead of the report (`--format csv`).
    pub events: bool,
    /// Also fit the real-contact models (slow: tens of seconds).
    pub contact_models: bool,
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
    // Arguments echoed in a message have their control characters escaped: one line.
    options_unescaped(args).map_err(|m| crate::strict::printable(&m).into_owned())
}

fn options_unescaped(args: &[String]) -> Result<Options, String> {
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
    let mut output = None;
    let mut plot = None;
    let mut events = false;
    let mut contact_models = false;
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().cloned().ok_or(format!("{name} needs a value"));
        match arg.as_str() {
            "--capture-format" => {
                format = Some(match value("--capture-format")?.as_str() {
                    "jsonl" => Format::Jsonl,
                    "csv" => Format::Csv,
                    "vcd" => Format::Vcd,
                    other => {
                        return Err(format!(
                            "--capture-format: '{other}' is not jsonl, csv or vcd"
                        ))
                    }
                });
            }
            // What is written, as every subcommand says it: the report, the windows as code,
            // or one CSV row per event (`--export` and `--events` are the older spellings).
            "--format" => match value("--format")?.as_str() {
                "report" | "markdown" => (export, events) = (None, false),
                "c" => (export, events) = (Some(false), false),
                "rust" => (export, events) = (Some(true), false),
                "csv" => (export, events) = (None, true),
                capture @ ("jsonl" | "vcd") => {
                    return Err(format!(
                        "--format: '{capture}' is a capture's format: --capture-format {capture}"
                    ))
                }
                other => {
                    return Err(format!(
                        "--format: '{other}' is not report, c, rust or csv (events)"
                    ))
                }
            },
            "--output" => output = Some(value("--output")?),
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
            "--contact-models" => contact_models = true,
            "--export" => {
                export = Some(match value("--export")?.as_str() {
                    "c" => false,
                    "rust" => true,
                    other => return Err(format!("--export: '{other}' is not c or rust")),
                });
            }
            other if other.starts_with('-') => return Err(format!("unknown option '{other}'")),
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
            _ => return Err(format!("{file}: say --capture-format jsonl|csv|vcd")),
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
        output,
        plot,
        events,
        contact_models,
    })
}

/// Reads the capture into events, leaving out what cannot be one press or release (see
/// [`capture::Skipped`]): sections the capture marks invalid, sections named by
/// `--skip-section`, and events with a quiet interval longer than `--quiet` inside (several
/// presses).
///
/// # Errors
/// The file cannot be read, or its content is malformed (named file and line).
pub fn load(o: &Options) -> Result<(Vec<Event>, capture::Skipped), CaptureError> {
    let text = std::fs::read_to_string(&o.file).map_err(|e| CaptureError {
        file: o.file.clone(),
        line: 0,
        reason: e.to_string(),
    })?;
    let name = std::path::Path::new(&o.file)
        .file_stem()
        .map_or_else(|| o.file.clone(), |s| s.to_string_lossy().into_owned());
    let (events, mut skipped) = match o.format {
        Format::Jsonl => capture::read_jsonl(&o.file, &text, &o.skip_sections)?,
        Format::Csv => (
            capture::read_csv(&o.file, &text, o.polarity)?.segment(&name, o.quiet),
            capture::Skipped::default(),
        ),
        Format::Vcd => (
            capture::read_vcd(&o.file, &text, o.signal.as_deref(), o.polarity)?
                .segment(&name, o.quiet),
            capture::Skipped::default(),
        ),
    };
    let events = capture::drop_several_presses(events, o.quiet, &mut skipped);
    Ok((events, skipped))
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
            (&["capture.bin"], "--capture-format"),
            (&["--format", "java", "c.csv"], "--format"),
            (&["--capture-format", "wav", "c.csv"], "--capture-format"),
            (&["a.csv", "b.csv"], "one capture"),
            (&[], "capture file"),
        ] {
            let e = options(&args(bad)).unwrap_err();
            assert!(e.contains(named), "{bad:?}: {e}");
        }
    }
}

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
    /// No real tap is shorter than this (s): windows are capped at it (`--min-tap`).
    pub min_tap: Option<f64>,
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

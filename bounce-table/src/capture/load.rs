//! Which capture to read and how: its options, its format, and the reader they choose.

use super::event::{drop_several_presses, CaptureError, Event, Polarity, Skipped};
use super::{csv::read_csv, jsonl::read_jsonl, scope, vcd::read_vcd};

/// The capture's format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// JSON Lines of the bouncy-button capture.
    Jsonl,
    /// `time,level` rows.
    Csv,
    /// Value Change Dump.
    Vcd,
    /// A scope's export (or `time,volts` rows) of this vendor; `None`: a CSV recognised by its
    /// header, a scope's export or `time,level` rows (the default for `.csv` files and folders).
    Scope(Option<scope::Vendor>),
}

/// How to read a capture: the file, its format, and how its changes are cut into events. What
/// is done with the events (`calibrate`'s windows, `replay`'s scores) is the command's.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// The capture file.
    pub file: String,
    /// Its format (from the extension unless given).
    pub format: Format,
    /// A change more than this after the previous one starts a new event in a stream (s); a
    /// JSON Lines event with a quiet interval this long inside holds several presses
    /// (`--event-gap`).
    pub event_gap: f64,
    /// The VCD signal.
    pub signal: Option<String>,
    /// An analog capture's channel (the only one when `None`).
    pub channel: Option<String>,
    /// An analog capture's thresholds.
    pub input: scope::Input,
    /// High = closed.
    pub polarity: Polarity,
    /// JSON Lines sections to leave out.
    pub skip_sections: Vec<String>,
}

/// What [`load`] read: the events, what it left out, and for an analog capture its report.
#[derive(Debug, Clone, PartialEq)]
pub struct Loaded {
    /// The events, in capture order.
    pub events: Vec<Event>,
    /// What was left out, and why.
    pub skipped: Skipped,
    /// An analog capture's swing, noise, edges, thresholds and marginal dips (one per file).
    pub analog: Vec<scope::Report>,
}

/// Reads the capture into events, leaving out what cannot be one press or release (see
/// [`Skipped`]): sections the capture marks invalid, sections named by
/// `--skip-section`, and events with a quiet interval longer than `--event-gap` inside (several
/// presses). A folder is read file by file (in name order; hidden files left out), each an
/// acquisition or several, all of one switch named after the folder.
///
/// # Errors
/// The file cannot be read, or its content is malformed (named file and line).
pub fn load(o: &Options) -> Result<Loaded, CaptureError> {
    let path = std::path::Path::new(&o.file);
    let unreadable = |file: &str, e: std::io::Error| CaptureError {
        file: file.to_owned(),
        line: 0,
        reason: e.to_string(),
    };
    let name = path
        .file_stem()
        .map_or_else(|| o.file.clone(), |s| s.to_string_lossy().into_owned());
    let files: Vec<String> = if path.is_dir() {
        let mut files: Vec<String> = std::fs::read_dir(path)
            .map_err(|e| unreadable(&o.file, e))?
            .filter_map(Result::ok)
            .filter(|e| e.path().is_file() && !e.file_name().to_string_lossy().starts_with('.'))
            .map(|e| e.path().to_string_lossy().into_owned())
            .collect();
        files.sort();
        if files.is_empty() {
            return Err(CaptureError {
                file: o.file.clone(),
                line: 0,
                reason: "an empty folder: no capture to read".to_owned(),
            });
        }
        files
    } else {
        vec![o.file.clone()]
    };
    let texts = files
        .into_iter()
        .map(|file| {
            let text = std::fs::read_to_string(&file).map_err(|e| unreadable(&file, e))?;
            Ok((file, text))
        })
        .collect::<Result<Vec<_>, CaptureError>>()?;
    load_text(o, &name, &texts)
}

/// [`load`] on captures already in memory: each (file name, text) of the switch `name` (a
/// folder's files, or one file), read by `o`'s format.
///
/// # Errors
/// A content that is malformed (named file and line).
pub fn load_text(
    o: &Options,
    name: &str,
    texts: &[(String, String)],
) -> Result<Loaded, CaptureError> {
    let mut loaded = Loaded {
        events: Vec::new(),
        skipped: Skipped::default(),
        analog: Vec::new(),
    };
    let several = texts.len() > 1;
    for (file, text) in texts {
        let (mut events, skipped) = read_one(o, file, text, name, several, &mut loaded.analog)?;
        loaded.events.append(&mut events);
        loaded.skipped.add(skipped);
    }
    let events = std::mem::take(&mut loaded.events);
    loaded.events = drop_several_presses(events, o.event_gap, &mut loaded.skipped);
    Ok(loaded)
}

/// One file of the capture: its events, what it left out, and its analog report if it has one.
fn read_one(
    o: &Options,
    file: &str,
    text: &str,
    name: &str,
    several: bool,
    analog: &mut Vec<scope::Report>,
) -> Result<(Vec<Event>, Skipped), CaptureError> {
    let format = match o.format {
        Format::Scope(None) if scope::recognise(text).is_none() => Format::Csv,
        f => f,
    };
    let events = match format {
        Format::Jsonl => return read_jsonl(file, text, &o.skip_sections),
        Format::Csv => read_csv(file, text, o.polarity)?.segment(name, o.event_gap),
        Format::Vcd => {
            read_vcd(file, text, o.signal.as_deref(), o.polarity)?.segment(name, o.event_gap)
        }
        Format::Scope(vendor) => {
            let (streams, report) = scope::load(
                file,
                text,
                vendor,
                o.channel.as_deref(),
                &o.input,
                o.polarity,
            )?;
            analog.push(report);
            let base = std::path::Path::new(file)
                .file_name()
                .map_or_else(|| file.to_owned(), |s| s.to_string_lossy().into_owned());
            let acquisitions = streams.len();
            let mut events = Vec::new();
            for (k, stream) in streams.iter().enumerate() {
                for mut e in stream.segment(name, o.event_gap) {
                    let mut at = Vec::new();
                    if several {
                        at.push(base.clone());
                    }
                    if acquisitions > 1 {
                        at.push(format!("acquisition {}", k + 1));
                    }
                    at.push(e.origin);
                    e.origin = at.join(", ");
                    events.push(e);
                }
            }
            events
        }
    };
    Ok((events, Skipped::default()))
}

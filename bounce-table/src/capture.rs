//! Real captures of a switch: import them (JSON Lines of the bouncy-button format, a CSV of
//! edges, a Value Change Dump), cut them into press and release events, and describe each
//! event's bounce: duration, transitions, resolved open intervals (flights) and closed intervals
//! (dwell), and the intervals too short for the instrument (chatter).
//!
//! Levels follow the usual wiring, a pull-up and a switch to ground: high = open, low = closed
//! (`Polarity::ActiveLow`); `Polarity::ActiveHigh` reads the other way.

use std::fmt;

use serde_json::Value;

/// Which way the switch moved: the core's own type (its debouncers report the same edges), so
/// that press and release have one name from the pin to the report.
pub use contact_bounce::Edge;

/// An edge's name in the outputs ("press", "release").
pub trait EdgeName {
    /// Its name.
    fn name(self) -> &'static str;
}

impl EdgeName for Edge {
    fn name(self) -> &'static str {
        match self {
            Edge::Press => "press",
            Edge::Release => "release",
        }
    }
}

/// How a logic level maps to the contact: the core's own type (its debouncer reads pins the
/// same way).
pub use contact_bounce::debounce::Polarity;

/// True when the pin level `high` means the contact is closed.
fn is_closed(polarity: Polarity, high: bool) -> bool {
    match polarity {
        Polarity::ActiveLow => !high,
        Polarity::ActiveHigh => high,
    }
}

/// One press or release: the contact's state before it, and the times of its changes (s).
#[derive(Debug, Clone, PartialEq)]
pub struct Event {
    /// The switch (a dataset, a file).
    pub switch: String,
    /// Where it came from (a line, a time), for messages.
    pub origin: String,
    /// Press or release (from the state before the first change).
    pub kind: Edge,
    /// The times of the changes, nondecreasing, in seconds; the contact alternates at each.
    pub changes: Vec<f64>,
    /// The part of the test protocol the event belongs to (the JSON Lines `section`: how the
    /// switch was operated), where the capture says.
    pub section: Option<String>,
}

/// A capture that cannot be read: the file, the line (1-based, 0 when it is the whole file)
/// and what is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CaptureError {
    /// The file.
    pub file: String,
    /// The line, 1-based; 0 for the file as a whole.
    pub line: usize,
    /// What is wrong.
    pub reason: String,
}

/// One line: control characters from the file are shown escaped.
impl fmt::Display for CaptureError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use crate::strict::printable;
        let (file, reason) = (printable(&self.file), printable(&self.reason));
        if self.line == 0 {
            write!(f, "{file}: {reason}")
        } else {
            write!(f, "{file}:{}: {reason}", self.line)
        }
    }
}

impl std::error::Error for CaptureError {}

fn error(file: &str, line: usize, reason: impl Into<String>) -> CaptureError {
    CaptureError {
        file: file.to_owned(),
        line,
        reason: reason.into(),
    }
}

/// A stream of level changes: the contact's state before the first, and the change times (s).
#[derive(Debug, Clone, PartialEq)]
pub struct Stream {
    /// Closed before the first change.
    pub closed_before: bool,
    /// Change times in seconds, nondecreasing.
    pub changes: Vec<f64>,
}

impl Stream {
    /// Cuts the stream into events: a new event starts at a change that follows the previous
    /// one by more than `quiet` seconds. Each event is a press if the contact was open before
    /// it, else a release.
    #[must_use]
    pub fn segment(&self, switch: &str, quiet: f64) -> Vec<Event> {
        let mut events = Vec::new();
        let mut closed = self.closed_before;
        let mut current: Vec<f64> = Vec::new();
        let mut start_closed = closed;
        for &t in &self.changes {
            if current.last().is_some_and(|&last| t - last > quiet) {
                events.push(event(switch, start_closed, std::mem::take(&mut current)));
                start_closed = closed;
            }
            current.push(t);
            closed = !closed;
        }
        if !current.is_empty() {
            events.push(event(switch, start_closed, current));
        }
        events
    }
}

fn event(switch: &str, closed_before: bool, changes: Vec<f64>) -> Event {
    Event {
        switch: switch.to_owned(),
        origin: format!("t = {:.6} s", changes.first().copied().unwrap_or(0.0)),
        kind: if closed_before {
            Edge::Release
        } else {
            Edge::Press
        },
        changes,
        section: None,
    }
}

/// Appends a change at `t` to `changes` if the contact state differs from `closed`; a repeated
/// level is no change. Times must not go back.
fn push_change(
    changes: &mut Vec<f64>,
    closed: &mut bool,
    now_closed: bool,
    t: f64,
) -> Result<(), String> {
    if !t.is_finite() {
        return Err(format!("time {t} is not a finite number"));
    }
    if changes.last().is_some_and(|&last| t < last) {
        return Err(format!("time {t} s goes back in time"));
    }
    if now_closed != *closed {
        changes.push(t);
        *closed = now_closed;
    }
    Ok(())
}

fn level(text: &str) -> Option<bool> {
    match text.trim() {
        "1" | "high" | "H" => Some(true),
        "0" | "low" | "L" => Some(false),
        _ => None,
    }
}

/// Reads a CSV of level changes: one `time,level` row per change (time in seconds, level 0 or
/// 1); an optional header row, blank lines and `#` comments are skipped. The first row gives
/// the level at the start of the capture (not a change).
///
/// # Errors
/// A row that is not two fields, a time that is not a finite number or goes back, a level
/// other than 0/1, or a file with no rows: the error names the line.
pub fn read_csv(file: &str, text: &str, polarity: Polarity) -> Result<Stream, CaptureError> {
    let mut start: Option<bool> = None;
    let mut closed = false;
    let mut changes = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let row = raw.trim();
        if row.is_empty() || row.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = row.split(',').map(str::trim).collect();
        let [time, value] = fields[..] else {
            return Err(error(
                file,
                line,
                format!("expected `time,level`, found {row:?}"),
            ));
        };
        let Ok(t) = time.parse::<f64>() else {
            if start.is_none() && changes.is_empty() && level(value).is_none() {
                continue; // a header row
            }
            return Err(error(file, line, format!("time {time:?} is not a number")));
        };
        let Some(high) = level(value) else {
            return Err(error(file, line, format!("level {value:?} is not 0 or 1")));
        };
        let now_closed = is_closed(polarity, high);
        if start.is_none() {
            if !t.is_finite() {
                return Err(error(
                    file,
                    line,
                    format!("time {t} is not a finite number"),
                ));
            }
            start = Some(now_closed);
            closed = now_closed;
            continue;
        }
        push_change(&mut changes, &mut closed, now_closed, t)
            .map_err(|reason| error(file, line, reason))?;
    }
    let Some(closed_before) = start else {
        return Err(error(file, 0, "no rows: expected `time,level` rows"));
    };
    Ok(Stream {
        closed_before,
        changes,
    })
}

/// Reads a Value Change Dump (IEEE 1364 sec. 18: what sigrok/PulseView and most logic
/// analyzers export) and returns the changes of one 1-bit signal: the one named `signal`, or
/// the only 1-bit signal when `signal` is `None`. The value at the first time stamp (or in
/// `$dumpvars`) is the starting level. Value changes may share a line with their time stamp
/// (as PulseView and sigrok-cli write them); a first line `META ...`, which sigrok-cli 0.7 writes
/// ahead of the header, is skipped.
///
/// # Errors
/// A malformed header or time stamp, an unknown or ambiguous signal, a signal wider than one
/// bit, an `x`/`z` value on the signal, or a signal with no value: the error names the line.
pub fn read_vcd(
    file: &str,
    text: &str,
    signal: Option<&str>,
    polarity: Polarity,
) -> Result<Stream, CaptureError> {
    // Tokens with their line numbers.
    let tokens: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .filter(|(i, l)| !(*i == 0 && l.starts_with("META ")))
        .flat_map(|(i, l)| l.split_whitespace().map(move |t| (i + 1, t)))
        .collect();
    let mut scale = None;
    let mut vars: Vec<(String, String, u32, usize)> = Vec::new(); // (id, name, width, line)
    let mut k = 0;
    let block_end = |from: usize| -> Result<usize, CaptureError> {
        tokens[from..]
            .iter()
            .position(|&(_, t)| t == "$end")
            .map(|p| from + p)
            .ok_or_else(|| error(file, tokens[from - 1].0, "a `$` section without `$end`"))
    };
    // The header, up to $enddefinitions.
    loop {
        let Some(&(line, tok)) = tokens.get(k) else {
            return Err(error(file, 0, "no `$enddefinitions $end`: not a VCD file"));
        };
        match tok {
            "$enddefinitions" => {
                k = block_end(k + 1)? + 1;
                break;
            }
            "$timescale" => {
                let end = block_end(k + 1)?;
                let spec: String = tokens[k + 1..end].iter().map(|&(_, t)| t).collect();
                scale = Some(timescale(&spec).ok_or_else(|| {
                    error(
                        file,
                        line,
                        format!("timescale {spec:?} is not 1/10/100 s|ms|us|ns|ps|fs"),
                    )
                })?);
                k = end + 1;
            }
            "$var" => {
                let end = block_end(k + 1)?;
                let fields: Vec<&str> = tokens[k + 1..end].iter().map(|&(_, t)| t).collect();
                let [_, width, id, name, ..] = fields[..] else {
                    return Err(error(
                        file,
                        line,
                        "`$var` needs a type, a width, an id and a name",
                    ));
                };
                let width = width
                    .parse()
                    .map_err(|_| error(file, line, format!("width {width:?} is not a number")))?;
                vars.push((id.to_owned(), name.to_owned(), width, line));
                k = end + 1;
            }
            t if t.starts_with('$') => k = block_end(k + 1)? + 1,
            other => {
                return Err(error(
                    file,
                    line,
                    format!("{other:?} before `$enddefinitions`"),
                ));
            }
        }
    }
    let scale = scale.ok_or_else(|| error(file, 0, "no `$timescale`"))?;
    let (id, name) = match signal {
        Some(wanted) => {
            let (id, name, width, line) = vars
                .iter()
                .find(|(_, n, _, _)| n == wanted)
                .ok_or_else(|| error(file, 0, format!("no signal named {wanted:?}")))?;
            if *width != 1 {
                return Err(error(
                    file,
                    *line,
                    format!("signal {name:?} is {width} bits wide, not 1"),
                ));
            }
            (id.clone(), name.clone())
        }
        None => {
            let one_bit: Vec<_> = vars.iter().filter(|v| v.2 == 1).collect();
            match one_bit[..] {
                [(id, name, _, _)] => (id.clone(), name.clone()),
                [] => return Err(error(file, 0, "no 1-bit signal")),
                _ => {
                    let names: Vec<&str> = one_bit.iter().map(|v| v.1.as_str()).collect();
                    return Err(error(
                        file,
                        0,
                        format!("several 1-bit signals ({}): name one", names.join(", ")),
                    ));
                }
            }
        }
    };
    let mut now: Option<f64> = None;
    let mut start: Option<bool> = None;
    let mut closed = false;
    let mut changes = Vec::new();
    while let Some(&(line, tok)) = tokens.get(k) {
        k += 1;
        if let Some(stamp) = tok.strip_prefix('#') {
            let ticks: u64 = stamp.parse().map_err(|_| {
                error(
                    file,
                    line,
                    format!("time stamp {tok:?} is not a whole number"),
                )
            })?;
            #[allow(clippy::cast_precision_loss)]
            let t = ticks as f64 * scale;
            if now.is_some_and(|n| t < n) {
                return Err(error(
                    file,
                    line,
                    format!("time stamp {tok:?} goes back in time"),
                ));
            }
            now = Some(t);
            continue;
        }
        if matches!(
            tok,
            "$dumpvars" | "$dumpall" | "$dumpon" | "$dumpoff" | "$end"
        ) {
            continue;
        }
        if tok.starts_with('$') {
            k = block_end(k)? + 1;
            continue;
        }
        // A vector or real value: `b0101 id` / `r1.5 id`, on another signal (ours is 1-bit).
        if tok.starts_with(['b', 'B', 'r', 'R']) {
            let Some(&(_, target)) = tokens.get(k) else {
                return Err(error(file, line, format!("{tok:?} without a signal id")));
            };
            if target == id {
                return Err(error(
                    file,
                    line,
                    format!("a vector value on the 1-bit signal {name:?}"),
                ));
            }
            k += 1;
            continue;
        }
        let mut chars = tok.chars();
        let value = chars.next().unwrap_or('?');
        if chars.as_str() != id {
            continue;
        }
        let high = match value {
            '1' => true,
            '0' => false,
            'x' | 'X' | 'z' | 'Z' => {
                return Err(error(
                    file,
                    line,
                    format!("signal {name:?} is {value} (unknown) here"),
                ));
            }
            other => {
                return Err(error(
                    file,
                    line,
                    format!("value {other:?} is not 0, 1, x or z"),
                ))
            }
        };
        let now_closed = is_closed(polarity, high);
        let Some(t) = now else {
            return Err(error(file, line, "a value before the first time stamp"));
        };
        if start.is_none() {
            start = Some(now_closed);
            closed = now_closed;
            continue;
        }
        push_change(&mut changes, &mut closed, now_closed, t)
            .map_err(|reason| error(file, line, reason))?;
    }
    let closed_before =
        start.ok_or_else(|| error(file, 0, format!("signal {name:?} never has a value")))?;
    Ok(Stream {
        closed_before,
        changes,
    })
}

/// Seconds per tick of a VCD `$timescale` such as `1ns`, `10 us`.
fn timescale(spec: &str) -> Option<f64> {
    let digits: String = spec.chars().take_while(char::is_ascii_digit).collect();
    let unit = &spec[digits.len()..];
    let n: f64 = match digits.as_str() {
        "1" => 1.0,
        "10" => 10.0,
        "100" => 100.0,
        _ => return None,
    };
    let unit = match unit {
        "s" => 1.0,
        "ms" => 1e-3,
        "us" => 1e-6,
        "ns" => 1e-9,
        "ps" => 1e-12,
        "fs" => 1e-15,
        _ => return None,
    };
    Some(n * unit)
}

/// What a capture's reader left out, and why: one count per reason, in a fixed order.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Skipped {
    /// Tests in a section the capture marks invalid on their own line.
    pub marked_invalid: usize,
    /// Tests in a section of the same name that the capture marks invalid for another switch
    /// (the same test protocol, logged before the instrument had the flag).
    pub marked_invalid_elsewhere: usize,
    /// Tests in a section named by `--skip-section`.
    pub named: usize,
    /// Events that hold several presses: a quiet interval inside them longer than the one that
    /// separates events (`--event-gap`).
    pub several_presses: usize,
    /// The sections behind the first two counts.
    pub sections: Vec<String>,
}

impl Skipped {
    /// Adds `other`'s counts and sections (another file of the same capture).
    pub fn add(&mut self, other: Skipped) {
        self.marked_invalid += other.marked_invalid;
        self.marked_invalid_elsewhere += other.marked_invalid_elsewhere;
        self.named += other.named;
        self.several_presses += other.several_presses;
        for s in other.sections {
            if !self.sections.contains(&s) {
                self.sections.push(s);
            }
        }
    }

    /// Tests or events left out in all.
    #[must_use]
    pub fn total(&self) -> usize {
        self.marked_invalid + self.marked_invalid_elsewhere + self.named + self.several_presses
    }

    /// One sentence for the report: how many were left out and why (empty if none).
    #[must_use]
    pub fn describe(&self, quiet: f64) -> String {
        let mut parts = Vec::new();
        let sections = self.sections.join(", ");
        if self.marked_invalid > 0 {
            parts.push(format!(
                "{} tests in sections the capture marks invalid ({sections})",
                self.marked_invalid
            ));
        }
        if self.marked_invalid_elsewhere > 0 {
            parts.push(format!(
                "{} tests in sections of the same name that the capture marks invalid for another switch",
                self.marked_invalid_elsewhere
            ));
        }
        if self.named > 0 {
            parts.push(format!(
                "{} tests in sections named by --skip-section",
                self.named
            ));
        }
        if self.several_presses > 0 {
            parts.push(format!(
                "{} events that hold several presses (quiet for over --event-gap {quiet} s inside)",
                self.several_presses
            ));
        }
        if parts.is_empty() {
            String::new()
        } else {
            format!("Left out: {}.", parts.join("; "))
        }
    }
}

/// Leaves out the events that hold several presses: a quiet interval inside them longer than
/// `quiet` (s), the gap that starts a new event in a stream. Counts them in `skipped`.
#[must_use]
pub fn drop_several_presses(events: Vec<Event>, quiet: f64, skipped: &mut Skipped) -> Vec<Event> {
    let (keep, drop): (Vec<Event>, Vec<Event>) = events
        .into_iter()
        .partition(|e| e.changes.windows(2).all(|w| w[1] - w[0] <= quiet));
    skipped.several_presses += drop.len();
    keep
}

/// Reads the JSON Lines of the bouncy-button capture: one test per line, `dataset`, `kind`,
/// `events` `[[t_ns, level], ...]` (the first entry is the level before the test; level 1 =
/// open), `section`, `section_invalid`. Tests are left out, and counted per reason, when their
/// section is marked invalid, when a section of the same name is marked invalid for another
/// dataset of the file (the same protocol, logged by an instrument that did not yet mark it),
/// or when `skip` names the section.
///
/// # Errors
/// A line that is not JSON, or misses a field, or whose events do not start with a level, go
/// back in time or disagree with `kind`: the error names the line.
pub fn read_jsonl(
    file: &str,
    text: &str,
    skip: &[String],
) -> Result<(Vec<Event>, Skipped), CaptureError> {
    // Every line parsed once; then the sections marked invalid anywhere in the file.
    let mut lines = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        if raw.trim().is_empty() {
            continue;
        }
        let v: Value =
            crate::strict::json(raw).map_err(|(_, message)| error(file, i + 1, message))?;
        lines.push((i + 1, v));
    }
    let mut invalid: Vec<String> = Vec::new();
    for (_, v) in &lines {
        if v.get("section_invalid").and_then(Value::as_bool) == Some(true) {
            if let Some(name) = v.get("section").and_then(Value::as_str) {
                if !invalid.iter().any(|s| s == name) {
                    invalid.push(name.to_owned());
                }
            }
        }
    }
    let mut events = Vec::new();
    let mut skipped = Skipped {
        sections: invalid.clone(),
        ..Skipped::default()
    };
    for (line, v) in lines {
        let section = v.get("section").and_then(Value::as_str);
        if v.get("section_invalid").and_then(Value::as_bool) == Some(true) {
            skipped.marked_invalid += 1;
            continue;
        }
        if section.is_some_and(|name| invalid.iter().any(|s| s == name)) {
            skipped.marked_invalid_elsewhere += 1;
            continue;
        }
        if section.is_some_and(|name| skip.iter().any(|s| s == name)) {
            skipped.named += 1;
            continue;
        }
        let field = |name: &str| {
            v.get(name)
                .ok_or_else(|| error(file, line, format!("no `{name}`")))
        };
        let switch = field("dataset")?
            .as_str()
            .ok_or_else(|| error(file, line, "`dataset` is not a string"))?;
        let kind = match field("kind")?.as_str() {
            Some("press") => Edge::Press,
            Some("release") => Edge::Release,
            _ => return Err(error(file, line, "`kind` is not \"press\" or \"release\"")),
        };
        let entries = field("events")?
            .as_array()
            .ok_or_else(|| error(file, line, "`events` is not an array"))?;
        let mut pairs = entries.iter().map(|e| {
            let t = e.get(0).and_then(Value::as_f64);
            let l = e.get(1).and_then(Value::as_u64);
            match (t, l) {
                (Some(t), Some(l @ (0 | 1))) => Ok((t * 1e-9, l == 1)),
                _ => Err(error(file, line, format!("event {e} is not [t_ns, 0|1]"))),
            }
        });
        let Some(first) = pairs.next() else {
            return Err(error(file, line, "`events` is empty: no starting level"));
        };
        let mut closed = is_closed(Polarity::ActiveLow, first?.1);
        let closed_before = closed;
        if (kind == Edge::Press) == closed_before {
            return Err(error(
                file,
                line,
                format!(
                    "a {} that starts {}",
                    kind.name(),
                    if closed { "closed" } else { "open" }
                ),
            ));
        }
        let mut changes = Vec::new();
        for p in pairs {
            let (t, high) = p?;
            push_change(
                &mut changes,
                &mut closed,
                is_closed(Polarity::ActiveLow, high),
                t,
            )
            .map_err(|reason| error(file, line, reason))?;
        }
        let test = v
            .get("test")
            .map_or_else(String::new, |t| format!(" test {t}"));
        events.push(Event {
            switch: switch.to_owned(),
            origin: format!("line {line}{test}"),
            kind,
            changes,
            section: section.map(str::to_owned),
        });
    }
    Ok((events, skipped))
}

/// One event described at an instrument resolution.
#[derive(Debug, Clone, PartialEq)]
pub struct Description {
    /// Last change minus first change (s); 0 for a clean edge.
    pub bounce: f64,
    /// Whether the bounce is at least the resolution. A shorter one was seen (the contact
    /// changed) but not timed: its intervals are all chatter, and its duration is the sampling
    /// of the instrument, not of the contact.
    pub timed: bool,
    /// Number of changes.
    pub transitions: usize,
    /// Open intervals inside the event at least `resolution` long (s), in order.
    pub flights: Vec<f64>,
    /// Closed intervals inside the event at least `resolution` long (s), in order.
    pub dwells: Vec<f64>,
    /// Intervals shorter than `resolution` (their times are not resolved).
    pub chatter: usize,
    /// The time those unresolved intervals add up to (s; as logged, so only bounded by
    /// `chatter * resolution`).
    pub chatter_time: f64,
    /// Bursts: runs of changes separated by a quiet interval of at least the burst gap. 0 for
    /// an event with no change, 1 for a single burst; more means the contact bounced again
    /// after settling for at least the gap.
    pub bursts: usize,
    /// How many of `flights` belong to the first burst.
    pub first_burst_flights: usize,
    /// The burst gap the event was described at (s): an event with more than one burst has a
    /// quiet interval at least this long inside, so its bounce is never shorter.
    pub burst_gap: f64,
    /// A press only: the longest closed dwell of the first burst after which the contact
    /// opens again, as a share of the burst's longest resolved flight (see [`Hold`]).
    pub hold: Option<Hold>,
    /// The event's [`Event::section`].
    pub section: Option<String>,
}

/// The longest closed dwell inside a press's first burst. A Newton impact has no dwell at
/// all, and a compliant contact dwells for its contact time, short beside the flights; a dwell
/// as long as the flights, after which the contact opens again, is what two bodies with unequal
/// partial frequencies do once their impacts have accumulated and they move together, until the
/// pair's swing turns the contact force tensile (the paper's Eq. 1): a reopening.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hold {
    /// When the dwell starts, from the first change (s).
    pub at: f64,
    /// How long the contact holds (s).
    pub dwell: f64,
    /// The dwell over the burst's longest resolved flight.
    pub share: f64,
}

impl Event {
    /// The event's bounce at an instrument resolution (s); a quiet interval at least
    /// `burst_gap` long (s) ends a burst.
    #[must_use]
    pub fn describe(&self, resolution: f64, burst_gap: f64) -> Description {
        let mut flights = Vec::new();
        let mut dwells = Vec::new();
        let mut chatter = 0;
        let mut chatter_time = 0.0;
        let mut bursts = usize::from(!self.changes.is_empty());
        let mut first_burst_flights = None;
        // After the first change the contact is closed for a press, open for a release.
        let mut closed = self.kind == Edge::Press;
        for w in self.changes.windows(2) {
            let d = w[1] - w[0];
            if d >= burst_gap {
                bursts += 1;
                first_burst_flights.get_or_insert(flights.len());
            }
            if d < resolution {
                chatter += 1;
                chatter_time += d;
            } else if closed {
                dwells.push(d);
            } else {
                flights.push(d);
            }
            closed = !closed;
        }
        let bounce = match (self.changes.first(), self.changes.last()) {
            (Some(a), Some(b)) => b - a,
            _ => 0.0,
        };
        let hold = self.hold(resolution, burst_gap);
        Description {
            bounce,
            timed: bounce >= resolution,
            transitions: self.changes.len(),
            first_burst_flights: first_burst_flights.unwrap_or(flights.len()),
            burst_gap,
            flights,
            dwells,
            chatter,
            chatter_time,
            bursts,
            hold,
            section: self.section.clone(),
        }
    }

    /// The press's [`Hold`], if any (see [`Description::hold`]).
    fn hold(&self, resolution: f64, burst_gap: f64) -> Option<Hold> {
        if self.kind != Edge::Press {
            return None;
        }
        let first = self.changes.first()?;
        // The first burst's intervals, the first one closed (a press has just made). Each
        // interval ends with a change, so a closed one is always followed by an opening.
        let burst: Vec<f64> = self
            .changes
            .windows(2)
            .map(|w| w[1] - w[0])
            .take_while(|d| *d < burst_gap)
            .collect();
        let longest = burst
            .iter()
            .skip(1)
            .step_by(2)
            .filter(|d| **d >= resolution)
            .fold(0.0, |a: f64, d| a.max(*d));
        if longest <= 0.0 {
            return None;
        }
        let i = (0..burst.len())
            .step_by(2)
            .filter(|&i| burst[i] >= resolution)
            .max_by(|&i, &j| burst[i].total_cmp(&burst[j]))?;
        Some(Hold {
            at: self.changes[i] - first,
            dwell: burst[i],
            share: burst[i] / longest,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stream_is_cut_at_quiet_gaps_and_kinds_alternate() {
        let s = Stream {
            closed_before: false,
            changes: vec![1.0, 1.001, 1.002, 2.0, 2.0005],
        };
        let e = s.segment("sw", 0.1);
        assert_eq!(e.len(), 2);
        assert_eq!(e[0].kind, Edge::Press);
        assert_eq!(e[0].changes, vec![1.0, 1.001, 1.002]);
        // Three changes leave it closed: the next event is a release.
        assert_eq!(e[1].kind, Edge::Release);
    }

    #[test]
    fn a_press_is_described_as_dwells_flights_and_chatter() {
        let e = Event {
            switch: "sw".into(),
            origin: String::new(),
            kind: Edge::Press,
            // closed 10 us, open 1 us (chatter), closed 20 us, open 30 us, closed.
            changes: vec![0.0, 10e-6, 11e-6, 31e-6, 61e-6],
            section: None,
        };
        let d = e.describe(3e-6, 1.0);
        assert_eq!(d.transitions, 5);
        assert_eq!(d.chatter, 1);
        assert_eq!(d.dwells.len(), 2);
        assert_eq!(d.flights.len(), 1);
        assert!((d.flights[0] - 30e-6).abs() < 1e-12);
        assert!((d.bounce - 61e-6).abs() < 1e-12);
        assert!((d.chatter_time - 1e-6).abs() < 1e-12);
        assert_eq!((d.bursts, d.first_burst_flights), (1, 1));
    }

    #[test]
    fn a_press_holds_for_its_longest_closed_dwell_inside_the_first_burst() {
        // closed 5, open 100, closed 2 (chatter), open 40, closed 300, open 20, closed; then,
        // after a quiet 10 ms (a late burst), a longer dwell that does not count.
        let mut e = Event {
            switch: "sw".into(),
            origin: String::new(),
            kind: Edge::Press,
            changes: vec![0.0, 5e-6, 105e-6, 107e-6, 147e-6, 447e-6, 467e-6],
            section: None,
        };
        let h = e.describe(3e-6, 5e-3).hold.unwrap();
        assert!((h.at - 147e-6).abs() < 1e-12 && (h.dwell - 300e-6).abs() < 1e-12);
        assert!((h.share - 3.0).abs() < 1e-9, "{h:?}");
        e.changes.extend([10.467e-3, 10.468e-3, 20.0e-3, 20.1e-3]);
        assert_eq!(e.describe(3e-6, 5e-3).hold, Some(h));
        // No resolved flight: nothing to compare a dwell with. A release has no hold.
        e.changes = vec![0.0, 300e-6, 301e-6];
        assert_eq!(e.describe(3e-6, 5e-3).hold, None);
        e.changes = vec![0.0, 5e-6, 105e-6, 405e-6, 406e-6];
        e.kind = Edge::Release;
        assert_eq!(e.describe(3e-6, 5e-3).hold, None);
    }

    #[test]
    fn a_quiet_interval_of_the_burst_gap_ends_a_burst() {
        let e = Event {
            switch: "sw".into(),
            origin: String::new(),
            kind: Edge::Release,
            // open 20 us, closed 10 us, open 5 ms (quiet), closed 30 us, open 2 ms (quiet),
            // closed 40 us, open.
            changes: vec![0.0, 20e-6, 30e-6, 5.03e-3, 5.06e-3, 7.06e-3, 7.1e-3],
            section: None,
        };
        let d = e.describe(3e-6, 1e-3);
        assert_eq!(d.bursts, 3);
        assert_eq!(d.first_burst_flights, 1);
        assert_eq!(d.flights.len(), 3);
        // A gap wider than every interval: one burst, all its flights.
        let d = e.describe(3e-6, 1.0);
        assert_eq!((d.bursts, d.first_burst_flights), (1, 3));
        let none = Event {
            changes: vec![],
            ..e.clone()
        };
        assert_eq!(none.describe(3e-6, 1e-3).bursts, 0);
    }

    #[test]
    fn csv_rejects_what_it_cannot_read_naming_the_line() {
        let bad = [
            ("time,level\n0,1\n0.5,2\n", 3, "level"),
            ("0,1\n0.5\n", 2, "expected"),
            ("0,1\n0.5,0\n0.4,1\n", 3, "back in time"),
            ("0,1\nabc,0\n", 2, "not a number"),
            ("0,1\nNaN,0\n", 2, "finite"),
        ];
        for (text, line, why) in bad {
            let e = read_csv("f.csv", text, Polarity::ActiveLow).unwrap_err();
            assert_eq!(e.line, line, "{text:?}: {e}");
            assert!(e.reason.contains(why), "{text:?}: {e}");
        }
        assert_eq!(
            read_csv("f.csv", "# nothing\n", Polarity::ActiveLow)
                .unwrap_err()
                .line,
            0
        );
    }

    #[test]
    fn vcd_rejects_what_it_cannot_read_naming_the_line() {
        let head = "$timescale 1ns $end\n$scope module top $end\n$var wire 1 ! sw $end\n$upscope $end\n$enddefinitions $end\n";
        let bad = [
            (format!("{head}#0\n1!\n#5\nx!\n"), 9, "unknown"),
            (format!("{head}#10\n1!\n#5\n0!\n"), 8, "back in time"),
            (format!("{head}1!\n"), 6, "before the first time stamp"),
            (format!("{head}#1.5\n"), 6, "whole number"),
            ("$timescale 3 ns $end\n".to_owned(), 1, "timescale"),
            ("#0\n1!\n".to_owned(), 1, "before `$enddefinitions`"),
            // sigrok-cli's META line is skipped only where sigrok-cli writes it: first.
            (
                format!("$comment x $end\nMETA samplerate: 1\n{head}"),
                2,
                "before `$enddefinitions`",
            ),
        ];
        for (text, line, why) in bad {
            let e = read_vcd("f.vcd", &text, None, Polarity::ActiveLow).unwrap_err();
            assert_eq!(e.line, line, "{text:?}: {e}");
            assert!(e.reason.contains(why), "{text:?}: {e}");
        }
        let e = read_vcd("f.vcd", head, Some("other"), Polarity::ActiveLow).unwrap_err();
        assert!(e.reason.contains("no signal named"), "{e}");
    }

    #[test]
    fn what_cannot_be_one_press_is_left_out_and_counted_per_reason() {
        let test = |dataset: &str, section: &str, invalid: bool, events: &str| {
            format!(
                "{{\"dataset\":\"{dataset}\",\"kind\":\"press\",\"section\":\"{section}\",\"section_invalid\":{invalid},\"events\":{events}}}\n"
            )
        };
        let one = "[[0,1],[10,0]]";
        let text = [
            test("a", "Slow", true, one),
            test("b", "Slow", false, one), // the same protocol, not flagged
            test("b", "Normal", false, one),
            test("b", "Odd", false, one),
            // closed, then open for 0.5 s, then closed again: two presses
            test("b", "Normal", false, "[[0,1],[10,0],[1e6,1],[5.01e8,0]]"),
        ]
        .concat();
        let (events, mut skipped) = read_jsonl("f.jsonl", &text, &["Odd".to_owned()]).unwrap();
        assert_eq!(events.len(), 2);
        let events = drop_several_presses(events, 0.2, &mut skipped);
        assert_eq!(events.len(), 1);
        assert_eq!(events[0].section.as_deref(), Some("Normal"));
        assert_eq!(
            (
                skipped.marked_invalid,
                skipped.marked_invalid_elsewhere,
                skipped.named,
                skipped.several_presses,
                skipped.total()
            ),
            (1, 1, 1, 1, 4)
        );
        let said = skipped.describe(0.2);
        for reason in [
            "(Slow)",
            "for another switch",
            "--skip-section",
            "several presses",
        ] {
            assert!(said.contains(reason), "{said}");
        }
        assert_eq!(Skipped::default().describe(0.2), "");
    }

    #[test]
    fn jsonl_rejects_a_kind_that_disagrees_with_the_starting_level() {
        let line = r#"{"dataset":"d","kind":"press","events":[[0,0],[10,1]]}"#;
        let e = read_jsonl("f.jsonl", line, &[]).unwrap_err();
        assert!(e.reason.contains("starts closed"), "{e}");
        // No `section`: the event has none.
        let line = r#"{"dataset":"d","kind":"press","events":[[0,1],[10,0]]}"#;
        assert_eq!(read_jsonl("f.jsonl", line, &[]).unwrap().0[0].section, None);
        let e = read_jsonl("f.jsonl", "{\n", &[]).unwrap_err();
        assert_eq!(e.line, 1);
    }
}

//! A capture cut into events: one press or release of one switch, with its bounce.

use std::fmt;

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
pub(crate) fn is_closed(polarity: Polarity, high: bool) -> bool {
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
        use crate::support::strict::printable;
        let (file, reason) = (printable(&self.file), printable(&self.reason));
        if self.line == 0 {
            write!(f, "{file}: {reason}")
        } else {
            write!(f, "{file}:{}: {reason}", self.line)
        }
    }
}

impl std::error::Error for CaptureError {}

pub(crate) fn error(file: &str, line: usize, reason: impl Into<String>) -> CaptureError {
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

pub(crate) fn event(switch: &str, closed_before: bool, changes: Vec<f64>) -> Event {
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
pub(crate) fn push_change(
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

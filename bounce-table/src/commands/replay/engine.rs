//! The replay itself: one debouncer (ours or a peer) run over the traces of one switch and kind,
//! as it sees the pin (sampled or by interrupt), and scored.

use contact_bounce::{Mode, State, Windows};

use crate::capture::{Edge, Event};

/// One test to replay: the contact before it and its changes (s, the first at 0).
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    /// Closed before the first change.
    pub closed_before: bool,
    /// Change times (s), nondecreasing, the first at 0.
    pub changes: Vec<f64>,
}

impl Trace {
    /// The trace of an event, its times multiplied by `scale`.
    #[must_use]
    pub fn of(e: &Event, scale: f64) -> Self {
        let t0 = e.changes.first().copied().unwrap_or(0.0);
        Self {
            closed_before: e.kind == Edge::Release,
            changes: e.changes.iter().map(|t| (t - t0) * scale).collect(),
        }
    }

    /// The contact at `t`: closed or not.
    #[must_use]
    pub fn closed_at(&self, t: f64) -> bool {
        let flips = self.changes.partition_point(|&c| c <= t);
        self.closed_before ^ (flips % 2 == 1)
    }

    /// The contact after the last change.
    #[must_use]
    pub fn closed_after(&self) -> bool {
        self.closed_before ^ (self.changes.len() % 2 == 1)
    }

    pub(crate) fn last(&self) -> f64 {
        self.changes.last().copied().unwrap_or(0.0)
    }
}

/// A debouncer that samples the pin: fed the time (s) and the contact (closed or not) at each
/// sample, it returns the new debounced state when it reports a change.
pub trait Polled {
    /// Settled at `closed`.
    fn reset(&mut self, closed: bool);
    /// One sample.
    fn sample(&mut self, now: f64, closed: bool) -> Option<bool>;
    /// The longer of its press and release windows now (s), where it learns them.
    fn window(&self) -> Option<f64> {
        None
    }
    /// Whether it says its switch reverts for as long as a tap, where it learns that.
    fn reverts_like_a_tap(&self) -> Option<bool> {
        None
    }
}

/// Ours: [`contact_bounce::State`] with press and release windows in samples.
#[derive(Debug, Clone)]
pub struct Ours {
    windows: Windows,
    state: State,
}

impl Polled for Ours {
    fn reset(&mut self, closed: bool) {
        self.state = State::new(closed);
    }
    fn sample(&mut self, _now: f64, closed: bool) -> Option<bool> {
        self.state
            .update(closed, &self.windows)
            .map(|e| e == contact_bounce::Edge::Press)
    }
}

/// How a debouncer sees the pin.
pub enum Sampling {
    /// Sampled every period.
    Polled(Box<dyn Polled>),
    /// Every edge interrupt restarts a timer of this many seconds; when it expires the pin is
    /// read and reported if it changed (Linux and Zephyr `gpio-keys`).
    Interrupt(f64),
}

/// A debouncer of the benchmark.
pub struct Row {
    /// Its name in the outputs.
    pub name: String,
    /// Its window (s), for the kind replayed; `None` when it has none in seconds.
    pub window: Option<f64>,
    /// The debouncer, and how it sees the pin.
    pub sampling: Sampling,
    /// The longest it may wait before reporting (s): how long to run after the last change.
    pub settle: f64,
}

/// What one debouncer did on the replayed tests of one switch and kind.
#[derive(Debug, Clone, PartialEq)]
pub struct Score {
    /// Tests replayed.
    pub events: usize,
    /// Reported edges beyond the one true edge of each test.
    pub false_edges: usize,
    /// Tests with at least one false edge.
    pub tests_with_false_edges: usize,
    /// From the first change to the first reported edge, per test with a true edge (s).
    pub latencies: Vec<f64>,
}

/// The phase of test `i`'s samples, as a fraction of the period: the golden-ratio sequence,
/// spread evenly and the same for every debouncer.
pub(crate) fn phase(i: usize) -> f64 {
    #[allow(clippy::cast_precision_loss)]
    let x = (i as f64 + 1.0) * 0.618_033_988_749_895;
    x - x.floor()
}

/// Replays `traces` through `row`'s debouncer, `period` (s) apart for a polled one.
#[must_use]
pub fn score(row: &mut Row, traces: &[Trace], period: f64) -> Score {
    let mut s = Score {
        events: traces.len(),
        false_edges: 0,
        tests_with_false_edges: 0,
        latencies: Vec::new(),
    };
    for (i, trace) in traces.iter().enumerate() {
        let end = trace.last() + row.settle + 4.0 * period;
        let edges: Vec<f64> = edges(&mut row.sampling, trace, phase(i), period, end)
            .into_iter()
            .map(|(t, _)| t)
            .collect();
        s.tally(trace, &edges);
    }
    s
}

/// Runs the debouncer `sampling` over `trace` from its settled state before it: a polled one samples at
/// `(phase + k) * period` up to `end` (s), an interrupt-driven one sees every change. Returns
/// the reported edges: their times (s) and the new state (closed or not).
pub fn edges(
    sampling: &mut Sampling,
    trace: &Trace,
    phase: f64,
    period: f64,
    end: f64,
) -> Vec<(f64, bool)> {
    let mut edges = Vec::new();
    match sampling {
        Sampling::Polled(d) => {
            d.reset(trace.closed_before);
            // The contact at each sample, walking the changes once.
            let (mut next, mut closed) = (0, trace.closed_before);
            let mut k = 0u64;
            loop {
                #[allow(clippy::cast_precision_loss)]
                let now = (phase + k as f64) * period;
                if now > end {
                    break;
                }
                while trace.changes.get(next).is_some_and(|&c| c <= now) {
                    closed = !closed;
                    next += 1;
                }
                if let Some(state) = d.sample(now, closed) {
                    edges.push((now, state));
                }
                k += 1;
            }
        }
        Sampling::Interrupt(delay) => {
            let mut reported = trace.closed_before;
            for (j, &c) in trace.changes.iter().enumerate() {
                let fires = c + *delay;
                if trace.changes.get(j + 1).is_some_and(|&next| next <= fires) {
                    continue; // rescheduled by the next edge
                }
                let level = trace.closed_at(fires);
                if level != reported {
                    reported = level;
                    edges.push((fires, level));
                }
            }
        }
    }
    edges
}

impl Score {
    /// Scores one test's reported edges (their times from the first change, s); returns its
    /// false edges (beyond the test's one true edge).
    pub(crate) fn tally(&mut self, trace: &Trace, edges: &[f64]) -> usize {
        let moved = trace.closed_after() != trace.closed_before;
        let extra = edges.len().saturating_sub(usize::from(moved));
        self.false_edges += extra;
        self.tests_with_false_edges += usize::from(extra > 0);
        if moved {
            if let Some(&first) = edges.first() {
                self.latencies.push(first);
            }
        }
        extra
    }
}

/// Our debouncer in both modes with `press` and `release` windows (s) at `period`; `None` when
/// a window does not fit [`Windows::MAX_TICKS`] samples.
#[must_use]
pub fn ours(label: &str, press: f64, release: f64, period: f64, kind: Edge) -> Option<Vec<Row>> {
    // The core's rounding (up); a window of 0 (every test clean) is one sample.
    let ticks = |w: f64| -> Option<u16> {
        let t = if w > 0.0 {
            contact_bounce::debounce::window::window_ticks(w, 1.0, period).ok()?
        } else {
            1
        };
        u16::try_from(t.max(1))
            .ok()
            .filter(|t| *t <= Windows::MAX_TICKS)
    };
    let (p, r) = (ticks(press)?, ticks(release)?);
    let shown = if kind == Edge::Press { press } else { release };
    Some(
        [("hold-off", Mode::HoldOff), ("confirm", Mode::Confirm)]
            .into_iter()
            .filter_map(|(mode_name, mode)| {
                let windows = Windows::new(p, r, mode).ok()?;
                Some(Row {
                    name: format!("{label} {mode_name}"),
                    window: Some(shown),
                    sampling: Sampling::Polled(Box::new(Ours {
                        windows,
                        state: State::new(false),
                    })),
                    settle: press.max(release) + 2.0 * period,
                })
            })
            .collect(),
    )
}

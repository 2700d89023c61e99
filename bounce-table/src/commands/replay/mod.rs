//! `bounce-table replay`: debouncers replayed on a real capture.
//!
//! For each switch and kind (press, release), the tests are taken in capture order: the earlier
//! part (`--split`, half by default) calibrates, the later part is replayed. A window is set now
//! and used later, so the split is chronological. Every debouncer starts each test settled at
//! the contact's level before it and is run until long after the test's last change; the
//! polled ones sample every `--sample-period` (1 ms by default, the scan rate of the keyboard
//! firmwares below) at a phase that differs from test to test and is the same for every
//! debouncer, the interrupt-driven ones see every change at its time.
//!
//! Per row: the reported edges beyond the one true edge of each test (`false_edges`), and the
//! latency from the first contact change to the first reported edge (P50, P99 over the tests).
//!
//! The peers are re-implemented from their documentation, each at its documented default, one
//! file each in [`mod@peers`] (which says how to add one).

mod engine;
pub mod peers;
pub mod taps;

use engine::phase;
pub use engine::{edges, ours, score, Ours, Polled, Row, Sampling, Score, Trace};
pub use peers::peers;

use crate::capture::EdgeName;
use std::collections::BTreeMap;

use contact_bounce::Windows;

use crate::capture::{self, Loaded};
use crate::capture::{Edge, Event};
use crate::render::output::time;
use crate::render::plot::{Axis, Plot, Quantity, Series, Style};
use crate::scene::priors::{self, Prior};
use crate::stats::{self, window};
use contact_bounce_reference::stats::nearest_rank;

/// What `replay` was asked for, beyond the capture.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    /// Seconds between samples of the polled debouncers.
    pub period: f64,
    /// The earlier share of each switch and kind's tests that calibrates.
    pub split: f64,
    /// Every time multiplied by this (a contactor-like 10, a reed-like 0.1).
    pub time_scale: f64,
    /// The switch type for the prior, where the switch's name gives none.
    pub switch_type: Option<&'static Prior>,
    /// Windows (s, press and release alike) to replay our debouncer with as they are: a
    /// firmware's fixed window checked against the capture.
    pub fixed: Vec<f64>,
    /// The fastest real tap (s): the learner always reports a change that lasts this long.
    pub fastest_tap: f64,
    /// The learner's prior window (s), where not the switch type's.
    pub learner_prior: Option<f64>,
}

/// One line of the benchmark.
#[derive(Debug, Clone, PartialEq)]
pub struct Line {
    /// The switch.
    pub switch: String,
    /// Press or release.
    pub kind: Edge,
    /// The debouncer.
    pub debouncer: String,
    /// Its window for this kind (s).
    pub window: Option<f64>,
    /// Its score on the later tests.
    pub score: Score,
}

impl Line {
    /// The latency quantile `q` (s).
    #[must_use]
    pub fn latency(&self, q: f64) -> Option<f64> {
        let mut v = self.score.latencies.clone();
        v.sort_by(f64::total_cmp);
        nearest_rank(&v, q)
    }
}

/// The calibrated window (s) of each switch and kind: `calibrate` on the earlier tests
/// (`s.split`), their times multiplied by `s.time_scale`, at most `c.min_tap` where given.
#[must_use]
pub fn calibrated(
    events: &[Event],
    c: &stats::Calibration,
    s: &Settings,
) -> BTreeMap<(String, Edge), f64> {
    let mut by: BTreeMap<(&str, Edge), Vec<&Event>> = BTreeMap::new();
    for e in events {
        by.entry((e.switch.as_str(), e.kind)).or_default().push(e);
    }
    let mut out = BTreeMap::new();
    for (&(switch, kind), list) in &by {
        let earlier: Vec<_> = list[..stats::earlier_count(list.len(), s.split)]
            .iter()
            .map(|e| {
                let scaled = Event {
                    changes: e.changes.iter().map(|t| t * s.time_scale).collect(),
                    ..(*e).clone()
                };
                scaled.describe(c.resolution * s.time_scale, c.burst_gap * s.time_scale)
            })
            .collect();
        let refs: Vec<_> = earlier.iter().collect();
        let w = window(&refs, c.percentile).recommended();
        out.insert(
            (switch.to_owned(), kind),
            c.min_tap.map_or(w, |cap| w.min(cap)),
        );
    }
    out
}

/// The benchmark on `events` (already read, with what cannot be one press left out), per switch
/// and kind in their order; `calibrate` describes the earlier tests at `resolution` with
/// `burst_gap` and sets the windows at `percentile`.
///
/// # Errors
/// A calibrated or prior window longer than our debouncer's counter holds at `period`.
pub fn run(events: &[Event], c: &stats::Calibration, s: &Settings) -> Result<Vec<Line>, String> {
    let mut by: BTreeMap<(&str, Edge), Vec<&Event>> = BTreeMap::new();
    for e in events {
        by.entry((e.switch.as_str(), e.kind)).or_default().push(e);
    }
    let cut = |n: usize| stats::earlier_count(n, s.split);
    let calibrated = calibrated(events, c, s);
    let mut lines = Vec::new();
    let mut learned_lines: Vec<Line> = Vec::new();
    for (switch, l) in learning_curves(events, s)? {
        for (kind, score, window) in l.rows {
            learned_lines.push(Line {
                switch: switch.clone(),
                kind,
                debouncer: "learned".to_owned(),
                window: Some(window),
                score,
            });
        }
    }
    for (&(switch, kind), list) in &by {
        let later: Vec<Trace> = list[cut(list.len())..]
            .iter()
            .map(|e| Trace::of(e, s.time_scale))
            .collect();
        let both = |k| {
            calibrated
                .get(&(switch.to_owned(), k))
                .copied()
                .unwrap_or(0.0)
        };
        let mut rows = ours(
            "calibrated",
            both(Edge::Press),
            both(Edge::Release),
            s.period,
            kind,
        )
        .ok_or_else(|| {
            format!("{switch}: a calibrated window does not fit {} samples of --sample-period {}: sample less often", Windows::MAX_TICKS, s.period)
        })?;
        if let Some(prior) = priors::from_switch_name(switch).or(s.switch_type) {
            let w = (prior.window() * s.time_scale).min(s.fastest_tap);
            rows.extend(ours("physics-prior", w, w, s.period, kind).ok_or_else(|| {
                format!("{switch}: the prior's window does not fit {} samples of --sample-period {}: sample less often", Windows::MAX_TICKS, s.period)
            })?);
        }
        for &w in &s.fixed {
            rows.extend(
                ours(&format!("fixed {}", time(w)), w, w, s.period, kind).ok_or_else(|| {
                    format!("--window {w}: it does not fit {} samples of --sample-period {}: sample less often", Windows::MAX_TICKS, s.period)
                })?,
            );
        }
        rows.extend(peers(s.period));
        for mut row in rows {
            let score = score(&mut row, &later, s.period);
            lines.push(Line {
                switch: switch.to_owned(),
                kind,
                debouncer: row.name,
                window: row.window,
                score,
            });
        }
    }
    // Each learned row after its switch and kind's prior rows.
    for l in learned_lines {
        let at = lines
            .iter()
            .rposition(|x| {
                x.switch == l.switch && x.kind == l.kind && x.debouncer.starts_with("physics-prior")
            })
            .map_or(lines.len(), |i| i + 1);
        lines.insert(at, l);
    }
    Ok(lines)
}

/// The learner's prior: `prior` (s) for both kinds and the fastest tap `fastest_tap` (s), in
/// samples of `period` (s): the prior rounded up, the tap rounded down (a tap of that length is
/// seen for at least that many samples at any phase).
///
/// # Errors
/// Either does not fit [`Windows::MAX_TICKS`] samples, or the tap is shorter than a sample.
pub fn learner_prior(
    prior: f64,
    fastest_tap: f64,
    period: f64,
) -> Result<contact_bounce::LearnerPrior, String> {
    let ticks = contact_bounce::debounce::window::window_ticks(prior, 1.0, period)
        .ok()
        .and_then(|t| u16::try_from(t.max(1)).ok())
        .filter(|t| *t <= Windows::MAX_TICKS)
        .ok_or_else(|| {
            format!(
                "the prior's window does not fit {} samples of --sample-period {period}: sample less often",
                Windows::MAX_TICKS
            )
        })?;
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let tap = ((fastest_tap / period) * (1.0 + 1e-9))
        .floor()
        .min(f64::from(u16::MAX)) as u16;
    contact_bounce::LearnerPrior::new(ticks, ticks, tap).map_err(|_| {
        format!(
            "--min-tap {fastest_tap} is {tap} samples of --sample-period {period}: it must be 1 to {}",
            Windows::MAX_TICKS
        )
    })
}

/// One test of the learner's run: after it, the window of its kind.
#[derive(Debug, Clone, PartialEq)]
pub struct CurvePoint {
    /// The test's number among the switch's tests, in capture order (from 1).
    pub test: usize,
    /// Press or release.
    pub kind: Edge,
    /// The learned window of that kind after the test (s).
    pub window: f64,
    /// Reported edges beyond the test's one true edge.
    pub false_edges: usize,
    /// Whether the test is in the scored (later) part.
    pub scored: bool,
}

/// What the learner did on one switch.
#[derive(Debug, Clone, PartialEq)]
pub struct Learning {
    /// Per kind: the score on the later tests and the window learned by the last test (s).
    pub rows: Vec<(Edge, Score, f64)>,
    /// Every test, in order.
    pub curve: Vec<CurvePoint>,
}

/// The learner ([`contact_bounce::LearningState`]) on every test of one switch in capture order,
/// from `prior` (s, both kinds): it learns online through all of them, and each kind's tests
/// from `cut(kind's count)` on are scored as the other rows are.
///
/// # Errors
/// The prior does not fit [`Windows::MAX_TICKS`] samples of `period`.
pub fn learned(events: &[&Event], prior: f64, s: &Settings) -> Result<Learning, String> {
    let windows = learner_prior(prior, s.fastest_tap, s.period)?;
    let count = |k: Edge| events.iter().filter(|e| e.kind == k).count();
    let cuts = [Edge::Press, Edge::Release].map(|k| (k, stats::earlier_count(count(k), s.split)));
    let mut scores: Vec<(Edge, Score)> = [Edge::Press, Edge::Release]
        .iter()
        .map(|&k| {
            (
                k,
                Score {
                    events: 0,
                    false_edges: 0,
                    tests_with_false_edges: 0,
                    latencies: Vec::new(),
                },
            )
        })
        .collect();
    let mut seen = [0usize; 2];
    let mut key = contact_bounce::LearningState::new(false);
    let mut curve = Vec::new();
    #[allow(clippy::cast_precision_loss)]
    let seconds = |t: u16| f64::from(t) * s.period;
    for (n, e) in events.iter().enumerate() {
        let slot = usize::from(e.kind == Edge::Release);
        let i = seen[slot];
        seen[slot] += 1;
        // The later tests sample at the phases every other row's do (counted from the cut).
        let p = phase(i.checked_sub(cuts[slot].1).unwrap_or(i));
        let trace = Trace::of(e, s.time_scale);
        key.settle(trace.closed_before);
        // Run until the learner has watched the bounce to its end, past the last change.
        let mut edges = Vec::new();
        let mut k = 0u64;
        loop {
            #[allow(clippy::cast_precision_loss)]
            let now = (p + k as f64) * s.period;
            if now > trace.last() + 4.0 * s.period && key.is_settled() {
                break;
            }
            if key.update(trace.closed_at(now), &windows).is_some() {
                edges.push(now);
            }
            k += 1;
        }
        let scored = i >= cuts[slot].1;
        let mut unscored = Score {
            events: 0,
            false_edges: 0,
            tests_with_false_edges: 0,
            latencies: Vec::new(),
        };
        let score = if scored {
            scores[slot].1.events += 1;
            &mut scores[slot].1
        } else {
            &mut unscored
        };
        let extra = score.tally(&trace, &edges);
        let (press, release) = key.learned().windows(&windows);
        curve.push(CurvePoint {
            test: n + 1,
            kind: e.kind,
            window: seconds(if e.kind == Edge::Press {
                press
            } else {
                release
            }),
            false_edges: extra,
            scored,
        });
    }
    let (press, release) = key.learned().windows(&windows);
    Ok(Learning {
        rows: scores
            .into_iter()
            .map(|(k, score)| {
                let w = if k == Edge::Press { press } else { release };
                (k, score, seconds(w))
            })
            .collect(),
        curve,
    })
}

/// The learner's run on every switch that has a prior (from its name or `s.switch_type`), in
/// the order the switches first appear.
///
/// # Errors
/// As [`learned`].
pub fn learning_curves(events: &[Event], s: &Settings) -> Result<Vec<(String, Learning)>, String> {
    let mut switches: Vec<&str> = Vec::new();
    for e in events {
        if !switches.contains(&e.switch.as_str()) {
            switches.push(&e.switch);
        }
    }
    let mut out = Vec::new();
    for switch in switches {
        if let Some(prior) = priors::from_switch_name(switch).or(s.switch_type) {
            let all: Vec<&Event> = events.iter().filter(|e| e.switch == switch).collect();
            let from = s
                .learner_prior
                .unwrap_or((prior.window() * s.time_scale).min(s.fastest_tap));
            let l = learned(&all, from, s).map_err(|e| format!("{switch}: {e}"))?;
            out.push((switch.to_owned(), l));
        }
    }
    Ok(out)
}

/// The learning curves as CSV: switch, test, kind, window_s, false_edges, scored.
#[must_use]
pub fn curve_csv(curves: &[(String, Learning)]) -> String {
    let mut out = String::from("switch,test,kind,window_s,false_edges,scored\n");
    for (switch, l) in curves {
        for p in &l.curve {
            out.push_str(&format!(
                "{},{},{},{:e},{},{}\n",
                switch,
                p.test,
                p.kind.name(),
                p.window,
                p.false_edges,
                p.scored
            ));
        }
    }
    out
}

pub(crate) fn json_number(x: Option<f64>) -> String {
    x.map_or_else(|| "null".to_owned(), |v| format!("{v:e}"))
}

/// One JSON object per line, with exactly the keys `switch`, `kind`, `debouncer`, `window_s`,
/// `events`, `false_edges`, `latency_p50_s`, `latency_p99_s`.
#[must_use]
pub fn json(lines: &[Line]) -> String {
    lines
        .iter()
        .map(|l| {
            format!(
                "{{\"switch\":{},\"kind\":\"{}\",\"debouncer\":{},\"window_s\":{},\"events\":{},\"false_edges\":{},\"latency_p50_s\":{},\"latency_p99_s\":{}}}\n",
                serde_json::Value::from(l.switch.as_str()),
                l.kind.name(),
                serde_json::Value::from(l.debouncer.as_str()),
                json_number(l.window),
                l.score.events,
                l.score.false_edges,
                json_number(l.latency(0.5)),
                json_number(l.latency(0.99)),
            )
        })
        .collect()
}

/// `replay`'s Markdown as the desk tool prints it: each analog capture's section, what was left
/// out of the capture (if anything), then the table of [`markdown`].
#[must_use]
pub fn report(loaded: &Loaded, quiet: f64, lines: &[Line]) -> String {
    let mut text = String::new();
    for a in &loaded.analog {
        text.push_str(&a.markdown());
        text.push('\n');
    }
    if loaded.skipped.total() > 0 {
        text.push_str(&loaded.skipped.describe(quiet));
        text.push_str("\n\n");
    }
    text.push_str(&markdown(lines));
    text
}

/// The rows as a markdown table (the table format is the same).
#[must_use]
pub fn markdown(lines: &[Line]) -> String {
    let mut out = String::from(
        "| switch | kind | debouncer | window | events | false edges | tests with false edges | latency P50 | latency P99 |\n|---|---|---|---:|---:|---:|---:|---:|---:|\n",
    );
    let show = |x: Option<f64>| x.map_or_else(|| "-".to_owned(), time);
    for l in lines {
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            l.switch,
            l.kind.name(),
            l.debouncer,
            show(l.window),
            l.score.events,
            l.score.false_edges,
            l.score.tests_with_false_edges,
            show(l.latency(0.5)),
            show(l.latency(0.99)),
        ));
    }
    out
}

/// Every switch and kind's Pareto plot ([`plot`]), each with its file name
/// (`<switch>-<kind>-replay.svg`, as `--plot DIR` writes them).
#[must_use]
pub fn plots(lines: &[Line]) -> Vec<(String, String)> {
    per_group(
        lines,
        |l| (l.switch.as_str(), l.kind.name()),
        "replay",
        plot,
    )
}

/// `rows` grouped by their switch and a group name (`key`), in order of both, each group drawn
/// by `draw` and named `<switch>-<group>-<suffix>.svg`: the files `--plot DIR` writes.
pub(crate) fn per_group<'a, L>(
    rows: &'a [L],
    key: impl Fn(&'a L) -> (&'a str, &'static str),
    suffix: &str,
    draw: impl Fn(&[&L]) -> String,
) -> Vec<(String, String)> {
    let mut groups: BTreeMap<(&str, &str), Vec<&L>> = BTreeMap::new();
    for row in rows {
        groups.entry(key(row)).or_default().push(row);
    }
    groups
        .into_iter()
        .map(|((switch, group), members)| {
            let stem = crate::render::output::identifier(switch).to_lowercase();
            (format!("{stem}-{group}-{suffix}.svg"), draw(&members))
        })
        .collect()
}

/// The Pareto front of one switch and kind as an SVG: false edges against latency P99 (log
/// time axis), ours and the peers apart, the rows on the front named beside their points.
#[must_use]
pub fn plot(lines: &[&Line]) -> String {
    let point = |l: &&Line| {
        l.latency(0.99).map(|t| {
            #[allow(clippy::cast_precision_loss)]
            let f = l.score.false_edges as f64;
            (t.max(1e-9), f)
        })
    };
    let is_ours = |l: &&&Line| {
        ["calibrated", "physics", "learned"]
            .iter()
            .any(|o| l.debouncer.starts_with(o))
    };
    let ours: Vec<(f64, f64)> = lines.iter().filter(is_ours).filter_map(point).collect();
    let theirs: Vec<(f64, f64)> = lines
        .iter()
        .filter(|l| !is_ours(l))
        .filter_map(point)
        .collect();
    // The front: no other row has both fewer false edges and a lower latency.
    let (front, names) = pareto_front(
        lines
            .iter()
            .filter_map(|l| point(l).map(|p| (l.debouncer.as_str(), p))),
    );
    let (switch, kind) = lines
        .first()
        .map_or(("", "press"), |l| (l.switch.as_str(), l.kind.name()));
    Plot {
        title: format!("{switch} {kind}: false edges against latency"),
        x: Axis::log("latency P99", Quantity::Time),
        y: Axis::linear("false edges", Quantity::Count),
        series: vec![
            Series::new("Pareto front", "#d62728", Style::Steps, front.clone()),
            Series::new("ours", "#2ca02c", Style::Dots, ours),
            Series::new("peers", "#1f77b4", Style::Dots, theirs),
            named(front, names),
        ],
        markers: Vec::new(),
    }
    .svg()
}

/// The Pareto front of named points (x, y), both smaller better: the points no other has both
/// a smaller x and a smaller y, in increasing x, each with its names (rows that tie on a point
/// are named together).
pub(crate) fn pareto_front<'a>(
    points: impl Iterator<Item = (&'a str, (f64, f64))>,
) -> (Vec<(f64, f64)>, Vec<String>) {
    let mut all: Vec<(&str, (f64, f64))> = points.collect();
    all.sort_by(|a, b| a.1 .0.total_cmp(&b.1 .0).then(a.1 .1.total_cmp(&b.1 .1)));
    let mut front: Vec<(f64, f64)> = Vec::new();
    let mut names: Vec<String> = Vec::new();
    for (name, p) in all {
        match front.last() {
            Some(last) if *last == p => {
                if let Some(n) = names.last_mut() {
                    n.push_str(", ");
                    n.push_str(name);
                }
            }
            Some(last) if p.1 >= last.1 => {}
            _ => {
                front.push(p);
                names.push(name.to_owned());
            }
        }
    }
    (front, names)
}

/// The front's points with their names written beside them.
pub(crate) fn named(front: Vec<(f64, f64)>, names: Vec<String>) -> Series {
    let mut s = Series::new("", "#d62728", Style::Dots, front);
    s.names = names;
    s
}

/// How `replay` prints its rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    /// A markdown table (also `table`).
    Markdown,
    /// One JSON object per row.
    Json,
    /// The learner's window and false edges after every test (CSV).
    Curve,
}

/// What `replay` was asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    /// The capture and how to read it.
    pub capture: capture::Options,
    /// How its events are timed and the calibrated windows fitted (`calibrate`'s).
    pub calibration: stats::Calibration,
    /// The replay's own settings.
    pub settings: Settings,
    /// How to print.
    pub output: Output,
    /// Write one Pareto SVG per switch and kind there.
    pub plot: Option<String>,
    /// Tap sequences instead of isolated presses (`--taps`).
    pub taps: Option<taps::TapSettings>,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trace(closed_before: bool, changes: &[f64]) -> Trace {
        Trace {
            closed_before,
            changes: changes.to_vec(),
        }
    }

    #[test]
    fn a_trace_knows_the_contact_at_any_time() {
        let t = trace(false, &[0.0, 1e-3, 2e-3]);
        assert!(!t.closed_at(-1e-9));
        assert!(t.closed_at(0.0) && t.closed_at(0.5e-3));
        assert!(!t.closed_at(1.5e-3));
        assert!(t.closed_at(3e-3) && t.closed_after());
    }

    #[test]
    fn interrupt_debouncers_report_after_the_quiet_delay() {
        // Bounces 0-2 ms, then a re-opening at 10-12 ms: a 5 ms gpio-keys reports the press at
        // 7 ms, a release at 15... no: the open interval 10-12 ms is 2 ms, shorter than 5 ms,
        // so the timer is rescheduled and fires at 17 ms, closed: one edge. A 1 ms delay sees
        // it: press at 3 ms, release at 11 ms, press at 13 ms.
        let t = trace(false, &[0.0, 1e-3, 2e-3, 10e-3, 12e-3]);
        let mut row = Row {
            name: "x".into(),
            window: None,
            sampling: Sampling::Interrupt(5e-3),
            settle: 5e-3,
        };
        let s = score(&mut row, std::slice::from_ref(&t), 1e-3);
        assert_eq!((s.false_edges, s.latencies.len()), (0, 1));
        assert!((s.latencies[0] - 7e-3).abs() < 1e-12);
        row.sampling = Sampling::Interrupt(1e-3);
        let s = score(&mut row, &[t], 1e-3);
        assert_eq!(s.false_edges, 2);
        assert!((s.latencies[0] - 3e-3).abs() < 1e-12);
    }

    #[test]
    fn a_hold_off_that_covers_the_bounce_has_no_false_edge_and_one_sample_of_latency() {
        // A press bouncing for 3.5 ms, sampled every 0.1 ms.
        let changes: Vec<f64> = (0..8).map(|i| f64::from(i) * 0.5e-3).collect();
        let t = trace(false, &changes[..7]);
        for (window, covers) in [(4e-3, true), (1e-3, false)] {
            let mut rows = ours("x", window, window, 1e-4, Edge::Press).unwrap();
            let s = score(&mut rows[0], std::slice::from_ref(&t), 1e-4);
            assert_eq!(s.false_edges == 0, covers, "window {window}");
            assert!(s.latencies[0] <= 1e-4 + 1e-12);
            // Confirm mode waits a window after the last change.
            let s = score(&mut rows[1], std::slice::from_ref(&t), 1e-4);
            assert_eq!(s.false_edges, 0);
            assert!(s.latencies[0] >= 3e-3 + window - 1e-4 - 1e-12);
        }
    }

    #[test]
    fn the_peers_behave_as_documented_on_a_long_reopening() {
        // A press closed 0-6 ms, open 6-12 ms, closed from 12 ms, sampled every 1 ms: what
        // reports a state held 5 ms (or at once, ignoring the pin for under 6 ms) reports a
        // false release and press; what needs 8 ms or more of stable input does not; Bounce2's
        // lock-out ignores the pin for 10 ms, reads the reopening at 10.6 ms, and does.
        let t = trace(false, &[0.0, 6e-3, 12e-3]);
        let want = [
            ("qmk sym_defer_pk", 2),
            ("qmk sym_eager_pk", 2),
            ("qmk asym_eager_defer_pk", 2),
            ("zmk integrator", 2),
            ("bounce2 stable", 0),
            ("bounce2 lock-out", 2),
            ("debouncr 4 samples", 2),
            ("debouncr 8 samples", 0),
            ("debouncr 16 samples", 0),
            ("linux gpio-keys", 2),
            ("zephyr gpio-keys", 0),
        ];
        let rows = peers(1e-3);
        assert_eq!(rows.len(), want.len());
        for (mut row, (name, false_edges)) in rows.into_iter().zip(want) {
            assert_eq!(row.name, name);
            let s = score(&mut row, std::slice::from_ref(&t), 1e-3);
            assert_eq!(s.false_edges, false_edges, "{name}");
            assert_eq!(s.latencies.len(), 1, "{name}");
        }
    }
}

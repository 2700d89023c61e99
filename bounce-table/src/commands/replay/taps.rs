//! `bounce-table replay --taps`: debouncers scored on a key tapped like a human taps it.
//!
//! The isolated-press replay ([`crate::commands::replay::run`]) gives every debouncer a settled contact
//! before each press and all the time it wants after it: any window long enough looks perfect
//! there. A key in use is pressed again soon after it is released. Here the capture's real
//! press and release waveforms (the later tests of each switch, never the ones a window was
//! calibrated on) are spliced into seeded sequences of taps with human timing, and every
//! debouncer runs through a whole sequence without a reset. A press waveform is cut at the
//! release, and a release waveform at the next press.
//!
//! Scored per tap: its press is looked for from the previous tap's release to its own, and
//! its release from its press to the next tap's press ([`TapScore::of`]).
//! - `missed`: no press reported (a real press lost);
//! - `false_edges`: presses beyond one and releases beyond one;
//! - `correct`: exactly one press and one release, the press first;
//! - latencies: from the press to the first reported press, and from the release to the first
//!   release reported after it.
//!
//! Human timing (`docs/human-timing.md` says where each figure comes from): a key is held
//! 116 ms (SD 24) when typing, the same key comes again 176 ms (SD 70) after its previous
//! press, and a fast hand taps up to 16 times a second (31 ms down and 31 ms up): no real tap is
//! down or up for less than [`FASTEST_TAP`], and every regime draws its times at or above it.

use std::collections::BTreeMap;

use contact_bounce::{LearnerPrior, LearningState, Windows};

use crate::capture::{Edge, Event};
use crate::commands::replay::{self, edges, peers, Polled, Row, Sampling, Trace};
use crate::render::output::time;
use crate::render::plot::{Axis, Plot, Quantity, Series, Style};
use crate::scene::priors;
use crate::stats;
use contact_bounce_reference::stats::nearest_rank;

/// The fastest real tap, down or up (s): 16 taps a second, the known record, is 31 ms down and
/// 31 ms up.
pub const FASTEST_TAP: f64 = 31e-3;

/// How the key is tapped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Regime {
    /// The same key typed twice and again: held 116 ms (SD 24), pressed again 176 ms (SD 70)
    /// after its previous press.
    Typing,
    /// Tapped as fast as a hand goes: down and up each 31-62 ms (8 to 16 taps a second).
    FastTaps,
    /// Double-clicks: two taps held as in typing with 31-62 ms between them, then 0.3-1 s
    /// before the next pair.
    DoubleClick,
    /// Held: down 0.5-2 s, up 0.2-1 s.
    Hold,
}

impl Regime {
    /// Every regime, in the outputs' order.
    pub const ALL: [Regime; 4] = [
        Regime::Typing,
        Regime::FastTaps,
        Regime::DoubleClick,
        Regime::Hold,
    ];

    /// Its name in the outputs.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Regime::Typing => "typing",
            Regime::FastTaps => "fast-taps",
            Regime::DoubleClick => "double-click",
            Regime::Hold => "hold",
        }
    }

    /// Its parameters, as the outputs state them.
    #[must_use]
    pub fn parameters(self) -> &'static str {
        match self {
            Regime::Typing => "down: normal, 116 ms (SD 24); press to next press: normal, 176 ms (SD 70); both redrawn until down and up are at least 31 ms (which leaves 112 ms down and 213 ms press to press on average)",
            Regime::FastTaps => "down and up: uniform, 31-62 ms (8 to 16 taps a second)",
            Regime::DoubleClick => "pairs of taps: down as typing, up between the two uniform 31-62 ms, up after the pair uniform 0.3-1 s",
            Regime::Hold => "down: uniform 0.5-2 s; up: uniform 0.2-1 s",
        }
    }

    /// Down and up times (s) of `n` taps.
    fn draw(self, rng: &mut Rng, n: usize) -> Vec<(f64, f64)> {
        let typed = |rng: &mut Rng| loop {
            let down = rng.normal(116e-3, 24e-3);
            let up = rng.normal(176e-3, 70e-3) - down;
            if down >= FASTEST_TAP && up >= FASTEST_TAP {
                return (down, up);
            }
        };
        let fast = |rng: &mut Rng| rng.uniform(FASTEST_TAP, 2.0 * FASTEST_TAP);
        (0..n)
            .map(|i| match self {
                Regime::Typing => typed(rng),
                Regime::FastTaps => (fast(rng), fast(rng)),
                Regime::DoubleClick => {
                    let (down, _) = typed(rng);
                    let up = if i % 2 == 0 {
                        fast(rng)
                    } else {
                        rng.uniform(0.3, 1.0)
                    };
                    (down, up)
                }
                Regime::Hold => (rng.uniform(0.5, 2.0), rng.uniform(0.2, 1.0)),
            })
            .collect()
    }
}

/// A small seeded generator (SplitMix64): the sequences are the same on every machine.
#[derive(Debug, Clone)]
pub struct Rng(u64);

impl Rng {
    /// Seeded.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        #[allow(clippy::cast_precision_loss)]
        let x = (self.next() >> 11) as f64;
        x / (1u64 << 53) as f64
    }

    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    fn normal(&mut self, mean: f64, sd: f64) -> f64 {
        // Box-Muller, one of the pair.
        let u = 1.0 - self.unit();
        let v = self.unit();
        mean + sd * (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }

    fn pick<'a, T>(&mut self, from: &'a [T]) -> Option<&'a T> {
        #[allow(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            clippy::cast_precision_loss
        )]
        let i = (self.unit() * from.len() as f64) as usize;
        from.get(i.min(from.len().saturating_sub(1)))
    }
}

/// A switch's waveforms to splice: presses (from open) and releases (from closed), each with its
/// first change at 0.
#[derive(Debug, Clone, PartialEq)]
pub struct Waveforms {
    /// The switch.
    pub switch: String,
    /// Press waveforms.
    pub presses: Vec<Trace>,
    /// Release waveforms.
    pub releases: Vec<Trace>,
}

/// The name of the switch with no bounce at all.
pub const CONTROL: &str = "no-bounce control";

impl Waveforms {
    /// The control: one clean change per press and per release.
    #[must_use]
    pub fn control() -> Self {
        Self {
            switch: CONTROL.to_owned(),
            presses: vec![Trace {
                closed_before: false,
                changes: vec![0.0],
            }],
            releases: vec![Trace {
                closed_before: true,
                changes: vec![0.0],
            }],
        }
    }
}

/// One tap of a sequence (s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tap {
    /// Its press.
    pub start: f64,
    /// How long it is down.
    pub down: f64,
    /// How long it is up after.
    pub up: f64,
}

/// A sequence of taps and the contact it gives.
#[derive(Debug, Clone, PartialEq)]
pub struct Sequence {
    /// The taps.
    pub taps: Vec<Tap>,
    /// The contact over the whole sequence, open before the first tap.
    pub signal: Trace,
    /// Where the sequence ends (s).
    pub end: f64,
    /// The sampling phase, as a fraction of the period.
    pub phase: f64,
}

/// Open before the first tap (s): every debouncer starts settled.
const LEAD: f64 = 0.5;
/// Open after the last tap's up time (s).
const TAIL: f64 = 1.0;

/// `n` taps of `regime` on `w` (whose waveforms are already in the time scale wanted: the human
/// timing is not scaled), from `seed`.
#[must_use]
pub fn sequence(w: &Waveforms, regime: Regime, n: usize, seed: u64) -> Sequence {
    let mut rng = Rng::new(seed);
    let times = regime.draw(&mut rng, n);
    let mut taps = Vec::with_capacity(n);
    let mut changes: Vec<f64> = Vec::new();
    let mut closed = false;
    let mut t = LEAD;
    // One piece of waveform from `start`, cut after `len`: the contact takes the waveform's
    // level at its start (if it is not there already), then follows its changes within `len`.
    let mut piece = |trace: &Trace, start: f64, len: f64| {
        let level = trace.closed_at(0.0);
        if level != closed {
            changes.push(start);
            closed = level;
        }
        for &c in trace.changes.iter().filter(|&&c| c > 0.0 && c < len) {
            changes.push(start + c);
            closed = !closed;
        }
    };
    for &(down, up) in &times {
        let (Some(press), Some(release)) = (rng.pick(&w.presses), rng.pick(&w.releases)) else {
            break;
        };
        taps.push(Tap { start: t, down, up });
        piece(press, t, down);
        piece(release, t + down, up);
        t += down + up;
    }
    let phase = rng.unit();
    Sequence {
        taps,
        signal: Trace {
            closed_before: false,
            changes,
        },
        end: t + TAIL,
        phase,
    }
}

/// What one debouncer did on one sequence.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TapScore {
    /// Taps.
    pub taps: usize,
    /// Taps with no press reported between their press and the next tap's.
    pub missed: usize,
    /// Presses beyond one and releases beyond one, summed over the taps.
    pub false_edges: usize,
    /// Taps with exactly one press and one release, the press first.
    pub correct: usize,
    /// From each press to the first press reported after it, within its tap (s).
    pub press_latencies: Vec<f64>,
    /// From each release to the first release reported after it, within its tap (s).
    pub release_latencies: Vec<f64>,
}

impl TapScore {
    /// Scores `edges` (time, closed; in time order) against the taps of `seq`. A tap's press is
    /// looked for from the previous tap's release (the sequence's start for the first) to its
    /// own release, and its release from its press to the next tap's press (the sequence's end
    /// for the last): a press reported while the contact had already closed again just before
    /// the finger's press (a release's late bounce running into the next press) is that tap's,
    /// with a latency of 0.
    #[must_use]
    pub fn of(seq: &Sequence, edges: &[(f64, bool)]) -> Self {
        let mut s = Self {
            taps: seq.taps.len(),
            ..Self::default()
        };
        let within = |from: f64, until: f64, closed: bool| {
            let first = edges.partition_point(|e| e.0 < from);
            let last = edges.partition_point(|e| e.0 < until);
            edges
                .get(first..last)
                .unwrap_or(&[])
                .iter()
                .filter(move |e| e.1 == closed)
        };
        let mut released = 0.0;
        for (k, tap) in seq.taps.iter().enumerate() {
            let release_at = tap.start + tap.down;
            let next = seq.taps.get(k + 1).map_or(seq.end, |t| t.start);
            let presses: Vec<f64> = within(released, release_at, true).map(|e| e.0).collect();
            let releases: Vec<f64> = within(tap.start, next, false).map(|e| e.0).collect();
            released = release_at;
            s.missed += usize::from(presses.is_empty());
            s.false_edges += presses.len().saturating_sub(1) + releases.len().saturating_sub(1);
            let in_order =
                matches!((presses.first(), releases.first()), (Some(p), Some(r)) if p < r);
            s.correct += usize::from(presses.len() == 1 && releases.len() == 1 && in_order);
            if let Some(p) = presses.first() {
                s.press_latencies.push((p - tap.start).max(0.0));
            }
            if let Some(r) = releases.iter().find(|&&r| r >= release_at) {
                s.release_latencies.push(r - release_at);
            }
        }
        s
    }
}

fn quantile(v: &[f64], q: f64) -> Option<f64> {
    let mut v = v.to_vec();
    v.sort_by(f64::total_cmp);
    nearest_rank(&v, q)
}

/// The core's learning debouncer as a replayed row.
#[derive(Debug, Clone)]
pub struct Learner {
    prior: LearnerPrior,
    state: LearningState,
    period: f64,
}

impl Learner {
    /// From `prior` (samples), sampled every `period` (s).
    #[must_use]
    pub fn new(prior: LearnerPrior, period: f64) -> Self {
        Self {
            prior,
            state: LearningState::new(false),
            period,
        }
    }
}

impl Polled for Learner {
    fn reset(&mut self, closed: bool) {
        self.state = LearningState::new(closed);
    }
    fn sample(&mut self, _now: f64, closed: bool) -> Option<bool> {
        self.state
            .update(closed, &self.prior)
            .map(|e| e == contact_bounce::Edge::Press)
    }
    fn window(&self) -> Option<f64> {
        let (p, r) = self.state.learned().windows(&self.prior);
        Some(f64::from(p.max(r)) * self.period)
    }
    fn reverts_like_a_tap(&self) -> Option<bool> {
        Some(self.state.learned().reverts_like_a_tap(&self.prior))
    }
}

/// What `replay --taps` was asked for, beyond `replay`'s settings.
#[derive(Debug, Clone, PartialEq)]
pub struct TapSettings {
    /// Taps per switch and regime.
    pub count: usize,
    /// The sequences' seed.
    pub seed: u64,
}

/// One row of the tap replay.
#[derive(Debug, Clone, PartialEq)]
pub struct TapLine {
    /// The switch.
    pub switch: String,
    /// The regime.
    pub regime: Regime,
    /// The debouncer.
    pub debouncer: String,
    /// Its window (s): the longer of its press and release windows; the learner's at the end.
    pub window: Option<f64>,
    /// Its score.
    pub score: TapScore,
    /// At the end, whether it says the switch reverts for as long as a tap (the learner).
    pub reverts_like_a_tap: Option<bool>,
}

impl TapLine {
    /// Press latency quantile `q` (s).
    #[must_use]
    pub fn press_latency(&self, q: f64) -> Option<f64> {
        quantile(&self.score.press_latencies, q)
    }
    /// Release latency quantile `q` (s).
    #[must_use]
    pub fn release_latency(&self, q: f64) -> Option<f64> {
        quantile(&self.score.release_latencies, q)
    }
}

/// The later tests of each switch in `events` as waveforms (times multiplied by `scale`), in
/// the order the switches first appear, and the control last.
#[must_use]
pub fn waveforms(events: &[Event], split: f64, scale: f64) -> Vec<Waveforms> {
    let mut out: Vec<Waveforms> = Vec::new();
    let mut by: BTreeMap<(&str, Edge), Vec<&Event>> = BTreeMap::new();
    for e in events {
        by.entry((e.switch.as_str(), e.kind)).or_default().push(e);
        if !out.iter().any(|w| w.switch == e.switch) {
            out.push(Waveforms {
                switch: e.switch.clone(),
                presses: Vec::new(),
                releases: Vec::new(),
            });
        }
    }
    for ((switch, kind), list) in by {
        let cut = stats::earlier_count(list.len(), split);
        let later = list.get(cut..).unwrap_or(&[]);
        if let Some(w) = out.iter_mut().find(|w| w.switch == switch) {
            let traces = later.iter().map(|e| Trace::of(e, scale)).collect();
            match kind {
                Edge::Press => w.presses = traces,
                Edge::Release => w.releases = traces,
            }
        }
    }
    out.retain(|w| !w.presses.is_empty() && !w.releases.is_empty());
    out.push(Waveforms::control());
    out
}

/// The debouncers of the tap replay for one switch: calibrated windows `(press, release)` (s),
/// the type's prior `prior` (s), the learner from that prior (or `--prior`), and the peers.
///
/// # Errors
/// A window that does not fit our debouncer's counter at `period`.
pub fn rows(calibrated: (f64, f64), prior: f64, s: &replay::Settings) -> Result<Vec<Row>, String> {
    let too_long = |what: &str| {
        format!(
            "{what} does not fit {} samples of --sample-period {}: sample less often",
            Windows::MAX_TICKS,
            s.period
        )
    };
    let mut rows = Vec::new();
    let longer = |mut v: Vec<Row>, w: f64| {
        for r in &mut v {
            r.window = Some(w);
        }
        v
    };
    let (p, r) = calibrated;
    rows.extend(longer(
        replay::ours("calibrated", p, r, s.period, Edge::Press)
            .ok_or_else(|| too_long("a calibrated window"))?,
        p.max(r),
    ));
    rows.extend(
        replay::ours("physics-prior", prior, prior, s.period, Edge::Press)
            .ok_or_else(|| too_long("the prior's window"))?,
    );
    for &w in &s.fixed {
        rows.extend(
            replay::ours(&format!("fixed {}", time(w)), w, w, s.period, Edge::Press)
                .ok_or_else(|| too_long("--window"))?,
        );
    }
    let learner = replay::learner_prior(s.learner_prior.unwrap_or(prior), s.fastest_tap, s.period)?;
    rows.push(Row {
        name: "learned".to_owned(),
        window: None,
        sampling: Sampling::Polled(Box::new(Learner::new(learner, s.period))),
        settle: 0.0,
    });
    rows.extend(peers(s.period));
    Ok(rows)
}

/// The seed of the `j`-th regime's sequences from the replay's `seed`: the same taps and phase
/// for every switch and debouncer of a regime.
fn regime_seed(seed: u64, j: usize) -> u64 {
    seed.wrapping_mul(0x0001_0000_0001)
        .wrapping_add(u64::try_from(j).unwrap_or(u64::MAX))
}

/// The tap replay on `events`: per switch (and the control), per regime, every debouncer.
///
/// # Errors
/// As [`rows`].
pub fn run(
    events: &[Event],
    c: &stats::Calibration,
    s: &replay::Settings,
    t: &TapSettings,
) -> Result<Vec<TapLine>, String> {
    let calibrated = replay::calibrated(events, c, s);
    let mut lines = Vec::new();
    for w in waveforms(events, s.split, s.time_scale) {
        let prior = priors::from_switch_name(&w.switch)
            .or(s.switch_type)
            .unwrap_or(&priors::HAND_OPERATED)
            .window()
            * s.time_scale;
        let prior = prior.min(s.fastest_tap);
        let both = |k| {
            calibrated
                .get(&(w.switch.clone(), k))
                .copied()
                .unwrap_or(0.0)
        };
        for (j, regime) in Regime::ALL.into_iter().enumerate() {
            let seq = sequence(&w, regime, t.count, regime_seed(t.seed, j));
            for mut row in rows((both(Edge::Press), both(Edge::Release)), prior, s)
                .map_err(|e| format!("{}: {e}", w.switch))?
            {
                let found = edges(&mut row.sampling, &seq.signal, seq.phase, s.period, seq.end);
                let (window, reverts_like_a_tap) = match &row.sampling {
                    Sampling::Polled(d) => (d.window().or(row.window), d.reverts_like_a_tap()),
                    Sampling::Interrupt(_) => (row.window, None),
                };
                lines.push(TapLine {
                    switch: w.switch.clone(),
                    regime,
                    debouncer: row.name,
                    window,
                    score: TapScore::of(&seq, &found),
                    reverts_like_a_tap,
                });
            }
        }
    }
    Ok(lines)
}

/// One JSON object per row, with exactly the keys `switch`, `regime`, `debouncer`, `window_s`,
/// `taps`, `missed`, `false_edges`, `correct`, `press_latency_p50_s`, `press_latency_p99_s`,
/// `release_latency_p99_s`.
#[must_use]
pub fn json(lines: &[TapLine]) -> String {
    lines
        .iter()
        .map(|l| {
            format!(
                "{{\"switch\":{},\"regime\":\"{}\",\"debouncer\":{},\"window_s\":{},\"taps\":{},\"missed\":{},\"false_edges\":{},\"correct\":{},\"press_latency_p50_s\":{},\"press_latency_p99_s\":{},\"release_latency_p99_s\":{}}}\n",
                serde_json::Value::from(l.switch.as_str()),
                l.regime.name(),
                serde_json::Value::from(l.debouncer.as_str()),
                replay::json_number(l.window),
                l.score.taps,
                l.score.missed,
                l.score.false_edges,
                l.score.correct,
                replay::json_number(l.press_latency(0.5)),
                replay::json_number(l.press_latency(0.99)),
                replay::json_number(l.release_latency(0.99)),
            )
        })
        .collect()
}

/// The regimes' parameters, then the rows as a markdown table.
#[must_use]
pub fn markdown(lines: &[TapLine], t: &TapSettings) -> String {
    let mut out = format!(
        "{} taps per switch and regime (seed {}); no tap is down or up for less than {}.\n\n",
        t.count,
        t.seed,
        time(FASTEST_TAP)
    );
    for r in Regime::ALL {
        out.push_str(&format!("- {}: {}\n", r.name(), r.parameters()));
    }
    out.push_str("\n| switch | regime | debouncer | window | taps | missed | false edges | correct | press latency P50 | press latency P99 | release latency P99 |\n|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    let show = |x: Option<f64>| x.map_or_else(|| "-".to_owned(), time);
    for l in lines {
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            l.switch,
            l.regime.name(),
            l.debouncer,
            show(l.window),
            l.score.taps,
            l.score.missed,
            l.score.false_edges,
            l.score.correct,
            show(l.press_latency(0.5)),
            show(l.press_latency(0.99)),
            show(l.release_latency(0.99)),
        ));
    }
    let says: Vec<String> = lines
        .iter()
        .filter_map(|l| {
            l.reverts_like_a_tap.map(|r| {
                format!(
                    "{} {} ({}): {}",
                    l.switch,
                    l.regime.name(),
                    l.debouncer,
                    if r { "yes" } else { "no" }
                )
            })
        })
        .collect();
    if !says.is_empty() {
        out.push_str(&format!(
            "\nThe switch reverts for as long as a tap (`reverts_like_a_tap`, at the end of each sequence): {}.\n",
            says.join("; ")
        ));
    }
    out
}

/// Every switch and regime's plot ([`plot`]), each with its file name
/// (`<switch>-<regime>-taps.svg`, as `--plot DIR` writes them).
#[must_use]
pub fn plots(lines: &[TapLine]) -> Vec<(String, String)> {
    replay::per_group(
        lines,
        |l| (l.switch.as_str(), l.regime.name()),
        "taps",
        plot,
    )
}

/// One switch and regime as an SVG: missed taps against false edges, ours and the peers apart,
/// the rows on the Pareto front (no other row has both fewer missed taps and fewer false edges)
/// named beside their points.
#[must_use]
pub fn plot(lines: &[&TapLine]) -> String {
    #[allow(clippy::cast_precision_loss)]
    let point = |l: &TapLine| (l.score.false_edges as f64, l.score.missed as f64);
    let is_ours = |l: &TapLine| {
        ["calibrated", "physics", "learned", "fixed"]
            .iter()
            .any(|o| l.debouncer.starts_with(o))
    };
    let ours: Vec<_> = lines
        .iter()
        .filter(|l| is_ours(l))
        .map(|l| point(l))
        .collect();
    let theirs: Vec<_> = lines
        .iter()
        .filter(|l| !is_ours(l))
        .map(|l| point(l))
        .collect();
    let (front, names) =
        replay::pareto_front(lines.iter().map(|l| (l.debouncer.as_str(), point(l))));
    let (switch, regime) = lines
        .first()
        .map_or(("", "typing"), |l| (l.switch.as_str(), l.regime.name()));
    Plot {
        title: format!("{switch}, {regime}: missed taps against false edges"),
        x: Axis::linear("false edges", Quantity::Count),
        y: Axis::linear("missed taps", Quantity::Count),
        series: vec![
            Series::new("Pareto front", "#d62728", Style::Steps, front.clone()),
            Series::new("ours", "#2ca02c", Style::Dots, ours),
            Series::new("peers", "#1f77b4", Style::Dots, theirs),
            replay::named(front, names),
        ],
        markers: Vec::new(),
    }
    .svg()
}

/// What `calibrate`'s windows cost in use, for its report: per switch, the windows fitted on the
/// earlier half of its tests (at most `c.min_tap` where given), in hold-off mode at 1 ms
/// samples, on 1,000 taps of each regime spliced from the later half (never the tests they were
/// fitted on). Cells: missed taps / false edges.
#[must_use]
pub fn window_costs(events: &[Event], c: &stats::Calibration) -> String {
    let s = replay::Settings {
        period: 1e-3,
        split: 0.5,
        time_scale: 1.0,
        switch_type: None,
        fixed: Vec::new(),
        fastest_tap: FASTEST_TAP,
        learner_prior: None,
    };
    let t = TapSettings {
        count: 1000,
        seed: 1,
    };
    let calibrated = replay::calibrated(events, c, &s);
    let mut out = String::from(
        "## Tapped like a key\n\nEach switch's windows fitted on the earlier half of its tests, in hold-off mode at 1 ms samples, on 1,000 taps of each regime spliced from the later half (`bounce-table replay --taps` has the regimes, every debouncer and latencies). Missed taps / false edges:\n\n| switch | windows (press / release) | ",
    );
    out.push_str(
        &Regime::ALL
            .iter()
            .map(|r| r.name())
            .collect::<Vec<_>>()
            .join(" | "),
    );
    out.push_str(" |\n|---|---:|");
    out.push_str(&"---:|".repeat(Regime::ALL.len()));
    out.push('\n');
    for w in waveforms(events, s.split, 1.0) {
        if w.switch == CONTROL {
            continue;
        }
        let both = |k| {
            calibrated
                .get(&(w.switch.clone(), k))
                .copied()
                .unwrap_or(0.0)
        };
        let (p, r) = (both(Edge::Press), both(Edge::Release));
        let mut cells = Vec::new();
        for (j, regime) in Regime::ALL.into_iter().enumerate() {
            let seq = sequence(&w, regime, t.count, regime_seed(t.seed, j));
            let cell = replay::ours("calibrated", p, r, s.period, Edge::Press)
                .and_then(|rows| rows.into_iter().next())
                .map_or_else(
                    || "window beyond the counter at 1 ms".to_owned(),
                    |mut row| {
                        let found =
                            edges(&mut row.sampling, &seq.signal, seq.phase, s.period, seq.end);
                        let score = TapScore::of(&seq, &found);
                        format!("{} / {}", score.missed, score.false_edges)
                    },
                );
            cells.push(cell);
        }
        out.push_str(&format!(
            "| {} | {} / {} | {} |\n",
            w.switch,
            time(p),
            time(r),
            cells.join(" | ")
        ));
    }
    out
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
    fn a_press_is_cut_at_the_release_and_a_release_at_the_next_press() {
        // A press that reopens from 20 to 60 ms, and a release that closes again from 10 to
        // 40 ms: fast taps (31-62 ms) cut both.
        let w = Waveforms {
            switch: "s".into(),
            presses: vec![trace(false, &[0.0, 20e-3, 60e-3])],
            releases: vec![trace(true, &[0.0, 10e-3, 40e-3])],
        };
        let seq = sequence(&w, Regime::FastTaps, 50, 3);
        assert_eq!(seq.taps.len(), 50);
        for (k, tap) in seq.taps.iter().enumerate() {
            assert!(tap.down >= FASTEST_TAP && tap.down <= 2.0 * FASTEST_TAP);
            assert!(tap.up >= FASTEST_TAP && tap.up <= 2.0 * FASTEST_TAP);
            let release = tap.start + tap.down;
            let next = seq.taps.get(k + 1).map_or(seq.end, |t| t.start);
            // The press: closed at its start, open from 20 ms (if still down), closed from
            // 60 ms (if still down); the release from its own start in the same way.
            let at = |t: f64| seq.signal.closed_at(t);
            assert!(at(tap.start + 1e-3));
            assert!(!at(tap.start + 21e-3) || tap.down <= 21e-3);
            if tap.down > 61e-3 {
                assert!(at(tap.start + 61e-3));
            }
            assert!(!at(release + 1e-3));
            assert!(at(release + 11e-3));
            if release + 41e-3 < next {
                assert!(!at(release + 41e-3));
            }
            // At the next press the contact closes (or is already closed, from the release's
            // late closing, when the up time ends before 40 ms).
            assert!(at(next + 1e-3) || next >= seq.end);
        }
        // The lead-in is open, and every debouncer starts settled there.
        assert!(!seq.signal.closed_at(0.4));
    }

    #[test]
    fn each_tap_is_scored_from_the_edges_in_its_own_time() {
        // Two taps: 100 ms down from 0.5 s, 100 ms up; the second from 0.7 s.
        let seq = Sequence {
            taps: vec![
                Tap {
                    start: 0.5,
                    down: 0.1,
                    up: 0.1,
                },
                Tap {
                    start: 0.7,
                    down: 0.1,
                    up: 0.1,
                },
            ],
            signal: trace(false, &[0.5, 0.6, 0.7, 0.8]),
            end: 1.9,
            phase: 0.0,
        };
        // Right: one press and one release each, 1 ms late.
        let right = [(0.501, true), (0.601, false), (0.701, true), (0.801, false)];
        let s = TapScore::of(&seq, &right);
        assert_eq!((s.missed, s.false_edges, s.correct), (0, 0, 2));
        assert_eq!(s.press_latencies.len(), 2);
        assert!((s.release_latencies[1] - 1e-3).abs() < 1e-12);
        // The second press lost (one long press): missed 1, and its release is reported once.
        let lost = [(0.501, true), (0.801, false)];
        let s = TapScore::of(&seq, &lost);
        assert_eq!((s.missed, s.false_edges, s.correct), (1, 0, 0));
        // A reopening in the first press reported: a release and a press too many.
        let chatter = [
            (0.501, true),
            (0.55, false),
            (0.56, true),
            (0.601, false),
            (0.701, true),
            (0.801, false),
        ];
        let s = TapScore::of(&seq, &chatter);
        assert_eq!((s.missed, s.false_edges, s.correct), (0, 2, 1));
        // A press reported before the finger's (the contact closed again at the end of the
        // release before) belongs to the tap it starts, with a latency of 0.
        let early = [(0.501, true), (0.601, false), (0.69, true), (0.801, false)];
        let s = TapScore::of(&seq, &early);
        assert_eq!((s.missed, s.false_edges, s.correct), (0, 0, 2));
        assert_eq!(s.press_latencies[1], 0.0);
    }

    #[test]
    fn the_regimes_draw_what_they_state() {
        let mut rng = Rng::new(11);
        for regime in Regime::ALL {
            let times = regime.draw(&mut rng, 20_000);
            assert!(times
                .iter()
                .all(|&(d, u)| d >= FASTEST_TAP && u >= FASTEST_TAP));
            #[allow(clippy::cast_precision_loss)]
            let mean = |v: &dyn Fn(&(f64, f64)) -> f64| times.iter().map(v).sum::<f64>() / 20_000.0;
            let (down, period) = (mean(&|t| t.0), mean(&|t| t.0 + t.1));
            match regime {
                // Redrawing until down and up are at least 31 ms keeps the slower pairs: 112 ms
                // held and 213 ms apart on average (a separate 200,000-draw computation), not
                // 116 and 176; the parameters say so. (20,000 draws: the means' standard
                // errors are 0.2 and 0.4 ms.)
                Regime::Typing => {
                    assert!((down - 111.6e-3).abs() < 1.5e-3, "{down}");
                    assert!((period - 213.5e-3).abs() < 3e-3, "{period}");
                }
                Regime::FastTaps => assert!((period - 93e-3).abs() < 2e-3, "{period}"),
                Regime::DoubleClick => assert!((period - 0.116 - 0.35).abs() < 0.02, "{period}"),
                Regime::Hold => assert!((period - 1.85).abs() < 0.03, "{period}"),
            }
        }
    }
}

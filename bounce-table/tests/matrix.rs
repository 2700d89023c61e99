//! The core's keyboard matrix (`contact_bounce::debounce::matrix::LearningMatrix`) typed on: 100 keys of
//! one switch, two hands tapping random keys of their half with human timing, every key's
//! contact spliced from a switch's press and release waveforms (`taps::sequence`). Scored per
//! key as the tap replay scores one key (`TapScore`): no tap may be lost, and the shared
//! windows must be learned from the first 20 events of any keys.
//!
//! The real capture (`../shared/data/bouncy-button-uno.jsonl`, or `CAPTURE=...`) is not part of
//! the repository: its test is ignored unless asked for (`scripts/test.sh` runs it when the
//! capture is there).

use bounce_table::capture;
use bounce_table::commands::replay::taps::{
    self, Regime, Sequence, Tap, TapScore, Waveforms, FASTEST_TAP,
};
use bounce_table::commands::replay::{learner_prior, Trace};
use bounce_table::scene::priors;
use contact_bounce::debounce::matrix::{KeyEvent, LearningMatrix, MATRIX_WARM_UP};
use contact_bounce::{Edge, LearnerPrior, LearningState};

/// One scan a millisecond, as keyboard firmware scans.
const PERIOD: f64 = 1e-3;
const ROWS: usize = 10;
const COLS: usize = 10;
const KEYS: usize = ROWS * COLS;
type Matrix = LearningMatrix<u16, ROWS, COLS>;

/// What a typing run gave.
#[derive(Debug, Default)]
struct Outcome {
    /// The keys' scores, summed.
    score: TapScore,
    /// Press and release events the model had counted when the 21st edge was reported, and its
    /// windows then (scans).
    at_21st: Option<((u8, u8), (u16, u16))>,
    /// The windows at the end (scans).
    windows: (u16, u16),
    /// Keys widened at the end.
    widened: usize,
    /// Scans that could not report an edge (the sink is large enough: must stay 0).
    deferred: usize,
    /// One learning debouncer per key (`LearningState`, 24 bytes each) on the same scans,
    /// summed over the keys.
    per_key: TapScore,
}

/// `n` taps of `regime` by each of two hands on `w`, hand `h` on keys `50 h .. 50 h + 50`, each
/// tap on a random key of its half; the matrix learns from `prior`.
fn type_on(
    w: &Waveforms,
    regime: Regime,
    n: usize,
    seed: u64,
    (prior, period): (LearnerPrior, f64),
) -> Outcome {
    let hands: Vec<Sequence> = (0..2u64)
        .map(|h| taps::sequence(w, regime, n, seed.wrapping_mul(31).wrapping_add(h)))
        .collect();
    // The key of every tap, per hand.
    let mut rng = taps::Rng::new(seed ^ 0x5eed);
    let keys: Vec<Vec<usize>> = hands
        .iter()
        .enumerate()
        .map(|(h, seq)| {
            seq.taps
                .iter()
                .map(|_| {
                    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
                    let k = (rng.unit() * (KEYS / 2) as f64) as usize;
                    h * KEYS / 2 + k.min(KEYS / 2 - 1)
                })
                .collect()
        })
        .collect();
    let end = hands.iter().map(|s| s.end).fold(0.0, f64::max);
    let phase = hands.first().map_or(0.5, |s| s.phase);
    let mut m = Matrix::new(prior).unwrap();
    let mut edges: Vec<Vec<(f64, bool)>> = vec![Vec::new(); KEYS];
    let mut singles = vec![LearningState::new(false); KEYS];
    let mut single_edges: Vec<Vec<(f64, bool)>> = vec![Vec::new(); KEYS];
    let mut reported = 0;
    let mut out = Outcome::default();
    // Per hand: the tap in progress and the changes passed.
    let mut tap_at = [0usize; 2];
    let mut change_at = [0usize; 2];
    let mut scan = 0u64;
    loop {
        #[allow(clippy::cast_precision_loss)]
        let t = (scan as f64 + phase) * period;
        if t >= end {
            break;
        }
        scan += 1;
        let mut rows = [0u16; ROWS];
        for (h, seq) in hands.iter().enumerate() {
            while seq.taps.get(tap_at[h] + 1).is_some_and(|x| x.start <= t) {
                tap_at[h] += 1;
            }
            while seq
                .signal
                .changes
                .get(change_at[h])
                .is_some_and(|&c| c <= t)
            {
                change_at[h] += 1;
            }
            let closed = seq.signal.closed_before ^ (change_at[h] % 2 == 1);
            if closed {
                let k = keys[h][tap_at[h]];
                rows[k / COLS] |= 1 << (k % COLS);
            }
        }
        let before = (
            (m.learned().press.events, m.learned().release.events),
            m.windows(),
        );
        for (k, key) in singles.iter_mut().enumerate() {
            let closed = rows[k / COLS] & (1 << (k % COLS)) != 0;
            if let Some(e) = key.update(closed, &prior) {
                single_edges[k].push((t, e == Edge::Press));
            }
        }
        let mut events = heapless::Vec::<KeyEvent, 8>::new();
        let s = m.scan(&rows, &mut events);
        out.deferred += usize::from(s.deferred);
        for e in &events {
            edges[usize::from(e.row) * COLS + usize::from(e.col)].push((t, e.edge == Edge::Press));
        }
        if reported < 21 && reported + events.len() >= 21 {
            out.at_21st = Some(before);
        }
        reported += events.len();
    }
    // Each key scored on its own taps, as the tap replay scores one key.
    for k in 0..KEYS {
        let mut mine: Vec<Tap> = Vec::new();
        for (h, seq) in hands.iter().enumerate() {
            for (i, tap) in seq.taps.iter().enumerate() {
                if keys[h][i] == k {
                    mine.push(*tap);
                }
            }
        }
        mine.sort_by(|a, b| a.start.total_cmp(&b.start));
        let seq = Sequence {
            taps: mine,
            signal: Trace {
                closed_before: false,
                changes: Vec::new(),
            },
            end,
            phase,
        };
        let single = TapScore::of(&seq, &single_edges[k]);
        out.per_key.taps += single.taps;
        out.per_key.missed += single.missed;
        out.per_key.false_edges += single.false_edges;
        out.per_key.correct += single.correct;
        let s = TapScore::of(&seq, &edges[k]);
        out.score.taps += s.taps;
        out.score.missed += s.missed;
        out.score.false_edges += s.false_edges;
        out.score.correct += s.correct;
        out.score.press_latencies.extend(s.press_latencies);
        out.score.release_latencies.extend(s.release_latencies);
    }
    out.windows = m.windows();
    out.widened = (0..ROWS)
        .flat_map(|r| (0..COLS).map(move |c| (r, c)))
        .filter(|&(r, c)| m.is_widened(r, c))
        .count();
    out
}

/// The hand-operated prior (at most the fastest tap) at scans of `period`, and the period.
fn hand_prior_at(period: f64) -> (LearnerPrior, f64) {
    let prior = priors::by_name("push-button").unwrap();
    let p = learner_prior(prior.window_in_use(FASTEST_TAP), FASTEST_TAP, period).unwrap();
    (p, period)
}

/// At 1 ms scans.
fn hand_prior() -> (LearnerPrior, f64) {
    hand_prior_at(PERIOD)
}

/// The window `m` scans of bounce ask for (`contact_bounce::debounce::learn`): `m + (m - 1) / 2`.
fn grow(m: u16) -> u16 {
    if m == 0 {
        1
    } else {
        m + (m - 1) / 2
    }
}

fn trace(closed_before: bool, changes: &[f64]) -> Trace {
    Trace {
        closed_before,
        changes: changes.to_vec(),
    }
}

#[test]
fn a_hundred_keys_keep_every_tap_and_share_windows_learned_from_the_first_20_events() {
    // Presses reopen from 1.2 to 2.5 ms or from 0.6 to 2.2 ms, releases close again from 0.8
    // to 1.5 ms: back for good within 3 scans and 2 scans. (Had the first 20 edges shown less
    // than the longest bounce, a later one would grow the model, at the price of two false
    // edges: the single learner's rule too.)
    let w = Waveforms {
        switch: "synthetic".to_owned(),
        presses: vec![
            trace(false, &[0.0, 1.2e-3, 2.5e-3]),
            trace(false, &[0.0, 0.6e-3, 2.2e-3]),
        ],
        releases: vec![trace(true, &[0.0, 0.8e-3, 1.5e-3])],
    };
    for regime in [Regime::Typing, Regime::FastTaps, Regime::DoubleClick] {
        for seed in 1..4 {
            let o = type_on(&w, regime, 600, seed, hand_prior());
            let what = format!(
                "{regime:?} seed {seed}: {} missed, {} false edges, {} correct, at the 21st edge {:?}, windows {:?}, {} widened",
                o.score.missed, o.score.false_edges, o.score.correct, o.at_21st, o.windows, o.widened
            );
            assert_eq!(o.score.taps, 1200, "{what}");
            assert_eq!(o.score.missed, 0, "{what}");
            assert_eq!(o.score.false_edges, 0, "{what}");
            assert_eq!(o.score.correct, 1200, "{what}");
            assert_eq!(o.deferred, 0, "{what}");
            assert_eq!(o.widened, 0, "{what}");
            let ((presses, releases), windows) = o.at_21st.unwrap();
            assert_eq!(
                u16::from(presses) + u16::from(releases),
                MATRIX_WARM_UP,
                "{what}"
            );
            // The bounce ends 2.5 ms and 1.5 ms after the first change: seen back within
            // 3 + 1 and 2 + 1 scans, whatever the phase; never more.
            assert!(windows.0 >= grow(3) && windows.0 <= grow(4), "{what}");
            assert!(windows.1 >= grow(2) && windows.1 <= grow(3), "{what}");
            assert_eq!(o.windows, windows, "{what}");
        }
    }
    // No bounce at all: one scan each way, every tap kept.
    let o = type_on(
        &Waveforms::control(),
        Regime::FastTaps,
        600,
        7,
        hand_prior(),
    );
    assert_eq!((o.score.missed, o.score.false_edges), (0, 0), "{o:?}");
    assert_eq!(o.windows, (1, 1), "{o:?}");
}

#[test]
fn one_worn_key_widens_its_own_window_and_costs_the_others_nothing() {
    // Every key bounces for 2 ms; key taps of one hand are sometimes on a key whose press
    // reopens 10 to 14 ms after it closes (past the shared window, back within a tap).
    let good = Waveforms {
        switch: "good".to_owned(),
        presses: vec![trace(false, &[0.0, 1.0e-3, 2.0e-3])],
        releases: vec![trace(true, &[0.0])],
    };
    let o = type_on(&good, Regime::Typing, 400, 11, hand_prior());
    assert_eq!(
        (o.score.missed, o.score.false_edges, o.widened),
        (0, 0, 0),
        "{o:?}"
    );
    // Then one key worn: a new matrix learns from 20 good presses, and the worn key is
    // widened after its first late reopening.
    let mut m = Matrix::new(hand_prior().0).unwrap();
    // One press of key `k` (bouncing open at scan 1, reopening at 10-13 if `reopen`), held
    // 100 scans and released for 100: the edges reported and the keys widened.
    let press = |m: &mut Matrix, k: usize, reopen: bool| {
        let (mut edges, mut widened) = (0, 0);
        for i in 0..200 {
            let closed = i < 100 && i != 1 && !(reopen && (10..14).contains(&i));
            let mut rows = [0u16; ROWS];
            if closed {
                rows[k / COLS] = 1 << (k % COLS);
            }
            let mut events = heapless::Vec::<KeyEvent, 8>::new();
            widened += m.scan(&rows, &mut events).widened;
            edges += events.len();
        }
        (edges, widened)
    };
    for k in 0..20 {
        assert_eq!(press(&mut m, k, false), (2, 0));
    }
    assert_eq!(m.windows(), (grow(2), 1));
    // Reopened past the shared window and back within a tap: two false edges, once.
    assert_eq!(press(&mut m, 42, true), (4, 1));
    assert!(m.is_widened(4, 2));
    assert_eq!(press(&mut m, 42, true), (2, 0));
    // The model kept the good keys' windows, and they still report their presses alone.
    assert_eq!(m.windows(), (grow(2), 1));
    assert_eq!(press(&mut m, 43, false), (2, 0));
}

/// The shared capture's events, if it is there.
fn shared_capture() -> Option<Vec<capture::Event>> {
    let path = std::env::var("CAPTURE").unwrap_or_else(|_| {
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../shared/data/bouncy-button-uno.jsonl"
        )
        .to_owned()
    });
    let text = std::fs::read_to_string(&path).ok()?;
    let (events, mut skipped) = capture::read_jsonl(&path, &text, &[]).unwrap();
    Some(capture::drop_several_presses(events, 0.2, &mut skipped))
}

#[test]
#[ignore = "needs the shared capture (../shared/data or CAPTURE=...): scripts/test.sh runs it"]
fn a_hundred_keys_of_each_real_switch_keep_every_tap() {
    let events = shared_capture().expect("the shared capture");
    // The later half of each switch's tests, as the tap replay takes them.
    // At 1 ms scans (keyboard firmware's usual) and at 0.25 ms (the fastest tap is 124 scans,
    // near the most a key counts).
    for period in [PERIOD, 0.25e-3] {
        for w in taps::waveforms(&events, 0.5, 1.0) {
            for regime in [Regime::Typing, Regime::FastTaps, Regime::DoubleClick] {
                let o = type_on(&w, regime, 1000, 3, hand_prior_at(period));
                let ((presses, releases), windows) = o.at_21st.unwrap();
                println!(
                    "{} {regime:?} at {} ms: {} taps, {} missed, {} false edges, windows at the 21st edge {windows:?} (events {presses}/{releases}), at the end {:?}, {} keys widened; a learner per key: {} missed, {} false edges",
                    w.switch, period * 1e3, o.score.taps, o.score.missed, o.score.false_edges, o.windows, o.widened, o.per_key.missed, o.per_key.false_edges
                );
                assert_eq!(o.score.taps, 2000);
                assert_eq!(o.score.missed, 0, "{} {regime:?}", w.switch);
                assert_eq!(o.deferred, 0);
                assert_eq!(u16::from(presses) + u16::from(releases), MATRIX_WARM_UP);
                // Learning once for all keys passes no more false edges than a learner per key.
                assert!(
                    o.score.false_edges <= o.per_key.false_edges,
                    "{} {regime:?}",
                    w.switch
                );
            }
        }
    }
}

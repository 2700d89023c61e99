//! `bounce-table replay --taps` on synthetic captures, and the learner tapped through the core's
//! public API (`LearnerPrior`, `LearningState`) at any prior and sampling period.

use std::process::Command;

use bounce_table::commands::replay::taps::{sequence, Learner, Regime, TapScore, Waveforms};
use bounce_table::commands::replay::{edges, Sampling, Trace};
use contact_bounce::LearnerPrior;

const BIN: &str = env!("CARGO_BIN_EXE_bounce-table");

/// A JSON Lines capture of `tests` press/release pairs of the switch `name`: each press closes
/// at 0 and, if `reopen` is given, opens from `reopen.0` to `reopen.1` (s); releases are clean.
fn capture(name: &str, tests: usize, reopen: Option<(f64, f64)>) -> String {
    let mut out = String::new();
    let ns = |t: f64| 100.0 + t * 1e9;
    for i in 0..tests {
        let events = match reopen {
            Some((a, b)) => format!("[[0,1],[100,0],[{},1],[{},0]]", ns(a), ns(b)),
            None => "[[0,1],[100,0]]".to_owned(),
        };
        out.push_str(&format!(
            "{{\"dataset\":\"{name}\",\"test\":{},\"kind\":\"press\",\"section\":\"Normal\",\"section_invalid\":false,\"events\":{events}}}\n",
            2 * i + 1
        ));
        out.push_str(&format!(
            "{{\"dataset\":\"{name}\",\"test\":{},\"kind\":\"release\",\"section\":\"Normal\",\"section_invalid\":false,\"events\":[[0,0],[100,1]]}}\n",
            2 * i + 2
        ));
    }
    out
}

fn write(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("taps-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn every_switch_regime_and_debouncer_gets_a_row_with_exactly_its_keys() {
    // A switch whose presses reopen from 6 to 12 ms (less than a tap), and a clean one.
    let mut text = capture("reopening", 20, Some((6e-3, 12e-3)));
    text.push_str(&capture("clean", 20, None));
    let path = write("two.jsonl", &text);
    let out = Command::new(BIN)
        .args(["replay", "--taps", "--tap-count", "200", "--format", "json"])
        .args(["--window", "157e-3"])
        .arg(&path)
        .args(["--switch-type", "push-button"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let rows: Vec<serde_json::Value> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let keys = [
        "switch",
        "regime",
        "debouncer",
        "window_s",
        "taps",
        "missed",
        "false_edges",
        "correct",
        "press_latency_p50_s",
        "press_latency_p99_s",
        "release_latency_p99_s",
    ];
    for r in &rows {
        let have: Vec<&str> = r.as_object().unwrap().keys().map(String::as_str).collect();
        assert_eq!(have, keys, "{r}");
        assert_eq!(r["taps"], 200, "{r}");
    }
    // Three switches (the control too), four regimes, 18 debouncers: ours (calibrated, prior
    // and the fixed window, each in both modes; the learner) and the 11 peers.
    assert_eq!(rows.len(), 3 * 4 * 18);
    for switch in ["reopening", "clean", "no-bounce control"] {
        for regime in ["typing", "fast-taps", "double-click", "hold"] {
            let of: Vec<_> = rows
                .iter()
                .filter(|r| r["switch"] == switch && r["regime"] == regime)
                .collect();
            assert_eq!(of.len(), 18, "{switch} {regime}");
            let learned = of.iter().find(|r| r["debouncer"] == "learned").unwrap();
            // A 6 ms reopening, less than a tap: the learner's window covers it from the start
            // (the prior, at most a tap), keeps every tap and passes no false edge.
            assert_eq!(learned["missed"], 0, "{learned}");
            assert_eq!(learned["false_edges"], 0, "{learned}");
            assert_eq!(learned["correct"], 200, "{learned}");
            if switch == "reopening" {
                // QMK's 5 ms reports the reopening: two false edges a tap.
                let qmk = of
                    .iter()
                    .find(|r| r["debouncer"] == "qmk sym_eager_pk")
                    .unwrap();
                assert_eq!(qmk["false_edges"], 400, "{qmk}");
            }
            // The type's prior is at most the fastest tap: in hold-off it loses no tap.
            let prior = of
                .iter()
                .find(|r| r["debouncer"] == "physics-prior hold-off")
                .unwrap();
            assert_eq!(prior["window_s"], 31e-3, "{prior}");
            assert_eq!(prior["missed"], 0, "{prior}");
            // 157 ms, the survey's worst switch, swallows fast taps even in hold-off mode.
            if regime == "fast-taps" {
                let long = of
                    .iter()
                    .find(|r| r["debouncer"] == "fixed 157.000 ms hold-off")
                    .unwrap();
                assert!(long["missed"].as_u64().unwrap() > 100, "{long}");
            }
        }
    }
}

#[test]
fn bad_tap_options_are_refused_with_their_name() {
    let path = write("one.jsonl", &capture("one", 4, None));
    for (args, named) in [
        (&["--taps", "--tap-count", "0"][..], "--tap-count"),
        (&["--taps", "--format", "curve"], "--format curve"),
        (&["--taps", "--min-tap", "1e-5"], "--min-tap"),
        (&["--taps", "--min-tap", "-1"], "--min-tap"),
        (&["--taps", "--prior", "nan"], "--prior"),
    ] {
        let out = Command::new(BIN)
            .arg("replay")
            .args(args)
            .arg(&path)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(named), "{args:?}: {err}");
    }
}

/// A synthetic rocker: each press bounces for about 1 ms (open 0.3-0.6 ms and 0.8-1.0 ms),
/// each release for 0.2 ms.
fn rocker() -> Waveforms {
    Waveforms {
        switch: "rocker-like".to_owned(),
        presses: vec![Trace {
            closed_before: false,
            changes: vec![0.0, 0.3e-3, 0.6e-3, 0.8e-3, 1.0e-3],
        }],
        releases: vec![Trace {
            closed_before: true,
            changes: vec![0.0, 0.1e-3, 0.2e-3],
        }],
    }
}

#[test]
fn the_learner_keeps_every_tap_from_any_prior_at_1_ms_and_0_1_ms() {
    // Through the public API: `LearnerPrior` in samples (the fastest tap, 31 ms, in whole
    // samples) and `LearningState::update` at each sample.
    for period in [1e-3, 1e-4] {
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let samples = |s: f64| ((s / period) * (1.0 + 1e-9)).ceil() as u16;
        for prior in [5e-3, 20e-3, 50e-3, 157e-3] {
            let tap = samples(31e-3);
            let p = LearnerPrior::new(samples(prior), samples(prior), tap).unwrap();
            for w in [Waveforms::control(), rocker()] {
                for (j, regime) in Regime::ALL.into_iter().enumerate() {
                    let seq = sequence(&w, regime, 200, 7 + j as u64);
                    let mut k = Sampling::Polled(Box::new(Learner::new(p, period)));
                    let found = edges(&mut k, &seq.signal, seq.phase, period, seq.end);
                    let s = TapScore::of(&seq, &found);
                    assert_eq!(
                        (s.missed, s.false_edges, s.correct),
                        (0, 0, 200),
                        "{} {} prior {prior} period {period}",
                        w.switch,
                        regime.name()
                    );
                }
            }
        }
    }
}

#[test]
fn calibrate_caps_its_windows_at_the_fastest_tap_and_says_what_it_costs() {
    // Presses that reopen from 40 to 100 ms: a window of about 100 ms without the cap, 31 ms
    // with.
    let path = write("long.jsonl", &capture("long", 20, Some((40e-3, 100e-3))));
    let run = |args: &[&str]| {
        let out = Command::new(BIN)
            .arg("calibrate")
            .args(args)
            .arg(&path)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    let header = run(&["--format", "c", "--min-tap", "31e-3"]);
    assert!(
        header.contains("LONG_PRESS_WINDOW_NS 31000000ull"),
        "{header}"
    );
    let uncapped = run(&["--format", "c"]);
    assert!(
        !uncapped.contains("LONG_PRESS_WINDOW_NS 31000000ull"),
        "{uncapped}"
    );
    let report = run(&["--min-tap", "31e-3"]);
    assert!(report.contains("Capped at 31.000 ms"), "{report}");
    assert!(
        report.contains("20 of the 20 presses bounce longer"),
        "{report}"
    );
    // The report's tap costs (missed / false edges per regime): the capped window keeps every
    // tap and lets the reopening through as false edges; without the cap the window swallows
    // fast taps.
    assert!(report.contains("## Tapped like a key"), "{report}");
    let cells = |text: &str| -> Vec<(u64, u64)> {
        let row = text
            .lines()
            .find(|l| l.starts_with("| long |"))
            .unwrap_or_else(|| panic!("no row: {text}"));
        row.split('|')
            .filter_map(|c| {
                let (a, b) = c.trim().split_once(" / ")?;
                Some((a.parse().ok()?, b.parse().ok()?))
            })
            .collect()
    };
    let capped = cells(&report);
    assert_eq!(capped.len(), 4, "{report}");
    assert!(capped.iter().all(|&(missed, _)| missed == 0), "{capped:?}");
    assert!(capped[0].1 > 0, "{capped:?}");
    let plain = cells(&run(&[]));
    assert!(plain[1].0 > 100, "fast taps: {plain:?}");
}

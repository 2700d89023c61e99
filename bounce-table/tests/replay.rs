//! `bounce-table replay` on synthetic captures whose answers are known.

use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_bounce-table");

/// A JSON Lines capture of `tests` press/release pairs of one switch: each press closes at 0,
/// reopens at `reopen` (s) and closes for good at `close` (s); each release is clean.
fn capture(name: &str, tests: usize, reopen: f64, close: f64) -> String {
    let mut out = String::new();
    for i in 0..tests {
        let ns = |t: f64| t * 1e9;
        out.push_str(&format!(
            "{{\"dataset\":\"{name}\",\"test\":{},\"kind\":\"press\",\"section\":\"Normal\",\"section_invalid\":false,\"events\":[[0,1],[100,0],[{},1],[{},0]]}}\n",
            2 * i + 1,
            100.0 + ns(reopen),
            100.0 + ns(close),
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
        .join(format!("replay-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

fn rows(args: &[&str]) -> Vec<serde_json::Value> {
    let out = Command::new(BIN).arg("replay").args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

fn row<'a>(rows: &'a [serde_json::Value], kind: &str, debouncer: &str) -> &'a serde_json::Value {
    rows.iter()
        .find(|r| r["kind"] == kind && r["debouncer"] == debouncer)
        .unwrap_or_else(|| panic!("no {kind} row for {debouncer}"))
}

#[test]
fn a_reopening_switch_gets_the_answers_the_peers_documentation_gives() {
    // Every press: closed 0-6 ms, open 6-12 ms, closed. 20 tests: 10 calibrate, 10 replayed.
    let path = write(
        "reopen-rocker.jsonl",
        &capture("reopen-rocker", 20, 6e-3, 12e-3),
    );
    let r = rows(&["--format", "json", path.to_str().unwrap()]);
    let keys = [
        "switch",
        "kind",
        "debouncer",
        "window_s",
        "events",
        "false_edges",
        "latency_p50_s",
        "latency_p99_s",
    ];
    for x in &r {
        let o = x.as_object().unwrap();
        assert_eq!(
            o.keys().collect::<Vec<_>>(),
            keys.iter().collect::<Vec<_>>()
        );
        assert_eq!(x["events"], 10);
    }
    // 2 kinds x (2 calibrated + 2 prior (the name says rocker) + learned + 11 peers).
    assert_eq!(r.len(), 2 * 16);
    // The calibrated window covers the 12 ms bounce: no false edge in either mode; hold-off
    // reports at the first sample (1 ms), confirm a window after the last change.
    for mode in ["calibrated hold-off", "calibrated confirm"] {
        let x = row(&r, "press", mode);
        assert_eq!(x["false_edges"], 0, "{x}");
        assert!(x["window_s"].as_f64().unwrap() >= 12e-3, "{x}");
    }
    assert!(
        row(&r, "press", "calibrated hold-off")["latency_p99_s"]
            .as_f64()
            .unwrap()
            <= 1e-3
    );
    let confirm = row(&r, "press", "calibrated confirm");
    assert!(
        confirm["latency_p50_s"].as_f64().unwrap()
            >= 12e-3 + confirm["window_s"].as_f64().unwrap() - 1e-3
    );
    // Each peer as its documentation says (see the unit test of the same trace): a false
    // release and press per test where a state held 5 ms is reported.
    for (peer, per_test) in [
        ("qmk sym_defer_pk", 2),
        ("qmk sym_eager_pk", 2),
        ("zmk integrator", 2),
        ("bounce2 stable", 0),
        ("bounce2 lock-out", 2),
        ("debouncr 16 samples", 0),
        ("linux gpio-keys", 2),
        ("zephyr gpio-keys", 0),
    ] {
        assert_eq!(
            row(&r, "press", peer)["false_edges"],
            10 * per_test,
            "{peer}"
        );
    }
    // Clean releases: nobody has a false edge; a rocker's prior holds.
    assert!(r
        .iter()
        .filter(|x| x["kind"] == "release")
        .all(|x| x["false_edges"] == 0));
    assert_eq!(row(&r, "press", "physics-prior hold-off")["false_edges"], 0);
    // The learner, from the rocker's prior, through all 40 tests: no false edge, the first
    // sample's latency, and a window learned from the 12 ms bounce seen at 1 ms samples (12 or
    // 13 samples from the edge's sample to the last change's): m + (m - 1) / 2.
    let learned = row(&r, "press", "learned");
    assert_eq!(learned["false_edges"], 0, "{learned}");
    assert!(learned["latency_p99_s"].as_f64().unwrap() <= 1e-3);
    let w = learned["window_s"].as_f64().unwrap();
    assert!((17e-3 - 1e-9..=19e-3 + 1e-9).contains(&w), "{learned}");
}

#[test]
fn time_scaled_captures_keep_the_calibrated_rows_clean() {
    let path = write("scaled.jsonl", &capture("scaled", 20, 6e-3, 12e-3));
    // (the fastest tap scales with the capture: a contactor-like or reed-like switch, whose
    // fastest real change is ten times or a tenth of a finger's)
    for (scale, period, tap) in [("10", "1e-3", "0.31"), ("0.1", "1e-5", "0.0031")] {
        let r = rows(&[
            "--format",
            "json",
            "--time-scale",
            scale,
            "--period",
            period,
            "--min-tap",
            tap,
            "--switch-type",
            "push-button",
            path.to_str().unwrap(),
        ]);
        for mode in ["calibrated hold-off", "calibrated confirm", "learned"] {
            assert_eq!(row(&r, "press", mode)["false_edges"], 0, "x{scale} {mode}");
        }
        let w = row(&r, "press", "calibrated hold-off")["window_s"]
            .as_f64()
            .unwrap();
        let bounce = 12e-3 * scale.parse::<f64>().unwrap();
        assert!(w >= bounce && w <= 2.0 * bounce, "x{scale}: {w}");
        // The prior scales with the capture too (a type's window, in the capture's time).
        assert!(row(&r, "press", "physics-prior confirm")["window_s"].is_number());
    }
}

#[test]
fn bad_captures_and_options_are_named() {
    let path = write(
        "bad.jsonl",
        "{\"dataset\":\"d\",\"kind\":\"press\",\"events\":[[0,1],[5,0]]}\nnot json\n",
    );
    let out = Command::new(BIN)
        .args(["replay", path.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("bad.jsonl:2: not JSON"), "{err}");
    for (args, named) in [
        (&["--split", "1", "x.jsonl"][..], "--split"),
        (&["--period", "0", "x.jsonl"], "--sample-period"),
        (&["--sample-period", "0", "x.jsonl"], "--sample-period"),
        (&["--switch-type", "valve", "x.jsonl"], "--switch-type"),
        (&["--format", "yaml", "x.jsonl"], "--format"),
        (&["--export", "c", "x.jsonl"], "--export"),
    ] {
        let out = Command::new(BIN).arg("replay").args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            String::from_utf8_lossy(&out.stderr).contains(named),
            "{args:?}"
        );
    }
    // A window that does not fit the debouncer's counter at the period asked: a clear error.
    let path = write("long.jsonl", &capture("long", 20, 6e-3, 12e-3));
    let out = Command::new(BIN)
        .args(["replay", "--period", "1e-7", path.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("sample less often"));
}

#[test]
fn a_fixed_window_is_replayed_as_it_is_in_both_modes() {
    // Every press reopens from 6 to 12 ms: a 1 ms window lets the reopening through in
    // hold-off mode (it reports the press, then the opening and the closing again: 2 false
    // edges a test); 20 ms covers it. Releases are clean for both.
    let path = write("fixed.jsonl", &capture("fixed", 20, 6e-3, 12e-3));
    let r = rows(&[
        "--format",
        "json",
        "--window",
        "1e-3",
        "--window=20e-3",
        path.to_str().unwrap(),
    ]);
    let short = row(&r, "press", "fixed 1.000 ms hold-off");
    assert_eq!(short["window_s"], 1e-3);
    assert_eq!(short["false_edges"], 20, "{short}");
    assert_eq!(
        row(&r, "press", "fixed 20.000 ms hold-off")["false_edges"],
        0
    );
    assert_eq!(
        row(&r, "press", "fixed 20.000 ms confirm")["false_edges"],
        0
    );
    assert_eq!(
        row(&r, "release", "fixed 1.000 ms hold-off")["false_edges"],
        0
    );
    // Not a positive number of seconds, or longer than the debouncer's counter: refused.
    for (bad, named) in [("0", "--window"), ("1e3", "--window 1000")] {
        let out = Command::new(BIN)
            .args(["replay", "--window", bad, path.to_str().unwrap()])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(named), "{bad}: {err}");
    }
}

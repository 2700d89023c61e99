//! The capture importers against files written by independent writers: a VCD by pyvcd, a CSV by
//! Python's csv module and a VCD exported by sigrok-cli (`scripts/capture-fixtures.py`), holding
//! the same synthetic capture as `expected.json`. And malformed variants of them, rejected with the line named.

use bounce_table::capture::{read_csv, read_vcd, Edge, Polarity, Stream};
use serde_json::Value;

fn fixture(name: &str) -> String {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn expected() -> Stream {
    let v: Value = serde_json::from_str(&fixture("expected.json")).unwrap();
    Stream {
        closed_before: v["closed_before"].as_bool().unwrap(),
        #[allow(clippy::cast_precision_loss)]
        changes: v["changes_ns"]
            .as_array()
            .unwrap()
            .iter()
            .map(|t| t.as_u64().unwrap() as f64 * 1e-9)
            .collect(),
    }
}

#[test]
fn pyvcd_output_reads_back_exactly() {
    let s = read_vcd(
        "button.vcd",
        &fixture("button.vcd"),
        Some("sw"),
        Polarity::ActiveLow,
    )
    .unwrap();
    assert_eq!(s, expected());
    // The other 1-bit signal is read too when named; the bus is refused.
    let led = read_vcd(
        "button.vcd",
        &fixture("button.vcd"),
        Some("led"),
        Polarity::ActiveLow,
    )
    .unwrap();
    assert!(!led.changes.is_empty());
    let e = read_vcd(
        "button.vcd",
        &fixture("button.vcd"),
        Some("bus"),
        Polarity::ActiveLow,
    )
    .unwrap_err();
    assert!(e.reason.contains("8 bits"), "{e}");
    let e = read_vcd(
        "button.vcd",
        &fixture("button.vcd"),
        None,
        Polarity::ActiveLow,
    )
    .unwrap_err();
    assert!(e.reason.contains("several 1-bit signals (sw, led)"), "{e}");
}

#[test]
fn sigrok_cli_export_reads_back() {
    // sigrok writes 100 ns ticks where pyvcd wrote nanoseconds: the same instants, up to the
    // rounding of ticks * 1e-7 against ns * 1e-9 (a few ulps of 1.7 s).
    let s = read_vcd(
        "button-sigrok.vcd",
        &fixture("button-sigrok.vcd"),
        Some("sw"),
        Polarity::ActiveLow,
    )
    .unwrap();
    let want = expected();
    assert_eq!(s.closed_before, want.closed_before);
    assert_eq!(s.changes.len(), want.changes.len());
    for (got, want) in s.changes.iter().zip(&want.changes) {
        assert!(
            (got - want).abs() <= 4.0 * f64::EPSILON * want,
            "{got} vs {want}"
        );
    }
    // Its second channel is there too, so the switch must be named.
    let e = read_vcd(
        "button-sigrok.vcd",
        &fixture("button-sigrok.vcd"),
        None,
        Polarity::ActiveLow,
    )
    .unwrap_err();
    assert!(e.reason.contains("several 1-bit signals (sw, led)"), "{e}");
}

#[test]
fn python_csv_output_reads_back_exactly() {
    let s = read_csv("button.csv", &fixture("button.csv"), Polarity::ActiveLow).unwrap();
    assert_eq!(s, expected());
    // Active high reads every level the other way: the same times, the contact closed first.
    let flipped = read_csv("button.csv", &fixture("button.csv"), Polarity::ActiveHigh).unwrap();
    assert_eq!(flipped.changes, s.changes);
    assert!(flipped.closed_before);
}

#[test]
fn the_capture_is_cut_into_its_presses_and_releases() {
    let s = expected();
    let events = s.segment("button", 0.2);
    let kinds: Vec<Edge> = events.iter().map(|e| e.kind).collect();
    assert_eq!(
        kinds,
        [Edge::Press, Edge::Release, Edge::Press, Edge::Release]
    );
    // A quiet gap shorter than the late re-close (1 ms after the release) splits that event.
    assert_eq!(s.segment("button", 0.5e-3).len(), 5);
    // The first press at 2 us resolution: closed 12 us, open 3 us, closed 45 us, open 1 us
    // (chatter), then closed.
    let d = events[0].describe(2e-6, 1.0);
    assert_eq!(
        (d.transitions, d.chatter, d.dwells.len(), d.flights.len()),
        (5, 1, 2, 1)
    );
    assert!((d.flights[0] - 3e-6).abs() < 1e-12, "{:?}", d.flights);
    assert!((d.bounce - 61e-6).abs() < 1e-12);
    // The last release: two chatter intervals, a flight of 998.4 us, the late re-close (chatter).
    let d = events[3].describe(2e-6, 1.0);
    assert_eq!(
        (d.chatter, d.flights.len(), d.dwells.len()),
        (3, 1, 0),
        "{d:?}"
    );
}

#[test]
fn malformed_variants_are_rejected_with_the_line() {
    let vcd = fixture("button.vcd");
    let no_header_end = vcd.replace("$enddefinitions $end", "");
    let e = read_vcd("v.vcd", &no_header_end, Some("sw"), Polarity::ActiveLow).unwrap_err();
    assert!(e.reason.contains("enddefinitions"), "{e}");
    let backwards = vcd.replacen("#600000000", "#6000", 1);
    let line = backwards.lines().position(|l| l == "#6000").unwrap() + 1;
    let e = read_vcd("v.vcd", &backwards, Some("sw"), Polarity::ActiveLow).unwrap_err();
    assert_eq!(
        (e.line, e.reason.contains("back in time")),
        (line, true),
        "{e}"
    );
    let unknown = vcd.replacen("\n0!\n", "\nx!\n", 1);
    let e = read_vcd("v.vcd", &unknown, Some("sw"), Polarity::ActiveLow).unwrap_err();
    assert!(e.reason.contains("unknown"), "{e}");

    let csv = fixture("button.csv");
    let mut lines: Vec<&str> = csv.lines().collect();
    lines[4] = "0.100015,2";
    let e = read_csv("c.csv", &lines.join("\n"), Polarity::ActiveLow).unwrap_err();
    assert_eq!(e.line, 5, "{e}");
    assert_eq!(e.to_string(), "c.csv:5: level \"2\" is not 0 or 1");
}

#[test]
fn calibrate_speaks_format_and_output_like_every_subcommand() {
    use std::process::Command;
    let bin = env!("CARGO_BIN_EXE_bounce-table");
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("bounce-table-calibrate-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let run = |args: &[&str]| {
        Command::new(bin)
            .arg("calibrate")
            .args(args)
            .output()
            .expect("run")
    };
    // Ten presses and releases of a switch that bounces 40-85 us (the CSV fixture has two of
    // each: too few for a window).
    let mut lines = String::new();
    for test in 0..10_u64 {
        let bounce = 40_000 + 5_000 * test;
        for (kind, open) in [("press", 1), ("release", 0)] {
            lines.push_str(&format!(
                "{{\"dataset\":\"s\",\"test\":{test},\"kind\":\"{kind}\",\"section\":\"Normal\",\"section_invalid\":false,\"events\":[[0,{open}],[812,{}],[{},{open}],[{},{}]]}}\n",
                1 - open,
                812 + bounce / 2,
                812 + bounce,
                1 - open
            ));
        }
    }
    let capture = dir.join("capture.jsonl");
    std::fs::write(&capture, lines).expect("write");
    let csv = capture.to_str().expect("utf8").to_owned();
    // The windows as code, written completely to --output (nothing on standard output).
    let header = dir.join("windows.h");
    let out = run(&[
        "--format",
        "c",
        "--output",
        header.to_str().expect("utf8"),
        &csv,
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stdout.is_empty());
    let text = std::fs::read_to_string(&header).expect("header");
    assert!(
        text.starts_with("/* Debounce windows from a capture")
            && text.contains("/* Generated by bounce-table ")
            && text.contains("#endif"),
        "{text}"
    );
    // Two presses and two releases, one pair 250 times apart: the fit's tail put the window at
    // 1e26 s, once exported as u64::MAX nanoseconds without a word. Too few events for any
    // window: refused, naming the switch and kind.
    let fixture_csv = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/button.csv");
    let out = run(&["--format", "c", fixture_csv]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("button press: 2 events are too few for a window (at least 10)"),
        "{stderr}"
    );
    let report = run(&[fixture_csv]);
    let summary = String::from_utf8_lossy(&report.stdout);
    assert!(
        summary.contains("- button release: no window: 2 events are too few")
            && !summary.contains("e26"),
        "{summary}"
    );
    // The older spelling (`--export c`) is gone: refused in one line, naming it.
    let old = run(&["--export", "c", &csv]);
    assert_eq!(old.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&old.stderr).contains("'--export'"));
    // Events as CSV; the capture's format said with --capture-format.
    let events = run(&["--format", "csv", "--capture-format", "jsonl", &csv]);
    assert!(events.status.success());
    assert!(String::from_utf8_lossy(&events.stdout).starts_with("switch,"));
    // A capture's format given to --format is refused with the option it belongs to.
    let out = run(&["--format", "vcd", &csv]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--capture-format vcd"));
    // The output may not be the capture itself, and a failed write leaves nothing behind.
    let copy = dir.join("copy.jsonl");
    std::fs::copy(&csv, &copy).expect("copy");
    let copy = copy.to_str().expect("utf8");
    let out = run(&["--format", "c", "--output", copy, copy]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        std::fs::read_to_string(copy).expect("read"),
        std::fs::read_to_string(&csv).expect("read")
    );
    let missing = dir.join("no-such-dir").join("w.h");
    let out = run(&[
        "--format",
        "c",
        "--output",
        missing.to_str().expect("utf8"),
        &csv,
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(std::fs::read_dir(&dir).expect("dir").all(|e| !e
        .expect("entry")
        .file_name()
        .to_string_lossy()
        .contains("tmp-")));
    // Kept when an assertion fails, to look at; removed when the test passes.
    std::fs::remove_dir_all(&dir).ok();
}

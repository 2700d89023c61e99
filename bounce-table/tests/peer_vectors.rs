//! The replay's peers checked against their projects' own test vectors.
//!
//! QMK: the single-key traces of its debounce unit tests (`quantum/debounce/tests/` in
//! qmk_firmware: `sym_defer_pk_tests.cpp`, `sym_eager_pk_tests.cpp`,
//! `asym_eager_defer_pk_tests.cpp`; two-key tests split into one trace per key, since these
//! algorithms keep one timer per key), transcribed here in a short notation of our own and
//! driven the way its `debounce_test_common.cpp` drives them: a scan at every event; between
//! events either a scan every millisecond with no change ("smooth") or none ("jumps", the
//! tests that ask for it and, as QMK also does, every other test); after each event up to three
//! extra scans at the same time that must change nothing; and a quiet minute at the end that
//! must change nothing either.
//!
//! Bounce2 (both modes, its `Bounce2.cpp`), debouncr and the two `gpio-keys`: a tap with a
//! bouncing press and release, with the edges their documented rules give, derived by hand.
//!
//! ZMK: its integrator (`zmk_debounce_update` in ZMK's `debounce.c`) compares the counter with
//! the threshold before adding the scan's elapsed milliseconds, so at 5 ms a key flips on the
//! 6th differing scan at 1 ms, the 4th at 2 ms and the 3rd at 4 ms. Checked on traces derived
//! by hand from that rule, and on random traces against an integer-millisecond model of it.

use bounce_table::commands::replay::{peers, Polled, Sampling};

/// One step: the time (ms), the pin's new level if it changes (`D` pressed, `U` released), and
/// the reported change expected at that scan.
#[derive(Debug, Clone, Copy)]
struct Step {
    ms: u32,
    input: Option<bool>,
    output: Option<bool>,
}

/// Parses `"0:D>D 1:U 5 10>U"`: at 0 ms the pin is pressed and the press is reported, at 1 ms it
/// is released, at 5 ms a scan changes nothing, at 10 ms the release is reported.
fn steps(text: &str) -> Vec<Step> {
    let level = |c: &str| match c {
        "D" => true,
        "U" => false,
        other => panic!("bad level {other:?} in {text:?}"),
    };
    text.split_whitespace()
        .map(|s| {
            let (head, output) = s
                .split_once('>')
                .map_or((s, None), |(h, o)| (h, Some(level(o))));
            let (ms, input) = head
                .split_once(':')
                .map_or((head, None), |(t, i)| (t, Some(level(i))));
            Step {
                ms: ms.parse().unwrap_or_else(|_| panic!("bad time in {s:?}")),
                input,
                output,
            }
        })
        .collect()
}

fn peer(name: &str) -> Box<dyn Polled> {
    let row = peers(1e-3)
        .into_iter()
        .find(|r| r.name == name)
        .unwrap_or_else(|| panic!("no peer {name}"));
    match row.sampling {
        Sampling::Polled(d) => d,
        Sampling::Interrupt(_) => panic!("{name} is not polled"),
    }
}

/// Runs one trace through a fresh `name`; `Err` names the first scan whose reported state
/// differs from the expected one.
fn run(name: &str, trace: &str, smooth: bool, extra: usize) -> Result<(), String> {
    let mut d = peer(name);
    d.reset(false);
    let (mut pin, mut expected, mut reported) = (false, false, false);
    let scan = |d: &mut Box<dyn Polled>, ms: u32, pin: bool, reported: &mut bool| {
        if let Some(state) = d.sample(f64::from(ms) * 1e-3, pin) {
            *reported = state;
        }
    };
    let mut clock: Option<u32> = None;
    for step in steps(trace) {
        if smooth {
            if let Some(t) = clock {
                for ms in t + 1..step.ms {
                    scan(&mut d, ms, pin, &mut reported);
                    if reported != expected {
                        return Err(format!("changed at {ms} ms between events"));
                    }
                }
            }
        }
        clock = Some(step.ms);
        if let Some(level) = step.input {
            pin = level;
        }
        scan(&mut d, step.ms, pin, &mut reported);
        if let Some(out) = step.output {
            expected = out;
        }
        if reported != expected {
            return Err(format!(
                "at {} ms reports {} where {} is expected",
                step.ms,
                if reported { "pressed" } else { "released" },
                if expected { "pressed" } else { "released" }
            ));
        }
        for _ in 0..extra {
            scan(&mut d, step.ms, pin, &mut reported);
            if reported != expected {
                return Err(format!("an extra scan at {} ms changed it", step.ms));
            }
        }
    }
    let end = clock.unwrap_or(0);
    for ms in end + 1..end + 60_000 {
        scan(&mut d, ms, pin, &mut reported);
        if reported != expected {
            return Err(format!("changed at {ms} ms in the quiet minute"));
        }
    }
    Ok(())
}

/// Every trace of `vectors` in every way QMK runs it; the failures, named.
fn failures(name: &str, vectors: &[(&str, bool, &str)]) -> Vec<String> {
    let mut out = Vec::new();
    for &(test, jumps_only, trace) in vectors {
        let modes: &[bool] = if jumps_only { &[false] } else { &[true, false] };
        for &smooth in modes {
            for extra in [0, 1, 3] {
                if let Err(e) = run(name, trace, smooth, extra) {
                    out.push(format!(
                        "{test} ({}, {extra} extra scans): {e}",
                        if smooth { "smooth" } else { "jumps" }
                    ));
                }
            }
        }
    }
    out
}

#[test]
fn qmk_sym_defer_pk_passes_qmk_s_own_test_vectors() {
    let vectors = [
        ("OneKeyShort1", false, "0:D 5>D 5:U 10>U"),
        ("OneKeyShort2", false, "0:D 5>D 6:U 11>U"),
        ("OneKeyShort3", false, "0:D 5>D 7:U 12>U"),
        ("OneKeyTooQuick1", false, "0:D 5:U"),
        ("OneKeyTooQuick2", false, "0:D 5>D 6:U 11:D"),
        ("OneKeyBouncing1", false, "0:D 1:U 2:D 3:U 4:D 5:U 6:D 11>D"),
        (
            "OneKeyBouncing2",
            false,
            "0:D 5>D 6:U 7:D 8:U 9:D 10:U 15>U",
        ),
        ("OneKeyLong", false, "0:D 5>D 25:U 30>U 50:D 55>D"),
        ("TwoKeysShort key 1", false, "0:D 1 5>D 6 7:U 8 12>U 13"),
        ("TwoKeysShort key 2", false, "0 1:D 5 6>D 7 8:U 12 13>U"),
        ("TwoKeysSimultaneous1", false, "0:D 5>D 6:U 11>U"),
        (
            "TwoKeysSimultaneous2 key 1",
            false,
            "0:D 1 5>D 6:U 7 11>U 12",
        ),
        (
            "TwoKeysSimultaneous2 key 2",
            false,
            "0 1:D 5 6>D 7:U 11 12>U",
        ),
        ("OneKeyDelayedScan1", true, "0:D 300>D 300:U 305>U"),
        ("OneKeyDelayedScan2", true, "0:D 300>D 301:U 306>U"),
        ("OneKeyDelayedScan3", true, "0:D 300:U"),
        ("OneKeyDelayedScan4", true, "0:D 50>D 51:U 56>U"),
    ];
    let f = failures("qmk sym_defer_pk", &vectors);
    assert!(f.is_empty(), "{}", f.join("\n"));
}

#[test]
fn qmk_sym_eager_pk_passes_qmk_s_own_test_vectors() {
    let vectors = [
        ("OneKeyShort1", false, "0:D>D 1:U 5>U 6:D 10>D"),
        ("OneKeyShort2", false, "0:D>D 1:U 5>U 7:D 10>D"),
        ("OneKeyShort3", false, "0:D>D 1:U 5>U 8:D 10>D"),
        ("OneKeyShort4", false, "0:D>D 1:U 5>U 9:D 10>D"),
        ("OneKeyShort5", false, "0:D>D 1:U 5>U 10:D>D"),
        ("OneKeyShort6", false, "0:D>D 1:U 5>U 11:D>D"),
        (
            "OneKeyBouncing1",
            false,
            "0:D>D 1:U 2:D 3:U 4:D 5:U>U 6:D 10>D",
        ),
        (
            "OneKeyBouncing2",
            false,
            "0:D>D 1:U 1:D 2:U 2:D 2:U 3:D 3:U 3:D 4:U 4:D 5:U>U 6:D 10>D",
        ),
        ("OneKeyLong", false, "0:D>D 25:U>U 50:D>D"),
        (
            "TwoKeysShort key 1",
            false,
            "0:D>D 1:U 2 3 5>U 6:D 7 9 10>D 12",
        ),
        (
            "TwoKeysShort key 2",
            false,
            "0 1 2:D>D 3:U 5 6 7>U 9:D 10 12>D",
        ),
        ("OneKeyDelayedScan1", true, "0:D>D 300:U>U"),
        ("OneKeyDelayedScan2", true, "0:D>D 300 300:U>U"),
        ("OneKeyDelayedScan3", true, "0:D>D 300 301:U>U"),
        ("OneKeyDelayedScan4", true, "0:D>D 50:U>U"),
        ("OneKeyDelayedScan5", true, "0:D>D 50 50:U>U"),
        ("OneKeyDelayedScan6", true, "0:D>D 50 51:U>U"),
    ];
    let f = failures("qmk sym_eager_pk", &vectors);
    assert!(f.is_empty(), "{}", f.join("\n"));
}

#[test]
fn qmk_asym_eager_defer_pk_passes_qmk_s_own_test_vectors() {
    let vectors = [
        ("OneKeyShort1", false, "0:D>D 1:U 5 10>U 11:D>D"),
        ("OneKeyShort2", false, "0:D>D 2:U 5 10>U 11:D>D"),
        ("OneKeyShort3", false, "0:D>D 3:U 5 10>U 11:D>D"),
        ("OneKeyShort4", false, "0:D>D 4:U 5 10>U 11:D>D"),
        ("OneKeyShort5", false, "0:D>D 5:U 10>U 11:D>D"),
        ("OneKeyShort6", false, "0:D>D 6:U 11>U 12:D>D"),
        ("OneKeyShort7", false, "0:D>D 7:U 12>U 13:D>D"),
        ("OneKeyShort8", false, "0:D>D 1:U 5 10>U 10:D>D"),
        ("OneKeyShort9", false, "0:D>D 1:U 5 10:D"),
        (
            "OneKeyBouncing1",
            false,
            "0:D>D 1:U 2:D 3:U 4:D 5:U 6:D 7:U 8:D 9:U 10:D 11:U 12:D 13:U 14:D 15:U 20>U 21:D>D",
        ),
        (
            "OneKeyBouncing2",
            false,
            "0:D>D 1:U 1:D 2:U 2:D 2:U 6:D 6:U 7:D 7:U 7:D 8:U 8:D 9:U 9:D 9:U 14>U 15:D>D",
        ),
        (
            "OneKeyLong",
            false,
            "0:D>D 25:U 30>U 50:D>D 75:U 80>U 100:D>D",
        ),
        (
            "TwoKeysShort key 1",
            false,
            "0:D>D 1 2:U 3 5 6 10>U 11:D>D 12",
        ),
        (
            "TwoKeysShort key 2",
            false,
            "0 1:D>D 2 3:U 5 6 10 11>U 12:D>D",
        ),
        ("OneKeyDelayedScan1", true, "0:D>D 300:U 305>U"),
        ("OneKeyDelayedScan2", true, "0:D>D 300:U 600>U"),
        ("OneKeyDelayedScan3", true, "0:D>D 300 301:U 306>U"),
        ("OneKeyDelayedScan4", true, "0:D>D 300 301:U 600>U"),
        ("OneKeyDelayedScan5", true, "0:D>D 5:U 300>U 300:D>D"),
        ("OneKeyDelayedScan6", true, "0:D>D 5:U 300>U 301:D>D"),
        ("OneKeyDelayedScan7", true, "0:D>D 5:U 300:D"),
        ("OneKeyDelayedScan8", true, "0:D>D 50 51:U 100>U"),
    ];
    let f = failures("qmk asym_eager_defer_pk", &vectors);
    assert!(f.is_empty(), "{}", f.join("\n"));
}

/// ZMK's rule in whole milliseconds, as its `zmk_debounce_update` states it: the scans (ms) at
/// which the state flips for the pin levels `pins`, one a scan, `period_ms` apart.
fn zmk_rule(pins: &[bool], period_ms: u32, threshold_ms: u32) -> Vec<u32> {
    let (mut pressed, mut counter, mut flips) = (false, 0_u32, Vec::new());
    for (i, &active) in pins.iter().enumerate() {
        let now = u32::try_from(i).unwrap_or(u32::MAX) * period_ms;
        if active == pressed {
            counter = counter.saturating_sub(period_ms);
        } else if counter < threshold_ms {
            counter += period_ms;
        } else {
            pressed = !pressed;
            counter = 0;
            flips.push(now);
        }
    }
    flips
}

fn zmk_ours(pins: &[bool], period_ms: u32) -> Vec<u32> {
    let period = f64::from(period_ms) * 1e-3;
    let row = peers(period)
        .into_iter()
        .find(|r| r.name == "zmk integrator")
        .unwrap_or_else(|| panic!("no zmk integrator"));
    let Sampling::Polled(mut d) = row.sampling else {
        panic!("the zmk integrator is polled")
    };
    d.reset(false);
    let mut flips = Vec::new();
    for (i, &pin) in pins.iter().enumerate() {
        let now = u32::try_from(i).unwrap_or(u32::MAX) * period_ms;
        if d.sample(f64::from(now) * 1e-3, pin).is_some() {
            flips.push(now);
        }
    }
    flips
}

#[test]
fn zmk_s_integrator_flips_at_zmk_s_scan_at_1_2_and_4_ms() {
    // Pressed from the first scan and held: counter 0, p, 2p, ... until it is at least 5 when
    // compared, then the flip: at 5 ms (1 ms scans), 6 ms (2 ms), 8 ms (4 ms).
    for (period, flip) in [(1, 5), (2, 6), (4, 8)] {
        assert_eq!(zmk_ours(&[true; 20], period), [flip], "{period} ms scans");
    }
    // One agreeing scan in the middle takes a period back off the counter (1 ms scans: 1, 2,
    // back to 1 at the third scan, which agrees, then 2, 3, 4, 5 at scans 3 to 6: flip at 7).
    let pins = [
        true, true, false, true, true, true, true, true, true, true, true,
    ];
    assert_eq!(zmk_ours(&pins, 1), [7]);
    // Random pins against the rule in whole milliseconds.
    let mut x: u64 = 0x2545_f491_4f6c_dd1d;
    for period in [1, 2, 4] {
        for _ in 0..2_000 {
            let pins: Vec<bool> = (0..60)
                .map(|_| {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    !x.is_multiple_of(3)
                })
                .collect();
            assert_eq!(
                zmk_ours(&pins, period),
                zmk_rule(&pins, period, 5),
                "{period} ms scans, pins {pins:?}"
            );
        }
    }
}

/// The edges (ms, pressed) `name` reports on a contact that changes at `changes` (ms; closed
/// after the first), sampled every millisecond on the millisecond.
fn timed(name: &str, changes: &[f64]) -> Vec<(u32, bool)> {
    let trace = bounce_table::commands::replay::Trace {
        closed_before: false,
        changes: changes.iter().map(|t| t * 1e-3).collect(),
    };
    let mut row = peers(1e-3)
        .into_iter()
        .find(|r| r.name == name)
        .unwrap_or_else(|| panic!("no peer {name}"));
    bounce_table::commands::replay::edges(&mut row.sampling, &trace, 0.0, 1e-3, 0.1)
        .into_iter()
        .map(|(t, closed)| {
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            let ms = (t * 1e3).round() as u32;
            (ms, closed)
        })
        .collect()
}

#[test]
fn bounce2_debouncr_and_gpio_keys_report_where_their_rules_say() {
    // Closed 0-3 ms, open 3-5, closed 5-20 (the press), open 20-21, closed 21-22, open from
    // 22 (the release).
    let tap = [0.0, 3.0, 5.0, 20.0, 21.0, 22.0];
    let want: [(&str, &[(u32, bool)]); 6] = [
        // Bounce2's default: a reading held for the interval (10 ms) since the last change.
        ("bounce2 stable", &[(15, true), (32, false)]),
        // Bounce2's BOUNCE_LOCK_OUT: at once, then nothing for the interval.
        ("bounce2 lock-out", &[(0, true), (20, false)]),
        // debouncr: four (eight) equal samples in a row.
        ("debouncr 4 samples", &[(8, true), (25, false)]),
        ("debouncr 8 samples", &[(12, true), (29, false)]),
        // gpio-keys: each edge restarts the timer; at its end the pin is read. Zephyr's 30 ms
        // never expires while the tap lasts, and at its end the pin reads open again.
        ("linux gpio-keys", &[(10, true), (27, false)]),
        ("zephyr gpio-keys", &[]),
    ];
    for (name, edges) in want {
        assert_eq!(timed(name, &tap), edges, "{name}");
    }
}

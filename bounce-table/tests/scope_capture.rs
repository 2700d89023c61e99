//! Analog captures: the scope exports of `tests/fixtures/scope/` (written by
//! `scripts/scope-fixtures.py` from a synthetic switch behind a pull-up and an RC, with noise)
//! read into the level changes an input sees, against the changes solved on the exact
//! exponentials (`expected.json`); `calibrate` on a Rigol export against the same transitions
//! given as `time,level` rows; thresholds that change what a marginal dip is; and bad files.

use std::process::Command;

use bounce_table::capture::scope::{self, Input, Vendor};
use bounce_table::capture::Polarity;
use serde_json::Value;

fn dir() -> String {
    format!("{}/tests/fixtures/scope", env!("CARGO_MANIFEST_DIR"))
}

fn fixture(name: &str) -> String {
    let path = format!("{}/{name}", dir());
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Reads an export through `input`, recognised by its header, the contact closed when low.
fn read(
    name: &str,
    text: &str,
    channel: Option<&str>,
    input: &Input,
) -> Result<(Vec<bounce_table::capture::Stream>, scope::Report), bounce_table::capture::CaptureError>
{
    scope::load(name, text, None, channel, input, Polarity::ActiveLow)
}

fn expected() -> Value {
    serde_json::from_str(&fixture("expected.json")).unwrap()
}

/// The changes of one acquisition in `expected.json`, at thresholds `which`.
fn changes(e: &Value, which: &str) -> (Vec<f64>, u64) {
    let t = &e[which];
    (
        t["changes"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect(),
        t["marginal"].as_u64().unwrap(),
    )
}

/// The input of `which` (`swing` or `atmega328p`).
fn input(which: &str) -> Input {
    match which {
        "swing" => Input::Swing,
        name => Input::Preset(scope::preset(name).unwrap(), Some(5.0)),
    }
}

/// Reads `name` and checks each acquisition's changes against `expected` within one sample
/// interval (the crossing is interpolated between two samples; the 0.1 us fall of a closing
/// contact lies inside one), the same count of changes and of marginal dips, and the level
/// before the first change.
fn check(name: &str, vendor: Vendor, channel: Option<&str>, expected: &[Value]) {
    let e = self::expected();
    let step = e["step"].as_f64().unwrap();
    let text = fixture(name);
    assert_eq!(scope::recognise(&text), Some(vendor), "{name}");
    for which in ["swing", "atmega328p"] {
        let (streams, report) =
            read(name, &text, channel, &input(which)).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(report.vendor, vendor);
        assert_eq!(streams.len(), expected.len(), "{name}: acquisitions");
        let mut marginal = vec![0; expected.len()];
        for (a, _) in &report.marginal {
            marginal[*a] += 1;
        }
        for (k, (stream, e)) in streams.iter().zip(expected).enumerate() {
            let (want, dips) = changes(e, which);
            assert_eq!(
                stream.closed_before,
                e["closed_before"].as_bool().unwrap(),
                "{name} #{k}"
            );
            assert_eq!(
                stream.changes.len(),
                want.len(),
                "{name} #{k} {which}: {:?} vs {want:?}",
                stream.changes
            );
            for (got, want) in stream.changes.iter().zip(&want) {
                assert!(
                    (got - want).abs() <= step,
                    "{name} #{k} {which}: {got} vs {want}"
                );
            }
            assert_eq!(marginal[k], dips, "{name} #{k} {which}: marginal dips");
        }
    }
}

#[test]
fn every_vendors_export_gives_the_changes_of_the_exact_waveform() {
    let e = expected();
    check(
        "rigol.csv",
        Vendor::Rigol,
        None,
        e["rigol.csv"].as_array().unwrap(),
    );
    for (name, vendor, channel) in [
        ("siglent.csv", Vendor::Siglent, None),
        ("keysight.csv", Vendor::Keysight, Some("CH1")),
        ("tektronix.csv", Vendor::Tektronix, None),
        ("tektronix-mso.csv", Vendor::Tektronix, None),
        ("volts.csv", Vendor::Volts, None),
    ] {
        check(name, vendor, channel, std::slice::from_ref(&e[name]));
    }
}

#[test]
fn the_report_states_swing_noise_and_the_rcs_rise() {
    let (_, r) = read("rigol.csv", &fixture("rigol.csv"), None, &Input::Swing).unwrap();
    assert_eq!((r.acquisitions, r.samples), (20, 20 * 301));
    assert!((r.step - 5e-7).abs() < 1e-12, "{}", r.step);
    // The rails 0 and 5 V with 5 mV of noise; the percentiles sit within a few sigma.
    assert!(
        r.swing.low.abs() < 0.02 && (r.swing.high - 5.0).abs() < 0.02,
        "{r:?}"
    );
    assert!((0.004..0.006).contains(&r.swing.noise), "{}", r.swing.noise);
    // A 6 us RC rises from 10 % to 90 % in 6 us ln 9 = 13.2 us, to a sample.
    let rise = r.rise.unwrap();
    assert!((rise - 6e-6 * 9f64.ln()).abs() <= 5e-7, "{rise}");
    // The closing contact's 0.1 us fall lies within a sample or two.
    assert!(r.fall.unwrap() <= 1e-6, "{:?}", r.fall);
    let text = r.markdown();
    assert!(
        text.contains("rigol export, channel CH1: 20 acquisitions"),
        "{text}"
    );
}

#[test]
fn an_mcu_preset_and_thresholds_change_what_a_marginal_dip_is() {
    // A press whose contact opens once past both thresholds (two changes beside the first),
    // for 6.4 us (to 3.28 V) and for 3.5 us (to 2.2 V). With the default thresholds
    // (1.5 / 3.5 V) the last two are marginal dips: 3 changes; the ATmega328P at 5 V
    // (1.5 / 3.0 V) reads the first as a bounce (two more changes) and the second stays
    // marginal. --thresholds 1.5,3.0 is the same; 1.0,2.0 makes both bounces.
    let text = fixture("volts.csv");
    let run = |input: Input| {
        let (s, r) = read("volts.csv", &text, None, &input).unwrap();
        (s[0].changes.len(), r.marginal.len())
    };
    assert_eq!(run(Input::Swing), (5, 2));
    let atmega = scope::preset("atmega328p").unwrap();
    assert_eq!(run(Input::Preset(atmega, Some(5.0))), (7, 1));
    assert_eq!(run(Input::Volts(1.5, 3.0)), (7, 1));
    assert_eq!(run(Input::Volts(1.0, 2.0)), (9, 0));
    // Through the desk tool, the report says so.
    let report = |args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_bounce-table"))
            .arg("calibrate")
            .args(args)
            .arg(format!("{}/volts.csv", dir()))
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).unwrap()
    };
    assert!(report(&[]).contains("2 marginal dips"));
    let atmega = report(&["--input", "atmega328p", "--vcc", "5"]);
    assert!(atmega.contains("1 marginal dips"), "{atmega}");
    assert!(
        atmega.contains("--input atmega328p at 5 V (--vcc)"),
        "{atmega}"
    );
    assert!(report(&["--thresholds", "1,2"]).contains("No marginal dip"));
}

/// `calibrate --format c` on `file` with `args`: the windows as C.
fn windows(file: &str, args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_bounce-table"))
        .arg("calibrate")
        .args(["--format", "c"])
        .args(args)
        .arg(file)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn calibrate_on_a_rigol_export_gives_the_windows_of_its_transitions_as_levels() {
    // The Rigol export's 20 acquisitions, and the same transitions written as one `time,level`
    // stream (each acquisition a second after the last, the level carried across): the same
    // events, so the same windows, byte for byte.
    let rigol = format!("{}/rigol.csv", dir());
    let (streams, _) = read("rigol.csv", &fixture("rigol.csv"), None, &Input::Swing).unwrap();
    let mut rows = vec![format!(
        "0,{}",
        if streams[0].closed_before { 0 } else { 1 }
    )];
    let mut closed = streams[0].closed_before;
    for (k, s) in streams.iter().enumerate() {
        assert_eq!(
            s.closed_before, closed,
            "acquisition {k} starts where the last ended"
        );
        for t in &s.changes {
            closed = !closed;
            #[allow(clippy::cast_precision_loss)]
            rows.push(format!(
                "{:.12},{}",
                1.0 + k as f64 + t,
                if closed { 0 } else { 1 }
            ));
        }
    }
    let tmp = std::env::temp_dir().join(format!("scope-levels-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    let levels = tmp.join("rigol.csv");
    std::fs::write(&levels, rows.join("\n") + "\n").unwrap();
    // (The header names the file read; the windows are the #define lines.)
    let defines = |c: String| -> Vec<String> {
        c.lines()
            .filter(|l| l.starts_with("#define RIGOL"))
            .map(str::to_owned)
            .collect()
    };
    let from_scope = defines(windows(&rigol, &[]));
    let from_levels = defines(windows(
        levels.to_str().unwrap(),
        &["--capture-format", "csv"],
    ));
    assert_eq!(from_scope.len(), 2, "{from_scope:?}");
    assert_eq!(from_scope, from_levels);
    std::fs::remove_dir_all(&tmp).ok();
}

#[test]
fn a_folder_of_exports_is_one_switch() {
    let tmp = std::env::temp_dir().join(format!("scope-folder-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).unwrap();
    for name in ["siglent.csv", "tektronix.csv", "volts.csv"] {
        std::fs::write(tmp.join(name), fixture(name)).unwrap();
    }
    std::fs::write(tmp.join(".hidden"), "not a capture").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_bounce-table"))
        .args(["calibrate", "--format", "csv"])
        .arg(&tmp)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = String::from_utf8(out.stdout).unwrap();
    // A header and one press per file, each named by its file.
    assert_eq!(csv.lines().count(), 4, "{csv}");
    for name in ["siglent.csv", "tektronix.csv", "volts.csv"] {
        assert!(csv.contains(name), "{csv}");
    }
    std::fs::remove_dir_all(&tmp).ok();
}

#[test]
fn thresholds_inside_the_noise_chatter_and_hysteresis_does_not() {
    // 5 mV of noise on the 5 V rail: thresholds 2 mV apart around 5 V flip on the noise;
    // the default, 2 V apart, give the changes of the exact waveform.
    let text = fixture("siglent.csv");
    let count = |input: Input| {
        read("siglent.csv", &text, None, &input).unwrap().0[0]
            .changes
            .len()
    };
    let exact = changes(&expected()["siglent.csv"], "swing").0.len();
    assert_eq!(count(Input::Swing), exact);
    let noisy = count(Input::Volts(4.999, 5.001));
    assert!(noisy > exact + 10, "{noisy} changes, {exact} without noise");
}

#[test]
fn bad_exports_are_refused_with_file_and_line() {
    let cases: Vec<(String, Option<Vendor>, Option<&str>, &str)> = vec![
        (
            fixture("rigol.csv").replacen("5.000000e-07", "0", 1),
            None,
            None,
            "rigol.csv:2: the increment 0 s is not a positive time",
        ),
        (
            fixture("rigol.csv").replacen("\n7,", "\n7,abc\n8,", 1),
            None,
            None,
            "rigol.csv:10: expected numbers (time, volts), found \"7,abc\"",
        ),
        (
            fixture("siglent.csv").replacen("Second,Volt", "Seconds,Volt", 1),
            Some(Vendor::Siglent),
            None,
            "siglent.csv:6: a data row before the column header",
        ),
        (
            fixture("keysight.csv"),
            None,
            None,
            "keysight.csv:1: several channels (1, 2): say --channel",
        ),
        (
            fixture("keysight.csv"),
            None,
            Some("CH3"),
            "keysight.csv:1: no channel \"CH3\" (the channels: 1, 2)",
        ),
        (
            "time,volts\n0,1\n1e-6,2\n0.5e-6,3\n".to_owned(),
            None,
            None,
            "volts.csv:4: time 0.0000005 s does not follow",
        ),
        (
            "time,volts\n0,2.5\n1e-6,2.5\n2e-6,2.5\n".to_owned(),
            None,
            None,
            "volts.csv: the trace never swings",
        ),
        (
            "X,CH1,Start,Increment,\nSequence,Volt,0,1e-6,\n0,1,\n".to_owned(),
            None,
            None,
            "volts.csv:1: an acquisition needs at least two samples",
        ),
    ];
    for (text, vendor, channel, want) in cases {
        let name = want.split(':').next().unwrap();
        let e = scope::load(
            name,
            &text,
            vendor,
            channel,
            &Input::Swing,
            Polarity::ActiveLow,
        )
        .unwrap_err();
        assert!(e.to_string().starts_with(want), "{e} (wanted {want})");
    }
    // Thresholds the trace never reaches.
    let e = read(
        "volts.csv",
        &fixture("volts.csv"),
        None,
        &Input::Volts(6.0, 7.0),
    )
    .unwrap_err();
    assert!(e.to_string().contains("the input never changes"), "{e}");
    // Through the desk tool: an unknown MCU, a bad pair, --vcc without --input.
    for (args, want) in [
        (&["--input", "pic16"][..], "not one of atmega328p, rp2040"),
        (&["--thresholds", "3,1"], "3 is not below 1"),
        (&["--vcc", "5"], "--input"),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_bounce-table"))
            .arg("calibrate")
            .args(args)
            .arg(format!("{}/volts.csv", dir()))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(want), "{args:?}: {err}");
    }
}

#[test]
fn replay_reads_an_export_and_states_what_it_read() {
    let out = Command::new(env!("CARGO_BIN_EXE_bounce-table"))
        .args(["replay", "--input", "atmega328p", "--vcc", "5"])
        .arg(format!("{}/rigol.csv", dir()))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("## Analog capture"), "{text}");
    assert!(text.contains("--input atmega328p at 5 V"), "{text}");
    // The later half of each kind is replayed: 5 presses and 5 releases.
    assert!(
        text.contains("| rigol | press | calibrated hold-off |"),
        "{text}"
    );
    assert!(
        text.contains("| rigol | release | calibrated hold-off |"),
        "{text}"
    );
}

#[test]
fn exports_appended_one_after_the_other_are_several_acquisitions() {
    // Every layout's header starts a new acquisition wherever it comes again: two exports of
    // the same press appended give that press twice.
    for (name, channel) in [
        ("siglent.csv", None),
        ("keysight.csv", Some("1")),
        ("tektronix.csv", None),
        ("tektronix-mso.csv", None),
        ("volts.csv", None),
    ] {
        let one = fixture(name);
        let two = format!("{one}{one}");
        let read = |text: &str| {
            read(name, text, channel, &Input::Swing)
                .unwrap_or_else(|e| panic!("{e}"))
                .0
        };
        let (single, double) = (read(&one), read(&two));
        assert_eq!(single.len(), 1, "{name}");
        assert_eq!(double.len(), 2, "{name}");
        assert_eq!(double[0], single[0], "{name}");
        assert_eq!(double[1], single[0], "{name}");
    }
}

//! The desk tool's parsers under a seeded random harness: scene files (TOML, JSON, JSON
//! Lines), `eval`'s lines, captures (JSON Lines, CSV, VCD) and the options of every
//! subcommand, each input a valid seed mutated one to three times (bytes flipped, inserted or
//! cut, lines repeated or swapped, numbers replaced by edge literals, keys repeated or
//! renamed, text truncated).
//!
//! Checked for every input: no panic; a refusal says where (the file, and the line or entry
//! it can name) and what, in one line; what is accepted is usable: its scenes analyse to
//! finite, positive bounces and windows that cover them (or a typed refusal), its captures
//! to events whose times are finite and in order, which then describe, fit and report without
//! a fault. `FUZZ_PARSERS` inputs per parser (default 2,000, ten times as many option lists;
//! `scripts/fuzz.sh` runs more). Each test prints a `fuzz-summary` line for that report.

use std::panic::{catch_unwind, AssertUnwindSafe};

use bounce_table::capture::{read_csv, read_jsonl, read_vcd, CaptureError, Event, Polarity};
use bounce_table::cli::{self, Invocation};
use bounce_table::scene::file::read;
use bounce_table::stats::analysis::{analyse, Settings};

fn cases() -> usize {
    std::env::var("FUZZ_PARSERS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2_000)
}

/// xorshift64*, seeded: a run is reproducible.
struct Rng(u64);

impl Rng {
    /// The stream `base`, moved by `FUZZ_SEED` when it is set and not 0 (a long run explores
    /// new inputs; CI and the default run keep `base`, so they are reproducible).
    fn seeded(base: u64) -> Self {
        let moved = std::env::var("FUZZ_SEED")
            .ok()
            .and_then(|v| v.parse::<u64>().ok())
            .filter(|s| *s != 0)
            .map_or(base, |s| base ^ s.wrapping_mul(0x9E37_79B9_7F4A_7C15));
        // xorshift never leaves 0.
        Self(if moved == 0 { base } else { moved })
    }
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: usize) -> usize {
        usize::try_from(self.next() % u64::try_from(n.max(1)).unwrap_or(1)).unwrap_or(0)
    }
    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[self.below(items.len())]
    }
}

/// Literals that sit at the edges of what a number, a key or a value can be.
const EDGES: &[&str] = &[
    "0",
    "-0",
    "-1",
    "1e-400",
    "1e400",
    "1e308",
    "4.9e-324",
    "5e-324",
    "1e-0000400",
    "nan",
    "inf",
    "-inf",
    "NaN",
    "1e30",
    "-1e30",
    "0.99999999999999",
    "1",
    "2",
    "18446744073709551616",
    "1.0e",
    "--1",
    "\"x\"",
    "\"\"",
    "null",
    "true",
    "[]",
    "{}",
    "[1,",
    "{\"min\": 1, \"max\": 0}",
    "{\"value\": 1, \"spread\": 2}",
    "{\"min\": 0, \"max\": 1e300}",
    "{\"value\": 1e-300, \"spread\": 0.5}",
    "\"\\u0000\"",
    "\"a\nb\"",
    "é",
    "\u{feff}",
    ",",
    ":",
    "\"name\": \"dup\",",
    "\"gap\": 1e-3,",
    "\"two_body\": {},",
    "\"kernel\": {\"kappa\": 1, \"tau\": 0},",
    "#",
    "$end",
    "x",
    "z",
    "b101 !",
    "1!",
    "0!",
    "#-5",
    "#99999999999999999999",
    "$var wire 2 ! sw $end",
    "$timescale 1 fs $end",
    "0.1,2",
    "0.1",
    ",,",
    "-0.5,0",
    "1e9,1",
];

/// A valid seed mutated one to three times.
fn mutate(rng: &mut Rng, seed: &str) -> String {
    let mut text = seed.to_owned();
    for _ in 0..=rng.below(3) {
        let bytes = text.as_bytes().to_vec();
        let at = rng.below(bytes.len() + 1);
        text = match rng.below(8) {
            // A byte flipped to a random printable or control one.
            0 if !bytes.is_empty() => {
                let mut b = bytes;
                let i = rng.below(b.len());
                b[i] = u8::try_from(rng.below(128)).unwrap_or(b' ');
                String::from_utf8_lossy(&b).into_owned()
            }
            // An edge literal inserted.
            1 => {
                let mut b = bytes;
                b.splice(at..at, rng.pick(EDGES).bytes());
                String::from_utf8_lossy(&b).into_owned()
            }
            // A range cut.
            2 if !bytes.is_empty() => {
                let mut b = bytes;
                let end = (at + 1 + rng.below(12)).min(b.len());
                let start = at.min(end);
                b.drain(start..end);
                String::from_utf8_lossy(&b).into_owned()
            }
            // A number literal replaced by an edge literal.
            3 => replace_number(rng, &text),
            // A line repeated (a duplicate key in TOML, a duplicate entry elsewhere).
            4 => {
                let mut lines: Vec<&str> = text.lines().collect();
                if !lines.is_empty() {
                    let i = rng.below(lines.len());
                    lines.insert(i, lines[i]);
                }
                lines.join("\n")
            }
            // Two lines swapped (times out of order, a header after its data).
            5 => {
                let mut lines: Vec<&str> = text.lines().collect();
                if lines.len() > 1 {
                    let (i, j) = (rng.below(lines.len()), rng.below(lines.len()));
                    lines.swap(i, j);
                }
                lines.join("\n")
            }
            // Truncated.
            6 => String::from_utf8_lossy(&bytes[..at]).into_owned(),
            // A key given twice in one object.
            _ => text.replacen('{', &format!("{{{} ", rng.pick(EDGES)), 1),
        };
    }
    text
}

fn replace_number(rng: &mut Rng, text: &str) -> String {
    let b = text.as_bytes();
    let starts: Vec<usize> = (0..b.len())
        .filter(|&i| b[i].is_ascii_digit() && (i == 0 || !b[i - 1].is_ascii_alphanumeric()))
        .collect();
    if starts.is_empty() {
        return text.to_owned();
    }
    let start = starts[rng.below(starts.len())];
    let end = (start..b.len())
        .find(|&i| !matches!(b[i], b'0'..=b'9' | b'.' | b'e' | b'E' | b'-' | b'+'))
        .unwrap_or(b.len());
    format!("{}{}{}", &text[..start], rng.pick(EDGES), &text[end..])
}

fn one_line(message: &str, what: &str) {
    assert!(!message.trim().is_empty(), "{what}: an empty message");
    assert!(
        !message.contains('\n'),
        "{what}: a message of several lines: {message}"
    );
}

/// A run of `f` that must not panic; the input is printed if it does.
fn no_panic<T>(what: &str, input: &str, f: impl FnOnce() -> T) -> T {
    catch_unwind(AssertUnwindSafe(f))
        .unwrap_or_else(|_| panic!("{what} panicked on this input:\n{input}"))
}

/// The line `scripts/fuzz.sh` collects: a fault is an assertion (the run fails), so the
/// fault columns are zero whenever the line is printed.
fn summary(harness: &str, inputs: usize, checked: usize) {
    println!(
        "fuzz-summary harness={harness} inputs={inputs} checked={checked} nan=0 inconsistent=0"
    );
}

fn settings() -> Settings {
    Settings {
        samples: 16,
        threads: 1,
        progress: false,
        ..Settings::default()
    }
}

#[test]
fn scene_files_are_read_or_refused_by_place() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("bounce-table-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let example =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/example.toml"))
            .expect("example");
    let catalogue = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/catalogue.jsonl"
    ))
    .expect("catalogue");
    let json = format!(
        "{{\"switch\": [{}]}}",
        catalogue.lines().take(3).collect::<Vec<_>>().join(",\n")
    );
    let seeds = [
        ("toml", example.as_str()),
        ("jsonl", catalogue.as_str()),
        ("json", json.as_str()),
    ];
    let mut rng = Rng::seeded(0x5EED_0F5C_E7E5);
    let (mut accepted, mut refused, mut analysed) = (0, 0, 0);
    for i in 0..cases() {
        let (ext, seed) = seeds[i % seeds.len()];
        let text = mutate(&mut rng, seed);
        let path = dir.join(format!("case.{ext}"));
        std::fs::write(&path, &text).expect("write");
        let path = path.to_str().expect("utf8").to_owned();
        match no_panic("scenes::read", &text, || read(&path)) {
            Ok(entries) => {
                accepted += 1;
                assert!(!entries.is_empty(), "accepted with no entry:\n{text}");
                for e in entries.iter().take(3) {
                    match no_panic("analyse", &text, || {
                        analyse(&e.name, &e.template, &settings())
                    }) {
                        Ok(a) => {
                            analysed += 1;
                            let b = a.nominal.bounce;
                            assert!(b.is_finite() && b >= 0.0, "bounce {b}:\n{text}");
                            assert!(
                                a.window >= b * (1.0 - 1e-12) && !a.window.is_nan(),
                                "window {} below bounce {b}:\n{text}",
                                a.window
                            );
                        }
                        Err(e) => one_line(&e.message, "analyse"),
                    }
                }
            }
            Err(errors) => {
                refused += 1;
                assert!(!errors.is_empty(), "refused with no reason:\n{text}");
                for e in errors {
                    assert_eq!(e.file, path, "{e}");
                    one_line(&e.to_string(), "scenes::read");
                }
            }
        }
    }
    println!(
        "scene files: {} inputs, {accepted} accepted ({analysed} analysed), {refused} refused",
        cases()
    );
    summary("scene-files", cases(), analysed + refused);
    assert!(
        accepted > 0 && refused > 0,
        "the mutations reach both sides"
    );
    // Kept when an assertion fails, to look at; removed when the test passes.
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn eval_lines_evaluate_or_are_refused() {
    let catalogue = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/catalogue.jsonl"
    ))
    .expect("catalogue");
    let lines: Vec<&str> = catalogue.lines().collect();
    let mut rng = Rng::seeded(0xE7A1);
    let (mut ok, mut refused) = (0, 0);
    for i in 0..cases() {
        let line = mutate(&mut rng, lines[i % lines.len()]).replace('\n', " ");
        for method in ["closed", "map", "auto", "reference"] {
            for precision in ["f32", "f64"] {
                let Ok(Invocation::Eval(options)) =
                    cli::parse(["eval", "--method", method, "--precision", precision])
                else {
                    panic!("valid options")
                };
                match no_panic("eval", &line, || {
                    bounce_table::commands::eval::evaluate(&line, 1, &options)
                }) {
                    Ok(v) => {
                        ok += 1;
                        assert!(v.is_object(), "{v}");
                    }
                    Err((_, e)) => {
                        refused += 1;
                        one_line(&e.message, "eval");
                    }
                }
            }
        }
    }
    println!(
        "eval lines: {} inputs, {ok} evaluations, {refused} refusals",
        cases()
    );
    summary("eval-lines", cases(), ok + refused);
    assert!(ok > 0 && refused > 0);
}

const JSONL_CAPTURE: &str = r#"{"dataset":"d","test":1,"kind":"press","section":"Normal","section_invalid":false,"events":[[0,1],[812,0],[5000,1],[9000,0]]}
{"dataset":"d","test":1,"kind":"release","section":"Normal","section_invalid":false,"events":[[0,0],[812,1],[4000,0],[4100,1]]}
{"dataset":"d","test":2,"kind":"press","section":"Slow","section_invalid":true,"events":[[0,1],[812,0]]}
{"dataset":"d","test":3,"kind":"press","section":"Normal","section_invalid":false,"events":[[0,1],[812,0],[20000,1],[20500,0],[9000000,1],[9000100,0]]}"#;

fn check_events(what: &str, input: &str, events: &[Event]) {
    for e in events {
        assert!(
            e.changes.iter().all(|t| t.is_finite()),
            "{what}: a time not finite:\n{input}"
        );
        assert!(
            e.changes.windows(2).all(|w| w[0] <= w[1]),
            "{what}: times out of order:\n{input}"
        );
    }
    // What was read describes, fits and reports.
    no_panic("calibrate", input, || {
        let groups = bounce_table::stats::group(events, 3e-6, 5e-3);
        let _ = bounce_table::commands::calibrate::describe(&groups, 3e-6);
        let _ = bounce_table::commands::calibrate::summary(&groups, 99.0, 5e-3, None);
        let _ = bounce_table::commands::calibrate::summary(&groups, 99.0, 5e-3, Some(31e-3));
    });
}

fn check_refusal(what: &str, input: &str, name: &str, e: &CaptureError) {
    assert_eq!(e.file, name, "{what}: {e}");
    assert!(
        e.line <= input.lines().count().max(1),
        "{what}: line {} of {}",
        e.line,
        input.lines().count()
    );
    one_line(&e.to_string(), what);
}

#[test]
fn captures_are_read_or_refused_by_line() {
    let csv = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/button.csv"
    ))
    .expect("csv");
    let vcd = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/button.vcd"
    ))
    .expect("vcd");
    let scope_fixture = |name: &str| {
        std::fs::read_to_string(format!(
            "{}/tests/fixtures/scope/{name}",
            env!("CARGO_MANIFEST_DIR")
        ))
        .expect("scope fixture")
    };
    let (siglent, keysight, tektronix) = (
        scope_fixture("siglent.csv"),
        scope_fixture("keysight.csv"),
        scope_fixture("tektronix.csv"),
    );
    let mut rng = Rng::seeded(0x00CA_970E);
    let (mut accepted, mut refused) = (0, 0);
    for i in 0..cases() {
        let (kind, seed) = [
            ("jsonl", JSONL_CAPTURE),
            ("csv", csv.as_str()),
            ("vcd", vcd.as_str()),
            ("siglent", siglent.as_str()),
            ("keysight", keysight.as_str()),
            ("tektronix", tektronix.as_str()),
        ][i % 6];
        let text = mutate(&mut rng, seed);
        let name = format!("capture.{kind}");
        let read = no_panic(kind, &text, || match kind {
            "jsonl" => read_jsonl(&name, &text, &[]).map(|(events, _)| events),
            "csv" => read_csv(&name, &text, Polarity::ActiveLow).map(|s| s.segment(&name, 0.2)),
            "vcd" => {
                read_vcd(&name, &text, None, Polarity::ActiveLow).map(|s| s.segment(&name, 0.2))
            }
            // A scope's export, recognised by its header (or refused), through the default
            // thresholds; the Keysight file's first channel.
            _ => {
                let channel = (kind == "keysight").then_some("1");
                let input = bounce_table::capture::scope::Input::Swing;
                bounce_table::capture::scope::load(
                    &name,
                    &text,
                    None,
                    channel,
                    &input,
                    Polarity::ActiveLow,
                )
                .map(|(streams, _)| streams.iter().flat_map(|s| s.segment(&name, 0.2)).collect())
            }
        });
        match read {
            Ok(events) => {
                accepted += 1;
                check_events(kind, &text, &events);
            }
            Err(e) => {
                refused += 1;
                check_refusal(kind, &text, &name, &e);
            }
        }
    }
    println!(
        "captures: {} inputs, {accepted} accepted, {refused} refused",
        cases()
    );
    summary("captures", cases(), accepted + refused);
    assert!(accepted > 0 && refused > 0);
}

#[test]
fn options_of_every_subcommand_parse_or_are_refused_in_one_line() {
    const WORDS: &[&str] = &[
        "--period",
        "--sample-period",
        "--tolerance",
        "--margin",
        "--percentile",
        "--samples",
        "--seed",
        "--threads",
        "--format",
        "--output",
        "--plot",
        "--method",
        "--precision",
        "--nodes",
        "--split",
        "--time-scale",
        "--switch-type",
        "--capture-format",
        "--resolution",
        "--burst-gap",
        "--quiet",
        "--event-gap",
        "--signal",
        "--active-high",
        "--skip-section",
        "--channel",
        "--input",
        "--thresholds",
        "--thresholds=1,2",
        "--vcc",
        "atmega328p",
        "rigol",
        "--export",
        "--events",
        "--contact-models",
        "--period=1e-3",
        "--format=csv",
        "--x",
        "-",
        "--",
        "=",
        "table",
        "json",
        "markdown",
        "csv",
        "c",
        "rust",
        "curve",
        "auto",
        "exact",
        "f32",
        "f64",
        "push-button",
        "8",
        "1e-4",
        "0.5",
        "1.5",
        "99",
        "100",
        "101",
        "0",
        "-1",
        "nan",
        "inf",
        "1e400",
        "18446744073709551616",
        "4096",
        "",
        "file.toml",
        "capture.jsonl",
        "--x\ny",
        "a\u{1b}[31m",
        "--format=\r",
    ];
    let mut rng = Rng::seeded(0x0097_10A5);
    let mut parsed = 0;
    for _ in 0..cases() * 10 {
        let args: Vec<String> = (0..rng.below(7))
            .map(|_| rng.pick(WORDS).to_owned())
            .collect();
        let input = format!("{args:?}");
        // The table mode's arguments, and each subcommand's.
        let results = no_panic("options", &input, || {
            [None, Some("eval"), Some("replay"), Some("calibrate")].map(|sub| {
                let line = sub
                    .map(str::to_owned)
                    .into_iter()
                    .chain(args.iter().cloned());
                cli::parse(line).map(|invocation| {
                    if let Invocation::Table(o) = invocation {
                        let s = o.settings;
                        assert!(s.period.is_finite() && s.period > 0.0, "{input}");
                        assert!(s.margin >= 1.0 && s.margin.is_finite(), "{input}");
                        assert!(s.percentile > 0.0 && s.percentile <= 100.0, "{input}");
                        assert!((1..=1024).contains(&s.threads), "{input}");
                    }
                })
            })
        });
        for r in results {
            match r {
                Ok(()) => parsed += 1,
                Err(refusal) => one_line(&refusal.message, &input),
            }
        }
    }
    println!("options: {} argument lists, {parsed} parsed", cases() * 10);
    summary("options", cases() * 10, cases() * 40);
    assert!(parsed > 0);
}

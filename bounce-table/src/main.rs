//! `bounce-table`: debounce windows for switches, from physics.
//!
//! ```text
//! bounce-table [OPTIONS] [SCENE_FILE]      the catalogue of typical switches, or your switches
//! bounce-table eval [OPTIONS] < scenes.jsonl
//! bounce-table calibrate [OPTIONS] CAPTURE   describe a capture of a real switch
//! ```

use std::process::ExitCode;

use bounce_table::cli::parse;
use bounce_table::output::{clash, identifier, render_to};
use bounce_table::scenes::{open, Entries};
use bounce_table::strict::printable;
use bounce_table::{calibrate, eval, plot, replay, table};

/// Writes to standard output. A reader that stopped early (`bounce-table ... | head`) ends the
/// run quietly with success, as it does for other command-line tools; any other failure to
/// write is an error (exit status 1), never a panic.
fn emit(text: &str) {
    use std::io::Write;
    let mut stdout = std::io::stdout().lock();
    if let Err(e) = stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            std::process::exit(0);
        }
        eprintln!("bounce-table: standard output: {e}");
        std::process::exit(1);
    }
}

/// `print!` through [`emit`].
macro_rules! out {
    ($($arg:tt)*) => { emit(&format!($($arg)*)) };
}

/// `println!` through [`emit`].
macro_rules! outln {
    ($($arg:tt)*) => { emit(&format!("{}\n", format!($($arg)*))) };
}

const SYNOPSIS: &str = "usage: bounce-table [OPTIONS] [SCENE_FILE]
       bounce-table eval [--method exact|exact-tier|map|averaged|closed|auto] [--tolerance X]
                         [--precision f32|f64] [--nodes N] [scenes.jsonl, else stdin]
       bounce-table replay [--period S] [--split F] [--time-scale X] [--switch-type TYPE]
                           [--format table|markdown|json|curve] [--plot DIR]
                           [--capture-format jsonl|csv|vcd] [calibrate's capture options] CAPTURE
       bounce-table calibrate [--format report|c|rust|csv] [--output FILE]
                              [--capture-format jsonl|csv|vcd] [--resolution S] [--burst-gap S]
                              [--quiet S] [--signal NAME] [--active-high]
                              [--skip-section NAME]
                              [--percentile P] [--seed N] [--plot DIR]
                              [--contact-models] CAPTURE";

/// The table mode's help (scene files, keys, options).
const TABLE_HELP: &str = "Prints predicted bounce and debounce windows: for the built-in catalogue of typical switches
(assumed values over assumed ranges, not a datasheet; windows the P99.9 over the ranges), or for the switches of SCENE_FILE
(.toml with [[switch]] tables, .json, or .jsonl; the keys of `eval`, and any number may be a
range: {min = a, max = b} or {value = x, spread = s}).

Scene keys (SI units; where to get each: docs/parameters.md in the repository):
  omega, or mass and stiffness    the natural frequency sqrt(stiffness / mass) (rad/s; kg, N/m)
  gap or preload_force            where the stop is: gap > 0 m, the contacts apart at rest;
                                  preload_force > 0 N, the spring presses them together
                                  (Delta = -preload_force / stiffness < 0)
  restitution                     R, the share of speed an impact keeps, in (0, 1]
  closing_speed                   the speed at first contact (m/s)
  damping_ratio                   viscous zeta (0 when absent)
  threshold_impulse, threshold_fraction
                                  where an endless bounce counts as ended
  kernel = {kappa, tau, state}, two_body = {m1, c1, d1, m2, c2, d2, x2, v2}
                                  a relaxation kernel; two bodies (the paper's Eq. 1)

Options (every subcommand also takes -h/--help, -V/--version, and --option=value):
  --period SECONDS     tick period of the windows (default 1e-4)
  --format FORMAT      table, markdown, csv, json, c (a header) or rust (constants)
  --output FILE        write there, completely or not at all (default: standard output)
  --tolerance X        relative error asked of the model, else the exact reference (0.1)
  --percentile P       percentile of the Monte Carlo window with ranges (99.9)
  --margin F           safety factor on every window, at least 1 (1: none; 1.5 for +50 %)
  --samples N          Monte Carlo samples (4000; at most 1e8)
  --seed S             Monte Carlo seed (1)
  --threads N          worker threads (all cores; at most 1024)
  --plot DIR           also write NAME-envelope.svg and NAME-motion.svg for each switch";

/// `eval`'s help.
const EVAL_HELP: &str = "eval: JSON Lines scenes (the scene keys of `bounce-table --help`; a file, else standard
input), one JSON result a line on standard output: the regime, the end of the bounce, the last impact above the threshold,
impact counts and the tier's expected error. A bad line gets an error object naming the line
and the field; the other lines still run, and the exit status is 1 if any line failed.
  --method M           exact (the host's exact reference), exact-tier (the core's exact tier),
                       map, averaged, closed or auto (auto)
  --tolerance X        the relative error auto must promise (0.01)
  --precision P        f32 or f64, for the core's tiers (f64)
  --nodes N            Gauss-Legendre nodes per panel of the averaged tier (8)";

/// `replay`'s help.
const REPLAY_HELP: &str =
    "replay: the benchmark of debouncers on a real capture. Per switch and kind, the earlier tests
(--split, 0.5) calibrate and the later ones are replayed through our debouncer with the
calibrated windows (hold-off and confirm), with the switch type's prior window (physics-prior:
the type from the switch's name or --switch-type), with the learning debouncer (learned: from
that prior, it learns online through every test of the switch in capture order and is scored on
the later ones), and through peers re-implemented from their documentation at their defaults
(QMK, ZMK, Bounce2, debouncr, Linux and Zephyr gpio-keys). Rows: false edges (reported edges
beyond each test's one) and latency P50/P99 from the first contact change.
  --format curve       instead, the learner's window and false edges after every test (CSV)
  --period S           seconds between samples of the polled debouncers (1e-3)
  --split F            the earlier share of the tests that calibrates (0.5)
  --time-scale X       every time multiplied by X (10: contactor-like, 0.1: reed-like)
  --switch-type TYPE   push-button, rocker, toggle, slide, tactile or hand-operated
  --plot DIR           also write SWITCH-KIND-replay.svg: false edges against latency";

/// `calibrate`'s help.
const CALIBRATE_HELP: &str =
    "calibrate: describes a capture (JSON Lines of the bouncy-button format, a CSV of `time,level`
rows, or a VCD; format from the extension) per switch and kind (bounce P50/P90/P99/max,
transitions, resolved flights and dwells, chatter), fits the impact model and a bounce model
with empirical terms (clean share, log-normal bursts, late bursts), checks them and the
empirical quantiles on held-out halves, and recommends windows. High = open unless
--active-high.
  --resolution S       intervals shorter than S are chatter, not timed (3e-6)
  --burst-gap S        a quiet interval of S ends a burst; later bursts are late bounce (5e-3)
  --quiet S            in CSV/VCD streams, a gap longer than S starts a new event (0.2)
  --signal NAME        the VCD signal (default: the only 1-bit one)
  --skip-section NAME  leave out a JSON Lines section (repeatable)
  --percentile P       the windows' percentile of the bounce (99)
  --seed N             the random held-out split's seed (1)
  --format F           report (default); c or rust: only the windows, as #defines or Rust
                       constants (ns); csv: each event's description, one row per event
  --output FILE        write there, completely or not at all (default: standard output)
  --capture-format F   jsonl, csv or vcd (default: from the file's extension)
  --contact-models     also fit the two-body and compliant-contact models to each switch's
                       presses and check them on held-out halves (about a minute)
  --plot DIR           also write SWITCH-KIND.svg: observed bounce distribution vs the models";

/// The help `--help` prints: everything for the table mode, one subcommand's for a subcommand.
fn help(subcommand: Option<&str>) -> String {
    let synopsis: Vec<&str> = SYNOPSIS.lines().collect();
    let pick = |from: usize, to: usize, text: &str| {
        let mut lines: Vec<String> = synopsis
            .get(from..to)
            .unwrap_or_default()
            .iter()
            .map(|l| l.trim_start().to_owned())
            .collect();
        for l in lines.iter_mut().skip(1) {
            *l = format!("       {l}");
        }
        format!("usage: {}\n\n{text}", lines.join("\n"))
    };
    match subcommand {
        Some("eval") => pick(1, 3, EVAL_HELP),
        Some("replay") => pick(3, 6, REPLAY_HELP),
        Some("calibrate") => pick(6, synopsis.len(), CALIBRATE_HELP),
        _ => format!(
            "{SYNOPSIS}\n\n{TABLE_HELP}\n\n{EVAL_HELP}\n\n{REPLAY_HELP}\n\n{CALIBRATE_HELP}"
        ),
    }
}

/// The scene file's entries (else the catalogue's); `None` when the file cannot be opened or
/// parsed as a whole (each fault reported).
fn open_entries(file: Option<&str>) -> Option<Entries> {
    match file {
        None => Some(Entries::catalogue()),
        Some(path) => open(path)
            .inspect_err(|errors| {
                for e in errors {
                    eprintln!("bounce-table: {e}");
                }
            })
            .ok(),
    }
}

/// Writes `text` to `path` completely or not at all (a temporary file, then a rename).
fn write_atomically(path: &str, text: &str) -> std::io::Result<()> {
    write_atomically_with(path, |w| w.write_all(text.as_bytes()))
}

/// Writes what `write` writes to `path` completely or not at all: into a temporary file beside
/// it, renamed over it once complete.
fn write_atomically_with(
    path: &str,
    write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let target = std::path::Path::new(path);
    let tmp = target.with_extension(format!("tmp-{}", std::process::id()));
    // A failed write (a full disk, an error while rendering) or rename leaves no temporary
    // file behind.
    std::fs::File::create(&tmp)
        .and_then(|file| {
            let mut w = std::io::BufWriter::new(file);
            write(&mut w)?;
            w.into_inner()
                .map_err(std::io::IntoInnerError::into_error)?
                .sync_all()
        })
        .and_then(|()| std::fs::rename(&tmp, target))
        .inspect_err(|_| {
            let _ = std::fs::remove_file(&tmp);
        })
}

/// `bounce-table replay`.
fn replay_main(args: &[String]) -> ExitCode {
    let request = match replay::options(args) {
        Ok(r) => r,
        Err(message) => {
            eprintln!(
                "bounce-table replay: {message}\n(bounce-table replay --help shows its usage)"
            );
            return ExitCode::from(2);
        }
    };
    let (events, skipped) = match calibrate::load(&request.capture) {
        Ok(x) => x,
        Err(e) => {
            eprintln!("bounce-table replay: {e}");
            return ExitCode::from(2);
        }
    };
    if request.output == replay::Output::Curve {
        return match replay::learning_curves(&events, &request.settings) {
            Ok(curves) => {
                out!("{}", replay::curve_csv(&curves));
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("bounce-table replay: {e}");
                ExitCode::from(2)
            }
        };
    }
    let lines = match replay::run(&events, &request.capture, &request.settings) {
        Ok(lines) => lines,
        Err(e) => {
            eprintln!("bounce-table replay: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(dir) = &request.plot {
        let mut groups: std::collections::BTreeMap<(&str, &str), Vec<&replay::Line>> =
            std::collections::BTreeMap::new();
        for l in &lines {
            groups
                .entry((l.switch.as_str(), l.kind.name()))
                .or_default()
                .push(l);
        }
        for ((switch, kind), group) in groups {
            let name = format!(
                "{dir}/{}-{kind}-replay.svg",
                identifier(switch).to_lowercase()
            );
            if let Err(e) = std::fs::create_dir_all(dir)
                .and_then(|()| write_atomically(&name, &replay::plot(&group)))
            {
                eprintln!("bounce-table replay: {name}: {e}");
                return ExitCode::FAILURE;
            }
        }
    }
    match request.output {
        replay::Output::Json => out!("{}", replay::json(&lines)),
        replay::Output::Curve => {}
        replay::Output::Markdown => {
            if skipped.total() > 0 {
                outln!("{}\n", skipped.describe(request.capture.quiet));
            }
            out!("{}", replay::markdown(&lines));
        }
    }
    ExitCode::SUCCESS
}

/// What an error adds after its message: where the usage is (not the whole usage).
const SEE_HELP: &str = "(bounce-table --help shows the usage)";

/// The arguments as given, with `--option=value` split into `--option value` (both forms are
/// accepted everywhere).
fn split_equals(args: impl Iterator<Item = String>) -> Vec<String> {
    let mut out = Vec::new();
    for arg in args {
        match arg.split_once('=') {
            Some((name, value)) if name.starts_with("--") && name.len() > 2 => {
                out.push(name.to_owned());
                out.push(value.to_owned());
            }
            _ => out.push(arg),
        }
    }
    out
}

fn main() -> ExitCode {
    let args = split_equals(std::env::args().skip(1));
    // Every subcommand takes --help and --version.
    if args.iter().any(|a| a == "--version" || a == "-V") {
        outln!("bounce-table {}", env!("CARGO_PKG_VERSION"));
        return ExitCode::SUCCESS;
    }
    if args.iter().any(|a| a == "--help" || a == "-h") {
        outln!("{}", help(args.first().map(String::as_str)));
        return ExitCode::SUCCESS;
    }
    if args.first().is_some_and(|a| a == "eval") {
        let options = match eval::options(args.get(1..).unwrap_or_default()) {
            Ok(o) => o,
            Err(message) => {
                eprintln!(
                    "bounce-table eval: {message}\n(bounce-table eval --help shows its usage)"
                );
                return ExitCode::from(2);
            }
        };
        let input = match eval::input(&options) {
            Ok(input) => input,
            Err(e) => {
                eprintln!("bounce-table eval: {e}");
                return ExitCode::from(2);
            }
        };
        return match eval::run(&options, input) {
            Ok(true) => ExitCode::SUCCESS,
            Ok(false) => ExitCode::FAILURE,
            Err(e) => {
                eprintln!("bounce-table eval: {e}");
                ExitCode::FAILURE
            }
        };
    }
    if args.first().is_some_and(|a| a == "replay") {
        return replay_main(args.get(1..).unwrap_or_default());
    }
    if args.first().is_some_and(|a| a == "calibrate") {
        let options = match calibrate::options(args.get(1..).unwrap_or_default()) {
            Ok(o) => o,
            Err(message) => {
                eprintln!("bounce-table calibrate: {message}\n(bounce-table calibrate --help shows its usage)");
                return ExitCode::from(2);
            }
        };
        if let Some(output) = &options.output {
            let same = std::fs::canonicalize(&options.file)
                .ok()
                .zip(std::fs::canonicalize(output).ok())
                .is_some_and(|(a, b)| a == b);
            if same {
                eprintln!(
                    "bounce-table calibrate: --output {} is the capture itself: refusing to overwrite it",
                    printable(output)
                );
                return ExitCode::from(2);
            }
        }
        let (events, skipped) = match calibrate::load(&options) {
            Ok(x) => x,
            Err(e) => {
                eprintln!("bounce-table calibrate: {e}");
                return ExitCode::from(2);
            }
        };
        let text = if options.events {
            calibrate::events_csv(&events, options.resolution, options.burst_gap)
        } else {
            let groups = calibrate::group(&events, options.resolution, options.burst_gap);
            if let Some(rust) = options.export {
                let names: Vec<String> = groups
                    .keys()
                    .map(|(switch, kind)| format!("{switch} {}", kind.name()))
                    .collect();
                if let Some((a, b, id)) = clash(names.iter().map(String::as_str)) {
                    eprintln!(
                        "bounce-table calibrate: {}: '{}' and '{}' both become {id} in generated code: rename a switch",
                        printable(&options.file),
                        printable(&a),
                        printable(&b)
                    );
                    return ExitCode::from(2);
                }
                let lang = if rust {
                    bounce_table::emit::Lang::Rust
                } else {
                    bounce_table::emit::Lang::C
                };
                match calibrate::export(&groups, options.percentile, lang, &options.file) {
                    Ok(text) => text,
                    Err(e) => {
                        eprintln!(
                            "bounce-table calibrate: {}: {}",
                            printable(&options.file),
                            printable(&e)
                        );
                        return ExitCode::from(2);
                    }
                }
            } else {
                if let Some(dir) = &options.plot {
                    for ((switch, kind), d) in &groups {
                        let name = format!(
                            "{dir}/{}-{}.svg",
                            identifier(switch).to_lowercase(),
                            kind.name()
                        );
                        let svg = calibrate::plot(switch, *kind, d, options.percentile);
                        if let Err(e) = std::fs::create_dir_all(dir)
                            .and_then(|()| write_atomically(&name, &svg))
                        {
                            eprintln!("bounce-table calibrate: {name}: {e}");
                            return ExitCode::FAILURE;
                        }
                    }
                }
                let mut report = format!(
                    "# Summary\n\n{}\n## Description\n\n{}",
                    calibrate::summary(&groups, options.percentile, options.burst_gap),
                    calibrate::describe(&groups, options.resolution)
                );
                if skipped.total() > 0 {
                    report.push_str(&format!("\n{}\n", skipped.describe(options.quiet)));
                }
                report.push_str(&calibrate::assess(
                    &groups,
                    options.percentile,
                    options.seed,
                ));
                if options.contact_models {
                    report.push_str(&calibrate::contact::report(&groups, options.seed));
                }
                report
            }
        };
        return match &options.output {
            Some(path) => match write_atomically(path, &text) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!(
                        "bounce-table calibrate: {}: cannot write it: {e}",
                        printable(path)
                    );
                    ExitCode::FAILURE
                }
            },
            None => {
                out!("{text}");
                ExitCode::SUCCESS
            }
        };
    }
    let options = match parse(&args) {
        Ok(o) => o,
        Err(message) => {
            eprintln!("bounce-table: {message}\n{SEE_HELP}");
            return ExitCode::from(2);
        }
    };
    let typical = options.file.is_none();
    let source = options
        .file
        .clone()
        .unwrap_or_else(|| "catalogue".to_owned());
    if let (Some(input), Some(output)) = (&options.file, &options.output) {
        let same = std::fs::canonicalize(input)
            .ok()
            .zip(std::fs::canonicalize(output).ok())
            .is_some_and(|(a, b)| a == b);
        if same {
            eprintln!("bounce-table: --output {output} is the scene file itself: refusing to overwrite it");
            return ExitCode::from(2);
        }
    }
    let Some(entries) = open_entries(options.file.as_deref()) else {
        return ExitCode::from(2);
    };
    let Some((mut analyses, layout)) = table::analyse_all(
        entries,
        &options.settings,
        options.format,
        &source,
        &mut |message| eprintln!("bounce-table: {}", printable(&message)),
    ) else {
        // Nothing is written when any switch failed.
        return ExitCode::from(2);
    };
    let (format, settings) = (options.format, &options.settings);
    let mut render = |w: &mut dyn std::io::Write| {
        render_to(
            w,
            format,
            &mut analyses,
            settings,
            typical,
            &source,
            Some(layout),
        )
    };
    let written = match &options.output {
        Some(path) => write_atomically_with(path, render),
        None => {
            let mut stdout = std::io::BufWriter::new(std::io::stdout().lock());
            render(&mut stdout)
                .and_then(|()| std::io::Write::flush(&mut stdout))
                .inspect_err(|e| {
                    // A reader that stopped early ends the run quietly (see `emit`).
                    if e.kind() == std::io::ErrorKind::BrokenPipe {
                        std::process::exit(0);
                    }
                })
        }
    };
    if let Err(e) = written {
        let path = options.output.as_deref().unwrap_or("standard output");
        eprintln!("bounce-table: {path}: cannot write it: {e}");
        return ExitCode::FAILURE;
    }
    if let Some(dir) = &options.plot {
        if let Err(e) = std::fs::create_dir_all(dir) {
            eprintln!("bounce-table: {dir}: {e}");
            return ExitCode::FAILURE;
        }
        let Some(entries) = open_entries(options.file.as_deref()) else {
            return ExitCode::FAILURE;
        };
        let rows = match analyses.rows() {
            Ok(rows) => rows,
            Err(e) => {
                eprintln!("bounce-table: {e}");
                return ExitCode::FAILURE;
            }
        };
        for (entry, a) in entries.zip(rows) {
            let (Ok(entry), Ok(a)) = (entry, a) else {
                continue;
            };
            let input = entry.template.nominal();
            match plot::plots(input, &a, settings.percentile) {
                Ok((envelope, motion)) => {
                    let stem = identifier(&entry.name).to_lowercase();
                    for (suffix, svg) in [("envelope", envelope), ("motion", motion)] {
                        let path = format!("{dir}/{stem}-{suffix}.svg");
                        if let Err(e) = write_atomically(&path, &svg) {
                            eprintln!("bounce-table: {path}: {e}");
                            return ExitCode::FAILURE;
                        }
                    }
                }
                Err(e) => eprintln!(
                    "bounce-table: {}: plot: {}: {}",
                    printable(&entry.name),
                    e.field,
                    e.message
                ),
            }
        }
    }
    ExitCode::SUCCESS
}

//! The command line, declared once (clap): the table mode, `bounce-table [OPTIONS]
//! [SCENE_FILE]`, and the subcommands `eval`, `replay` and `calibrate`, each parsed into its
//! mode's options. Every subcommand takes `-h`/`--help`, `-V`/`--version` and `--option=value`;
//! a refused command line is one line (control characters escaped) naming what is wrong.

use clap::error::ErrorKind;
use clap::{Args, Parser, Subcommand};

use crate::capture::scope;
use crate::capture::Polarity;
use crate::capture::{self, Format as CaptureFormat};
use crate::commands::calibrate::{self, Written};
use crate::commands::eval::{self, EvalMethod, Precision};
use crate::commands::replay;
use crate::render::output::Format;
use crate::scene::priors::{self, Prior};
use crate::stats;
use crate::stats::analysis::Settings;
use contact_bounce::Nodes;

/// The most worker threads `--threads` takes: each is a stack, and a run asks for no more
/// than its work can use.
pub const MAX_THREADS: u64 = 1024;
/// At most this many Monte Carlo samples: each keeps 16 bytes of results, so a run takes at
/// most 1.6 GB (and minutes), not an allocation the system refuses.
pub const MAX_SAMPLES: u64 = 100_000_000;

/// The help's layout: the usage first, then what the command does and its options.
const TEMPLATE: &str = "usage: {usage}\n\n{about-with-newline}\n{all-args}{after-help}";

/// The table mode's options (`bounce-table [OPTIONS] [SCENE_FILE]`).
#[derive(Debug, Clone)]
pub struct Options {
    /// How to analyse.
    pub settings: Settings,
    /// The output format.
    pub format: Format,
    /// Where to write (else standard output).
    pub output: Option<String>,
    /// Where to write plots.
    pub plot: Option<String>,
    /// The scene file (else the catalogue).
    pub file: Option<String>,
}

/// What a command line asks for.
#[derive(Debug, Clone)]
pub enum Invocation {
    /// The table mode.
    Table(Options),
    /// `eval`.
    Eval(eval::Options),
    /// `replay`.
    Replay(replay::Request),
    /// `calibrate`.
    Calibrate(calibrate::Request),
    /// `--help`: the text to print.
    Help(String),
    /// `--version`.
    Version,
}

/// A refused command line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    /// The subcommand refused (`None`: the table mode).
    pub subcommand: Option<&'static str>,
    /// What is wrong, in one line.
    pub message: String,
}

impl std::fmt::Display for Refusal {
    /// The message and where the usage is, as `bounce-table` prints them (two lines).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let command = match self.subcommand {
            Some(name) => format!("bounce-table {name}"),
            None => "bounce-table".to_owned(),
        };
        write!(
            f,
            "{command}: {}\n({command} --help shows its usage)",
            self.message
        )
    }
}

/// Parses the arguments after the program's name.
///
/// # Errors
/// A [`Refusal`]: an unknown option, a missing or bad value, a missing or extra file.
pub fn parse<I, S>(args: I) -> Result<Invocation, Refusal>
where
    I: IntoIterator<Item = S>,
    S: Into<String>,
{
    let args: Vec<String> = args.into_iter().map(Into::into).collect();
    let subcommand = match args.first().map(String::as_str) {
        Some("eval") => Some("eval"),
        Some("replay") => Some("replay"),
        Some("calibrate") => Some("calibrate"),
        _ => None,
    };
    let refuse = |message: String| Refusal {
        subcommand,
        message: crate::support::strict::printable(&message).into_owned(),
    };
    let cli = match Cli::try_parse_from(std::iter::once("bounce-table".to_owned()).chain(args)) {
        Ok(cli) => cli,
        Err(e) => {
            return match e.kind() {
                ErrorKind::DisplayHelp => Ok(Invocation::Help(e.render().to_string())),
                ErrorKind::DisplayVersion => Ok(Invocation::Version),
                _ => Err(refuse(one_line(&e))),
            }
        }
    };
    match cli.command {
        None => Ok(Invocation::Table(cli.table.into_options())),
        Some(Command::Eval(a)) => Ok(Invocation::Eval(eval::Options {
            method: a.method,
            tolerance: a.tolerance,
            precision: a.precision,
            nodes: a.nodes,
            file: a.file,
        })),
        Some(Command::Replay(a)) => {
            let (capture, calibration) = a.capture.into_options().map_err(refuse)?;
            Ok(Invocation::Replay(replay::Request {
                capture,
                calibration,
                settings: replay::Settings {
                    period: a.period,
                    split: a.split,
                    time_scale: a.time_scale,
                    switch_type: a.switch_type,
                    fixed: a.window,
                    fastest_tap: a.min_tap,
                    learner_prior: a.prior,
                },
                output: a.format,
                plot: a.plot,
                taps: a
                    .taps
                    .then_some(crate::commands::replay::taps::TapSettings {
                        count: a.tap_count,
                        seed: a.tap_seed,
                    }),
            }))
        }
        Some(Command::Calibrate(a)) => {
            let (capture, calibration) = a.capture.into_options().map_err(refuse)?;
            Ok(Invocation::Calibrate(calibrate::Request {
                capture,
                calibration: stats::Calibration {
                    min_tap: a.min_tap,
                    ..calibration
                },
                written: a.format,
                output: a.output,
                plot: a.plot,
                contact_models: a.contact_models,
            }))
        }
    }
}

/// clap's error as one line: its message, without the tips and the usage that follow it (an
/// argument's own control characters are escaped by the caller).
fn one_line(e: &clap::Error) -> String {
    let text = e.render().to_string();
    let message = text.strip_prefix("error: ").unwrap_or(&text);
    let first = message.split("\n\n").next().unwrap_or(message).trim_end();
    // clap continues its own lines with an indent (the possible values).
    first.replace("\n  ", " ")
}

#[derive(Parser, Debug)]
#[command(
    name = "bounce-table",
    version,
    propagate_version = true,
    about = "Predicted bounce and debounce windows for the catalogue's switches or yours",
    long_about = TABLE_ABOUT,
    after_help = SCENE_KEYS,
    help_template = TEMPLATE,
    args_conflicts_with_subcommands = true,
    args_override_self = true,
    allow_negative_numbers = true,
    disable_help_subcommand = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    table: TableArgs,
}

const TABLE_ABOUT: &str = "Prints predicted bounce and debounce windows: for the built-in catalogue of typical switches
(assumed values over assumed ranges, not a datasheet; windows the P99.9 over the ranges), or for the switches of SCENE_FILE
(.toml with [[switch]] tables, .json, or .jsonl; the keys of `eval`, and any number may be a
range: {min = a, max = b} or {value = x, spread = s}).";

const SCENE_KEYS: &str =
    "Scene keys (SI units; where to get each: docs/parameters.md in the repository):
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
                                  a relaxation kernel; two bodies (the paper's Eq. 1)";

/// The table mode's arguments.
#[derive(Args, Debug)]
struct TableArgs {
    /// The debouncer's sample period (s): the windows are given in its ticks
    #[arg(long = "sample-period", visible_alias = "period", value_name = "SECONDS", default_value_t = 1e-4, value_parser = positive)]
    period: f64,
    /// table, markdown, csv, json, c (a header) or rust (constants)
    #[arg(long, value_name = "FORMAT", default_value = "table", value_parser = table_format)]
    format: Format,
    /// Write there, completely or not at all (default: standard output)
    #[arg(long, value_name = "FILE")]
    output: Option<String>,
    /// Relative error asked of the model, else the exact reference
    #[arg(long, value_name = "X", default_value_t = 0.1, value_parser = positive)]
    tolerance: f64,
    /// Percentile of the Monte Carlo window with ranges
    #[arg(long, value_name = "P", default_value_t = 99.9, value_parser = percentile)]
    percentile: f64,
    /// Safety factor on every window, at least 1 (1: none; 1.5 for +50 %)
    #[arg(long, value_name = "F", default_value_t = 1.0, value_parser = margin)]
    margin: f64,
    /// Monte Carlo samples (at most 1e8)
    #[arg(long, value_name = "N", default_value_t = 4000, value_parser = samples)]
    samples: u64,
    /// Monte Carlo seed
    #[arg(long, value_name = "S", default_value_t = 1, value_parser = whole)]
    seed: u64,
    /// Worker threads (default: all cores; at most 1024)
    #[arg(long, value_name = "N", value_parser = threads)]
    threads: Option<usize>,
    /// Also write NAME-envelope.svg and NAME-motion.svg for each switch there
    #[arg(long, value_name = "DIR")]
    plot: Option<String>,
    /// The scene file (default: the built-in catalogue)
    #[arg(value_name = "SCENE_FILE")]
    file: Option<String>,
}

impl TableArgs {
    fn into_options(self) -> Options {
        let mut settings = Settings {
            period: self.period,
            tolerance: self.tolerance,
            percentile: self.percentile,
            samples: self.samples,
            seed: self.seed,
            margin: self.margin,
            ..Settings::default()
        };
        if let Some(threads) = self.threads {
            settings.threads = threads;
        }
        settings.progress = std::io::IsTerminal::is_terminal(&std::io::stderr());
        Options {
            settings,
            format: self.format,
            output: self.output,
            plot: self.plot,
            file: self.file,
        }
    }
}

#[derive(Subcommand, Debug)]
enum Command {
    #[command(
        about = "The model and the exact reference on JSON Lines scenes, one JSON result a line",
        long_about = EVAL_ABOUT,
        help_template = TEMPLATE,
        args_override_self = true,
        allow_negative_numbers = true
    )]
    Eval(EvalArgs),
    #[command(
        about = "Debouncers (ours and the peers') replayed on a real capture: false edges and latency",
        long_about = REPLAY_ABOUT,
        help_template = TEMPLATE,
        args_override_self = true,
        allow_negative_numbers = true
    )]
    Replay(ReplayArgs),
    #[command(
        about = "A capture of a real switch described, fitted and turned into windows",
        long_about = CALIBRATE_ABOUT,
        help_template = TEMPLATE,
        args_override_self = true,
        allow_negative_numbers = true
    )]
    Calibrate(CalibrateArgs),
}

const EVAL_ABOUT: &str = "eval: JSON Lines scenes (the scene keys of `bounce-table --help`; a file, else standard
input), one JSON result a line on standard output: the regime, the end of the bounce, the last impact above the threshold,
impact counts and the tier's expected error. A bad line gets an error object naming the line
and the field; the other lines still run, and the exit status is 1 if any line failed.";

/// `eval`'s arguments.
#[derive(Args, Debug)]
struct EvalArgs {
    /// reference (the host's exact reference), exact-tier (the core's exact tier), map,
    /// averaged, closed or auto
    #[arg(long, value_name = "M", default_value = "auto", value_parser = method)]
    method: EvalMethod,
    /// The relative error auto must promise
    #[arg(long, value_name = "X", default_value_t = 0.01, value_parser = positive)]
    tolerance: f64,
    /// f32 or f64, for the core's tiers
    #[arg(long, value_name = "P", default_value = "f64", value_parser = precision)]
    precision: Precision,
    /// Gauss-Legendre nodes per panel of the averaged tier
    #[arg(long, value_name = "N", default_value = "8", value_parser = nodes)]
    nodes: Nodes,
    /// The JSON Lines scenes (default: standard input)
    #[arg(value_name = "SCENES")]
    file: Option<String>,
}

const REPLAY_ABOUT: &str =
    "replay: the benchmark of debouncers on a real capture. Per switch and kind, the earlier tests
(--split) calibrate and the later ones are replayed through our debouncer with the
calibrated windows (hold-off and confirm), with the switch type's prior window (physics-prior:
the type from the switch's name or --switch-type), with the learning debouncer (learned: from
that prior, it learns online through every test of the switch in capture order and is scored on
the later ones), and through peers re-implemented from their documentation at their defaults
(QMK, ZMK, Bounce2, debouncr, Linux and Zephyr gpio-keys). Rows: false edges (reported edges
beyond each test's one) and latency P50/P99 from the first contact change.";

/// `replay`'s arguments.
#[derive(Args, Debug)]
struct ReplayArgs {
    /// table (markdown), json (one object a row), or curve: the learner's window and false
    /// edges after every test (CSV)
    #[arg(long, value_name = "F", default_value = "table", value_parser = replay_format)]
    format: replay::Output,
    /// The polled debouncers' sample period (s)
    #[arg(long = "sample-period", visible_alias = "period", value_name = "SECONDS", default_value_t = 1e-3, value_parser = positive)]
    period: f64,
    /// The earlier share of the tests that calibrates, below 1
    #[arg(long, value_name = "F", default_value_t = 0.5, value_parser = split)]
    split: f64,
    /// Every time multiplied by X (10: contactor-like, 0.1: reed-like)
    #[arg(long, value_name = "X", default_value_t = 1.0, value_parser = positive)]
    time_scale: f64,
    /// push-button, rocker, toggle, slide, tactile or hand-operated
    #[arg(long, value_name = "TYPE", value_parser = switch_type)]
    switch_type: Option<&'static Prior>,
    /// Also write SWITCH-KIND-replay.svg there: false edges against latency
    #[arg(long, value_name = "DIR")]
    plot: Option<String>,
    /// Also replay our debouncer with this window (s) for presses and releases, as it is (a
    /// firmware's fixed window; repeatable)
    #[arg(long, value_name = "S", value_parser = seconds)]
    window: Vec<f64>,
    /// The learner's prior window (s), for presses and releases (default: the switch type's)
    #[arg(long, value_name = "S", value_parser = seconds)]
    prior: Option<f64>,
    /// No real tap is down or up for less than S: the learner always reports a change that
    /// lasts this long
    #[arg(long, value_name = "S", default_value_t = 31e-3, value_parser = positive)]
    min_tap: f64,
    /// Score every debouncer on seeded sequences of taps with human timing (typing, fast taps,
    /// double-clicks, holds), spliced from the capture's later presses and releases, and on a
    /// switch with no bounce: missed taps, false edges, correct taps, latencies
    #[arg(long)]
    taps: bool,
    /// Taps per switch and regime (--taps)
    #[arg(long, value_name = "N", default_value_t = 1000, value_parser = tap_count)]
    tap_count: usize,
    /// The tap sequences' seed (--taps)
    #[arg(long, value_name = "N", default_value_t = 1)]
    tap_seed: u64,
    #[command(flatten)]
    capture: CaptureArgs,
}

fn tap_count(v: &str) -> Result<usize, String> {
    match v.parse::<usize>() {
        Ok(n) if (1..=1_000_000).contains(&n) => Ok(n),
        _ => Err(format!("'{v}' is not a count of taps from 1 to 1000000")),
    }
}

const CALIBRATE_ABOUT: &str =
    "calibrate: describes a capture (JSON Lines of the bouncy-button format, a CSV of `time,level`
rows, a VCD, or an oscilloscope's CSV export of volts, read through an input's two thresholds;
format from the extension and the header) per switch and kind (bounce P50/P90/P99/max,
transitions, resolved flights and dwells, chatter), fits the impact model and a bounce model
with empirical terms (clean share, log-normal bursts, late bursts), checks them and the
empirical quantiles on held-out halves, and recommends windows. High = open unless
--active-high.";

/// `calibrate`'s arguments.
#[derive(Args, Debug)]
struct CalibrateArgs {
    /// report; c or rust: only the windows, as #defines or Rust constants (ns); csv: each
    /// event's description, one row per event
    #[arg(long, value_name = "F", default_value = "report", value_parser = written)]
    format: Written,
    /// Write there, completely or not at all (default: standard output)
    #[arg(long, value_name = "FILE")]
    output: Option<String>,
    /// Also fit the two-body and compliant-contact models to each switch's presses and check
    /// them on held-out halves (about a minute)
    #[arg(long)]
    contact_models: bool,
    /// Also write SWITCH-KIND.svg there: observed bounce distribution vs the models
    #[arg(long, value_name = "DIR")]
    plot: Option<String>,
    /// No real tap is shorter than S: cap every window at S, and say what the cap leaves
    /// through on the capture (31e-3: 16 taps a second)
    #[arg(long, value_name = "S", value_parser = seconds)]
    min_tap: Option<f64>,
    #[command(flatten)]
    capture: CaptureArgs,
}

/// The capture and how to read and calibrate it (`calibrate`'s, and `replay`'s).
#[derive(Args, Debug)]
struct CaptureArgs {
    /// jsonl, csv (time,level rows), vcd; a scope's export: rigol, siglent, keysight,
    /// tektronix, or volts (time,volts rows). Default: from the extension; a .csv file or a
    /// folder of them recognised by its header
    #[arg(long, value_name = "F", value_parser = capture_format)]
    capture_format: Option<CaptureFormat>,
    /// An analog capture's channel (CH1 or 1; default: the only one)
    #[arg(long, value_name = "NAME")]
    channel: Option<String>,
    /// An analog capture read by this MCU's input thresholds (its datasheet's V_IL and V_IH):
    /// atmega328p, rp2040, stm32f103, stm32f030 or esp32 (default: 30 % and 70 % of the
    /// trace's swing)
    #[arg(long, value_name = "MCU", value_parser = mcu, conflicts_with = "thresholds")]
    input: Option<&'static scope::Preset>,
    /// An analog capture read with these thresholds, LOW,HIGH in volts
    #[arg(long, value_name = "LOW,HIGH", value_parser = volt_pair)]
    thresholds: Option<(f64, f64)>,
    /// The supply the --input thresholds scale with (V; default: the trace's high level)
    #[arg(long, value_name = "V", value_parser = volts, requires = "input")]
    vcc: Option<f64>,
    /// Intervals shorter than S are chatter, not timed
    #[arg(long, value_name = "S", default_value_t = 3e-6, value_parser = seconds)]
    resolution: f64,
    /// A quiet interval of S ends a burst; later bursts are late bounce
    #[arg(long, value_name = "S", default_value_t = 5e-3, value_parser = seconds)]
    burst_gap: f64,
    /// In CSV/VCD streams, a quiet gap longer than this (s) starts a new event
    #[arg(long = "event-gap", visible_alias = "quiet", value_name = "SECONDS", default_value_t = 0.2, value_parser = seconds)]
    event_gap: f64,
    /// The VCD signal (default: the only 1-bit one)
    #[arg(long, value_name = "NAME")]
    signal: Option<String>,
    /// The contacts are closed when the level is high
    #[arg(long)]
    active_high: bool,
    /// Leave out a JSON Lines section (repeatable)
    #[arg(long, value_name = "NAME")]
    skip_section: Vec<String>,
    /// The windows' percentile of the bounce
    #[arg(long, value_name = "P", default_value_t = 99.0, value_parser = percentile)]
    percentile: f64,
    /// The random held-out split's seed
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = whole)]
    seed: u64,
    /// The capture
    #[arg(value_name = "CAPTURE")]
    file: String,
}

impl CaptureArgs {
    /// The capture to read and how, and how its windows are calibrated (`--min-tap` apart:
    /// its meaning is the command's).
    fn into_options(self) -> Result<(capture::Options, stats::Calibration), String> {
        let format = match self.capture_format {
            Some(f) => f,
            None if std::path::Path::new(&self.file).is_dir() => CaptureFormat::Scope(None),
            None => match self.file.rsplit('.').next() {
                Some("jsonl") => CaptureFormat::Jsonl,
                Some("csv") => CaptureFormat::Scope(None),
                Some("vcd") => CaptureFormat::Vcd,
                _ => {
                    return Err(format!(
                        "{}: say --capture-format (jsonl, csv, vcd, rigol, siglent, keysight, tektronix or volts)",
                        self.file
                    ))
                }
            },
        };
        let input = match (self.input, self.thresholds) {
            (Some(p), _) => scope::Input::Preset(p, self.vcc),
            (None, Some((low, high))) => scope::Input::Volts(low, high),
            (None, None) => scope::Input::Swing,
        };
        let capture = capture::Options {
            file: self.file,
            format,
            event_gap: self.event_gap,
            signal: self.signal,
            channel: self.channel,
            input,
            polarity: if self.active_high {
                Polarity::ActiveHigh
            } else {
                Polarity::ActiveLow
            },
            skip_sections: self.skip_section,
        };
        let calibration = stats::Calibration {
            resolution: self.resolution,
            burst_gap: self.burst_gap,
            percentile: self.percentile / 100.0,
            seed: self.seed,
            min_tap: None,
        };
        Ok((capture, calibration))
    }
}

// The values' parsers: each names what it takes (clap adds the option and the value).

fn positive(v: &str) -> Result<f64, String> {
    v.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite() && *x > 0.0)
        .ok_or_else(|| "not a positive number".to_owned())
}

fn seconds(v: &str) -> Result<f64, String> {
    positive(v).map_err(|_| "not a positive number of seconds".to_owned())
}

fn margin(v: &str) -> Result<f64, String> {
    let m = positive(v)?;
    if m < 1.0 {
        return Err(format!(
            "{m} is below 1 (a factor the window is multiplied by)"
        ));
    }
    Ok(m)
}

fn percentile(v: &str) -> Result<f64, String> {
    positive(v)
        .ok()
        .filter(|p| *p <= 100.0)
        .ok_or_else(|| "not in (0, 100]".to_owned())
}

fn split(v: &str) -> Result<f64, String> {
    let f = positive(v)?;
    if f >= 1.0 {
        return Err(format!(
            "{f} leaves no later test to replay: give a share below 1"
        ));
    }
    Ok(f)
}

fn whole(v: &str) -> Result<u64, String> {
    v.parse::<u64>()
        .map_err(|_| "not a whole number".to_owned())
}

fn samples(v: &str) -> Result<u64, String> {
    match whole(v)? {
        0 => Err("not a whole number above 0".to_owned()),
        n if n > MAX_SAMPLES => Err(format!("{n} is above {MAX_SAMPLES}")),
        n => Ok(n),
    }
}

fn threads(v: &str) -> Result<usize, String> {
    match whole(v)? {
        0 => Err("not a whole number above 0".to_owned()),
        n if n > MAX_THREADS => Err(format!("{n} is above {MAX_THREADS}")),
        n => usize::try_from(n).map_err(|_| format!("{n} is above {MAX_THREADS}")),
    }
}

fn table_format(v: &str) -> Result<Format, String> {
    Format::parse(v).ok_or_else(|| "not table, markdown, csv, json, c or rust".to_owned())
}

fn method(v: &str) -> Result<EvalMethod, String> {
    Ok(match v {
        "reference" => EvalMethod::Reference,
        "exact-tier" => EvalMethod::ExactTier,
        "exact" => {
            return Err(
                "ambiguous: say reference (the host's exact reference, which `exact` named \
                        before) or exact-tier (the core's exact tier)"
                    .to_owned(),
            )
        }
        "map" => EvalMethod::Map,
        "averaged" => EvalMethod::Averaged,
        "closed" => EvalMethod::Closed,
        "auto" => EvalMethod::Auto,
        _ => {
            return Err("not one of reference, exact-tier, map, averaged, closed, auto".to_owned())
        }
    })
}

fn precision(v: &str) -> Result<Precision, String> {
    match v {
        "f32" => Ok(Precision::F32),
        "f64" => Ok(Precision::F64),
        _ => Err("not f32 or f64".to_owned()),
    }
}

fn nodes(v: &str) -> Result<Nodes, String> {
    v.parse::<u32>()
        .ok()
        .and_then(Nodes::from_count)
        .ok_or_else(|| "not one of 2, 4, 6, 8, 10, 12, 16, 20".to_owned())
}

fn replay_format(v: &str) -> Result<replay::Output, String> {
    match v {
        "table" | "markdown" => Ok(replay::Output::Markdown),
        "json" => Ok(replay::Output::Json),
        "curve" => Ok(replay::Output::Curve),
        _ => Err("not table, markdown, json or curve".to_owned()),
    }
}

fn switch_type(v: &str) -> Result<&'static Prior, String> {
    priors::by_name(v).ok_or_else(|| {
        let names: Vec<&str> = priors::TYPES.iter().map(|(n, _)| *n).collect();
        format!("not one of {}", names.join(", "))
    })
}

fn capture_format(v: &str) -> Result<CaptureFormat, String> {
    match v {
        "jsonl" => Ok(CaptureFormat::Jsonl),
        "csv" => Ok(CaptureFormat::Csv),
        "vcd" => Ok(CaptureFormat::Vcd),
        _ => scope::Vendor::parse(v)
            .map(|vendor| CaptureFormat::Scope(Some(vendor)))
            .ok_or_else(|| {
                "not jsonl, csv, vcd, rigol, siglent, keysight, tektronix or volts".to_owned()
            }),
    }
}

fn mcu(v: &str) -> Result<&'static scope::Preset, String> {
    scope::preset(v).ok_or_else(|| {
        let names: Vec<&str> = scope::PRESETS.iter().map(|p| p.name).collect();
        format!("not one of {}", names.join(", "))
    })
}

fn volts(v: &str) -> Result<f64, String> {
    positive(v).map_err(|_| "not a positive number of volts".to_owned())
}

fn volt_pair(v: &str) -> Result<(f64, f64), String> {
    let parsed: Vec<Option<f64>> = v
        .split(',')
        .map(|x| x.trim().parse::<f64>().ok().filter(|x| x.is_finite()))
        .collect();
    match parsed[..] {
        [Some(low), Some(high)] if low < high => Ok((low, high)),
        [Some(low), Some(high)] => Err(format!("{low} is not below {high}: give LOW,HIGH")),
        _ => Err("not two numbers of volts, LOW,HIGH".to_owned()),
    }
}

fn written(v: &str) -> Result<Written, String> {
    match v {
        "report" | "markdown" => Ok(Written::Report),
        "c" => Ok(Written::C),
        "rust" => Ok(Written::Rust),
        "csv" => Ok(Written::Events),
        capture @ ("jsonl" | "vcd") => Err(format!(
            "'{capture}' is a capture's format: --capture-format {capture}"
        )),
        _ => Err("not report, c, rust or csv (events)".to_owned()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn calibrate(args: &[&str]) -> Result<calibrate::Request, Refusal> {
        match parse(std::iter::once("calibrate").chain(args.iter().copied()))? {
            Invocation::Calibrate(o) => Ok(o),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn calibrates_options_have_stated_defaults_and_name_the_bad_one() {
        let o = calibrate(&["capture.vcd"]).expect("valid");
        assert_eq!(o.capture.format, CaptureFormat::Vcd);
        assert_eq!(
            (o.calibration.resolution, o.calibration.burst_gap),
            (3e-6, 5e-3)
        );
        assert_eq!((o.capture.event_gap, o.calibration.percentile), (0.2, 0.99));
        assert_eq!((o.written, o.calibration.min_tap), (Written::Report, None));
        let o =
            calibrate(&["--burst-gap", "2e-2", "--percentile", "99.9", "c.csv"]).expect("valid");
        // A .csv file is recognised by its header when it is read: a scope's or levels.
        assert_eq!(
            (o.calibration.burst_gap, o.capture.format),
            (2e-2, CaptureFormat::Scope(None))
        );
        assert!((o.calibration.percentile - 0.999).abs() < 1e-15);
        let o =
            calibrate(&["--capture-format", "rigol", "--channel", "2", "c.csv"]).expect("valid");
        assert_eq!(
            (o.capture.format, o.capture.channel.as_deref()),
            (CaptureFormat::Scope(Some(scope::Vendor::Rigol)), Some("2"))
        );
        assert_eq!(o.capture.input, scope::Input::Swing);
        let o = calibrate(&["--input", "rp2040", "c.csv"]).expect("valid");
        assert_eq!(
            o.capture.input,
            scope::Input::Preset(scope::preset("rp2040").expect("a preset"), None)
        );
        let o = calibrate(&["--thresholds", "0.8,2", "c.csv"]).expect("valid");
        assert_eq!(o.capture.input, scope::Input::Volts(0.8, 2.0));
        let o = calibrate(&["--format=rust", "--min-tap", "0.03", "c.csv"]).expect("valid");
        assert_eq!(
            (o.written, o.calibration.min_tap),
            (Written::Rust, Some(0.03))
        );
        // A repeatable option keeps every value; any other, the last one given.
        let o = calibrate(&[
            "--skip-section",
            "Fast",
            "--skip-section=Slow",
            "--seed",
            "1",
            "--seed",
            "7",
            "c.jsonl",
        ])
        .expect("valid");
        assert_eq!(
            (o.capture.skip_sections.as_slice(), o.calibration.seed),
            (&["Fast".to_owned(), "Slow".to_owned()][..], 7)
        );
        for (bad, named) in [
            (&["--burst-gap", "0", "c.csv"][..], "--burst-gap"),
            (&["--burst-gap", "NaN", "c.csv"], "--burst-gap"),
            (&["--burst-gap"], "--burst-gap"),
            (&["--resolution", "-1", "c.csv"], "--resolution"),
            (&["--percentile", "0", "c.csv"], "--percentile"),
            (&["--frobnicate", "c.csv"], "--frobnicate"),
            (&["capture.bin"], "--capture-format"),
            (&["--format", "java", "c.csv"], "--format"),
            (&["--format", "vcd", "c.csv"], "--capture-format vcd"),
            (&["--capture-format", "wav", "c.csv"], "--capture-format"),
            (&["--input", "z80", "c.csv"], "--input"),
            (&["--thresholds", "2,1", "c.csv"], "--thresholds"),
            (&["--thresholds", "1", "c.csv"], "--thresholds"),
            (
                &["--input", "rp2040", "--thresholds", "1,2", "c.csv"],
                "--thresholds",
            ),
            (&["--vcc", "3.3", "c.csv"], "--input"),
            (&["a.csv", "b.csv"], "b.csv"),
            (&[], "CAPTURE"),
        ] {
            let e = calibrate(bad).expect_err("refused");
            assert_eq!(e.subcommand, Some("calibrate"));
            assert!(e.message.contains(named), "{bad:?}: {}", e.message);
            assert!(!e.message.contains('\n'), "{bad:?}: {}", e.message);
        }
    }

    #[test]
    fn help_and_version_are_answers_not_refusals() {
        for args in [&["--help"][..], &["eval", "-h"], &["calibrate", "--help"]] {
            let Ok(Invocation::Help(text)) = parse(args.iter().copied()) else {
                panic!("{args:?}")
            };
            assert!(text.starts_with("usage: bounce-table"), "{text}");
        }
        for args in [&["-V"][..], &["replay", "--version"], &["calibrate", "-V"]] {
            assert!(matches!(
                parse(args.iter().copied()),
                Ok(Invocation::Version)
            ));
        }
    }
}

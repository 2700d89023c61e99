//! Analog captures: an oscilloscope's export read as volts over time, and turned into the level
//! changes an input pin would see.
//!
//! A bounce seen on a scope is a voltage through a pull-up, often through an RC filter; whether
//! a dip is a bounce depends on the input's thresholds. An input reads low below its V_IL and
//! high above its V_IH, and between them it keeps what it read (a Schmitt trigger, or the
//! worst case of one without). [`to_levels`] follows a trace with those two thresholds: a
//! change to low where the voltage falls through V_IL, to high where it rises through V_IH
//! (each at the crossing, interpolated between the two samples around it), and a *marginal dip*
//! where it crosses one threshold and turns back before the other: a contact that a part at one
//! end of the datasheet's range reads as a bounce and another does not.
//!
//! The exports read ([`Vendor`], `docs/scope-captures.md` for each layout): Rigol (`X,CH1,Start,
//! Increment,` then `Sequence,Volt,<start>,<increment>,` then index and volts), Siglent
//! (`Record Length,...` lines, then `Second,Volt`), Keysight InfiniiVision (`x-axis,1` then
//! `second,Volt`), Tektronix (the five-column `Record Length,...` spreadsheet of the TBS/TDS
//! scopes, or the MSO's header lines then `TIME,CH1`), and plain `time,volts` rows with an
//! optional header. A file may hold several acquisitions, each starting with its header again
//! (exports appended one after the other); several channels are columns, one chosen by name.

use crate::capture::{CaptureError, Polarity, Stream};

/// The export a file comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Vendor {
    /// Rigol DS1000Z and the like: a start time and an increment, then index and volts.
    Rigol,
    /// Siglent SDS: setting lines, then `Second,Volt` and time, volts.
    Siglent,
    /// Keysight (Agilent) InfiniiVision: `x-axis,1`, `second,Volt`, then time, volts.
    Keysight,
    /// Tektronix: the five-column spreadsheet export (settings in the first three columns,
    /// time and volts in the last two) or the MSO's setting lines then `TIME,CH1`.
    Tektronix,
    /// Plain `time,volts` rows (more columns: more channels), with an optional header.
    Volts,
}

impl Vendor {
    /// Every vendor, in the order `--capture-format` lists them.
    pub const ALL: [Vendor; 5] = [
        Vendor::Rigol,
        Vendor::Siglent,
        Vendor::Keysight,
        Vendor::Tektronix,
        Vendor::Volts,
    ];

    /// Its `--capture-format` name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Vendor::Rigol => "rigol",
            Vendor::Siglent => "siglent",
            Vendor::Keysight => "keysight",
            Vendor::Tektronix => "tektronix",
            Vendor::Volts => "volts",
        }
    }

    /// The vendor of a `--capture-format` name.
    #[must_use]
    pub fn parse(name: &str) -> Option<Vendor> {
        Vendor::ALL.into_iter().find(|v| v.name() == name)
    }
}

/// One channel of one acquisition: sample times (s, increasing) and voltages (V).
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    /// The channel's name as the file gives it (`CH1`, `1`, ...).
    pub channel: String,
    /// The line its header (or first row) is on, for messages.
    pub line: usize,
    /// Sample times (s).
    pub times: Vec<f64>,
    /// Voltages (V).
    pub volts: Vec<f64>,
}

fn error(file: &str, line: usize, reason: impl Into<String>) -> CaptureError {
    CaptureError {
        file: file.to_owned(),
        line,
        reason: reason.into(),
    }
}

/// The fields of a row, trimmed, with a trailing empty field (a trailing comma) dropped.
fn fields(row: &str) -> Vec<&str> {
    let mut f: Vec<&str> = row.split(',').map(str::trim).collect();
    while f.len() > 1 && f.last().is_some_and(|s| s.is_empty()) {
        f.pop();
    }
    f
}

fn number(text: &str) -> Option<f64> {
    text.parse::<f64>().ok().filter(|x| x.is_finite())
}

/// True when the row is all numbers (a data row).
fn numeric(row: &str) -> bool {
    let f = fields(row);
    !f.is_empty() && f.iter().all(|x| number(x).is_some())
}

/// The export a text comes from, recognised by its first lines; `None` when it is none of the
/// scopes' and not volts (a `time,level` CSV of 0 and 1 rows, say).
#[must_use]
pub fn recognise(text: &str) -> Option<Vendor> {
    let lines: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .take(40)
        .collect();
    let first = lines.first()?;
    let head = fields(first);
    let key = head
        .first()
        .map(|s| s.to_ascii_lowercase())
        .unwrap_or_default();
    if key == "x" && head.iter().any(|f| f.eq_ignore_ascii_case("increment")) {
        return Some(Vendor::Rigol);
    }
    if key == "x-axis" {
        return Some(Vendor::Keysight);
    }
    if key == "record length" && head.len() >= 5 {
        return Some(Vendor::Tektronix);
    }
    for l in &lines {
        let k = fields(l).first().map(|s| s.to_ascii_lowercase());
        match k.as_deref() {
            Some("second") => return Some(Vendor::Siglent),
            Some("time") if !numeric(l) && lines.len() > 1 && key != "time" => {
                return Some(Vendor::Tektronix)
            }
            _ => {}
        }
    }
    // Plain rows: volts unless every value is a level (0 or 1).
    let data: Vec<Vec<&str>> = lines
        .iter()
        .filter(|l| numeric(l))
        .map(|l| fields(l))
        .collect();
    let two = data.iter().all(|f| f.len() >= 2) && !data.is_empty();
    let levels = data
        .iter()
        .all(|f| f.iter().skip(1).all(|v| matches!(*v, "0" | "1")));
    (two && !levels).then_some(Vendor::Volts)
}

/// How an acquisition's rows give their time.
enum TimeBase {
    /// The first column is the time (s).
    Column,
    /// The first column is a sample index: time = start + index * increment.
    Indexed { start: f64, increment: f64 },
    /// Five columns (Tektronix spreadsheet): time and volts in the fourth and fifth.
    Spreadsheet,
}

/// One acquisition's header: its channels and time base, and where its data rows start.
struct Header {
    channels: Vec<String>,
    base: TimeBase,
    line: usize,
    data: usize,
}

/// Reads a scope export (or plain `time,volts` rows) into one trace per acquisition of the
/// channel `channel` (by name, `CH1` and `1` alike, any case; the only one when `None`).
/// `vendor` `None`: recognised from the header ([`recognise`]).
///
/// # Errors
/// A file that is no export known here, a header without its settings, a data row that is not
/// numbers or has too few fields, times that go back, an unknown channel, or several channels
/// and none named: the error names the file and line.
pub fn read(
    file: &str,
    text: &str,
    vendor: Option<Vendor>,
    channel: Option<&str>,
) -> Result<Vec<Trace>, CaptureError> {
    let vendor = match vendor.or_else(|| recognise(text)) {
        Some(v) => v,
        None => {
            return Err(error(
                file,
                1,
                "not a scope export known here (rigol, siglent, keysight, tektronix) nor `time,volts` rows: say --capture-format",
            ))
        }
    };
    let lines: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
        .collect();
    let mut traces = Vec::new();
    let mut at = 0;
    while at < lines.len() {
        let header = header(file, vendor, &lines, at)?;
        let column = pick(file, &header, channel)?;
        let mut trace = Trace {
            channel: header.channels.get(column).cloned().unwrap_or_default(),
            line: header.line,
            times: Vec::new(),
            volts: Vec::new(),
        };
        at = header.data;
        while let Some(&(line, row)) = lines.get(at) {
            let f = fields(row);
            let first_numeric = f.first().and_then(|x| number(x)).is_some();
            let spreadsheet = matches!(header.base, TimeBase::Spreadsheet);
            if !first_numeric && !spreadsheet {
                break; // the next acquisition's header
            }
            let (t, v) = match header.base {
                TimeBase::Column => (f.first().and_then(|x| number(x)), f.get(column + 1)),
                TimeBase::Indexed { start, increment } => (
                    f.first()
                        .and_then(|x| number(x))
                        .map(|i| start + i * increment),
                    f.get(column + 1),
                ),
                TimeBase::Spreadsheet => {
                    if f.first()
                        .is_some_and(|k| k.eq_ignore_ascii_case("record length"))
                        && !trace.times.is_empty()
                    {
                        break; // the next acquisition
                    }
                    (f.get(3).and_then(|x| number(x)), f.get(4))
                }
            };
            let Some(v) = v else {
                return Err(error(
                    file,
                    line,
                    format!("expected a value for channel {} in {row:?}", trace.channel),
                ));
            };
            let (Some(t), Some(v)) = (t, number(v)) else {
                return Err(error(
                    file,
                    line,
                    format!("expected numbers (time, volts), found {row:?}"),
                ));
            };
            if trace.times.last().is_some_and(|&last| t <= last) {
                return Err(error(
                    file,
                    line,
                    format!("time {t} s does not follow the previous sample's"),
                ));
            }
            trace.times.push(t);
            trace.volts.push(v);
            at += 1;
        }
        if trace.times.len() < 2 {
            return Err(error(
                file,
                header.line,
                "an acquisition needs at least two samples",
            ));
        }
        traces.push(trace);
    }
    if traces.is_empty() {
        return Err(error(file, 0, "no samples"));
    }
    Ok(traces)
}

/// The channel's column among the header's channels.
fn pick(file: &str, header: &Header, channel: Option<&str>) -> Result<usize, CaptureError> {
    let bare = |s: &str| {
        let s = s.trim().to_ascii_lowercase();
        s.strip_prefix("ch").map(str::to_owned).unwrap_or(s)
    };
    let names = header.channels.join(", ");
    match channel {
        Some(wanted) => header
            .channels
            .iter()
            .position(|c| bare(c) == bare(wanted))
            .ok_or_else(|| {
                error(
                    file,
                    header.line,
                    format!("no channel {wanted:?} (the channels: {names})"),
                )
            }),
        None if header.channels.len() == 1 => Ok(0),
        None => Err(error(
            file,
            header.line,
            format!("several channels ({names}): say --channel"),
        )),
    }
}

/// The header of the acquisition that starts at `lines[at]`.
fn header(
    file: &str,
    vendor: Vendor,
    lines: &[(usize, &str)],
    at: usize,
) -> Result<Header, CaptureError> {
    let (line, row) = lines.get(at).copied().unwrap_or((0, ""));
    let head = fields(row);
    let expect = |what: &str| error(file, line, format!("expected {what}, found {row:?}"));
    match vendor {
        Vendor::Rigol => {
            let start_col = head.iter().position(|f| f.eq_ignore_ascii_case("start"));
            let inc_col = head
                .iter()
                .position(|f| f.eq_ignore_ascii_case("increment"));
            let (Some(s), Some(i), true) = (
                start_col,
                inc_col,
                head.first().is_some_and(|f| f.eq_ignore_ascii_case("x")),
            ) else {
                return Err(expect("a Rigol header `X,CH1,...,Start,Increment`"));
            };
            let channels: Vec<String> = head[1..s.min(i)].iter().map(|c| (*c).to_owned()).collect();
            let (uline, urow) = lines.get(at + 1).copied().unwrap_or((line, ""));
            let units = fields(urow);
            let (Some(start), Some(increment)) = (
                units.get(s).and_then(|x| number(x)),
                units.get(i).and_then(|x| number(x)),
            ) else {
                return Err(error(
                    file,
                    uline,
                    format!("expected `Sequence,Volt,...,<start>,<increment>`, found {urow:?}"),
                ));
            };
            if increment <= 0.0 {
                return Err(error(
                    file,
                    uline,
                    format!("the increment {increment} s is not a positive time"),
                ));
            }
            Ok(Header {
                channels,
                base: TimeBase::Indexed { start, increment },
                line,
                data: at + 2,
            })
        }
        Vendor::Keysight => {
            if !head
                .first()
                .is_some_and(|f| f.eq_ignore_ascii_case("x-axis"))
                || head.len() < 2
            {
                return Err(expect("a Keysight header `x-axis,1`"));
            }
            let channels = head[1..].iter().map(|c| (*c).to_owned()).collect();
            let (uline, urow) = lines.get(at + 1).copied().unwrap_or((line, ""));
            if !fields(urow)
                .first()
                .is_some_and(|f| f.eq_ignore_ascii_case("second"))
            {
                return Err(error(
                    file,
                    uline,
                    format!("expected `second,Volt`, found {urow:?}"),
                ));
            }
            Ok(Header {
                channels,
                base: TimeBase::Column,
                line,
                data: at + 2,
            })
        }
        Vendor::Siglent | Vendor::Tektronix | Vendor::Volts => {
            if vendor == Vendor::Tektronix
                && head
                    .first()
                    .is_some_and(|f| f.eq_ignore_ascii_case("record length"))
                && head.len() >= 5
            {
                // The spreadsheet: the source is a setting of the first columns.
                let source = lines[at..]
                    .iter()
                    .take(30)
                    .map(|(_, r)| fields(r))
                    .find(|f| f.first().is_some_and(|k| k.eq_ignore_ascii_case("source")))
                    .and_then(|f| f.get(1).map(|s| (*s).to_owned()))
                    .unwrap_or_else(|| "CH1".to_owned());
                return Ok(Header {
                    channels: vec![source],
                    base: TimeBase::Spreadsheet,
                    line,
                    data: at,
                });
            }
            // Setting lines up to the column header (`Second`, `TIME`, or a plain header), or
            // straight to the data.
            let key = match vendor {
                Vendor::Siglent => Some("second"),
                Vendor::Tektronix => Some("time"),
                _ => None,
            };
            let mut k = at;
            let mut source = None;
            loop {
                let Some(&(hline, hrow)) = lines.get(k) else {
                    return Err(expect(match vendor {
                        Vendor::Siglent => "a `Second,Volt` column header",
                        Vendor::Tektronix => "a `TIME,CH1` column header",
                        _ => "`time,volts` rows",
                    }));
                };
                let f = fields(hrow);
                if f.first().is_some_and(|s| s.eq_ignore_ascii_case("source")) {
                    source = f.get(1).map(|s| (*s).to_owned());
                }
                if numeric(hrow) {
                    if key.is_some() {
                        return Err(error(
                            file,
                            hline,
                            format!("a data row before the column header: {hrow:?}"),
                        ));
                    }
                    // Plain rows without a header: the columns are CH1, CH2, ...
                    let channels = (1..f.len()).map(|c| format!("CH{c}")).collect();
                    return Ok(Header {
                        channels,
                        base: TimeBase::Column,
                        line: hline,
                        data: k,
                    });
                }
                let first = f.first().map(|s| s.to_ascii_lowercase());
                let is_header = match key {
                    Some(key) => first.as_deref() == Some(key),
                    None => true,
                };
                if is_header {
                    if f.len() < 2 {
                        return Err(error(
                            file,
                            hline,
                            format!(
                                "a column header names a time and at least one channel: {hrow:?}"
                            ),
                        ));
                    }
                    // Siglent names the unit (`Volt`, `Value`), not the channel: the source
                    // setting does, else CH1.
                    let channels = f[1..]
                        .iter()
                        .map(|c| {
                            let unit = matches!(
                                c.to_ascii_lowercase().as_str(),
                                "volt" | "volts" | "value" | "v"
                            );
                            if unit && f.len() == 2 {
                                source.clone().unwrap_or_else(|| "CH1".to_owned())
                            } else {
                                (*c).to_owned()
                            }
                        })
                        .collect();
                    return Ok(Header {
                        channels,
                        base: TimeBase::Column,
                        line: hline,
                        data: k + 1,
                    });
                }
                k += 1;
            }
        }
    }
}

/// An MCU's input thresholds from its datasheet, at the supply voltage `vcc`: (V_IL max,
/// V_IH min), each in volts. `docs/scope-captures.md` cites each.
#[derive(Debug, Clone, Copy)]
pub struct Preset {
    /// Its `--input` name.
    pub name: &'static str,
    /// The datasheet and table the values come from.
    pub source: &'static str,
    /// Whether the thresholds depend on the supply (else `vcc` is ignored).
    pub scales: bool,
    thresholds: fn(f64) -> (f64, f64),
}

/// Presets are one by name.
impl PartialEq for Preset {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

impl Preset {
    /// (V_IL max, V_IH min) at supply `vcc` (V).
    #[must_use]
    pub fn at(&self, vcc: f64) -> (f64, f64) {
        (self.thresholds)(vcc)
    }
}

/// The presets of `--input`.
pub const PRESETS: [Preset; 5] = [
    Preset {
        name: "atmega328p",
        source: "ATmega328P datasheet, Common DC Characteristics: V_IL max 0.3 VCC, V_IH min 0.6 VCC (VCC 2.4-5.5 V)",
        scales: true,
        thresholds: |vcc| (0.3 * vcc, 0.6 * vcc),
    },
    Preset {
        name: "rp2040",
        source: "RP2040 datasheet, GPIO DC characteristics at IOVDD = 3.3 V: V_IL max 0.8 V, V_IH min 2.0 V",
        scales: false,
        thresholds: |_| (0.8, 2.0),
    },
    Preset {
        name: "stm32f103",
        source: "STM32F103x8/B datasheet, I/O static characteristics, standard I/O: V_IL max 0.28 (VDD - 2 V) + 0.8 V, V_IH min 0.41 (VDD - 2 V) + 1.3 V",
        scales: true,
        thresholds: |vdd| (0.28 * (vdd - 2.0) + 0.8, 0.41 * (vdd - 2.0) + 1.3),
    },
    Preset {
        name: "stm32f030",
        source: "STM32F030 datasheet, I/O static characteristics, all I/Os except BOOT0: V_IL max 0.3 VDD, V_IH min 0.7 VDD",
        scales: true,
        thresholds: |vdd| (0.3 * vdd, 0.7 * vdd),
    },
    Preset {
        name: "esp32",
        source: "ESP32 datasheet, DC characteristics (3.3 V): V_IL max 0.25 VDD, V_IH min 0.75 VDD",
        scales: true,
        thresholds: |vdd| (0.25 * vdd, 0.75 * vdd),
    },
];

/// The preset of an `--input` name.
#[must_use]
pub fn preset(name: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.name == name)
}

/// Where the thresholds come from.
#[derive(Debug, Clone, PartialEq)]
pub enum Input {
    /// Fractions of the trace's swing: low at 0.3, high at 0.7 (a generic CMOS input).
    Swing,
    /// An MCU's datasheet values, at the supply `vcc` (V; the trace's high level when `None`).
    Preset(&'static Preset, Option<f64>),
    /// Given in volts: (low, high), low below high.
    Volts(f64, f64),
}

/// The default thresholds' fractions of the swing.
pub const SWING_FRACTIONS: (f64, f64) = (0.3, 0.7);

/// A trace's levels and edges: what its report says of it.
#[derive(Debug, Clone, PartialEq)]
pub struct Swing {
    /// The low level (the 2nd percentile of the samples, V).
    pub low: f64,
    /// The high level (the 98th percentile, V).
    pub high: f64,
    /// The noise (V, one standard deviation): from the second differences of samples within
    /// 10 % of the swing of either level (where the curve itself is nearly flat), by their
    /// median absolute value (robust to the edges among them).
    pub noise: f64,
}

/// The levels of every trace together: the 2nd and 98th percentiles and the noise about them.
///
/// # Errors
/// A trace that never swings (its levels within its noise): no thresholds can be placed.
pub fn swing(file: &str, traces: &[Trace]) -> Result<Swing, CaptureError> {
    let mut all: Vec<f64> = traces
        .iter()
        .flat_map(|t| t.volts.iter().copied())
        .collect();
    all.sort_by(f64::total_cmp);
    let at = |q: f64| {
        #[allow(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            clippy::cast_precision_loss
        )]
        let i = ((all.len() - 1) as f64 * q).round() as usize;
        all[i.min(all.len() - 1)]
    };
    let (low, high) = (at(0.02), at(0.98));
    let span = high - low;
    // v[i] - (v[i-1] + v[i+1]) / 2 of white noise sigma has a deviation sigma sqrt(3/2); the
    // median of its absolute value is 0.6745 of that.
    let near = |v: f64| (v - low).abs() <= 0.1 * span || (v - high).abs() <= 0.1 * span;
    let seconds: Vec<f64> = traces
        .iter()
        .flat_map(|t| t.volts.windows(3))
        .filter(|w| w.iter().all(|&v| near(v)))
        .map(|w| (w[1] - 0.5 * (w[0] + w[2])).abs())
        .collect();
    let noise = median(&seconds).map_or(0.0, |m| m / 0.6745 / 1.5f64.sqrt());
    if span <= 0.0 || span <= 4.0 * noise {
        return Err(error(
            file,
            0,
            format!(
                "the trace never swings: its levels {low:.4} V and {high:.4} V are within its noise ({noise:.4} V)"
            ),
        ));
    }
    Ok(Swing { low, high, noise })
}

/// The thresholds (low, high) in volts, and a phrase saying where they come from.
///
/// # Errors
/// Thresholds outside the trace's swing (the input would never change), or a low threshold
/// not below the high one.
pub fn thresholds(
    file: &str,
    input: &Input,
    s: &Swing,
) -> Result<(f64, f64, String), CaptureError> {
    let (low, high, how) = match input {
        Input::Swing => {
            let span = s.high - s.low;
            (
                s.low + SWING_FRACTIONS.0 * span,
                s.low + SWING_FRACTIONS.1 * span,
                format!(
                    "{:.0} % and {:.0} % of the swing (the default; --input or --thresholds to say the MCU's)",
                    SWING_FRACTIONS.0 * 100.0,
                    SWING_FRACTIONS.1 * 100.0
                ),
            )
        }
        Input::Preset(p, vcc) => {
            let supply = vcc.unwrap_or(s.high);
            let (low, high) = p.at(supply);
            let at = if p.scales {
                match vcc {
                    Some(v) => format!(" at {v} V (--vcc)"),
                    None => format!(" at {supply:.3} V (the trace's high level; --vcc to say it)"),
                }
            } else {
                String::new()
            };
            (low, high, format!("--input {}{at}: {}", p.name, p.source))
        }
        Input::Volts(low, high) => (*low, *high, "--thresholds".to_owned()),
    };
    if low.partial_cmp(&high) != Some(std::cmp::Ordering::Less) {
        return Err(error(
            file,
            0,
            format!("the low threshold {low} V is not below the high one {high} V"),
        ));
    }
    if high <= s.low || low >= s.high {
        return Err(error(
            file,
            0,
            format!(
                "the thresholds {low:.3} V and {high:.3} V ({how}) are outside the trace's levels {:.3} V to {:.3} V: the input never changes",
                s.low, s.high
            ),
        ));
    }
    Ok((low, high, how))
}

/// A dip that crossed one threshold and turned back before the other.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Marginal {
    /// When it crossed the first threshold (s).
    pub time: f64,
    /// The voltage it turned at (V).
    pub extreme: f64,
    /// True for a dip from high (towards low), false for a rise from low.
    pub from_high: bool,
}

/// What [`to_levels`] found in one trace.
#[derive(Debug, Clone, PartialEq)]
pub struct Levels {
    /// The level changes, as a capture of levels gives them.
    pub stream: Stream,
    /// The marginal dips.
    pub marginal: Vec<Marginal>,
    /// 10-90 % rise times of the changes to high, and 90-10 % fall times of those to low (s).
    pub rises: Vec<f64>,
    /// The same, falls.
    pub falls: Vec<f64>,
}

/// The level changes an input with thresholds `low` < `high` sees in `trace` (high above
/// `high`, low below `low`, the last level kept between), the contact read through `polarity`.
/// The level before the first change is the one the first sample outside the band gives.
/// `swing` places the 10 % and 90 % points of the rise and fall times.
#[must_use]
pub fn to_levels(trace: &Trace, low: f64, high: f64, swing: &Swing, polarity: Polarity) -> Levels {
    let closed = |is_high: bool| match polarity {
        Polarity::ActiveLow => !is_high,
        Polarity::ActiveHigh => is_high,
    };
    let (t, v) = (&trace.times, &trace.volts);
    let start = v.iter().position(|&x| x <= low || x >= high);
    let mut state = start.is_some_and(|i| v[i] >= high);
    let mut changes = Vec::new();
    let mut marginal = Vec::new();
    let (mut rises, mut falls) = (Vec::new(), Vec::new());
    // A band entered from the current level: (when, the extreme so far).
    let mut dip: Option<(f64, f64)> = None;
    let crossing = |i: usize, level: f64| {
        let (t0, t1, v0, v1) = (t[i - 1], t[i], v[i - 1], v[i]);
        if v1 == v0 {
            t1
        } else {
            t0 + (t1 - t0) * ((level - v0) / (v1 - v0)).clamp(0.0, 1.0)
        }
    };
    let span = swing.high - swing.low;
    let (p10, p90) = (swing.low + 0.1 * span, swing.low + 0.9 * span);
    for i in start.map_or(v.len(), |s| s + 1)..v.len() {
        let x = v[i];
        if state {
            if x <= low {
                changes.push(crossing(i, low));
                falls.extend(edge_time(t, v, i, p90, p10));
                state = false;
                dip = None;
            } else if x < high {
                let (when, extreme) = dip.unwrap_or((crossing(i, high), x));
                dip = Some((when, extreme.min(x)));
            } else if let Some((time, extreme)) = dip.take() {
                marginal.push(Marginal {
                    time,
                    extreme,
                    from_high: true,
                });
            }
        } else if x >= high {
            changes.push(crossing(i, high));
            rises.extend(edge_time(t, v, i, p10, p90));
            state = true;
            dip = None;
        } else if x > low {
            let (when, extreme) = dip.unwrap_or((crossing(i, low), x));
            dip = Some((when, extreme.max(x)));
        } else if let Some((time, extreme)) = dip.take() {
            marginal.push(Marginal {
                time,
                extreme,
                from_high: false,
            });
        }
    }
    let first_high = start.is_some_and(|i| v[i] >= high);
    Levels {
        stream: Stream {
            closed_before: closed(first_high),
            changes,
        },
        marginal,
        rises,
        falls,
    }
}

/// The time from `from` to `to` (volts) through the edge at sample `i`: back from `i` to the
/// last sample on `from`'s side, on to the first on `to`'s side. `None` where either end is
/// past the trace, or the edge falls back to `from` before it reaches `to` (a bounce, not a
/// clean edge).
fn edge_time(t: &[f64], v: &[f64], i: usize, from: f64, to: f64) -> Option<f64> {
    let rising = to > from;
    let before = |x: f64| if rising { x <= from } else { x >= from };
    let after = |x: f64| if rising { x >= to } else { x <= to };
    let back = (0..i).rev().find(|&k| before(v[k]))?;
    let on = (i..v.len()).find(|&k| after(v[k]))?;
    let clean = !(i..on).any(|k| before(v[k]));
    clean.then(|| t[on] - t[back])
}

/// The median of `xs`, `None` when empty.
#[must_use]
pub fn median(xs: &[f64]) -> Option<f64> {
    let mut s = xs.to_vec();
    s.sort_by(f64::total_cmp);
    s.get(s.len() / 2).copied()
}

/// What an analog capture was, for the report: its acquisitions, swing, noise, edges, the
/// thresholds and where they came from, and its marginal dips.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// The export read.
    pub vendor: Vendor,
    /// The channel.
    pub channel: String,
    /// Acquisitions and samples read.
    pub acquisitions: usize,
    /// Samples read.
    pub samples: usize,
    /// The median sample interval (s).
    pub step: f64,
    /// The levels and noise.
    pub swing: Swing,
    /// The thresholds (V) and where they came from.
    pub thresholds: (f64, f64, String),
    /// Level changes found.
    pub changes: usize,
    /// Median 10-90 % rise and 90-10 % fall times (s), over the clean edges.
    pub rise: Option<f64>,
    /// See `rise`.
    pub fall: Option<f64>,
    /// The marginal dips: the acquisition (0-based) and the dip.
    pub marginal: Vec<(usize, Marginal)>,
}

impl Report {
    /// The report's section, in Markdown.
    #[must_use]
    pub fn markdown(&self) -> String {
        let us =
            |s: Option<f64>| s.map_or_else(|| "-".to_owned(), |s| format!("{:.3} us", s * 1e6));
        let mut out = format!(
            "## Analog capture\n\n{} export, channel {}: {} acquisitions, {} samples {:.3} us apart. \
             Levels {:.3} V and {:.3} V (2nd and 98th percentiles), noise {:.1} mV (one standard deviation); \
             rise time (10-90 %) {}, fall time {} (medians of the clean edges). \
             Thresholds {:.3} V and {:.3} V: {}. {} level changes.\n",
            self.vendor.name(),
            self.channel,
            self.acquisitions,
            self.samples,
            self.step * 1e6,
            self.swing.low,
            self.swing.high,
            self.swing.noise * 1e3,
            us(self.rise),
            us(self.fall),
            self.thresholds.0,
            self.thresholds.1,
            self.thresholds.2,
            self.changes,
        );
        if self.marginal.is_empty() {
            out.push_str("\nNo marginal dip: every excursion that crossed one threshold crossed the other.\n");
        } else {
            out.push_str(&format!(
                "\n{} marginal dips crossed one threshold and turned back before the other (an input at one end of its datasheet's range reads them as bounces, one at the other does not):\n\n| acquisition | t (s) | from | turned at (V) |\n|---:|---:|---|---:|\n",
                self.marginal.len()
            ));
            for (a, m) in self.marginal.iter().take(20) {
                out.push_str(&format!(
                    "| {} | {:.9} | {} | {:.3} |\n",
                    a + 1,
                    m.time,
                    if m.from_high { "high" } else { "low" },
                    m.extreme
                ));
            }
            if self.marginal.len() > 20 {
                out.push_str(&format!(
                    "\n({} more not listed.)\n",
                    self.marginal.len() - 20
                ));
            }
        }
        out
    }
}

/// Reads an analog capture and turns each acquisition into level changes: the streams (one per
/// acquisition) and the report.
///
/// # Errors
/// What [`read`], [`swing`] and [`thresholds`] refuse.
pub fn load(
    file: &str,
    text: &str,
    vendor: Option<Vendor>,
    channel: Option<&str>,
    input: &Input,
    polarity: Polarity,
) -> Result<(Vec<Stream>, Report), CaptureError> {
    let vendor = vendor.or_else(|| recognise(text));
    let traces = read(file, text, vendor, channel)?;
    let vendor = vendor.unwrap_or(Vendor::Volts);
    let s = swing(file, &traces)?;
    let (low, high, how) = thresholds(file, input, &s)?;
    let mut streams = Vec::new();
    let (mut rises, mut falls, mut marginal) = (Vec::new(), Vec::new(), Vec::new());
    let mut steps = Vec::new();
    for (k, trace) in traces.iter().enumerate() {
        let levels = to_levels(trace, low, high, &s, polarity);
        rises.extend(levels.rises);
        falls.extend(levels.falls);
        marginal.extend(levels.marginal.into_iter().map(|m| (k, m)));
        steps.extend(trace.times.windows(2).map(|w| w[1] - w[0]));
        streams.push(levels.stream);
    }
    let report = Report {
        vendor,
        channel: traces[0].channel.clone(),
        acquisitions: traces.len(),
        samples: traces.iter().map(|t| t.times.len()).sum(),
        step: median(&steps).unwrap_or(0.0),
        swing: s,
        thresholds: (low, high, how),
        changes: streams.iter().map(|s| s.changes.len()).sum(),
        rise: median(&rises),
        fall: median(&falls),
        marginal,
    };
    Ok((streams, report))
}

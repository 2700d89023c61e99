//! The desk tool's library for the page in `web/`: one entry point, [`call`], taking a command
//! and its input as text and giving back text, the same functions the `bounce-table` command
//! calls (no re-implementation in JavaScript). Exported to WebAssembly as `cb_alloc`,
//! `cb_free` and `cb_call` (C ABI, memory passed by pointer and length).
//!
//! Commands, each a JSON object in and a JSON object out (`{"ok": ...}` or `{"error": "..."}`,
//! the error in the command line tool's words):
//! - `eval`: `{"line": <an eval line>, "method": "auto", "precision": "f64"}` -> the result
//!   object `bounce-table eval` prints for it;
//! - `calibrate` / `replay`: `{"args": [<options>], "files": [[name, text], ...]}` -> the text
//!   the subcommand prints (the report, or `--format c|rust|csv|json`); for `replay` (with
//!   `--taps` or not), `{"text": ..., "plots": [{"name", "svg"}]}`, the plots `--plot DIR`
//!   writes (the Pareto fronts);
//! - `trace`: `{"args": [<options>], "files": [[name, text], ...]}` -> each test to draw: an
//!   analog capture's acquisitions (times and volts, at most 4,000 points each) with their
//!   file's thresholds, or a capture of levels' events; with calibrate's windows;
//! - `table`: `{"text": <scene lines>, "args": [<table options>]}` -> the table mode's output
//!   for those switches (`--format table|c|rust|...`, `--sample-period`, `--margin`, ...) and, for
//!   each, its two plots (the envelope J(t) with the exact impacts, and the motion) as SVG.
//!
//! Several files in `files` are a folder's, read as the CLI reads a folder: `"switch"` names
//! it (else the first file's name without its extension names the switch).

use bounce_table::capture::EdgeName;
use bounce_table::capture::{self, scope};
use bounce_table::cli;
use bounce_table::commands::replay::{self, taps};
use bounce_table::commands::{calibrate, eval, table};
use bounce_table::render::output::render_to;
use bounce_table::render::plot;
use bounce_table::scene::file::Entries;
use bounce_table::stats;
use serde_json::{json, Value};

/// Runs `command` on `input` (JSON): the JSON answer.
#[must_use]
pub fn call(command: &str, input: &str) -> String {
    let answer = match serde_json::from_str::<Value>(input) {
        Ok(v) => match command {
            "eval" => eval_line(&v),
            "calibrate" | "replay" => subcommand(command, &v).map_err(|e| json!({ "error": e })),
            "trace" => trace(&v).map_err(|e| json!({ "error": e })),
            "table" => table_mode(&v).map_err(|e| json!({ "error": e })),
            "catalogue" => Ok(catalogue()),
            _ => Err(json!({ "error": format!("unknown command {command:?}") })),
        },
        Err(e) => Err(json!({ "error": format!("the input is not JSON: {e}") })),
    };
    match answer {
        Ok(v) => json!({ "ok": v }).to_string(),
        Err(e) => e.to_string(),
    }
}

/// The catalogue's switches as eval lines (`bounce-table/scenes/catalogue.jsonl`).
fn catalogue() -> Value {
    let lines: Vec<Value> = include_str!("../../../bounce-table/scenes/catalogue.jsonl")
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| Value::String(l.to_owned()))
        .collect();
    Value::Array(lines)
}

fn strings(v: &Value, key: &str) -> Vec<String> {
    v.get(key)
        .and_then(Value::as_array)
        .map(|a| {
            a.iter()
                .filter_map(|x| x.as_str().map(str::to_owned))
                .collect()
        })
        .unwrap_or_default()
}

/// An eval line's result, or its refusal: the message and the field at fault (empty for the
/// line), as `bounce-table eval` reports them.
fn eval_line(v: &Value) -> Result<Value, Value> {
    let line = v.get("line").and_then(Value::as_str).unwrap_or("");
    let mut args = vec!["eval".to_owned()];
    for key in ["method", "precision"] {
        if let Some(x) = v.get(key).and_then(Value::as_str) {
            args.push(format!("--{key}={x}"));
        }
    }
    let options = match cli::parse(args) {
        Ok(cli::Invocation::Eval(o)) => o,
        Ok(_) => return Err(json!({ "error": "not an eval" })),
        Err(e) => return Err(json!({ "error": e.message })),
    };
    eval::evaluate(line, 1, &options)
        .map_err(|(name, e)| json!({ "error": e.message, "field": e.field, "name": name }))
}

/// The capture's files: (name, text) pairs.
fn files(v: &Value) -> Vec<(String, String)> {
    v.get("files")
        .and_then(Value::as_array)
        .map(|a| {
            a.iter()
                .filter_map(|f| {
                    let pair = f.as_array()?;
                    Some((
                        pair.first()?.as_str()?.to_owned(),
                        pair.get(1)?.as_str()?.to_owned(),
                    ))
                })
                .collect()
        })
        .unwrap_or_default()
}

/// The switch the capture's files are: `"switch"` where given (a folder's name, for several
/// files), else the first file's name without its extension, as the CLI names them.
fn switch_name(v: &Value, files: &[(String, String)]) -> String {
    if let Some(name) = v.get("switch").and_then(Value::as_str) {
        return name.to_owned();
    }
    let first = files.first().map_or("capture", |(name, _)| name.as_str());
    std::path::Path::new(first)
        .file_stem()
        .map_or_else(|| first.to_owned(), |s| s.to_string_lossy().into_owned())
}

fn subcommand(command: &str, v: &Value) -> Result<Value, String> {
    let files = files(v);
    let Some((first, _)) = files.first() else {
        return Err("no capture".to_owned());
    };
    let mut args = vec![command.to_owned()];
    args.extend(strings(v, "args"));
    args.push(first.clone());
    let invocation = cli::parse(args).map_err(|e| e.message)?;
    let name = switch_name(v, &files);
    match invocation {
        cli::Invocation::Calibrate(o) => {
            let loaded =
                capture::load_text(&o.capture, &name, &files).map_err(|e| e.to_string())?;
            calibrate::written(&o, &loaded, || {
                taps::window_costs(&loaded.events, &o.calibration)
            })
            .map(Value::String)
        }
        cli::Invocation::Replay(request) => {
            let loaded =
                capture::load_text(&request.capture, &name, &files).map_err(|e| e.to_string())?;
            let json = request.output == replay::Output::Json;
            let (text, plots) = if request.output == replay::Output::Curve {
                if request.taps.is_some() {
                    return Err("--format curve is the isolated replay's learning curve; with --taps, give table or json".to_owned());
                }
                let curves = replay::learning_curves(&loaded.events, &request.settings)?;
                (replay::curve_csv(&curves), Vec::new())
            } else if let Some(t) = &request.taps {
                let lines = taps::run(&loaded.events, &request.calibration, &request.settings, t)?;
                let text = if json {
                    taps::json(&lines)
                } else {
                    taps::markdown(&lines, t)
                };
                (text, taps::plots(&lines))
            } else {
                let lines = replay::run(&loaded.events, &request.calibration, &request.settings)?;
                let text = if json {
                    replay::json(&lines)
                } else {
                    replay::report(&loaded, request.capture.event_gap, &lines)
                };
                (text, replay::plots(&lines))
            };
            let plots: Vec<Value> = plots
                .into_iter()
                .map(|(name, svg)| json!({ "name": name, "svg": svg }))
                .collect();
            Ok(json!({ "text": text, "plots": plots }))
        }
        _ => Err(format!("not {command}")),
    }
}

/// Each test of a capture to draw, with the window calibrate recommends for its switch and
/// kind: an analog capture's acquisitions (times and volts, at most 4,000 points each, with
/// the level changes the input's thresholds give), or a capture of levels' events (their
/// changes).
fn trace(v: &Value) -> Result<Value, String> {
    let files = files(v);
    let Some((first, _)) = files.first() else {
        return Err("no capture".to_owned());
    };
    let mut args = vec!["calibrate".to_owned()];
    args.extend(strings(v, "args"));
    args.push(first.clone());
    let o = match cli::parse(args).map_err(|e| e.message)? {
        cli::Invocation::Calibrate(o) => o,
        _ => return Err("not calibrate".to_owned()),
    };
    let stem = switch_name(v, &files);
    let loaded = capture::load_text(&o.capture, &stem, &files).map_err(|e| e.to_string())?;
    // The windows calibrate recommends, per switch and kind (none below its minimum of
    // events), keyed "switch/kind".
    let groups = stats::group(
        &loaded.events,
        o.calibration.resolution,
        o.calibration.burst_gap,
    );
    let mut windows = serde_json::Map::new();
    for ((switch, kind), d) in &groups {
        let refs: Vec<&bounce_table::capture::Description> = d.iter().collect();
        let w = stats::window(&refs, o.calibration.percentile);
        if !w.too_few() {
            windows.insert(format!("{switch}/{}", kind.name()), json!(w.recommended()));
        }
    }
    let capture::Format::Scope(vendor) = o.capture.format else {
        let tests: Vec<Value> = loaded
            .events
            .iter()
            .map(|e| {
                json!({
                    "switch": e.switch,
                    "kind": e.kind.name(),
                    "origin": e.origin,
                    "section": e.section,
                    "changes": e.changes,
                })
            })
            .collect();
        return Ok(json!({ "acquisitions": tests, "windows": windows }));
    };
    // Each file's acquisitions, with that file's thresholds (a folder's files are read one
    // by one, as the CLI reads them).
    let mut acquisitions = Vec::new();
    for (name, text) in &files {
        let traces = scope::read(name, text, vendor, o.capture.channel.as_deref())
            .map_err(|e| e.to_string())?;
        let swing = scope::swing(name, &traces).map_err(|e| e.to_string())?;
        let (low, high, how) =
            scope::thresholds(name, &o.capture.input, &swing).map_err(|e| e.to_string())?;
        for t in &traces {
            let levels = scope::to_levels(t, low, high, &swing, o.capture.polarity);
            let step = (t.times.len() / 4000).max(1);
            let pick = |xs: &[f64]| xs.iter().step_by(step).copied().collect::<Vec<f64>>();
            let kind = if levels.stream.closed_before {
                "release"
            } else {
                "press"
            };
            acquisitions.push(json!({
                "switch": stem,
                "file": name,
                "channel": t.channel,
                "t": pick(&t.times),
                "v": pick(&t.volts),
                "changes": levels.stream.changes,
                "kind": kind,
                "low": low,
                "high": high,
                "how": how,
            }));
        }
    }
    Ok(json!({ "acquisitions": acquisitions, "windows": windows }))
}

/// The name the page's scene lines go by, in faults and in generated code.
const PAGE_SCENES: &str = "scenes.jsonl";

/// The table mode on the page's scene lines, as `bounce-table [OPTIONS] scenes.jsonl` runs it,
/// with each switch's plots.
fn table_mode(v: &Value) -> Result<Value, String> {
    let text = v.get("text").and_then(Value::as_str).unwrap_or("");
    let mut args = strings(v, "args");
    args.push(PAGE_SCENES.to_owned());
    let options = match cli::parse(args).map_err(|e| e.message)? {
        cli::Invocation::Table(o) => o,
        _ => return Err("not the table mode".to_owned()),
    };
    let mut faults = Vec::new();
    let analysed = table::analyse_all(
        Entries::from_json_lines(PAGE_SCENES, text),
        &options.settings,
        options.format,
        PAGE_SCENES,
        &mut |message| faults.push(message),
    );
    let Some((mut analyses, layout)) = analysed else {
        return Err(faults.join("\n"));
    };
    let mut out = Vec::new();
    render_to(
        &mut out,
        options.format,
        &mut analyses,
        &options.settings,
        false,
        PAGE_SCENES,
        Some(layout),
    )
    .map_err(|e| e.to_string())?;
    let mut plots = Vec::new();
    let rows = analyses.rows().map_err(|e| e.to_string())?;
    for (entry, a) in Entries::from_json_lines(PAGE_SCENES, text).zip(rows) {
        let (Ok(entry), Ok(a)) = (entry, a) else {
            continue;
        };
        let (envelope, motion) =
            plot::plots(entry.template.nominal(), &a, options.settings.percentile)
                .map_err(|e| format!("{}: {}", e.field, e.message))?;
        plots.push(json!({
            "name": entry.name,
            "window": a.window,
            "bounce": a.nominal.bounce,
            "envelope": envelope,
            "motion": motion,
        }));
    }
    Ok(json!({
        "text": String::from_utf8_lossy(&out),
        "plots": plots,
    }))
}

/// Reserves `len` bytes in the module's memory for the page to write into.
#[no_mangle]
pub extern "C" fn cb_alloc(len: usize) -> *mut u8 {
    let mut buffer = Vec::<u8>::with_capacity(len.max(1));
    let pointer = buffer.as_mut_ptr();
    std::mem::forget(buffer);
    pointer
}

/// Gives back what [`cb_alloc`] or [`cb_call`] reserved (`len`: the length reserved).
///
/// # Safety
/// `pointer` and `len` are what one of them gave, once.
#[no_mangle]
pub unsafe extern "C" fn cb_free(pointer: *mut u8, len: usize) {
    drop(Vec::from_raw_parts(pointer, 0, len.max(1)));
}

/// Runs a command: its name and input are UTF-8 at the pointers given. Returns a pointer to
/// 8 bytes (the answer's address and length, little-endian u32 each) followed by nothing
/// else; free the answer and then those 8 bytes with [`cb_free`].
///
/// # Safety
/// The pointers and lengths describe memory [`cb_alloc`] gave and the page wrote.
#[no_mangle]
pub unsafe extern "C" fn cb_call(
    command: *const u8,
    command_len: usize,
    input: *const u8,
    input_len: usize,
) -> *mut u8 {
    let command = String::from_utf8_lossy(std::slice::from_raw_parts(command, command_len));
    let input = String::from_utf8_lossy(std::slice::from_raw_parts(input, input_len));
    let answer = call(&command, &input).into_bytes();
    let (pointer, len) = (answer.as_ptr() as usize, answer.len());
    std::mem::forget(answer.into_boxed_slice());
    let mut header = Vec::with_capacity(8);
    header.extend_from_slice(&(pointer as u32).to_le_bytes());
    header.extend_from_slice(&(len as u32).to_le_bytes());
    let out = header.as_mut_ptr();
    std::mem::forget(header);
    out
}

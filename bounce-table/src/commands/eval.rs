//! `bounce-table eval`: JSON Lines scenes on stdin, one JSON result per line on stdout.
//!
//! Options: `--method reference|exact-tier|map|averaged|closed|auto` (default auto; `reference`
//! is the host's exact reference, `exact-tier` the core's exact tier), `--tolerance X` (for
//! auto, default 0.01), `--precision f32|f64` (core tiers, default f64), `--nodes N` (averaged,
//! default 8). A bad line gets an error object naming the line and the field; the other lines
//! still run, and the exit status is 1 if any line failed.

use std::io::{BufRead, Write};

use contact_bounce::{
    tiers::Count, tiers::MapImpacts, tiers::Time, tiers::DEFAULT_MAX_IMPACTS, Float, Method, Nodes,
    Prediction, Tolerance,
};
use serde_json::{json, Value};

use crate::scene::input::{FieldError, SceneInput};
use crate::scene::reference::outcome;

/// The tier asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EvalMethod {
    /// The host's exact reference (`contact-bounce-reference`; host only).
    Reference,
    /// The core's exact tier (the core's `Method::Exact`, the same in firmware).
    ExactTier,
    /// The semi-discrete map.
    Map,
    /// The averaged model.
    Averaged,
    /// Closed forms.
    Closed,
    /// The cheapest tier meeting the tolerance.
    Auto,
}

impl EvalMethod {
    fn name(self) -> &'static str {
        match self {
            Self::Reference => "reference",
            Self::ExactTier => "exact-tier",
            Self::Map => "map",
            Self::Averaged => "averaged",
            Self::Closed => "closed",
            Self::Auto => "auto",
        }
    }
}

/// The float of `--precision`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Precision {
    /// `f32`, as most firmware would run.
    F32,
    /// `f64`.
    F64,
}

impl Precision {
    /// As `--precision` and the results write it.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::F32 => "f32",
            Self::F64 => "f64",
        }
    }
}

/// Parsed options.
#[derive(Debug, Clone)]
pub struct Options {
    /// Tier.
    pub method: EvalMethod,
    /// Relative tolerance for auto.
    pub tolerance: f64,
    /// The float the core's tiers run in.
    pub precision: Precision,
    /// Averaged tier nodes.
    pub nodes: Nodes,
    /// The JSON Lines file to read; standard input when `None`.
    pub file: Option<String>,
}

fn time<F: Float>(t: Time<F>) -> Value {
    t.seconds().map_or(Value::Null, |s| json!(s.to_f64()))
}

fn count<F: Float>(n: Count<F>, whole: bool) -> Value {
    match n.value() {
        None => Value::Null,
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        Some(v) if whole && v.to_f64() < 9.0e15 => json!(v.to_f64().round() as u64),
        Some(v) => json!(v.to_f64()),
    }
}

fn significant(x: f64, digits: i32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    #[allow(clippy::cast_possible_truncation)]
    let magnitude = x.abs().log10().floor() as i32;
    let scale = 10f64.powi(digits - 1 - magnitude);
    (x * scale).round() / scale
}

/// How far rounding the restitution coefficient to F can move the bounce, relative: the loss
/// r = 1 - R moves by the ratio rho = r_F / r, and the bounce goes as r^-s with s in [0, 1]
/// (1 on a preload's accumulation, less in a gap), so by at most max(|rho - 1|, |1/rho - 1|)
/// (0 for f64, and where R is exact in F). The other inputs round by at most F's epsilon,
/// relative, which moves the bounce by a few epsilon: below every tier's stated error in f32.
fn restitution_rounding<F: Float>(restitution: f64) -> f64 {
    let loss = 1.0 - restitution;
    if loss <= 0.0 {
        return 0.0;
    }
    let rounded = 1.0 - F::from_f64(restitution).to_f64();
    if rounded <= 0.0 {
        // R rounds to 1 in F: the loss is gone, and the bounce no longer ends.
        return f64::INFINITY;
    }
    let ratio = rounded / loss;
    (ratio - 1.0).abs().max((1.0 / ratio - 1.0).abs())
}

fn core_result<F: Float>(input: &SceneInput, options: &Options) -> Result<Value, FieldError> {
    let scene = input.core::<F>()?;
    let method = match options.method {
        EvalMethod::Map => Method::Map {
            max_impacts: DEFAULT_MAX_IMPACTS,
        },
        EvalMethod::Averaged => Method::Averaged(options.nodes),
        EvalMethod::Closed => Method::Closed,
        EvalMethod::ExactTier => Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        },
        EvalMethod::Auto | EvalMethod::Reference => {
            Method::Auto(Tolerance::new(F::from_f64(options.tolerance)).map_err(FieldError::from)?)
        }
    };
    let p: Prediction<F> = scene.predict(method);
    // The scene was given in f64 and is evaluated in F: where R is near 1, rounding R moves
    // r = 1 - R, and the bounce (~ 1 / r) with it, by far more than the tier's own error
    // (R = 0.99999995 is 1 - 5.96e-8 in f32: 19 % off). That share belongs in the error.
    let rounding = restitution_rounding::<F>(input.restitution);
    let expected = p.expected_error.map(|e| e.to_f64() + rounding);
    // The averaged tier counts in real numbers; the others in whole impacts.
    let whole = !matches!(p.tier, contact_bounce::tiers::Tier::Averaged(_));
    let first = if options.method == EvalMethod::Map {
        let impacts: Vec<Value> = MapImpacts::new(&scene, DEFAULT_MAX_IMPACTS)
            .take(5)
            .map(|i| json!([i.time.to_f64(), i.impulse.to_f64()]))
            .collect();
        Value::Array(impacts)
    } else {
        Value::Null
    };
    let approximate = p
        .approximations
        .contains(contact_bounce::tiers::Approximations::TWO_BODY_RAYLEIGH)
        || p.approximations
            .contains(contact_bounce::tiers::Approximations::OUTSIDE_VALIDITY);
    let mut out = json!({
        "name": input.name,
        "method": options.method.name(),
        "regime": p.regime.name(),
        "end_time": time(p.end_time),
        "impacts_total": count(p.impacts_total, whole),
        "last_above_time": time(p.last_above_time),
        "impacts_above": count(p.impacts_above, whole),
        "first_impacts": first,
        "approximate": approximate,
        "approximations": p.approximations.names().collect::<Vec<_>>(),
        "tier": format!("{:?}", p.tier),
        // Expected errors are estimates (some stored as f32): four significant digits.
        "expected_error": expected.map(|e| significant(e, 4)),
        "precision": options.precision.name(),
    });
    if options.method == EvalMethod::Auto {
        if let (Some(map), Ok(t)) = (
            out.as_object_mut(),
            Tolerance::new(F::from_f64(options.tolerance)),
        ) {
            let kept = expected.is_some_and(|e| e <= options.tolerance);
            map.insert("promised".to_owned(), json!(p.promises(t) && kept));
        }
    }
    Ok(out)
}

fn reference_result(input: &SceneInput) -> Result<Value, FieldError> {
    let out = outcome(input)?;
    let regime = out.regime.name();
    Ok(json!({
        "name": input.name,
        "method": "reference",
        "regime": regime,
        "end_time": out.end_time,
        "impacts_total": out.impacts_total,
        "last_above_time": out.last_above_time,
        "impacts_above": out.impacts_above,
        "first_impacts": out.first_impacts.iter().map(|(t, p)| json!([t, p])).collect::<Vec<_>>(),
        "approximate": false,
        "approximations": [],
    }))
}

/// Evaluates one line.
///
/// # Errors
/// The field at fault.
pub fn evaluate(
    line: &str,
    number: usize,
    options: &Options,
) -> Result<Value, (String, FieldError)> {
    let default_name = format!("line {number}");
    let value: Value = crate::support::strict::json(line).map_err(|(_, message)| {
        (
            default_name.clone(),
            FieldError {
                field: String::new(),
                message,
            },
        )
    })?;
    let input = SceneInput::from_json(&value, &default_name).map_err(|e| {
        let name = value
            .get("name")
            .and_then(Value::as_str)
            .unwrap_or(&default_name)
            .to_owned();
        (name, e)
    })?;
    let result = match (options.method, options.precision) {
        (EvalMethod::Reference, _) => reference_result(&input),
        (_, Precision::F32) => core_result::<f32>(&input, options),
        (_, Precision::F64) => core_result::<f64>(&input, options),
    };
    result.map_err(|e| (input.name.clone(), e))
}

/// The scene file to read, or standard input.
///
/// # Errors
/// When the file cannot be opened (the message names it).
pub fn input(options: &Options) -> std::io::Result<Box<dyn BufRead>> {
    Ok(match &options.file {
        Some(path) => Box::new(std::io::BufReader::new(
            std::fs::File::open(path)
                .map_err(|e| std::io::Error::new(e.kind(), format!("{path}: {e}")))?,
        )),
        None => Box::new(std::io::stdin().lock()),
    })
}

/// Runs `eval` over `input` ([`input`]); returns whether every line succeeded.
///
/// # Errors
/// When reading the input or writing stdout fails.
pub fn run(options: &Options, input: Box<dyn BufRead>) -> std::io::Result<bool> {
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let mut all_ok = true;
    for (index, line) in input.lines().enumerate() {
        let line = line?;
        if line.trim().is_empty() {
            continue;
        }
        let number = index + 1;
        let value = match evaluate(&line, number, options) {
            Ok(v) => v,
            Err((name, e)) => {
                all_ok = false;
                json!({ "line": number, "name": name, "field": e.field, "error": e.message })
            }
        };
        if let Err(e) = writeln!(out, "{value}") {
            // A reader that stopped early (`| head`) is not a failure of ours.
            if e.kind() == std::io::ErrorKind::BrokenPipe {
                return Ok(all_ok);
            }
            return Err(e);
        }
    }
    Ok(all_ok)
}

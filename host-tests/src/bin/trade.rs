//! The accuracy side of the speed/accuracy trade: every tier, in f64 and f32, against the
//! exact reference on the committed grid (`host_tests::grid`): median, P95 and max relative
//! error of the end time and of the last-above-threshold time, per regime. Prints JSON (read
//! by `scripts/trade-report.py`); with `--scenes FILE` also writes the grid's scenes and their
//! reference answers for the peer simulation (`scripts/peer.py`).
//!
//! The f32 backend is this build's (`--features contact-bounce/micromath` for micromath).

use std::collections::BTreeMap;

use contact_bounce::{numeric::F32_BACKEND, Method, Nodes, Prediction};
use host_tests::grid::grid;
use host_tests::reference::{simulate, Outcome, DEFAULT_BUDGET};
use host_tests::stats::nearest_rank;
use serde_json::json;

fn methods<F: contact_bounce::Float>() -> Vec<(&'static str, Method<F>)> {
    vec![
        ("closed", Method::Closed),
        ("averaged N2", Method::Averaged(Nodes::N2)),
        ("averaged N4", Method::Averaged(Nodes::N4)),
        ("averaged N8", Method::Averaged(Nodes::N8)),
        ("averaged N16", Method::Averaged(Nodes::N16)),
        (
            "map",
            Method::Map {
                max_impacts: 10_000_000,
            },
        ),
        (
            "exact",
            Method::Exact {
                max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
            },
        ),
    ]
}

fn relative(c: Option<f64>, t: f64) -> f64 {
    match c {
        Some(c) if t > 0.0 => (c / t - 1.0).abs(),
        Some(0.0) => 0.0,
        _ => f64::INFINITY,
    }
}

fn errors<F: contact_bounce::Float>(
    p: &Prediction<F>,
    truth: &Outcome,
) -> [(&'static str, Option<f64>); 2] {
    let end = truth
        .end_time
        .map(|t| relative(p.end_time.seconds().map(F::to_f64), t));
    let above = truth
        .last_above_time
        .filter(|_| truth.end_time.is_none() || p.impacts_above.value().is_some())
        .filter(|_| truth.impacts_above.is_some())
        .map(|t| relative(p.last_above_time.seconds().map(F::to_f64), t));
    [("end", end), ("last_above", above)]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let scenes_out = args
        .iter()
        .position(|a| a == "--scenes")
        .and_then(|i| args.get(i + 1))
        .cloned();
    let mut samples: BTreeMap<(String, &str, &str, &str), Vec<f64>> = BTreeMap::new();
    let mut exported = Vec::new();
    for g in grid() {
        let Ok(truth) = simulate(&g.reference, DEFAULT_BUDGET) else {
            continue;
        };
        let family = truth.regime.name();
        exported.push(json!({
            "name": g.name, "family": g.family, "regime": family,
            "omega": g.reference.omega, "delta": g.reference.delta, "restitution": g.reference.restitution,
            "zeta": g.reference.zeta, "closing_speed": g.reference.closing_speed, "threshold": g.reference.threshold,
            "end_time": truth.end_time, "last_above_time": truth.last_above_time,
        }));
        if let Ok(s64) = g.core() {
            for (tier, m) in methods::<f64>() {
                for (what, e) in errors(&s64.predict(m), &truth) {
                    if let Some(e) = e {
                        samples
                            .entry((tier.to_owned(), "f64", family, what))
                            .or_default()
                            .push(e);
                    }
                }
            }
        }
        if let Ok(s32) = g.core_f32() {
            for (tier, m) in methods::<f32>() {
                for (what, e) in errors(&s32.predict(m), &truth) {
                    if let Some(e) = e {
                        samples
                            .entry((tier.to_owned(), "f32", family, what))
                            .or_default()
                            .push(e);
                    }
                }
            }
        }
    }
    let rows: Vec<_> = samples
        .into_iter()
        .map(|((tier, precision, regime, what), mut v)| {
            v.sort_by(f64::total_cmp);
            let at = |q: f64| match nearest_rank(&v, q) {
                Some(x) if x.is_finite() => json!(x),
                _ => json!("inf"),
            };
            json!({
                "tier": tier, "precision": precision, "backend": if precision == "f32" { F32_BACKEND } else { "libm" },
                "regime": regime, "quantity": what, "scenes": v.len(),
                "median": at(0.5), "p95": at(0.95), "max": at(1.0),
            })
        })
        .collect();
    println!(
        "{}",
        serde_json::to_string_pretty(&json!({ "f32_backend": F32_BACKEND, "rows": rows }))
            .unwrap_or_default()
    );
    if let Some(path) = scenes_out {
        if let Err(e) = std::fs::write(
            &path,
            serde_json::to_string_pretty(&exported).unwrap_or_default(),
        ) {
            eprintln!("trade: {path}: {e}");
            std::process::exit(1);
        }
    }
}

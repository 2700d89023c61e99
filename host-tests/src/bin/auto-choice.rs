//! How well `Method::Auto` chooses on the host: for each scene of the committed grid, 200 scenes
//! off it and the kernel grid (`host_tests::grid`), f64, at a tolerance (default 1 %), the time
//! of Auto and the time of the cheapest tier that keeps the tolerance (closed, averaged N8, the
//! map, the exact tier: each run, and timed where it promises). Prints, for the scenes with
//! viscous damping and those with a relaxation kernel: how many Auto promised, Auto's median
//! and P90 time, Auto's median where a tier cheaper than the exact one promises, and the ratio
//! of Auto's time to the cheapest promising tier's (median, P90, max). Auto weighs the tiers by
//! costs fitted on a Cortex-M4F (`docs/reports/cost-report.md`), so on this host it can pick a tier
//! that is not the fastest here: the ratio says how far that costs.
//!
//! Each time is the best of 5 runs of at least 200 us of repeated calls: a measurement, not a
//! test (quote medians and ratios).
//!
//! `cargo run --release -p host-tests --bin auto-choice [-- TOLERANCE]`

use std::hint::black_box;
use std::time::Instant;

use contact_bounce::scene::Dissipation;
use contact_bounce::{Method, Nodes, Scene, Tolerance};
use host_tests::grid::{grid, kernel_grid, off_grid};
use host_tests::stats::nearest_rank_unsorted as nearest_rank;

/// One scene: Auto's time, the cheapest promising tier's (if any), whether Auto promised, and
/// whether a tier cheaper than the exact one promised.
struct Choice {
    auto: f64,
    cheapest: Option<f64>,
    promised: bool,
    cheaper_than_exact: bool,
}

fn time<D: Dissipation<f64>>(scene: &Scene<f64, D>, method: Method<f64>) -> f64 {
    let mut best = f64::MAX;
    for _ in 0..5 {
        let start = Instant::now();
        let mut calls = 0_u32;
        while start.elapsed().as_secs_f64() < 2e-4 {
            black_box(black_box(scene).predict(black_box(method)));
            calls += 1;
        }
        best = best.min(start.elapsed().as_secs_f64() / f64::from(calls));
    }
    best
}

fn choice<D: Dissipation<f64>>(scene: &Scene<f64, D>, tolerance: Tolerance<f64>) -> Choice {
    let auto = Method::Auto(tolerance);
    let mut cheapest: Option<f64> = None;
    let mut cheaper_than_exact = false;
    for method in [
        Method::Closed,
        Method::Averaged(Nodes::N8),
        Method::Map {
            max_impacts: contact_bounce::tiers::DEFAULT_MAX_IMPACTS,
        },
        Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        },
    ] {
        if scene.predict(method).promises(tolerance) {
            let t = time(scene, method);
            cheapest = Some(cheapest.map_or(t, |c| c.min(t)));
            cheaper_than_exact |= !matches!(method, Method::Exact { .. });
        }
    }
    Choice {
        auto: time(scene, auto),
        cheapest,
        promised: scene.predict(auto).promises(tolerance),
        cheaper_than_exact,
    }
}

fn summary(name: &str, choices: &[Choice]) {
    let mut autos: Vec<f64> = choices.iter().map(|c| c.auto).collect();
    let mut cheaper: Vec<f64> = choices
        .iter()
        .filter(|c| c.cheaper_than_exact)
        .map(|c| c.auto)
        .collect();
    let mut ratios: Vec<f64> = choices
        .iter()
        .filter_map(|c| c.cheapest.map(|t| c.auto / t))
        .collect();
    let promised = choices.iter().filter(|c| c.promised).count();
    let ns = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{:.0} ns", v * 1e9));
    let ratio = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.2}"));
    let max = nearest_rank(&mut ratios, 1.0);
    println!(
        "{name}: {} scenes, {promised} promised; Auto median {} (P90 {}); where a tier cheaper than \
         the exact one promises ({} scenes) median {}; Auto / cheapest promising: median {}, P90 {}, max {}",
        choices.len(),
        ns(nearest_rank(&mut autos, 0.5)),
        ns(nearest_rank(&mut autos, 0.9)),
        cheaper.len(),
        ns(nearest_rank(&mut cheaper, 0.5)),
        ratio(nearest_rank(&mut ratios, 0.5)),
        ratio(nearest_rank(&mut ratios, 0.9)),
        ratio(max),
    );
}

fn main() {
    let relative: f64 = std::env::args()
        .nth(1)
        .map_or(Ok(0.01), |a| a.parse())
        .unwrap_or_else(|e| panic!("the tolerance: {e}"));
    let tolerance = Tolerance::new(relative).unwrap_or_else(|e| panic!("the tolerance: {e}"));
    println!("Auto at {relative} (f64, this host)");
    let mut viscous = Vec::new();
    for scene in grid().iter().chain(off_grid(200, 7).iter()) {
        if let Ok(core) = scene.core() {
            viscous.push(choice(&core, tolerance));
        }
    }
    summary("viscous damping", &viscous);
    let kernels: Vec<Choice> = kernel_grid()
        .iter()
        .filter_map(|k| k.core().ok())
        .map(|core| choice(&core, tolerance))
        .collect();
    summary("relaxation kernel", &kernels);
}

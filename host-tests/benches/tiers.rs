//! The cost side of the speed/accuracy trade on the host: time per prediction of every tier
//! (f64 and f32) and of the exact reference, on representative scenes of the committed grid
//! (one per regime family, and switches of physics.md sec. 7). Medians, by criterion; read by
//! `scripts/trade-report.py` from target/criterion.
//!
//! A benchmark, not a test: CI only builds it and runs each case once (`-- --test`).

use std::hint::black_box;
use std::time::Duration;

use contact_bounce::{catalogue, Method, Nodes, Tolerance, EXACT_MAX_IMPACTS};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use host_tests::grid::{grid, GridScene};
use host_tests::reference::{simulate, DEFAULT_BUDGET};

/// The scenes timed: their names in the grid.
pub const SCENES: [&str; 7] = [
    "preload R=0.7 zeta=0.01 j0=1",
    "preload R=0.99 zeta=0.05 j0=3",
    "gap R=0.9 zeta=0.01 j0=10",
    "gap-undamped R=0.9 zeta=0 j0=1 P_end=0.001P0",
    "grazing R=0.9 zeta=0.01 j0=1 P_end=0.001P0",
    "tactile dome",
    "large contactor",
];

fn tiers(c: &mut Criterion) {
    let all = grid();
    let scenes: Vec<&GridScene> = SCENES
        .iter()
        .map(|n| {
            all.iter()
                .find(|g| g.name == *n)
                .expect("scene in the grid")
        })
        .collect();
    let tiers: [(&str, Method<f64>, Method<f32>); 7] = [
        ("closed", Method::Closed, Method::Closed),
        (
            "averaged N2",
            Method::Averaged(Nodes::N2),
            Method::Averaged(Nodes::N2),
        ),
        (
            "averaged N4",
            Method::Averaged(Nodes::N4),
            Method::Averaged(Nodes::N4),
        ),
        (
            "averaged N8",
            Method::Averaged(Nodes::N8),
            Method::Averaged(Nodes::N8),
        ),
        (
            "averaged N16",
            Method::Averaged(Nodes::N16),
            Method::Averaged(Nodes::N16),
        ),
        (
            "map",
            Method::Map {
                max_impacts: 10_000_000,
            },
            Method::Map {
                max_impacts: 10_000_000,
            },
        ),
        (
            "exact",
            Method::Exact {
                max_impacts: EXACT_MAX_IMPACTS,
            },
            Method::Exact {
                max_impacts: EXACT_MAX_IMPACTS,
            },
        ),
    ];
    for (tier, m64, m32) in tiers {
        let mut group = c.benchmark_group(format!("f64 {tier}"));
        for g in &scenes {
            let s = g.core().expect("valid");
            group.bench_with_input(BenchmarkId::from_parameter(&g.name), &s, |b, s| {
                b.iter(|| black_box(s).predict(black_box(m64)))
            });
        }
        group.finish();
        let mut group = c.benchmark_group(format!("f32 {tier}"));
        for g in &scenes {
            let s = g.core_f32().expect("valid");
            group.bench_with_input(BenchmarkId::from_parameter(&g.name), &s, |b, s| {
                b.iter(|| black_box(s).predict(black_box(m32)))
            });
        }
        group.finish();
    }
    let mut group = c.benchmark_group("exact reference");
    for g in &scenes {
        group.bench_with_input(
            BenchmarkId::from_parameter(&g.name),
            &g.reference,
            |b, r| b.iter(|| simulate(black_box(r), DEFAULT_BUDGET)),
        );
    }
    group.finish();
    catalogue_switches(c);
}

/// The eight catalogue switches (f64): the exact tier, and Auto at 1 %.
fn catalogue_switches(c: &mut Criterion) {
    let auto = Method::Auto(Tolerance::new(0.01).expect("valid"));
    let exact = Method::Exact {
        max_impacts: EXACT_MAX_IMPACTS,
    };
    for (label, method) in [("catalogue exact", exact), ("catalogue auto 1%", auto)] {
        let mut group = c.benchmark_group(label);
        for switch in catalogue::ALL {
            let s = switch.scene::<f64>().expect("valid");
            group.bench_with_input(BenchmarkId::from_parameter(switch.name), &s, |b, s| {
                b.iter(|| black_box(s).predict(black_box(method)))
            });
        }
        group.finish();
    }
}

fn config() -> Criterion {
    Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_millis(600))
}

criterion_group! { name = benches; config = config(); targets = tiers }
criterion_main!(benches);

//! The cost side of the speed/accuracy trade on the host: time per prediction of every tier
//! (f64 and f32) and of the exact reference, on representative scenes of the committed grid
//! (one per regime family, and switches of docs/physics.md sec. 7). Medians, by criterion; read by
//! `scripts/trade-report.py` from target/criterion.
//!
//! A benchmark, not a test: CI only builds it and runs each case once (`-- --test`).

use std::hint::black_box;
use std::time::Duration;

use contact_bounce::{scene::catalogue, tiers::EXACT_MAX_IMPACTS, Method, Nodes, Tolerance};
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
    penalty_peer(c);
}

extern "C" {
    /// `benches/penalty_rk4.c`: the end of the bounce by a penalty contact integrated with RK4
    /// at a fixed step (-1 if it does not end before `t_max`).
    fn penalty_rk4_end(
        omega: f64,
        delta: f64,
        restitution: f64,
        zeta: f64,
        closing_speed: f64,
        beta: f64,
        steps_per_contact: f64,
        t_max: f64,
    ) -> f64;
}

/// Steps per contact time of the penalty peer (RK4 is accurate to ~1e-6 per contact at 16).
const PENALTY_STEPS: f64 = 16.0;

fn penalty_end(s: &host_tests::reference::OneBody, beta: f64, t_max: f64) -> f64 {
    // SAFETY: a pure C function of plain numbers, no pointers.
    unsafe {
        penalty_rk4_end(
            s.omega,
            s.delta,
            s.restitution,
            s.zeta,
            s.closing_speed,
            beta,
            PENALTY_STEPS,
            t_max,
        )
    }
}

/// The penalty-contact RK4 peer (C) on the catalogue switches, tuned per switch: the contact
/// stiffness ratio beta doubles from 10 until the end of the bounce is within 1 % of the exact
/// reference there and at the next two doublings; the run at that beta is timed, alone (criterion)
/// and paired with the exact tier ([`paired_ratio`]). The tuning (beta, error) and the paired
/// ratio go to target/penalty-rk4.json for the trade report.
fn penalty_peer(c: &mut Criterion) {
    use host_tests::reference::OneBody;
    let mut group = c.benchmark_group("catalogue penalty rk4 1%");
    let mut tuning = Vec::new();
    for switch in catalogue::ALL {
        let scene = OneBody::typical(&switch);
        let Some(truth) = simulate(&scene, DEFAULT_BUDGET)
            .ok()
            .and_then(|o| o.end_time)
        else {
            continue;
        };
        let t_max = 3.0 * truth;
        let mut beta = 10.0;
        let mut tuned = None;
        // A penalty model's error is not monotone in beta (errors of opposite sign cancel at
        // some beta by chance): beta counts as tuned when it and the next two doublings are
        // all within 1 %, and the largest of their errors is reported.
        let error_at = |beta: f64| {
            let end = penalty_end(&scene, beta, t_max);
            if end > 0.0 {
                (end / truth - 1.0).abs()
            } else {
                f64::INFINITY
            }
        };
        while beta <= 1e5 {
            let worst = [beta, 2.0 * beta, 4.0 * beta]
                .map(error_at)
                .into_iter()
                .fold(0.0, f64::max);
            if worst <= 0.01 {
                tuned = Some((beta, error_at(beta)));
                break;
            }
            beta *= 2.0;
        }
        let Some((beta, error)) = tuned else { continue };
        let paired = paired_ratio(&switch, &scene, beta, t_max);
        tuning.push(format!(
            "{{\"name\": \"{}\", \"beta\": {beta}, \"error\": {error}, \"paired\": {paired}}}",
            switch.name
        ));
        group.bench_with_input(BenchmarkId::from_parameter(switch.name), &scene, |b, s| {
            b.iter(|| penalty_end(black_box(s), black_box(beta), t_max))
        });
    }
    group.finish();
    let _ = std::fs::write(
        "../target/penalty-rk4.json",
        format!("[{}]\n", tuning.join(", ")),
    );
}

/// Rounds of the paired timing ([`paired_ratio`]); 3 in criterion's test mode (`-- --test`).
const PAIRED_ROUNDS: usize = 31;
/// Time per timed block of one side of a round (s).
const PAIRED_BLOCK: f64 = 2e-3;

/// How many times the penalty peer's time the exact tier's is on `switch`, timed in pairs: each
/// round times a block of exact predictions and then a block of penalty runs, and the median of
/// the rounds' ratios is returned. The two criterion groups are timed minutes apart, and the
/// ratio of their medians moves with the machine's speed in between (26.9 to 32.4 in the five
/// trade reports before this was added); within a round both sides see the same machine.
fn paired_ratio(
    switch: &catalogue::Typical,
    scene: &host_tests::reference::OneBody,
    beta: f64,
    t_max: f64,
) -> f64 {
    use std::time::Instant;
    let core = switch.scene::<f64>().expect("valid");
    let exact = Method::Exact {
        max_impacts: EXACT_MAX_IMPACTS,
    };
    // Seconds a call of `f`, over `n` calls.
    fn block(n: u32, mut f: impl FnMut()) -> f64 {
        let start = Instant::now();
        for _ in 0..n {
            f();
        }
        start.elapsed().as_secs_f64() / f64::from(n)
    }
    let mut exact_call = || {
        black_box(black_box(&core).predict(black_box(exact)));
    };
    let mut penalty_call = || {
        black_box(penalty_end(black_box(scene), black_box(beta), t_max));
    };
    // Calls per block, from one block of a few calls each.
    let calls = |seconds: f64| -> u32 {
        let n = (PAIRED_BLOCK / seconds.max(1e-9)).ceil();
        if n >= f64::from(u32::MAX) {
            u32::MAX
        } else {
            (n as u32).max(1)
        }
    };
    let n_exact = calls(block(100, &mut exact_call));
    let n_penalty = calls(block(3, &mut penalty_call));
    let rounds = if std::env::args().any(|a| a == "--test") {
        3
    } else {
        PAIRED_ROUNDS
    };
    let mut ratios: Vec<f64> = (0..rounds)
        .map(|_| {
            let e = block(n_exact, &mut exact_call);
            let p = block(n_penalty, &mut penalty_call);
            p / e
        })
        .collect();
    ratios.sort_by(f64::total_cmp);
    ratios[ratios.len() / 2]
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

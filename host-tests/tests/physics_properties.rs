//! Properties physics guarantees, on the exact reference and every tier: a faster closing
//! speed bounces longer on a preload, more loss at the impacts (larger r) bounces shorter,
//! and the time to a fixed threshold is continuous across Delta = 0; a switch sped up or
//! slowed down in time bounces in the scaled time (every tier and every reference), and one
//! scaled in length bounces in the same time (every tier, f32 and f64). And f32
//! follows f64 within a stated error over the whole reference grid.

use contact_bounce::{
    Contact, Frequency, Method, Nodes, Offset, Restitution, Scene, Threshold, Viscous,
};
use host_tests::grid::grid;
use host_tests::reference::{simulate, OneBody, DEFAULT_BUDGET};

const OMEGA: f64 = 1000.0;

fn one(delta: f64, r: f64, zeta: f64, v0: f64, threshold: Option<f64>) -> OneBody {
    OneBody {
        omega: OMEGA,
        delta,
        restitution: 1.0 - r,
        zeta,
        closing_speed: v0,
        threshold,
    }
}

fn core(s: &OneBody) -> Scene<f64, Option<Viscous<f64>>> {
    Scene::new(
        Contact {
            frequency: Frequency::Omega(s.omega),
            offset: Offset::Delta(s.delta),
            restitution: Restitution::Loss(1.0 - s.restitution),
            closing_speed: s.closing_speed,
            threshold: s.threshold.map_or(Threshold::None, Threshold::Impulse),
        },
        Viscous::optional(s.zeta).unwrap(),
    )
    .unwrap()
}

/// The bounce time by the reference and by each tier.
fn times(s: &OneBody) -> Vec<(&'static str, f64)> {
    let truth = simulate(s, DEFAULT_BUDGET).unwrap();
    let scene = core(s);
    let mut out = vec![("exact", truth.end_time.or(truth.last_above_time).unwrap())];
    for (name, m) in [
        ("closed", Method::Closed),
        ("averaged", Method::Averaged(Nodes::N8)),
        (
            "map",
            Method::Map {
                max_impacts: 10_000_000,
            },
        ),
    ] {
        out.push((name, scene.predict(m).bounce_time().unwrap()));
    }
    out
}

#[test]
fn a_faster_closing_speed_bounces_longer_on_a_preload() {
    // Preload flights lengthen with speed (T = (2/Omega) atan(a / (Omega |Delta|))), so the
    // accumulation time and the time to a fixed threshold grow with v0: strictly, for the
    // reference and for every tier.
    for (r, zeta, threshold) in [
        (0.3, 0.0, None),
        (0.05, 0.01, None),
        (0.5, 0.1, None),
        (0.3, 0.01, Some(1e-3)),
        (0.0, 0.05, Some(1e-3)),
    ] {
        let mut previous: Option<Vec<(&str, f64)>> = None;
        for v0 in [0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0] {
            let now = times(&one(-1e-3, r, zeta, v0, threshold));
            if let Some(before) = &previous {
                for ((name, t0), (_, t1)) in before.iter().zip(&now) {
                    assert!(
                        t1 > t0,
                        "{name}, r {r}, zeta {zeta}: t({v0}) = {t1} <= {t0}"
                    );
                }
            }
            previous = Some(now);
        }
    }
}

#[test]
fn the_continuous_tiers_bounce_longer_for_faster_closing_in_a_gap_too() {
    // In a gap the exact last impact is a sawtooth in v0 (flights shorten with speed while
    // the count steps up), but the averaged and closed tiers are integrals from J_B: monotone.
    for (r, zeta) in [(0.1, 0.01), (0.5, 0.001), (0.0, 0.05)] {
        let mut previous: Option<(f64, f64)> = None;
        for v0 in [0.3, 1.0, 3.0, 10.0, 30.0] {
            let scene = core(&one(1e-3, r, zeta, v0, None));
            let a = scene
                .predict(Method::Averaged(Nodes::N8))
                .bounce_time()
                .unwrap();
            let c = scene.predict(Method::Closed).bounce_time().unwrap();
            if let Some((a0, c0)) = previous {
                assert!(a > a0 && c > c0, "r {r} zeta {zeta} v0 {v0}");
            }
            previous = Some((a, c));
        }
    }
}

#[test]
fn more_loss_at_the_impacts_bounces_shorter() {
    for (zeta, threshold) in [(0.0, None), (0.02, None), (0.02, Some(1e-3))] {
        let mut previous: Option<Vec<(&str, f64)>> = None;
        for r in [0.001, 0.01, 0.05, 0.2, 0.5, 0.8, 0.95] {
            let now = times(&one(-1e-3, r, zeta, 0.5, threshold));
            if let Some(before) = &previous {
                for ((name, t0), (_, t1)) in before.iter().zip(&now) {
                    assert!(t1 < t0, "{name}, zeta {zeta}: t(r = {r}) = {t1} >= {t0}");
                }
            }
            previous = Some(now);
        }
    }
}

#[test]
fn the_time_to_a_threshold_is_continuous_across_zero_offset() {
    // Delta -> 0 from both sides at a fixed threshold (1e-3 of the first impulse): the
    // reference, the averaged model and the map tend to their Delta = 0 value like 1/j_end,
    // j_end = J_end / (Omega |Delta|) = 1e-3 j0 the dimensionless impulse at the threshold
    // (measured: 0.12-0.16 / j_end). Asserted: below 1 / j_end, and shrinking with |Delta|.
    for (r, zeta) in [(0.3, 0.01), (0.1, 0.05)] {
        let v0 = 0.5;
        let at = |delta: f64| {
            let s = one(delta, r, zeta, v0, Some(1e-3 * (2.0 - r) * v0));
            let truth = simulate(&s, DEFAULT_BUDGET)
                .unwrap()
                .last_above_time
                .unwrap();
            let scene = core(&s);
            let averaged = scene
                .predict(Method::Averaged(Nodes::N8))
                .last_above_time
                .seconds()
                .unwrap();
            let map = scene
                .predict(Method::Map {
                    max_impacts: 10_000_000,
                })
                .last_above_time
                .seconds()
                .unwrap();
            [truth, averaged, map]
        };
        let zero = at(0.0);
        for side in [-1.0, 1.0] {
            let mut previous = [f64::INFINITY; 3];
            for j0 in [1e4, 1e6, 1e8, 1e10] {
                let delta = side * 2.0 * (1.0 - r) * v0 / (OMEGA * j0);
                let near = at(delta);
                for k in 0..3 {
                    let gap = (near[k] / zero[k] - 1.0).abs();
                    assert!(
                        gap < 1.0 / (1e-3 * j0),
                        "tier {k}, r {r}, side {side}, j0 {j0}: {} vs {}",
                        near[k],
                        zero[k]
                    );
                    assert!(
                        gap < previous[k],
                        "tier {k}, r {r}, side {side}: not converging at j0 {j0}"
                    );
                    previous[k] = gap;
                }
            }
        }
    }
}

#[test]
fn f32_follows_f64_over_the_grid() {
    // libm backend, R given as r: measured at most 3.6e-5 (the map with zeta = 0.1-0.3 at small
    // j0, where f32's tail cutoff of 5e-3 takes over sooner), else below 4e-7.
    let mut worst: f64 = 0.0;
    for g in grid() {
        let Ok(s64) = g.core() else { continue };
        let s32 = g.core_f32().unwrap();
        for (a, b) in [
            (Method::Closed, Method::Closed),
            (Method::Averaged(Nodes::N8), Method::Averaged(Nodes::N8)),
            (
                Method::Map {
                    max_impacts: 1_000_000,
                },
                Method::Map {
                    max_impacts: 1_000_000,
                },
            ),
        ] {
            let (t64, t32) = (s64.predict(a).bounce_time(), s32.predict(b).bounce_time());
            assert_eq!(t64.is_some(), t32.is_some(), "{}", g.name);
            if let (Some(x), Some(y)) = (t64, t32) {
                if x > 0.0 {
                    worst = worst.max((f64::from(y) / x - 1.0).abs());
                }
            }
        }
    }
    assert!(worst < 1e-4, "f32 departs from f64 by {worst}");
}

/// Every tier, the iterating ones uncapped in practice: what the scaling tests run.
fn every_tier<F: contact_bounce::Float>() -> [Method<F>; 4] {
    [
        Method::Closed,
        Method::Averaged(Nodes::N8),
        Method::Map {
            max_impacts: 10_000_000,
        },
        Method::Exact {
            max_impacts: 10_000_000,
        },
    ]
}

/// The scales a switch is sped up or slowed down by in [`a_switch_scaled_in_time_bounces_in_scaled_time`]:
/// from a contactor's milliseconds to a MEMS contact's nanoseconds.
const TIME_SCALES: [f64; 3] = [1e-3, 1e3, 1e6];

/// A reference's end of bounce (times s, from `end`) at each of [`TIME_SCALES`] against its end
/// at s = 1: within 1e-12, else a problem named `name`.
fn scaled_alike(
    name: &str,
    end: &dyn Fn(f64) -> Option<f64>,
    compared: &mut usize,
    problems: &mut Vec<String>,
) {
    let base = end(1.0);
    for s in TIME_SCALES {
        match (base, end(s)) {
            (Some(a), Some(b)) if (a - b).abs() <= 1e-12 * a.abs().max(b.abs()) => *compared += 1,
            (a, b) => problems.push(format!("{name} s {s:e}: {a:?} vs {b:?}")),
        }
    }
}

#[test]
fn a_switch_scaled_in_time_bounces_in_scaled_time() {
    // Every frequency times s, lengths kept (closing speeds and thresholds times s; two bodies'
    // stiffnesses s^2 and dampers s; a kernel's tau / s and kappa s^3): the same motion in a time
    // 1 / s. Each tier is a function of the scene's dimensionless numbers, so its bounce time
    // times s must not move beyond rounding: the closed, averaged and map tiers and the
    // references to 1e-12 (measured at most 1.8e-14: the map, whose walk rounds at each of
    // 1.5 million impacts; the references 7.6e-14), the exact tier within the two predictions'
    // stated errors. The two-body reference failed this at s = 1e4 (a MEMS pair, one impact
    // ending at 0: its flight series overflowed), and the kernel reference was 5e-8 off at
    // Omega = 5.5e7 (its matrix exponential unbalanced).
    use contact_bounce::tiers::Tier;
    use host_tests::grid::{kernel_grid, two_body_grid, GridScene};
    use host_tests::reference::{hereditary, two_body};
    // Within `tol` of each other, relative (two zeros agree: a gap that ends at its first contact).
    let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol * a.abs().max(b.abs());
    let mut problems = Vec::new();
    let methods = every_tier::<f64>();
    let mut compared = 0;
    for g in grid() {
        let base = g.reference;
        let scaled = |s: f64| OneBody {
            omega: base.omega * s,
            closing_speed: base.closing_speed * s,
            threshold: base.threshold.map(|p| p * s),
            ..base
        };
        let Ok(scene) = g.core() else { continue };
        let truth = simulate(&base, DEFAULT_BUDGET)
            .ok()
            .and_then(|o| o.end_time.or(o.last_above_time));
        for s in TIME_SCALES {
            let moved = scaled(s);
            let Ok(fast) = GridScene::of(&g.name, g.family, moved).core() else {
                problems.push(format!("{} s {s:e}: refused", g.name));
                continue;
            };
            for method in methods {
                let (p, q) = (scene.predict(method), fast.predict(method));
                let (Some(a), Some(b)) = (p.bounce_time(), q.bounce_time()) else {
                    if p.bounce_time().is_some() != q.bounce_time().is_some() {
                        problems.push(format!("{} s {s:e} {method:?}: {p:?} vs {q:?}", g.name));
                    }
                    continue;
                };
                let bound = if p.tier == Tier::Exact {
                    p.expected_error.unwrap_or(0.0) + q.expected_error.unwrap_or(0.0)
                } else {
                    1e-12
                };
                compared += 1;
                if !close(a, b * s, bound) {
                    problems.push(format!(
                        "{} s {s:e} {method:?}: {a:e} vs {:e}",
                        g.name,
                        b * s
                    ));
                }
            }
            let moved_truth = simulate(&moved, DEFAULT_BUDGET)
                .ok()
                .and_then(|o| o.end_time.or(o.last_above_time));
            match (truth, moved_truth) {
                (Some(a), Some(b)) if close(a, b * s, 1e-12) => compared += 1,
                (None, None) => {}
                _ => problems.push(format!(
                    "{} s {s:e} reference: {truth:?} vs {:?}",
                    g.name,
                    moved_truth.map(|b| b * s)
                )),
            }
        }
    }
    for g in two_body_grid() {
        let b = g.reference;
        let end = |s: f64| {
            let r = two_body::TwoBodies {
                c: b.c.map(|x| x * s * s),
                d: b.d.map(|x| x * s),
                closing_speed: b.closing_speed * s,
                v2: b.v2 * s,
                threshold: b.threshold.map(|p| p * s),
                ..b
            };
            two_body::simulate(&r, 50_000_000)
                .ok()
                .and_then(|o| o.end_time.or(o.last_above_time))
                .map(|t| t * s)
        };
        scaled_alike(&g.name, &end, &mut compared, &mut problems);
    }
    for g in kernel_grid() {
        let k = g.reference;
        let end = |s: f64| {
            let r = hereditary::Kernelled {
                omega: k.omega * s,
                closing_speed: k.closing_speed * s,
                tau: k.tau / s,
                kappa: k.kappa * s * s * s,
                state: k.state.map(|y| y / s),
                threshold: k.threshold.map(|p| p * s),
                ..k
            };
            hereditary::simulate(&r, 50_000_000)
                .ok()
                .and_then(|o| o.end_time.or(o.last_above_time))
                .map(|t| t * s)
        };
        scaled_alike(&g.name, &end, &mut compared, &mut problems);
    }
    assert!(
        problems.is_empty(),
        "{} of {compared}:\n{}",
        problems.len(),
        problems.join("\n")
    );
    assert!(compared > 1000, "{compared}");
}

#[test]
fn a_switch_scaled_in_length_bounces_in_the_same_time() {
    // Every length times s (Delta, the closing speed, the threshold impulse), frequencies kept:
    // the same motion, in the same time. With s a power of two every input scales exactly, in
    // either float, so only a tier's own arithmetic can move its answer:
    // - the map, the exact tier and the reference work in ratios of lengths, and must answer
    //   within 4 epsilon (measured: identically);
    // - the closed and averaged tiers take logarithms of impulses, each a rounding of about
    //   |ln s| epsilon of its own: within 4 (|ln s| + 1) epsilon (measured at most 1.3 times
    //   (|ln s| + 1) epsilon, f32 and f64);
    // - a figure is stated at every scale or at none.
    // The exact tier failed this in f32 from s = 2^-50 (Delta 9e-19 m): its Halley step formed
    // y v and v^2, which fell below the normal range as the bounce decayed; a preload at R = 1
    // ended 23 % early stating 5 %, and from s = 2^-60 at 678 s, after 10 million impacts,
    // where it had ended at 0.69 s.
    use contact_bounce::Float;
    use host_tests::grid::GridScene;
    fn check<F: Float>(scales: &[i32], problems: &mut Vec<String>, worst: &mut f64) -> usize {
        let methods = every_tier::<F>();
        let eps = F::EPSILON.to_f64();
        let (double, bits) = if eps < 1e-10 { (true, 64) } else { (false, 32) };
        let mut compared = 0;
        for g in grid() {
            let Ok(scene) = g.core_in::<F>() else {
                continue;
            };
            for &e in scales {
                let s = 2f64.powi(e);
                let b = g.reference;
                let moved = OneBody {
                    delta: b.delta * s,
                    closing_speed: b.closing_speed * s,
                    threshold: b.threshold.map(|p| p * s),
                    ..b
                };
                let Ok(scaled) = GridScene::of(&g.name, g.family, moved).core_in::<F>() else {
                    problems.push(format!("{} 2^{e}: refused", g.name));
                    continue;
                };
                for (k, method) in methods.into_iter().enumerate() {
                    let (p, q) = (scene.predict(method), scaled.predict(method));
                    let name = format!("{} 2^{e} {method:?} (f{bits})", g.name);
                    if p.expected_error.is_some() != q.expected_error.is_some() {
                        problems.push(format!(
                            "{name}: figure {:?} vs {:?}",
                            p.expected_error.map(F::to_f64),
                            q.expected_error.map(F::to_f64)
                        ));
                    }
                    let (Some(a), Some(b)) = (p.bounce_time(), q.bounce_time()) else {
                        if p.bounce_time().is_some() != q.bounce_time().is_some() {
                            problems.push(format!("{name}: {p:?} vs {q:?}"));
                        }
                        continue;
                    };
                    let (a, b) = (a.to_f64(), b.to_f64());
                    let off = (a - b).abs() / a.abs().max(b.abs()).max(f64::MIN_POSITIVE);
                    let logs = f64::from(e.unsigned_abs()) * core::f64::consts::LN_2 + 1.0;
                    let bound = if k < 2 { 4.0 * logs * eps } else { 4.0 * eps };
                    if k < 2 {
                        *worst = worst.max(off / (logs * eps));
                    }
                    compared += 1;
                    if off > bound {
                        problems.push(format!("{name}: {a:e} vs {b:e}"));
                    }
                }
                if double {
                    let end = |o: &OneBody| {
                        simulate(o, DEFAULT_BUDGET)
                            .ok()
                            .and_then(|o| o.end_time.or(o.last_above_time))
                    };
                    match (end(&b), end(&moved)) {
                        (Some(x), Some(y)) if (x - y).abs() <= 4.0 * eps * x.abs() => {
                            compared += 1;
                        }
                        (None, None) => {}
                        (x, y) => {
                            problems.push(format!("{} 2^{e} reference: {x:?} vs {y:?}", g.name))
                        }
                    }
                }
            }
        }
        compared
    }
    let (mut problems, mut worst) = (Vec::new(), 0.0_f64);
    let compared = check::<f32>(&[-60, -50, -20, 20, 40], &mut problems, &mut worst)
        + check::<f64>(&[-60, -20, 20, 60], &mut problems, &mut worst);
    assert!(
        problems.is_empty(),
        "{} of {compared}:\n{}",
        problems.len(),
        problems.join("\n")
    );
    assert!(compared > 10_000, "{compared}");
    eprintln!("length scaling: {compared} compared; closed and averaged at most {worst:.2} (|ln s| + 1) epsilon");
}

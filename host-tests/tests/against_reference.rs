//! Every tier of the core against the exact reference, on the grid of `host_tests::grid`
//! (every regime of docs/physics.md sec. 4 and the switches of sec. 7) and on scenes off it: the
//! regime agrees, and wherever a tier states an expected error, the measured error is within
//! it. The expected errors are docs/physics.md sec. 6, corrected where the reference showed them
//! wrong (see src/accuracy and docs/reports/error-table.md); none is widened here.

use contact_bounce::{Method, Nodes};
use host_tests::grid::{compare, grid, off_grid, two_body_grid, GridScene, Row, TwoBodyScene};
use host_tests::reference::two_body::simulate as simulate_two;

fn check(rows: &[Row]) -> Vec<String> {
    rows.iter()
        .filter_map(|r| {
            if !r.regime_agrees {
                return Some(format!("{} / {}: regime disagrees", r.scene, r.tier));
            }
            match r.expected {
                Some(e) if r.error > e => Some(format!(
                    "{} / {}: error {:.4} > expected {:.4} (reference {:?}, core {:?})",
                    r.scene, r.tier, r.error, e, r.truth, r.predicted
                )),
                _ => None,
            }
        })
        .collect()
}

#[test]
fn every_tier_keeps_its_expected_error_on_the_grid() {
    let mut problems = Vec::new();
    let mut compared = 0;
    for scene in grid() {
        match compare(&scene) {
            Ok(rows) => {
                compared += rows.len();
                problems.extend(check(&rows));
            }
            Err(e) => problems.push(e),
        }
    }
    assert!(compared > 1000);
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn every_tier_keeps_its_expected_error_off_the_grid() {
    let mut problems = Vec::new();
    let mut stated = 0;
    for scene in off_grid(300, 0x5eed_b0c3) {
        match compare(&scene) {
            Ok(rows) => {
                stated += rows.iter().filter(|r| r.expected.is_some()).count();
                problems.extend(check(&rows));
            }
            Err(e) => problems.push(e),
        }
    }
    assert!(stated > 500, "only {stated} stated errors");
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn exact_tiers_reproduce_the_reference_to_rounding() {
    // zeta = 0 (any Delta) and Delta = 0: the closed tier's sums and the reference agree.
    for scene in grid()
        .iter()
        .filter(|s| s.reference.zeta == 0.0 || s.reference.delta == 0.0)
    {
        let rows = compare(scene).unwrap();
        for row in rows.iter().filter(|r| {
            r.tier.starts_with("Closed(Undamped)") || r.tier.starts_with("Closed(Grazing)")
        }) {
            assert!(
                row.error < 1e-9,
                "{} / {}: {}",
                row.scene,
                row.tier,
                row.error
            );
        }
    }
}

#[test]
fn the_exact_tier_reproduces_the_reference_to_1e_9() {
    // Method::Exact against the reference, on the grid and off it: wherever the tier solved
    // flights (Tier::Exact) and did not hand a rest to the averaged model past its cap.
    let mut worst = (0.0_f64, String::new());
    let mut solved = 0;
    let scenes: Vec<_> = grid()
        .into_iter()
        .chain(off_grid(300, 0x000e_4ac7))
        .collect();
    for scene in &scenes {
        let Ok(core) = scene.core() else { continue };
        let p = core.predict(Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        });
        if p.tier != contact_bounce::tiers::Tier::Exact
            || p.approximations
                .contains(contact_bounce::tiers::Approximations::MAP_CONTINUED_AVERAGED)
        {
            continue;
        }
        solved += 1;
        let rows = compare(scene).unwrap();
        let row = rows.iter().find(|r| r.tier == "Exact").unwrap();
        assert!(row.regime_agrees, "{}", row.scene);
        if row.error > worst.0 {
            worst = (
                row.error,
                format!("{} ({:?} vs {:?})", row.scene, row.predicted, row.truth),
            );
        }
        assert!(
            row.error < 1e-9,
            "{}: error {:e} (core {:?}, reference {:?})",
            row.scene,
            row.error,
            row.predicted,
            row.truth
        );
    }
    eprintln!(
        "exact tier: {solved} scenes solved, worst {:e} at {}",
        worst.0, worst.1
    );
    assert!(solved > 200, "{solved}");
}

#[test]
fn the_exact_tier_in_f32_keeps_its_expected_error() {
    // f32: the expected error is 8 epsilon per solved flight (plus the tail's and the backend's
    // share); wherever it is stated, the f32 tier is within it of the f64 reference.
    use host_tests::reference::{simulate, DEFAULT_BUDGET};
    let mut stated = 0;
    let mut worst = 0.0_f64;
    let mut problems = Vec::new();
    for scene in grid().into_iter().chain(off_grid(2_000, 0x0f32_0f32)) {
        let Ok(core) = scene.core_f32() else { continue };
        let p = core.predict(Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        });
        let (Some(e), Some(c)) = (p.expected_error, p.bounce_time()) else {
            continue;
        };
        let truth = simulate(&scene.reference, DEFAULT_BUDGET).expect("reference");
        let Some(t) = truth.end_time.or(truth.last_above_time) else {
            continue;
        };
        stated += 1;
        let error = if t == 0.0 {
            f64::from(c).abs()
        } else {
            (f64::from(c) / t - 1.0).abs()
        };
        // The inputs are rounded to f32 first: their rounding moves the answer by about the
        // same epsilon, which the stated figure covers together with the tier's own.
        worst = worst.max(error / f64::from(e));
        if error > f64::from(e) {
            problems.push(format!(
                "{} / {:?}: error {error:e} > expected {e:e}",
                scene.name, p.tier
            ));
        }
    }
    eprintln!("f32 exact: {stated} stated, worst error / expected {worst:.3}");
    assert!(stated > 1000, "{stated}");
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn a_gap_that_ends_at_the_first_contact_is_exact_in_every_tier() {
    // zeta = 0.5, R = 0.5 in a gap: the first flight falls short of the stop, so the bounce is
    // one impact at t = 0. The closed forms (t_b2r) and the averaged model used to report a
    // later end (1.125 and 1.08 in the units of the issue), and no expected error.
    use host_tests::reference::{simulate, OneBody, DEFAULT_BUDGET};
    for (zeta, v0) in [(0.5, 0.2), (0.3, 0.05), (0.9, 1.0)] {
        let reference = OneBody {
            omega: 1000.0,
            delta: 1e-3,
            restitution: 0.5,
            zeta,
            closing_speed: v0,
            threshold: None,
        };
        let truth = simulate(&reference, DEFAULT_BUDGET).expect("reference");
        assert_eq!(
            (truth.end_time, truth.impacts_total),
            (Some(0.0), Some(1)),
            "the scene must end at the first contact: {zeta} {v0}"
        );
        let scene = GridScene::of("first contact", "gap", reference)
            .core()
            .expect("valid");
        for method in host_tests::grid::methods() {
            let p = scene.predict(method);
            assert_eq!(p.bounce_time(), Some(0.0), "{method:?}: {p:?}");
            assert_eq!(p.impacts_total.value(), Some(1.0), "{method:?}");
            assert_eq!(p.expected_error, Some(0.0), "{method:?}");
        }
    }
}

#[test]
fn a_preload_with_a_tiny_first_impulse_is_resolved_and_exact() {
    // End of bounce 5e-9 to 5e-13 s: the reference used to sum the whole bounce as one
    // geometric tail from the first flight (listing impact 0 alone, and off by up to 5e-9:
    // damping drifts the flight ratio). Now it resolves 5 impacts and sums the tail only once
    // that drift is negligible; the exact tier agrees with it to 1e-9 (measured: 1e-12).
    use host_tests::reference::{simulate, OneBody, DEFAULT_BUDGET};
    for v0 in [1e-6, 1e-8, 1e-10] {
        for zeta in [0.05, 0.5] {
            let reference = OneBody {
                omega: 1000.0,
                delta: -1e-3,
                restitution: 0.7,
                zeta,
                closing_speed: v0,
                threshold: None,
            };
            let truth = simulate(&reference, DEFAULT_BUDGET).expect("reference");
            assert_eq!(truth.first_impacts.len(), 5, "{v0} {zeta}");
            let scene = GridScene::of("tiny impulse", "preload", reference)
                .core()
                .expect("valid");
            let p = scene.predict(Method::Exact {
                max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
            });
            let (t, c) = (
                truth.end_time.expect("ends"),
                p.bounce_time().expect("ends"),
            );
            assert!((c / t - 1.0).abs() < 1e-9, "{v0} {zeta}: {c:e} vs {t:e}");
        }
    }
}

#[test]
fn the_averaged_tier_keeps_its_threshold_figure_on_preloads_at_r_1() {
    // A preload at R = 1 with viscous damping bounces without end: its bounce time is the last
    // impact above a threshold. The averaged tier placed its continuous crossing as if every
    // flight lasted pi / Omega and lost pi zeta (Delta = 0), where a preload's flights are
    // shorter and shorten as the impulse falls (the promise harness found it 4.9 % off where
    // 4.6 % was stated, at j0 = 317). On this grid of a few to tens of impacts above the threshold,
    // j0 to 6e4, that broke 26 of its 207 figures, by up to 4.4 times; taken within the flight
    // after the last impact above (up to 1 / m), none.
    use host_tests::reference::{simulate, OneBody, DEFAULT_BUDGET};
    let (mut held, mut problems) = (0, Vec::new());
    for j0 in [0.5, 3.0, 6.8, 15.0, 28.0, 60.0, 208.0, 1000.0, 6e4] {
        for zeta in [0.03, 0.06, 0.13, 0.19, 0.26] {
            for fraction in [0.04, 0.2, 0.38, 0.43, 0.47] {
                let v0 = j0 * 1000.0 * 1e-3 / 2.0;
                let reference = OneBody {
                    omega: 1000.0,
                    delta: -1e-3,
                    restitution: 1.0,
                    zeta,
                    closing_speed: v0,
                    threshold: Some(fraction * 2.0 * v0),
                };
                let what = format!("j0 {j0} zeta {zeta} fraction {fraction}");
                let truth = simulate(&reference, DEFAULT_BUDGET)
                    .expect("reference")
                    .last_above_time
                    .expect("crosses");
                let scene = GridScene::of(&what, "preload-R1", reference)
                    .core()
                    .expect("valid");
                let p = scene.predict(Method::Averaged(Nodes::N8));
                let (Some(t), Some(e)) = (p.bounce_time(), p.expected_error) else {
                    continue;
                };
                held += 1;
                let error = (t / truth - 1.0).abs();
                if error > e {
                    problems.push(format!("{what}: {error:.4} where {e:.4} is stated"));
                }
            }
        }
    }
    assert!(
        problems.is_empty(),
        "{} of {held} broken:\n{}",
        problems.len(),
        problems.join("\n")
    );
    assert!(held >= 200, "{held}");
}

#[test]
fn the_map_counts_a_bouncing_balls_impacts_exactly() {
    // Undamped preload with tiny flights (a bouncing ball: j0 ~ 1e-5): the map summed the
    // impacts above the threshold on the continuous asymptote once the impulse was small, and
    // counted 47 where there are 44. Undamped, the map is exact: it now iterates every impact
    // above the threshold.
    use host_tests::reference::{simulate, OneBody, DEFAULT_BUDGET};
    for (r, v0, fraction) in [(0.9, 1e-5, 1e-2), (0.9, 1e-6, 1e-2), (0.5, 1e-6, 1e-6)] {
        let reference = OneBody {
            omega: 1000.0,
            delta: -1e-3,
            restitution: r,
            zeta: 0.0,
            closing_speed: v0,
            threshold: Some(fraction * (1.0 + r) * v0),
        };
        let truth = simulate(&reference, DEFAULT_BUDGET).expect("reference");
        let scene = GridScene::of("bouncing ball", "preload", reference)
            .core()
            .expect("valid");
        let p = scene.predict(Method::Map {
            max_impacts: contact_bounce::tiers::DEFAULT_MAX_IMPACTS,
        });
        #[allow(clippy::cast_precision_loss)]
        let count = truth.impacts_above.expect("counted") as f64;
        assert_eq!(p.impacts_above.value(), Some(count), "{r} {v0}");
        let (t, c) = (
            truth.last_above_time.expect("ends"),
            p.last_above_time.seconds().expect("ends"),
        );
        assert!((c / t - 1.0).abs() < 1e-9, "{r} {v0}: {c:e} vs {t:e}");
    }
}

#[test]
fn the_map_solves_the_flights_whose_first_order_loss_exceeds_their_impulse() {
    // Heavy damping, large first impulses: the first-order loss over the first flight exceeds
    // its impulse, and the map stopped there. A gap (zeta 0.5, j0 = 100) reported 1 impact
    // ending at 0 where there are 2 ending at 3.78 (units Omega = |Delta| = 1); a preload
    // (zeta 0.5 and 0.9, j0 = 10) reported 1 impact above the threshold, at 0, where there
    // are 7-8. Such a flight is now solved exactly and the map goes on from its return.
    use host_tests::reference::{simulate, OneBody, DEFAULT_BUDGET};
    let max_impacts = contact_bounce::tiers::DEFAULT_MAX_IMPACTS;
    // Gaps: every flight stalls, so every flight is exact: the same count, the same end.
    for r in [0.5, 0.7, 0.9] {
        for v0 in [100.0, 1000.0] {
            let reference = OneBody {
                omega: 1000.0,
                delta: 1e-3,
                restitution: r,
                zeta: 0.5,
                closing_speed: v0,
                threshold: None,
            };
            let truth = simulate(&reference, DEFAULT_BUDGET).expect("reference");
            let p = GridScene::of("heavy gap", "gap", reference)
                .core()
                .expect("valid")
                .predict(Method::Map { max_impacts });
            #[allow(clippy::cast_precision_loss)]
            let count = truth.impacts_total.expect("finite") as f64;
            assert!(count >= 2.0, "{r} {v0}");
            assert_eq!(p.impacts_total.value(), Some(count), "{r} {v0}");
            let (t, c) = (
                truth.end_time.expect("ends"),
                p.bounce_time().expect("ends"),
            );
            assert!((c / t - 1.0).abs() < 1e-9, "{r} {v0}: {c:e} vs {t:e}");
        }
    }
    // Preloads: exact flights while they stall, first-order ones once the loss is small. The
    // map is outside its stated validity here (no expected error), so this checks only that
    // the count is not lost: within one impact of the reference (measured: 0 at j0 = 10, 1 at
    // j0 = 100) and the last time above within 5 % (measured: 2.1 % at most).
    for zeta in [0.5, 0.9] {
        for v0 in [10.0, 100.0] {
            let reference = OneBody {
                omega: 1000.0,
                delta: -1e-3,
                restitution: 0.5,
                zeta,
                closing_speed: v0,
                threshold: Some(1e-3 * 1.5 * v0),
            };
            let truth = simulate(&reference, DEFAULT_BUDGET).expect("reference");
            let p = GridScene::of("heavy preload", "preload", reference)
                .core()
                .expect("valid")
                .predict(Method::Map { max_impacts });
            #[allow(clippy::cast_precision_loss)]
            let count = truth.impacts_above.expect("counted") as f64;
            let counted = p.impacts_above.value().expect("counted");
            assert!(
                count >= 4.0 && (counted - count).abs() <= 1.0,
                "{zeta} {v0}: {counted} vs {count}"
            );
            let (t, c) = (
                truth.last_above_time.expect("ends"),
                p.last_above_time.seconds().expect("ends"),
            );
            assert!((c / t - 1.0).abs() < 0.05, "{zeta} {v0}: {c:e} vs {t:e}");
        }
    }
}

#[test]
fn the_f32_map_agrees_with_the_f64_map_below_the_f32_tail_cutoff() {
    // The tactile dome with thresholds from 1e-1 to 1e-5 of the first impulse: where the
    // threshold fell below f32's tail cutoff (5e-3 Omega |Delta|), the f32 map counted on the
    // asymptote (14.007 impacts where f64 counts 13, last-above time off by 3.6e-3). It now
    // iterates every impact above the threshold in both floats: the same count, times within
    // 1e-4 (measured: 3e-8).
    use contact_bounce::{scene::catalogue, Scene, Threshold, Viscous};
    for fraction in [1e-1, 1e-2, 1e-3, 1e-4, 1e-5] {
        let mut wide = catalogue::TACTILE_DOME.contact::<f64>();
        wide.threshold = Threshold::FractionOfFirst(fraction);
        let mut narrow = catalogue::TACTILE_DOME.contact::<f32>();
        #[allow(clippy::cast_possible_truncation)]
        let narrow_fraction = fraction as f32;
        narrow.threshold = Threshold::FractionOfFirst(narrow_fraction);
        let zeta = catalogue::TACTILE_DOME.damping_ratio;
        let wide = Scene::new(wide, Viscous::new(zeta).expect("valid")).expect("valid");
        #[allow(clippy::cast_possible_truncation)]
        let narrow_zeta = zeta as f32;
        let narrow = Scene::new(narrow, Viscous::new(narrow_zeta).expect("valid")).expect("valid");
        let max_impacts = contact_bounce::tiers::DEFAULT_MAX_IMPACTS;
        let a = wide.predict(Method::Map { max_impacts });
        let b = narrow.predict(Method::Map { max_impacts });
        assert_eq!(
            a.impacts_above.value(),
            b.impacts_above.value().map(f64::from),
            "{fraction}"
        );
        let (t, c) = (
            a.last_above_time.seconds().expect("ends"),
            f64::from(b.last_above_time.seconds().expect("ends")),
        );
        assert!((c / t - 1.0).abs() < 1e-4, "{fraction}: {c:e} vs {t:e}");
    }
}

fn two_body_problems(scenes: &[TwoBodyScene]) -> (Vec<String>, usize) {
    let mut problems = Vec::new();
    let mut stated = 0;
    for scene in scenes {
        let exact = simulate_two(&scene.reference, 50_000_000).expect("reference");
        let truth = exact.end_time.expect("a preload sticks");
        let core = scene.core().expect("valid");
        for method in [
            Method::Averaged(Nodes::N8),
            Method::Map {
                max_impacts: 1_000_000,
            },
            Method::Closed,
        ] {
            let p = core.predict(method);
            let error = (p.bounce_time().expect("finite") / truth - 1.0).abs();
            if let Some(e) = p.expected_error {
                stated += 1;
                if error > e {
                    problems.push(format!(
                        "{} / {:?}: error {error:.4} > expected {e:.4}",
                        scene.name, p.tier
                    ));
                }
            }
        }
    }
    (problems, stated)
}

#[test]
fn two_bodies_keep_their_expected_error() {
    // The core's one-body reduction (exact for equal partial frequencies, Rayleigh otherwise)
    // against the exact two-body simulation.
    let (problems, stated) = two_body_problems(&two_body_grid());
    assert!(stated > 200, "{stated}");
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn two_bodies_keep_their_expected_error_off_the_grid() {
    use host_tests::reference::two_body::TwoBodies;
    let mut scenes = Vec::new();
    for (i, (mismatch, ratio, zeta, r, v0)) in [
        (1.03, 0.5, 0.01, 0.7, 0.4),
        (1.07, 2.0, 0.0, 0.5, 0.8),
        (1.15, 0.7, 0.03, 0.8, 0.3),
        (1.25, 1.5, 0.005, 0.4, 1.2),
        (1.4, 0.4, 0.02, 0.95, 0.1),
        (1.45, 4.0, 0.0, 0.3, 0.6),
    ]
    .into_iter()
    .enumerate()
    {
        let m = [2e-3, 2e-3 * ratio];
        scenes.push(TwoBodyScene {
            name: format!("off-grid two-body {i}"),
            mismatch,
            reference: TwoBodies {
                m,
                c: [2e3 * 0.8, m[1] * 0.8e6 * mismatch * mismatch],
                d: [
                    2.0 * zeta * 894.4 * m[0],
                    2.0 * zeta * 894.4 * mismatch * m[1],
                ],
                delta: -5e-4,
                restitution: r,
                closing_speed: v0,
                x2: 0.0,
                v2: 0.0,
                threshold: None,
            },
        });
    }
    let (problems, stated) = two_body_problems(&scenes);
    assert!(stated >= 12, "{stated}");
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn kernels_keep_their_expected_error() {
    use host_tests::grid::kernel_grid;
    use host_tests::reference::hereditary::simulate as simulate_kernel;
    let mut problems = Vec::new();
    let mut stated = 0;
    for scene in kernel_grid() {
        let exact = simulate_kernel(&scene.reference, 50_000_000).expect("reference");
        let truth = exact.end_time.expect("a finite end");
        let core = scene.core().expect("valid");
        for method in [
            Method::Averaged(Nodes::N8),
            Method::Map {
                max_impacts: 1_000_000,
            },
            Method::Closed,
        ] {
            let p = core.predict(method);
            if let (Some(e), Some(t)) = (p.expected_error, p.bounce_time()) {
                stated += 1;
                let error = (t / truth - 1.0).abs();
                if error > e {
                    problems.push(format!(
                        "{} / {:?}: error {error:.4} > expected {e:.4}",
                        scene.name, p.tier
                    ));
                }
            }
        }
    }
    // 8 of the grid's figures remain: the averaged model's gap figure now needs a viscous
    // zeta of 1e-3 or more (its measured domain; below it a sweep of gaps found it off by up to
    // 5 times), and the kernel grid's gaps have no viscous damping (their damping is the
    // kernel's; 25 were stated before); and no tier that averages the kernel's force states a
    // figure beyond Omega tau = 1 (the promise harness found the averaged tier up to 98 % short
    // there), which takes the 6 of the grid's preloads at Omega tau = 10 (14 were stated).
    assert!(stated >= 8, "{stated}");
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn auto_keeps_its_promise_at_ten_one_and_a_tenth_of_a_percent() {
    // Auto, and Auto among the closed forms and the exact tier alone
    // (`predict_auto_among::<{ AutoTiers::EXACT }>`, the firmware that cannot link every tier),
    // on the grid and 10,000 scenes off it. (Among every tier it is `Method::Auto` by
    // construction: both call the same function.) Among the map and the averaged model it never
    // answers with the exact tier.
    use contact_bounce::tiers::{AutoTiers, Tier};
    use contact_bounce::Tolerance;
    use host_tests::reference::{simulate, DEFAULT_BUDGET};
    let mut promised = [[0_usize; 3]; 2];
    let mut finite = 0;
    let mut problems = Vec::new();
    let scenes: Vec<_> = grid().into_iter().chain(off_grid(10_000, 0xa070)).collect();
    for scene in &scenes {
        let Ok(core) = scene.core() else { continue };
        let truth = simulate(&scene.reference, DEFAULT_BUDGET).expect("reference");
        let Some(t) = truth.end_time.or(truth.last_above_time) else {
            continue;
        };
        finite += 1;
        for (k, tol) in [0.1, 0.01, 0.001].into_iter().enumerate() {
            let tolerance = Tolerance::new(tol).expect("valid");
            let auto = core.predict(Method::Auto(tolerance));
            let cheap =
                core.predict_auto_among::<{ AutoTiers::MAP | AutoTiers::AVERAGED }>(tolerance);
            assert_ne!(cheap.tier, Tier::Exact, "{}", scene.name);
            let lean = core.predict_auto_among::<{ AutoTiers::EXACT }>(tolerance);
            assert!(
                matches!(lean.tier, Tier::Closed(_) | Tier::Exact | Tier::Regime),
                "{}: {:?}",
                scene.name,
                lean.tier
            );
            for (set, p) in [auto, lean].into_iter().enumerate() {
                if !p.promises(tolerance) {
                    continue; // Auto says it cannot promise: ask the exact reference instead
                }
                promised[set][k] += 1;
                let c = p.bounce_time().expect("a promised bounce is finite");
                let error = if t == 0.0 {
                    if c == 0.0 {
                        0.0
                    } else {
                        f64::INFINITY
                    }
                } else {
                    (c / t - 1.0).abs()
                };
                if error > tol {
                    problems.push(format!(
                        "{} at {tol} (set {set}): {:?} error {error:.5}",
                        scene.name, p.tier
                    ));
                }
            }
        }
    }
    // Auto promises on every valid one-body scene with a finite bounce time (the exact tier
    // answers where no cheaper tier does), among every tier and among the closed forms and the
    // exact tier alike, and keeps every promise.
    eprintln!("promised at 10 %, 1 %, 0.1 % (every tier; closed and exact): {promised:?} of {finite} scenes");
    assert!(finite > 500, "{finite}");
    assert_eq!(promised, [[finite; 3]; 2], "of {finite}");
    assert!(
        problems.is_empty(),
        "{} broken promises:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn the_exact_tier_solves_kernels_to_1e_11() {
    // Method::Exact with a relaxation kernel (the core's modal flights) against the reference's
    // matrix exponential, on the kernel grid: same count, end within 1e-11. The reference is the
    // looser of the two here: on the 5,450-impact gap (R = 1, Omega tau = 10, kernel damping
    // 0.01) it is 1.1e-12 from the 60-digit solution, the tier 2e-13 (measured: the two differ
    // by 1.0e-12 there, the grid's worst; 3.0e-10 before the reference's exponential was
    // balanced, `Kernelled::propagator`); the bound is about ten times the reference's own error
    // (`python3 scripts/exact_mp.py 1000 0 1e-3 1 3 1e-2 2e5`: 23.34548347425504, a few
    // minutes; shorter cases run in `the_exact_kernel_tier_keeps_its_expected_error_to_60_digits`).
    use contact_bounce::tiers::Tier;
    use host_tests::grid::kernel_grid;
    use host_tests::reference::hereditary::simulate as simulate_kernel;
    let mut worst = (0.0_f64, String::new());
    let mut f32_figures = 0;
    for scene in kernel_grid() {
        let exact = simulate_kernel(&scene.reference, 50_000_000).expect("reference");
        let core = scene.core().expect("valid");
        let p = core.predict(Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        });
        assert_eq!(p.tier, Tier::Exact, "{}", scene.name);
        let truth = exact.end_time.expect("a finite end");
        let t = p.bounce_time().expect("a finite end");
        let error = (t / truth - 1.0).abs();
        assert!(error < 1e-11, "{}: {t} vs {truth}", scene.name);
        match exact.impacts_total {
            Some(n) => assert_eq!(p.impacts_total.value(), Some(n as f64), "{}", scene.name),
            None => assert_eq!(p.impacts_total, contact_bounce::tiers::Count::Infinite),
        }
        assert!(
            p.expected_error.is_some_and(|e| e < 1e-10),
            "{}: {p:?}",
            scene.name
        );
        if error > worst.0 {
            worst = (error, scene.name.clone());
        }
        // f32: within its own expected error of f64's answer.
        let k = &scene.reference;
        let narrow = contact_bounce::Scene::new(
            contact_bounce::Contact {
                frequency: contact_bounce::Frequency::Omega(k.omega as f32),
                offset: contact_bounce::Offset::Delta(k.delta as f32),
                restitution: contact_bounce::Restitution::Coefficient(k.restitution as f32),
                closing_speed: k.closing_speed as f32,
                threshold: contact_bounce::Threshold::None,
            },
            contact_bounce::Hereditary::exponential(k.kappa as f32, k.tau as f32).unwrap(),
        )
        .unwrap()
        .predict(Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        });
        if let Some(e) = narrow.expected_error {
            let off = (f64::from(narrow.bounce_time().unwrap()) / t - 1.0).abs();
            assert!(off <= f64::from(e), "f32 {}: {off:e} > {e:e}", scene.name);
            f32_figures += 1;
        }
    }
    eprintln!(
        "exact tier with a kernel: worst {:e} at {}",
        worst.0, worst.1
    );
    assert!(f32_figures >= 25, "{f32_figures}");
}

/// The end time and the count (or "inf") of `scripts/exact_mp.py` (60 digits) for
/// (Omega, zeta, Delta, R, v0, tau, kappa); kappa 0 is the viscous body alone.
fn sixty_digits(args: [f64; 7]) -> (f64, String) {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/../scripts/exact_mp.py");
    let out = std::process::Command::new("python3")
        .arg(script)
        .args(args.map(|x| format!("{x:e}")))
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let mut words = text.split_whitespace();
    let truth: f64 = words.next().unwrap().parse().unwrap();
    (truth, words.next().unwrap().to_owned())
}

#[test]
fn the_exact_viscous_tier_keeps_its_expected_error_to_60_digits() {
    // Preloads with viscous damping, whose Zeno tails are summed as series in the departure
    // (`src/tiers/exact/tail.rs`): against `scripts/exact_mp.py` without a kernel. The tactile dome,
    // heavy damping (zeta 0.5, 0.95), R near 1, and a first departure of 3 Omega |Delta| (the
    // series reaches only 0.25); f64 within its expected error, f32 within its own.
    use contact_bounce::{Contact, Frequency, Offset, Restitution, Scene, Threshold, Viscous};
    // (Omega, zeta, Delta, R, v0)
    let cases = [
        (1e4, 0.03, -2e-4, 0.7, 0.5),
        (1000.0, 0.5, -1e-3, 0.9, 0.5),
        (1000.0, 0.95, -1e-3, 0.3, 2.0),
        (1000.0, 0.2, -1e-3, 0.95, 0.05),
        (1000.0, 0.01, -1e-3, 0.5, 3.0),
    ];
    for (omega, zeta, delta, r, v0) in cases {
        let (truth, count) = sixty_digits([omega, zeta, delta, r, v0, 1e-3, 0.0]);
        assert_eq!(count, "inf");
        let contact = Contact {
            frequency: Frequency::Omega(omega),
            offset: Offset::Delta(delta),
            restitution: Restitution::Coefficient(r),
            closing_speed: v0,
            threshold: Threshold::None,
        };
        let exact = Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        };
        let p = Scene::new(contact, Viscous::new(zeta).unwrap())
            .unwrap()
            .predict(exact);
        let error = (p.bounce_time().unwrap() / truth - 1.0).abs();
        let expected = p.expected_error.expect("a figure");
        eprintln!("f64 {zeta} {r} {v0}: error {error:e}, expected {expected:e}");
        assert!(error <= expected, "{p:?} vs {truth}");
        assert_eq!(p.impacts_total, contact_bounce::tiers::Count::Infinite);
        // f32: the inputs rounded to f32 move the answer too; both are in its figure.
        let f32_contact = Contact {
            frequency: Frequency::Omega(omega as f32),
            offset: Offset::Delta(delta as f32),
            restitution: Restitution::Coefficient(r as f32),
            closing_speed: v0 as f32,
            threshold: Threshold::None,
        };
        let q = Scene::new(f32_contact, Viscous::new(zeta as f32).unwrap())
            .unwrap()
            .predict(Method::Exact {
                max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
            });
        let error = (f64::from(q.bounce_time().unwrap()) / truth - 1.0).abs();
        let expected = f64::from(q.expected_error.expect("a figure"));
        eprintln!("f32 {zeta} {r} {v0}: error {error:e}, expected {expected:e}");
        assert!(error <= expected, "{q:?} vs {truth}");
    }
}

#[test]
fn the_exact_kernel_tier_keeps_its_expected_error_to_60_digits() {
    // Against `scripts/exact_mp.py` (60-digit modes, steps and roots of its own): the kernel
    // alone, and with viscous damping, preload and gap, strong and weak kernels. The host
    // reference is too loose for this (up to 3e-10 on long gaps).
    use contact_bounce::{
        Contact, Frequency, Hereditary, Offset, Restitution, Scene, Threshold, Viscous,
    };
    // (Omega, zeta, Delta, R, v0, tau, kappa)
    let cases = [
        (1000.0, 0.0, -1e-3, 0.5, 0.3, 1e-4, 6e9),
        (1000.0, 0.05, -1e-3, 0.9, 0.1, 1e-3, 2e7),
        (1000.0, 0.02, 1e-3, 0.9, 3.0, 1e-3, 2e7),
        (1000.0, 0.0, 1e-3, 0.9, 3.0, 1e-2, 4e4),
    ];
    for (omega, zeta, delta, r, v0, tau, kappa) in cases {
        let (truth, count) = sixty_digits([omega, zeta, delta, r, v0, tau, kappa]);
        let count = count.as_str();
        let scene = Scene::new(
            Contact {
                frequency: Frequency::Omega(omega),
                offset: Offset::Delta(delta),
                restitution: Restitution::Coefficient(r),
                closing_speed: v0,
                threshold: Threshold::None,
            },
            (
                Viscous::optional(zeta).unwrap(),
                Hereditary::exponential(kappa, tau).unwrap(),
            ),
        )
        .unwrap();
        let p = scene.predict(Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        });
        let error = (p.bounce_time().unwrap() / truth - 1.0).abs();
        let expected = p.expected_error.expect("a figure");
        eprintln!("{zeta} {delta} {r} {tau} {kappa}: error {error:e}, expected {expected:e}");
        assert!(error <= expected, "{p:?} vs {truth}");
        match count {
            "inf" => assert_eq!(p.impacts_total, contact_bounce::tiers::Count::Infinite),
            n => assert_eq!(p.impacts_total.value(), Some(n.parse::<f64>().unwrap())),
        }
    }
}

#[test]
fn auto_promises_on_every_kernel_scene_and_keeps_it() {
    // With a relaxation kernel the exact tier answers where nothing cheaper promises: every
    // scene of the kernel grid gets a promise at 10 %, 1 % and 0.1 %, and keeps it against the
    // reference (within the reference's own 1e-9 on these scenes).
    use contact_bounce::Tolerance;
    use host_tests::grid::kernel_grid;
    use host_tests::reference::hereditary::simulate as simulate_kernel;
    let mut tiers = std::collections::BTreeMap::new();
    for scene in kernel_grid() {
        let truth = simulate_kernel(&scene.reference, 50_000_000)
            .expect("reference")
            .end_time
            .expect("a finite end");
        let core = scene.core().expect("valid");
        for tol in [0.1, 0.01, 0.001] {
            let tolerance = Tolerance::new(tol).expect("valid");
            let p = core.predict(Method::Auto(tolerance));
            assert!(p.promises(tolerance), "{} at {tol}: {p:?}", scene.name);
            let error = (p.bounce_time().expect("finite") / truth - 1.0).abs();
            assert!(
                error <= tol,
                "{} at {tol}: {:?} off {error:e}",
                scene.name,
                p.tier
            );
            *tiers.entry(format!("{:?}", p.tier)).or_insert(0) += 1;
        }
    }
    eprintln!("tiers Auto took on the kernel grid: {tiers:?}");
}

#[test]
fn the_exact_tier_solves_kernels_off_the_grid() {
    // 200 random kernel scenes (with and without viscous damping): the exact tier against the
    // reference, same count and within 1e-11 (as on the grid; measured: 2.2e-13), and Auto's
    // promises at 10 %, 1 % and 0.1 % kept.
    use contact_bounce::{tiers::Tier, Threshold, Tolerance};
    use host_tests::grid::kernel_off_grid;
    use host_tests::reference::hereditary::simulate as simulate_kernel;
    let mut worst = (0.0_f64, String::new());
    let mut solved = 0;
    for scene in kernel_off_grid(200, 0x6b65_726e) {
        let k = &scene.reference;
        let exact = simulate_kernel(k, 50_000_000).expect("reference");
        let truth = exact.end_time.expect("a finite end");
        // (A gap whose first flight does not return ends at 0.)
        let off = |t: f64| {
            if truth == 0.0 {
                t.abs()
            } else {
                (t / truth - 1.0).abs()
            }
        };
        let core = scene.core_with_viscous(Threshold::None).expect("valid");
        let p = core.predict(Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        });
        if p.tier == Tier::Exact {
            solved += 1;
            let error = off(p.bounce_time().expect("finite"));
            assert!(error < 1e-11, "{}: {p:?} vs {truth}", scene.name);
            match exact.impacts_total {
                Some(n) => assert_eq!(p.impacts_total.value(), Some(n as f64), "{}", scene.name),
                None => assert_eq!(p.impacts_total, contact_bounce::tiers::Count::Infinite),
            }
            if error > worst.0 {
                worst = (error, scene.name.clone());
            }
        }
        for tol in [0.1, 0.01, 0.001] {
            let tolerance = Tolerance::new(tol).expect("valid");
            let a = core.predict(Method::Auto(tolerance));
            assert!(a.promises(tolerance), "{} at {tol}: {a:?}", scene.name);
            let error = off(a.bounce_time().expect("finite"));
            assert!(
                error <= tol,
                "{} at {tol}: {:?} off {error:e}",
                scene.name,
                a.tier
            );
        }
    }
    eprintln!(
        "kernels off the grid: {solved} of 200 solved by the exact tier, worst {:e} at {}",
        worst.0, worst.1
    );
    assert!(solved >= 190, "{solved}");
}

#[test]
fn kernel_thresholds_are_counted_as_the_reference_counts_them() {
    // The 200 kernel scenes off the grid with a threshold, on a preload also one below the
    // impulse where the reference starts to sum its Zeno tail (a departure of 1e-8
    // Omega |Delta|): the exact tier's last impact above and its count against the reference,
    // which counts the tail's impacts above a threshold (it once stopped counting where the
    // tail starts). Auto's promise on that time is kept at 10 %, 1 % and 0.1 %.
    use contact_bounce::{tiers::Tier, Threshold, Tolerance};
    use host_tests::grid::kernel_off_grid;
    use host_tests::reference::hereditary::simulate as simulate_kernel;
    let (mut compared, mut below_tail) = (0, 0);
    for scene in kernel_off_grid(200, 0x6b65_726e) {
        let k = scene.reference;
        let first = (1.0 + k.restitution) * k.closing_speed;
        for fraction in [1e-3, 1e-10] {
            let threshold = fraction * first;
            let tail_start = 2.0 * 1e-8 * k.omega * k.delta.abs();
            if k.delta > 0.0 && fraction < 1e-3 {
                continue; // (a gap ends long before; one threshold is enough there)
            }
            let exact = simulate_kernel(
                &host_tests::reference::hereditary::Kernelled {
                    threshold: Some(threshold),
                    ..k
                },
                50_000_000,
            )
            .expect("reference");
            let (Some(truth), Some(count)) = (exact.last_above_time, exact.impacts_above) else {
                continue;
            };
            let core = scene
                .core_with_viscous(Threshold::Impulse(threshold))
                .expect("valid");
            let p = core.predict(Method::Exact {
                max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
            });
            if p.tier != Tier::Exact
                || p.approximations != contact_bounce::tiers::Approximations::NONE
            {
                continue;
            }
            compared += 1;
            if threshold < tail_start {
                below_tail += 1;
            }
            #[allow(clippy::cast_precision_loss)]
            let count = count as f64;
            assert_eq!(
                p.impacts_above.value(),
                Some(count),
                "{} at {fraction}: {p:?}",
                scene.name
            );
            // (A gap whose first flight does not return has its last impact above at 0.)
            let relative = |t: f64| {
                if truth == 0.0 {
                    t.abs()
                } else {
                    (t / truth - 1.0).abs()
                }
            };
            let time = p.last_above_time.seconds().expect("finite");
            let off = relative(time);
            assert!(
                off < 1e-9,
                "{} at {fraction}: {time} vs {truth}",
                scene.name
            );
            for tol in [0.1, 0.01, 0.001] {
                let tolerance = Tolerance::new(tol).expect("valid");
                let a = core.predict(Method::Auto(tolerance));
                assert!(a.promises(tolerance), "{} at {tol}: {a:?}", scene.name);
                let off = relative(a.last_above_time.seconds().expect("finite"));
                assert!(
                    off <= tol,
                    "{} at {tol}: {:?} off {off:e}",
                    scene.name,
                    a.tier
                );
            }
        }
    }
    eprintln!("kernel thresholds: {compared} compared, {below_tail} below the reference's tail");
    assert!(
        compared >= 250 && below_tail >= 50,
        "{compared}, {below_tail}"
    );
}

/// Every tier, and Auto at 10 %, 1 % and 0.1 %: what two builds of one scene must agree on.
fn every_method<F: contact_bounce::Float>() -> Vec<contact_bounce::Method<F>> {
    use contact_bounce::{Method, Nodes, Tolerance};
    let mut methods = vec![
        Method::Closed,
        Method::Averaged(Nodes::N8),
        Method::Map {
            max_impacts: 100_000,
        },
        Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        },
    ];
    for tol in [0.1, 0.01, 0.001] {
        methods.extend(Tolerance::new(F::from_f64(tol)).map(Method::Auto));
    }
    methods
}

/// A damped scene typed `Viscous` (always dissipating, so its undamped paths are left out at
/// compile time) predicts bit for bit what the same scene as `Option<Viscous>` (damping chosen
/// at run time) predicts: every tier and Auto at 10 %, 1 % and 0.1 %, in f64 and f32, on the
/// grid and 300 scenes off it (Delta = 0 among them, where the exact tier takes the grazing
/// sums).
#[test]
fn a_viscous_scene_predicts_what_the_run_time_choice_predicts() {
    fn same<F: contact_bounce::Float>(scene: &GridScene, checked: &mut usize) {
        let Some(typed) = scene.core_damped::<F>() else {
            return;
        };
        let chosen = scene.core_in::<F>();
        assert_eq!(
            typed.as_ref().map(|_| ()).map_err(|e| *e),
            chosen.as_ref().map(|_| ()).map_err(|e| *e),
            "{}: accepted alike",
            scene.name
        );
        let (Ok(typed), Ok(chosen)) = (typed, chosen) else {
            return;
        };
        let methods = every_method::<F>();
        for m in methods {
            assert_eq!(typed.predict(m), chosen.predict(m), "{} {m:?}", scene.name);
            *checked += 1;
        }
    }
    let scenes: Vec<GridScene> = grid().into_iter().chain(off_grid(300, 11)).collect();
    let mut checked = 0;
    for scene in &scenes {
        same::<f64>(scene, &mut checked);
        same::<f32>(scene, &mut checked);
    }
    assert!(checked > 1000, "{checked} predictions compared");
}

/// A scene typed by the sign of its Delta (`Scene::new_preload`, `Scene::new_gap`: the other
/// side's code left out at compile time) predicts bit for bit what the same scene decided at
/// run time (`Scene::new`) predicts: every tier and Auto at 10 %, 1 % and 0.1 %, in f64 and
/// f32, on the grid and 300 scenes off it; with the same regime, the same closed forms and the
/// same work bound. The other constructor refuses it, naming Delta; Delta = 0 is refused by both.
#[test]
fn a_scene_typed_by_its_sign_predicts_what_the_run_time_sign_predicts() {
    use contact_bounce::scene::{AnySign, OffsetSign};
    use contact_bounce::{Parameter, Reason, Scene, Viscous};
    fn same<F: contact_bounce::Float, S: OffsetSign>(
        name: &str,
        typed: &Scene<F, Option<Viscous<F>>, S>,
        chosen: &Scene<F, Option<Viscous<F>>, AnySign>,
    ) -> usize {
        assert_eq!(typed.regime(), chosen.regime(), "{name}");
        assert_eq!(typed.t_b1v(), chosen.t_b1v(), "{name}");
        assert_eq!(typed.t_b2r(), chosen.t_b2r(), "{name}");
        assert_eq!(typed.exact_work(1000), chosen.exact_work(1000), "{name}");
        let methods = every_method::<F>();
        for m in &methods {
            assert_eq!(typed.predict(*m), chosen.predict(*m), "{name} {m:?}");
        }
        methods.len()
    }
    fn check<F: contact_bounce::Float>(scene: &GridScene, counts: &mut [usize; 3]) {
        let zeta = Viscous::optional(F::from_f64(scene.reference.zeta)).expect("valid zeta");
        let contact = scene.contact::<F>();
        let (preload, gap) = (
            Scene::new_preload(contact, zeta),
            Scene::new_gap(contact, zeta),
        );
        let Ok(chosen) = scene.core_in::<F>() else {
            return;
        };
        let delta = chosen.delta();
        if delta < F::ZERO {
            let typed = preload.expect("a preload is accepted as one");
            counts[0] += same(&scene.name, &typed, &chosen);
            assert_eq!(Scene::from(typed), chosen, "{}: as AnySign", scene.name);
            assert_eq!(
                gap,
                Err(contact_bounce::Error::new(
                    Parameter::Delta,
                    Reason::NotPositive
                ))
            );
        } else if delta > F::ZERO {
            let typed = gap.expect("a gap is accepted as one");
            counts[1] += same(&scene.name, &typed, &chosen);
            assert_eq!(Scene::from(typed), chosen, "{}: as AnySign", scene.name);
            assert_eq!(
                preload,
                Err(contact_bounce::Error::new(
                    Parameter::Delta,
                    Reason::OutOfRange
                ))
            );
        } else {
            assert!(
                preload.is_err() && gap.is_err(),
                "{}: Delta = 0",
                scene.name
            );
            counts[2] += 1;
        }
    }
    let scenes: Vec<GridScene> = grid().into_iter().chain(off_grid(300, 11)).collect();
    let mut counts = [0; 3];
    for scene in &scenes {
        check::<f64>(scene, &mut counts);
        check::<f32>(scene, &mut counts);
    }
    eprintln!("typed by sign: {counts:?} (preload, gap predictions; Delta = 0 scenes)");
    assert!(
        counts[0] > 1000 && counts[1] > 1000 && counts[2] > 10,
        "{counts:?}"
    );
}

/// The window-only path (`Scene::bounce_time`, `Window::from_scene`: no counts and no expected
/// error worked out) gives the bounce time of the whole prediction, bit for bit: every tier and
/// Auto at 10 %, 1 % and 0.1 %; f64 and f32; the grid and 300 scenes off it as `Scene::new`
/// builds them, typed by their sign, and (damped) typed `Viscous`; the kernel and two-body grids
/// (f64); each one-body scene also without its threshold (`Scene::new` refuses the endless
/// ones). Where a time is beyond the float's range both paths give `None` and the same typed
/// error for the window.
#[test]
fn the_window_only_path_gives_the_bounce_time_of_the_prediction() {
    use contact_bounce::scene::{Dissipation, OffsetSign};
    use contact_bounce::{Float, Margin, Scene, Window};
    use host_tests::grid::kernel_grid;
    fn same<F: Float, D: Dissipation<F>, S: OffsetSign>(
        name: &str,
        scene: &Scene<F, D, S>,
        counts: &mut [usize; 2],
    ) {
        let margin = Margin::new(F::from_f64(1.5), F::ZERO).expect("valid margin");
        let period = F::from_f64(1e-6);
        for m in every_method::<F>() {
            let whole = scene.predict(m);
            let time = scene.bounce_time(m);
            assert_eq!(
                time.map(|t| t.to_f64().to_bits()),
                whole.bounce_time().map(|t| t.to_f64().to_bits()),
                "{name} {m:?}"
            );
            assert_eq!(
                Window::from_scene(scene, m, &margin, period),
                Window::from_prediction(&whole, &margin, period),
                "{name} {m:?}"
            );
            counts[usize::from(time.is_none())] += 1;
        }
    }
    fn check<F: Float>(scene: &GridScene, counts: &mut [usize; 2]) {
        let Ok(chosen) = scene.core_in::<F>() else {
            return;
        };
        same(&scene.name, &chosen, counts);
        let contact = scene.contact::<F>();
        let zeta = Viscous::optional(F::from_f64(scene.reference.zeta)).expect("valid zeta");
        if let Ok(typed) = Scene::new_preload(contact, zeta) {
            same(&scene.name, &typed, counts);
        }
        if let Ok(typed) = Scene::new_gap(contact, zeta) {
            same(&scene.name, &typed, counts);
        }
        if let Some(Ok(damped)) = scene.core_damped::<F>() {
            same(&scene.name, &damped, counts);
        }
        // Without its threshold.
        let open = contact_bounce::Contact {
            threshold: contact_bounce::Threshold::None,
            ..contact
        };
        if let Ok(unbounded) = Scene::new(open, zeta) {
            same(&scene.name, &unbounded, counts);
        }
    }
    use contact_bounce::Viscous;
    let mut counts = [0; 2];
    for scene in grid().iter().chain(&off_grid(300, 11)) {
        check::<f64>(scene, &mut counts);
        check::<f32>(scene, &mut counts);
    }
    for scene in kernel_grid() {
        if let Ok(core) = scene.core() {
            same(&scene.name, &core, &mut counts);
        }
    }
    for scene in two_body_grid() {
        if let Ok(core) = scene.core() {
            same(&scene.name, &core, &mut counts);
        }
    }
    eprintln!("window-only path: {counts:?} (bounce times, none)");
    assert!(counts[0] > 20_000, "{counts:?}");
}

/// A preload force is always a preload: `Scene::new_gap` refuses it, naming the force.
#[test]
fn a_preload_force_is_not_a_gap() {
    use contact_bounce::{scene::catalogue, Error, Parameter, Reason, Scene, Viscous};
    let d = catalogue::TACTILE_DOME;
    let damping = Viscous::new(d.damping_ratio).expect("valid");
    assert_eq!(
        Scene::new_gap(d.contact::<f64>(), damping),
        Err(Error::new(Parameter::PreloadForce, Reason::OutOfRange))
    );
    assert!(Scene::new_preload(d.contact::<f64>(), damping).is_ok());
}

#[test]
fn the_f32_exact_tier_solves_the_flights_of_fast_switches() {
    // Every catalogue switch in f32 with a threshold (so that flights are solved, not summed
    // as a tail): the exact tier states its error and agrees with f64 within it. The Taylor
    // series of a short flight was summed in seconds: its coefficients grow as Omega^k and
    // overflowed f32 at the MEMS switch's Omega = 1e6 rad/s (NaN, then a flight that "did not
    // return", no expected error); they are now summed in units of 1 / Omega.
    use contact_bounce::{scene::catalogue, Scene, Threshold, Viscous};
    for s in catalogue::ALL {
        for fraction in [1e-1, 1e-2, 1e-3] {
            let mut wide = s.contact::<f64>();
            wide.threshold = Threshold::FractionOfFirst(fraction);
            let mut narrow = s.contact::<f32>();
            #[allow(clippy::cast_possible_truncation)]
            let narrow_fraction = fraction as f32;
            narrow.threshold = Threshold::FractionOfFirst(narrow_fraction);
            let wide =
                Scene::new(wide, Viscous::new(s.damping_ratio).expect("valid")).expect("valid");
            #[allow(clippy::cast_possible_truncation)]
            let narrow_zeta = s.damping_ratio as f32;
            let narrow =
                Scene::new(narrow, Viscous::new(narrow_zeta).expect("valid")).expect("valid");
            let max_impacts = contact_bounce::tiers::EXACT_MAX_IMPACTS;
            let a = wide.predict(Method::Exact { max_impacts });
            let b = narrow.predict(Method::Exact { max_impacts });
            let e = b
                .expected_error
                .unwrap_or_else(|| panic!("{} {fraction}: no expected error: {b:?}", s.name));
            assert_eq!(
                a.impacts_above.value(),
                b.impacts_above.value().map(f64::from),
                "{} {fraction}",
                s.name
            );
            let (t, c) = (
                a.last_above_time.seconds().expect("ends"),
                f64::from(b.last_above_time.seconds().expect("ends")),
            );
            // Within the stated error, beside the inputs' own rounding to f32 (a few
            // epsilon of each, which moves the answer as much: see the test above).
            let bound = f64::from(e) + 8.0 * f64::from(f32::EPSILON);
            assert!(
                (c / t - 1.0).abs() <= bound,
                "{} {fraction}: {c:e} vs {t:e}, bound {bound:e}",
                s.name
            );
        }
    }
}

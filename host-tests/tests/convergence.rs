//! The averaged tier agrees with the closed forms in their limits and converges as nodes grow;
//! the envelope inverts t(J); the tiers agree with each other where docs/physics.md says they must.

use contact_bounce::{
    scene::Regime, scene::TwoBody, tiers::Bodies, tiers::Count, tiers::Time, Contact, Frequency,
    Method, Nodes, Offset, Restitution, Scene, Threshold, Undamped, Viscous,
};

const OMEGA: f64 = 2000.0;

fn contact(delta: f64, r: f64, v0: f64, threshold: Threshold<f64>) -> Contact<f64> {
    Contact {
        frequency: Frequency::Omega(OMEGA),
        offset: Offset::Delta(delta),
        restitution: Restitution::Loss(r),
        closing_speed: v0,
        threshold,
    }
}

fn v0_for(j0: f64, delta: f64, r: f64) -> f64 {
    j0 * OMEGA * delta.abs() / (2.0 * (1.0 - r))
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn averaged_end<D: contact_bounce::scene::Dissipation<f64>>(
    scene: &Scene<f64, D>,
    nodes: Nodes,
) -> f64 {
    scene
        .predict(Method::Averaged(nodes))
        .bounce_time()
        .unwrap()
}

#[test]
fn averaged_tends_to_t_b1v_as_j0_vanishes() {
    // t_b1v is the exact integral of the small-J asymptote -(r Omega^2|Delta| + (2/3) zeta Omega J):
    // the averaged model departs from it at O(j0^2) (atan linearisation) -- bound j0^2.
    let delta = -1e-3;
    for (r, zeta) in [(0.5, 0.0), (0.3, 0.05), (1e-3, 0.1), (0.05, 0.5)] {
        for j0 in [1e-2, 1e-3] {
            let scene = Scene::new(
                contact(delta, r, v0_for(j0, delta, r), Threshold::None),
                Viscous::optional(zeta).unwrap(),
            )
            .unwrap();
            let closed = scene.t_b1v().unwrap().time;
            let averaged = averaged_end(&scene, Nodes::N8);
            assert!(
                rel(averaged, closed) <= j0 * j0,
                "r {r} zeta {zeta} j0 {j0}: {averaged} vs {closed}"
            );
            if zeta > 0.0 {
                // (At zeta = 0 the closed tier uses the exact sum instead.)
                assert_eq!(scene.predict(Method::Closed).end_time, Time::At(closed));
            }
        }
    }
}

#[test]
fn averaged_tends_to_t_b2_and_t_b2r_as_j0_vanishes() {
    // In a gap E1 -> -(r Omega J/(2 pi) + 4 zeta Omega^3 Delta^2/J) with O(j) corrections:
    // t_b2r (t_b2 at R = 1) is its exact integral, so the averaged end departs by O(j0).
    // The damping is light enough for the first flight to come back (its top clears the stop
    // by about Delta j^2 / 2, damping takes about pi zeta Delta): with more, the bounce ends
    // at the first contact, which every tier now reports exactly instead of the model's end.
    let delta = 1e-3;
    for (r, zeta) in [(0.0, 1e-8), (0.05, 1e-8), (0.5, 1e-8)] {
        for j0 in [1e-2, 1e-3] {
            let scene = Scene::new(
                contact(delta, r, v0_for(j0, delta, r), Threshold::None),
                Viscous::optional(zeta).unwrap(),
            )
            .unwrap();
            let closed = if r == 0.0 {
                scene.t_b2()
            } else {
                scene.t_b2r()
            }
            .unwrap()
            .time;
            let averaged = averaged_end(&scene, Nodes::N8);
            assert!(
                rel(averaged, closed) <= j0,
                "r {r} zeta {zeta} j0 {j0}: {averaged} vs {closed}"
            );
        }
    }
    // t_b2r -> t_b2 as r -> 0.
    let scene = Scene::new(
        contact(delta, 1e-9, 0.1, Threshold::None),
        Viscous::optional(0.01).unwrap(),
    )
    .unwrap();
    assert!(rel(scene.t_b2r().unwrap().time, scene.t_b2().unwrap().time) < 1e-6);
}

#[test]
fn t_b2_states_no_figure_where_it_is_far_off() {
    // The gap's closed forms once stated 10 % for j0 <= 0.03; the fuzzing harness found them
    // 11-118 % off there. Against the exact tier on gaps with j0 3e-4 to 0.03, R 0.1-1 and
    // zeta 1e-9 to 0.3: the bounces of more than one impact (the others end at the first
    // contact, which every tier reports exactly) are mostly well beyond 10 %, so the closed
    // tier states no figure for them (docs/physics.md sec. 5 gives these counts).
    use contact_bounce::tiers::{Approximations, ClosedForm, Tier};
    let (omega, delta) = (1000.0, 1e-3);
    let mut errors = Vec::new();
    for r in [0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0] {
        for zeta in [1e-9, 1e-6, 1e-4, 1e-3, 1e-2, 0.1, 0.3] {
            for j0 in [3e-4, 1e-3, 3e-3, 1e-2, 3e-2] {
                let scene = Scene::new(
                    Contact {
                        frequency: Frequency::Omega(omega),
                        offset: Offset::Delta(delta),
                        restitution: Restitution::Coefficient(r),
                        closing_speed: j0 * omega * delta / (2.0 * r),
                        threshold: Threshold::None,
                    },
                    Viscous::new(zeta).unwrap(),
                )
                .unwrap();
                let closed = scene.predict(Method::Closed);
                if !matches!(
                    closed.tier,
                    Tier::Closed(ClosedForm::Tb2 | ClosedForm::Tb2r)
                ) {
                    continue;
                }
                assert_eq!(closed.expected_error, None, "r {r} zeta {zeta} j0 {j0}");
                let exact = scene.predict(Method::Exact {
                    max_impacts: 10_000_000,
                });
                assert_eq!(exact.approximations, Approximations::NONE);
                let (Some(t), Some(u)) = (closed.bounce_time(), exact.bounce_time()) else {
                    continue;
                };
                if exact.impacts_total.value().is_some_and(|n| n > 1.0) {
                    errors.push(rel(t, u));
                }
            }
        }
    }
    errors.sort_by(f64::total_cmp);
    let within = errors.iter().filter(|e| **e <= 0.1).count();
    let median = errors[errors.len() / 2];
    let worst = errors[errors.len() - 1];
    eprintln!(
        "t_b2 / t_b2r: {within} of {} within 10 %, median {median:.3}, worst {worst:.3}",
        errors.len()
    );
    assert!(errors.len() >= 40 && within < errors.len() / 2 && median > 0.1 && worst > 1.0);
}

/// Wherever `method` states a figure for the end of a gap, the exact tier's end must be within
/// it: 20,000 gaps (Omega 1000 rad/s, Delta 1 mm) drawn with R in 0.05-1 (log-spread toward both
/// ends), zeta from one of three `zeta_bands` (`None`: no damping; else log-uniform in the
/// range) and j0 log-uniform in `j0`. Returns the figures held, the worst error as a share of
/// its figure, and the broken ones (the scene and both answers).
fn gap_figure_sweep(
    method: Method<f64>,
    zeta_bands: [Option<(f64, f64)>; 3],
    j0: (f64, f64),
) -> (usize, f64, Vec<String>) {
    let mut state = 0x1234_5678_9abc_def0_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        #[allow(clippy::cast_precision_loss)]
        let u = (state >> 11) as f64 / (1_u64 << 53) as f64;
        u
    };
    let log_uniform = |u: f64, lo: f64, hi: f64| (lo.ln() + u * (hi.ln() - lo.ln())).exp();
    let (omega, delta) = (1000.0, 1e-3);
    let (mut held, mut worst, mut broken) = (0, 0.0_f64, Vec::new());
    for _ in 0..20_000 {
        let r = match next() * 3.0 {
            k if k < 1.0 => log_uniform(next(), 0.05, 1.0),
            k if k < 2.0 => 1.0 - log_uniform(next(), 1e-6, 0.5),
            _ => 0.05 + 0.95 * next(),
        };
        // (The band's index from one draw, its value from another where it has a range.)
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let band = zeta_bands[((next() * 3.0) as usize).min(2)];
        let zeta = band.map_or(0.0, |(lo, hi)| log_uniform(next(), lo, hi));
        let j0 = log_uniform(next(), j0.0, j0.1);
        let Ok(scene) = Scene::new(
            Contact {
                frequency: Frequency::Omega(omega),
                offset: Offset::Delta(delta),
                restitution: Restitution::Coefficient(r),
                closing_speed: j0 * omega * delta / (2.0 * r),
                threshold: Threshold::None,
            },
            Viscous::optional(zeta).unwrap(),
        ) else {
            continue;
        };
        let tier = scene.predict(method);
        let Some(stated) = tier.expected_error else {
            continue;
        };
        let exact = scene.predict(Method::Exact {
            max_impacts: 10_000_000,
        });
        let (Some(t), Some(u)) = (tier.bounce_time(), exact.bounce_time()) else {
            continue;
        };
        if u <= 0.0 || exact.approximations != contact_bounce::tiers::Approximations::NONE {
            continue;
        }
        held += 1;
        let ratio = rel(t, u) / stated;
        worst = worst.max(ratio);
        if ratio > 1.0 {
            broken.push(format!("R {r} zeta {zeta:e} j0 {j0}: {tier:?} vs {u}"));
        }
    }
    (held, worst, broken)
}

#[test]
fn the_averaged_gap_figure_holds_on_a_wide_sweep() {
    // j0 0.01-40, zeta 0 or log-spread over 1e-12 to 0.5. Before the figure was limited to
    // zeta >= 1e-3 (and its 7 % branch dropped), 1,878 of 6,442 stated figures were broken
    // here, by up to 5 times below zeta 1e-6 and 2 times below 1e-3.
    let (held, worst, broken) = gap_figure_sweep(
        Method::Averaged(Nodes::N4),
        [None, Some((1e-12, 1e-3)), Some((1e-3, 0.5))],
        (0.01, 40.0),
    );
    eprintln!("averaged gap figures: {held} held, worst at {worst:.2} of its figure");
    assert!(held > 900, "{held}");
    assert!(
        broken.is_empty(),
        "{} broken: {:?}",
        broken.len(),
        &broken[..broken.len().min(5)]
    );
}

#[test]
fn the_map_gap_figure_holds_on_a_wide_sweep() {
    // j0 1e-4-40, zeta log-spread over 1e-12 to 0.02. With one misjudged flight in the figure
    // (1.1 spread / (N - 2)), 66 of 9,759 were broken here, by up to 1.76 times, all below
    // zeta = 1e-3 and all ending two impacts before the map's count.
    let (held, worst, broken) = gap_figure_sweep(
        Method::Map {
            max_impacts: 10_000,
        },
        [Some((1e-12, 1e-6)), Some((1e-6, 1e-3)), Some((1e-3, 0.02))],
        (1e-4, 40.0),
    );
    eprintln!("map gap figures: {held} held, worst at {worst:.2} of its figure");
    assert!(held > 5000, "{held}");
    assert!(
        broken.is_empty(),
        "{} broken: {:?}",
        broken.len(),
        &broken[..broken.len().min(5)]
    );
}

#[test]
fn averaged_converges_as_nodes_grow() {
    // Errors against 20 nodes fall as the rule grows and reach rounding by 8-12 nodes
    // (docs/physics.md sec. 3: 8-12 nodes on panels 0.5 wide in ln J).
    let cases: [(f64, f64, f64, f64, Threshold<f64>); 5] = [
        (-1e-3, 0.3, 0.03, 0.35, Threshold::None), // tactile-dome-like preload
        (-1e-3, 0.01, 0.1, 30.0, Threshold::None), // zeta >> r, large j0
        (1e-3, 0.05, 0.002, 3.0, Threshold::None), // gap, many impacts
        (1e-3, 0.1, 0.0, 0.5, Threshold::FractionOfFirst(1e-3)), // endless gap
        (-1e-4, 0.0, 0.05, 100.0, Threshold::FractionOfFirst(1e-2)), // preload R = 1
    ];
    for (delta, r, zeta, j0, threshold) in cases {
        let scene = Scene::new(
            contact(delta, r, v0_for(j0, delta, r), threshold),
            Viscous::optional(zeta).unwrap(),
        )
        .unwrap();
        let reference = averaged_end(&scene, Nodes::N20);
        let errors: Vec<f64> = [Nodes::N2, Nodes::N4, Nodes::N8, Nodes::N12]
            .iter()
            .map(|&n| rel(averaged_end(&scene, n), reference))
            .collect();
        assert!(
            errors[3] < 1e-12 && errors[2] < 1e-9,
            "{delta} {r} {zeta}: {errors:?}"
        );
        assert!(
            errors[0] >= errors[2] && errors[1] >= errors[3],
            "not converging: {errors:?}"
        );
    }
}

#[test]
fn averaged_matches_the_exact_undamped_sum() {
    // Preload, zeta = 0. Simulation suggested 1 % for j0 <= 1 at every R in [0.05, 0.999];
    // exactly (Ti2 against the sums, scripts/averaged_error_table.py) it is 4.7 % at R = 0.05,
    // 1.7 % at R = 0.5, 0.26 % at R = 0.9; 4 % at R = 0.9 and 0.38 % at R = 0.99 for j0 = 100.
    let delta = -1e-3;
    for (r, j0, bound) in [
        (0.95, 1.0, 0.047),
        (0.5, 1.0, 0.0174),
        (0.1, 1.0, 0.0026),
        (1e-3, 1.0, 2.5e-5),
        (0.1, 100.0, 0.04),
        (0.01, 100.0, 0.0038),
    ] {
        let scene = Scene::new(
            contact(delta, r, v0_for(j0, delta, r), Threshold::None),
            Undamped,
        )
        .unwrap();
        let exact = scene.undamped_accumulation_time().unwrap();
        let averaged = averaged_end(&scene, Nodes::N8);
        assert!(
            rel(averaged, exact) <= bound,
            "r {r} j0 {j0}: {averaged} vs {exact}"
        );
        let p = scene.predict(Method::Averaged(Nodes::N8));
        assert!(
            p.expected_error.unwrap() >= rel(averaged, exact),
            "expected error too small: {p:?}"
        );
    }
}

#[test]
fn envelope_inverts_the_bounce_time() {
    let delta = -1e-3;
    let scene = Scene::new(
        contact(
            delta,
            0.3,
            v0_for(2.0, delta, 0.3),
            Threshold::FractionOfFirst(1e-3),
        ),
        Viscous::optional(0.05).unwrap(),
    )
    .unwrap();
    let averaged = scene.averaged(Nodes::N8);
    let p = averaged.predict();
    let (t_above, t_end) = (
        p.last_above_time.seconds().unwrap(),
        p.end_time.seconds().unwrap(),
    );
    // J(0) = J_B, J(t_above) = J_end, J(t_end+) = 0, and J decreases in between.
    assert!(
        rel(
            averaged.envelope(0.0).unwrap().impulse,
            scene.start_impulse()
        ) < 1e-14
    );
    let at_threshold = averaged.envelope(t_above).unwrap();
    assert!(rel(at_threshold.impulse, scene.threshold_generating().unwrap()) < 1e-9);
    match (at_threshold.impacts, p.impacts_above) {
        (Count::Finite(a), Count::Finite(b)) => assert!(rel(a, b) < 1e-9),
        other => panic!("{other:?}"),
    }
    assert_eq!(averaged.envelope(t_end * 1.000_001).unwrap().impulse, 0.0);
    let mut last = f64::INFINITY;
    for i in 0..=200 {
        let t = t_end * f64::from(i) / 200.0;
        let j = averaged.envelope(t).unwrap().impulse;
        assert!(j <= last && j >= 0.0, "not decreasing at {t}");
        last = j;
    }
    assert!(averaged.envelope(-1.0).is_err() && averaged.envelope(f64::NAN).is_err());
}

#[test]
fn envelope_of_an_endless_regime_decays_without_end() {
    let scene = Scene::new(
        contact(1e-3, 0.1, 0.2, Threshold::FractionOfFirst(1e-3)),
        Undamped,
    )
    .unwrap();
    let averaged = scene.averaged(Nodes::N8);
    let t = averaged.predict().last_above_time.seconds().unwrap();
    assert!(
        rel(
            averaged.envelope(t).unwrap().impulse,
            scene.threshold_generating().unwrap()
        ) < 1e-9
    );
    // Ten times longer: J ~ J_B 1e-30, still positive; far beyond, it underflows to 0, not NaN.
    let far = averaged.envelope(10.0 * t).unwrap().impulse;
    assert!(far > 0.0 && far < 1e-25 * scene.start_impulse(), "{far}");
    assert_eq!(averaged.envelope(1e4 * t).unwrap().impulse, 0.0);
}

#[test]
fn laws_of_motion_start_at_the_stop_and_follow_the_orbit() {
    let delta = -1e-3;
    let scene = Scene::new(
        contact(delta, 0.3, v0_for(1.0, delta, 0.3), Threshold::None),
        Viscous::optional(0.02).unwrap(),
    )
    .unwrap();
    let averaged = scene.averaged(Nodes::N8);
    let paper = Bodies::equal_at_rest();
    let m = averaged.motion(0.0, &paper).unwrap();
    assert!((m.relative - delta).abs() < 1e-15);
    // Equal masses, centre at rest: x1 = x/2, x2 = -x/2 (the paper's +-J chi/2).
    let m = averaged.motion(1e-4, &paper).unwrap();
    assert!(
        (m.body1 - m.relative / 2.0).abs() < 1e-18 && (m.body2 + m.relative / 2.0).abs() < 1e-18
    );
    assert!((m.body1 - m.body2 - m.relative).abs() < 1e-18);
    // In flight the contacts are apart: x <= Delta (free side), and rest after the end.
    let end = averaged.predict().end_time.seconds().unwrap();
    for i in 1..100 {
        let x = averaged
            .motion(end * f64::from(i) / 100.0, &paper)
            .unwrap()
            .relative;
        assert!(x <= delta + 1e-15, "{x}");
    }
    assert_eq!(averaged.motion(2.0 * end, &paper).unwrap().relative, delta);
    // A moving centre of mass shifts both bodies alike.
    let moving = Bodies::from_initial(0.25, delta, scene.closing_speed(), 0.0, 0.0);
    let m = averaged.motion(1e-4, &moving).unwrap();
    assert!((m.body1 - m.body2 - m.relative).abs() < 1e-15);
}

#[test]
fn map_agrees_with_averaged_where_section_6_says_it_is_good() {
    // Preload: map within 0.3 % for zeta <= 0.01, 2.5 % for zeta <= 0.1 of exact; the averaged
    // model within 1 % for j0 <= 1: so they agree within the sum of both.
    let delta = -1e-3;
    for (r, zeta, bound) in [(0.3, 0.01, 0.013), (0.05, 0.1, 0.035), (0.5, 0.005, 0.013)] {
        let scene = Scene::new(
            contact(delta, r, v0_for(0.8, delta, r), Threshold::None),
            Viscous::optional(zeta).unwrap(),
        )
        .unwrap();
        let map = scene
            .predict(Method::Map {
                max_impacts: 100_000,
            })
            .bounce_time()
            .unwrap();
        let averaged = averaged_end(&scene, Nodes::N8);
        assert!(
            rel(map, averaged) < bound,
            "r {r} zeta {zeta}: {map} vs {averaged}"
        );
    }
}

#[test]
fn map_hands_over_to_averaged_past_its_cap() {
    let delta = -1e-3;
    let scene = Scene::new(
        contact(delta, 1e-4, v0_for(1.0, delta, 1e-4), Threshold::None),
        Viscous::optional(0.001).unwrap(),
    )
    .unwrap();
    let capped = scene.predict(Method::Map { max_impacts: 100 });
    let full = scene.predict(Method::Map {
        max_impacts: 10_000_000,
    });
    assert!(capped
        .approximations
        .contains(contact_bounce::tiers::Approximations::MAP_CONTINUED_AVERAGED));
    assert!(!full
        .approximations
        .contains(contact_bounce::tiers::Approximations::MAP_CONTINUED_AVERAGED));
    assert!(rel(capped.bounce_time().unwrap(), full.bounce_time().unwrap()) < 0.01);
}

#[test]
fn the_map_sums_a_dissipating_tail_early_and_a_lossless_one_exactly() {
    // Where the scene dissipates, the map hands a preload's Zeno tail to the asymptote once the
    // generating impulse is below 5e-3 Omega |Delta| (the asymptote then leaves out a few 1e-4
    // of the tail, a tenth of the map's smallest figure). f64 once walked down to 6e-6: 32
    // impacts on the tactile dome where 13 do, and its maps took longer than the exact tier.
    // With restitution alone the map is exact, and keeps walking to 6e-6: its end is the exact
    // sum's to rounding.
    use contact_bounce::tiers::{MapEnd, MapImpacts};
    let dome = contact_bounce::scene::catalogue::TACTILE_DOME
        .scene::<f64>()
        .unwrap();
    let mut walk = MapImpacts::new(&dome, 1_000);
    let walked = walk.by_ref().count();
    let scale = dome.omega() * dome.delta().abs();
    let Some(MapEnd::ZenoTail(j)) = walk.end() else {
        panic!("a Zeno tail: {:?}", walk.end());
    };
    assert!(j > 1e-3 * scale && j <= 5e-3 * scale, "{j} of {scale}");
    assert!(walked <= 15, "{walked} impacts walked");
    let exact = dome.predict(Method::Exact {
        max_impacts: 10_000_000,
    });
    let map = dome.predict(Method::Map {
        max_impacts: 10_000_000,
    });
    let off = rel(map.bounce_time().unwrap(), exact.bounce_time().unwrap());
    assert!(off <= map.expected_error.unwrap(), "{off} {map:?}");
    for (r, j0) in [(0.5, 0.3), (0.7, 1.0), (0.9, 3.0)] {
        let delta = -1e-3;
        let lossless = Scene::new(
            contact(delta, r, v0_for(j0, delta, r), Threshold::None),
            Viscous::optional(0.0).unwrap(),
        )
        .unwrap();
        let map = lossless.predict(Method::Map {
            max_impacts: 10_000_000,
        });
        let exact = lossless.predict(Method::Exact {
            max_impacts: 10_000_000,
        });
        let off = rel(map.bounce_time().unwrap(), exact.bounce_time().unwrap());
        assert!(off < 1e-12, "R {r} j0 {j0}: {off:e}");
    }
}

#[test]
fn two_bodies_with_equal_partial_frequencies_reduce_exactly() {
    // c/m = 1e6 and d/m = 40 for both bodies: Omega = 1000, zeta = 0.02, exact.
    let bodies = TwoBody {
        m1: 1e-3,
        c1: 1e3,
        d1: 0.04,
        m2: 3e-3,
        c2: 3e3,
        d2: 0.12,
    };
    let reduced = bodies.reduce().unwrap();
    assert!(reduced.exact);
    assert!(rel(reduced.omega, 1000.0) < 1e-15 && rel(reduced.zeta, 0.02) < 1e-14);
    assert!(rel(reduced.reduced_mass, 0.75e-3) < 1e-15);
    let two = Scene::two_body(
        bodies,
        Offset::Delta(-1e-3),
        Restitution::Coefficient(0.6),
        0.3,
        Threshold::None,
        None,
    )
    .unwrap();
    let one = Scene::new(
        Contact {
            frequency: Frequency::Omega(1000.0),
            offset: Offset::Delta(-1e-3),
            restitution: Restitution::Coefficient(0.6),
            closing_speed: 0.3,
            threshold: Threshold::None,
        },
        Viscous::optional(0.02).unwrap(),
    )
    .unwrap();
    for method in [
        Method::Closed,
        Method::Averaged(Nodes::N8),
        Method::Map {
            max_impacts: 10_000,
        },
    ] {
        let (a, b) = (two.predict(method), one.predict(method));
        assert!(rel(a.bounce_time().unwrap(), b.bounce_time().unwrap()) < 1e-12);
        assert!(a.approximations.is_empty(), "{a:?}");
    }
    // A preload force on two bodies uses the series stiffness mu Omega^2 = 750 N/m.
    let pressed = Scene::two_body(
        bodies,
        Offset::PreloadForce(0.75),
        Restitution::Coefficient(0.6),
        0.3,
        Threshold::None,
        None,
    )
    .unwrap();
    assert!(rel(pressed.delta(), -1e-3) < 1e-14);
}

#[test]
fn two_bodies_with_unequal_frequencies_are_flagged() {
    // A 10 % frequency mismatch: the Rayleigh frequency, flagged; a preload keeps an expected
    // error (~1 % more), a gap loses it (docs/physics.md sec. 1: 1.7-4.5x).
    let bodies = TwoBody {
        m1: 1e-3,
        c1: 1e3,
        d1: 0.0,
        m2: 1e-3,
        c2: 1.21e3,
        d2: 0.0,
    };
    let reduced = bodies.reduce().unwrap();
    assert!(!reduced.exact && rel(reduced.frequency_mismatch, 1.1) < 1e-12);
    assert!(rel(reduced.omega, (1.105e6_f64).sqrt()) < 1e-14);
    for (delta, expected_known) in [(-1e-3, true), (1e-3, false)] {
        let s = Scene::two_body(
            bodies,
            Offset::Delta(delta),
            Restitution::Coefficient(0.6),
            0.3,
            Threshold::FractionOfFirst(0.01),
            None,
        )
        .unwrap();
        let p = s.predict(Method::Averaged(Nodes::N8));
        assert!(p
            .approximations
            .contains(contact_bounce::tiers::Approximations::TWO_BODY_RAYLEIGH));
        assert_eq!(p.expected_error.is_some(), expected_known, "{p:?}");
    }
}

#[test]
fn single_impact_and_periodic_need_no_model() {
    let single = Scene::new(
        contact(1e-3, 0.3, 0.1, Threshold::None),
        Viscous::optional(1.0).unwrap(),
    )
    .unwrap();
    let periodic = Scene::new(contact(-1e-3, 0.0, 0.1, Threshold::None), Undamped).unwrap();
    for method in [
        Method::Closed,
        Method::Averaged(Nodes::N2),
        Method::Map { max_impacts: 10 },
    ] {
        let p = single.predict(method);
        assert_eq!(
            (p.regime, p.end_time, p.impacts_total),
            (Regime::SingleImpact, Time::At(0.0), Count::Finite(1.0))
        );
        let p = periodic.predict(method);
        assert_eq!(
            (p.regime, p.end_time, p.impacts_total),
            (Regime::Periodic, Time::Never, Count::Infinite)
        );
        assert!(p.bounce_time().is_none());
    }
}

#[test]
fn f32_follows_f64_where_well_conditioned() {
    // Same scenes in both precisions, R given as r so f32 keeps its digits: agreement within
    // 1e-4 relative (a few hundred f32 ULP over sums of up to ~1e3 terms).
    let cases: [(f64, f64, f64, f64, Option<f64>); 4] = [
        (-1e-3, 0.3, 0.03, 0.35, None),
        (-1e-3, 1e-3, 0.0, 0.2, Some(0.01)),
        (1e-3, 0.01, 0.001, 3.0, None),
        (0.0, 0.1, 0.01, 0.1, Some(0.01)),
    ];
    for (delta, r, zeta, j0, fraction) in cases {
        let v0 = if delta == 0.0 {
            0.1
        } else {
            v0_for(j0, delta, r)
        };
        let th64 = fraction.map_or(Threshold::None, Threshold::FractionOfFirst);
        #[allow(clippy::cast_possible_truncation)]
        let th32 = fraction.map_or(Threshold::None, |f| Threshold::FractionOfFirst(f as f32));
        let s64 = Scene::new(
            contact(delta, r, v0, th64),
            Viscous::optional(zeta).unwrap(),
        )
        .unwrap();
        #[allow(clippy::cast_possible_truncation)]
        let s32 = Scene::new(
            Contact {
                frequency: Frequency::Omega(OMEGA as f32),
                offset: Offset::Delta(delta as f32),
                restitution: Restitution::Loss(r as f32),
                closing_speed: v0 as f32,
                threshold: th32,
            },
            Viscous::optional(zeta as f32).unwrap(),
        )
        .unwrap();
        for (m64, m32) in [
            (Method::Closed, Method::Closed),
            (Method::Averaged(Nodes::N8), Method::Averaged(Nodes::N8)),
            (
                Method::Map {
                    max_impacts: 100_000,
                },
                Method::Map {
                    max_impacts: 100_000,
                },
            ),
        ] {
            let a = s64.predict(m64).bounce_time().unwrap();
            let b = f64::from(s32.predict(m32).bounce_time().unwrap());
            assert!(
                rel(b, a) < 1e-4,
                "{delta} {r} {zeta} {m64:?}: f32 {b} vs f64 {a}"
            );
        }
    }
}

#[test]
fn restitution_only_averaged_matches_a_direct_quadrature_of_its_integral() {
    // Without damping the averaged tier is closed form (the inverse tangent integral): checked
    // against Simpson's rule on t = (2 / (r Omega)) integral theta(J) dJ / J in ln J (20,000
    // panels: error ~1e-15) for a preload to the end and to a threshold, a gap and Delta = 0 to
    // a threshold; counts against ln(J_B / J_end) / r; and against the quadrature a damped
    // scene type with zeta = 0 takes.
    for (delta, r, j0, fraction) in [
        (-1e-3, 0.3, 1.0, None),
        (-1e-3, 0.05, 30.0, None),
        (-1e-3, 0.3, 1.0, Some(1e-3)),
        (1e-3, 0.1, 3.0, Some(1e-2)),
        (1e-3, 0.01, 100.0, Some(1e-4)),
        (0.0, 0.2, 1.0, Some(1e-3)),
    ] {
        let threshold = fraction.map_or(Threshold::None, Threshold::FractionOfFirst);
        let v0 = if delta == 0.0 {
            1.0
        } else {
            v0_for(j0, delta, r)
        };
        let scene = Scene::new(contact(delta, r, v0, threshold), Undamped).expect("valid");
        let p = scene.predict(Method::Averaged(Nodes::N2));
        let start = scene.start_impulse();
        let end = scene.threshold_generating().unwrap_or(start * 1e-14);
        let q = 2.0 * OMEGA * delta;
        let theta = |j: f64| {
            if q < 0.0 {
                (j / -q).atan()
            } else if q > 0.0 {
                std::f64::consts::PI - (j / q).atan()
            } else {
                std::f64::consts::FRAC_PI_2
            }
        };
        let (a, b) = (end.ln(), start.ln());
        let n = 20_000;
        let h = (b - a) / f64::from(n);
        let mut sum = theta(a.exp()) + theta(b.exp());
        for i in 1..n {
            let w = if i % 2 == 1 { 4.0 } else { 2.0 };
            sum += w * theta((a + h * f64::from(i)).exp());
        }
        let mut want = 2.0 / (r * OMEGA) * sum * h / 3.0;
        if fraction.is_none() {
            // The rest below 1e-14 J_B: theta ~ J / |q| there, so its integral is ~ end / |q|.
            want += 2.0 / (r * OMEGA) * end / -q;
        }
        let got = if fraction.is_some() {
            p.last_above_time.seconds()
        } else {
            p.end_time.seconds()
        }
        .expect("ends");
        assert!(rel(got, want) < 1e-9, "{delta} {r} {j0}: {got} vs {want}");
        // A damped type with zeta = 0 takes the quadrature: the same, to its error.
        let quadrature = Scene::new(
            contact(delta, r, v0, threshold),
            Viscous::optional(0.0).unwrap(),
        )
        .expect("valid")
        .predict(Method::Averaged(Nodes::N20));
        let other = if fraction.is_some() {
            quadrature.last_above_time.seconds()
        } else {
            quadrature.end_time.seconds()
        }
        .expect("ends");
        assert!(rel(other, got) < 1e-9, "{delta} {r} {j0}: {other} vs {got}");
        if fraction.is_some() {
            let count = 1.0 + (start / end).ln() / r;
            let n_above = p.impacts_above.value().expect("finite");
            assert!(
                rel(n_above, count) < 1e-12,
                "{delta} {r}: {n_above} vs {count}"
            );
        }
    }
}

//! Property tests: every constructor, fed arbitrary f64 bit patterns, returns Ok or a typed
//! error and never panics; NaN or infinity anywhere is always an error; every scene it accepts
//! predicts without NaN in every tier. Random realistic scenes likewise.

use contact_bounce::{
    scene::TwoBody, tiers::Count, tiers::Time, Contact, Float, Frequency, Hereditary, Margin,
    Method, Nodes, Offset, Prediction, Restitution, Scene, Threshold, Tolerance, Viscous, Window,
};
use proptest::prelude::*;

fn any_f64() -> impl Strategy<Value = f64> {
    // Raw bit patterns (NaN payloads, infinities, subnormals, huge) mixed with plain values.
    prop_oneof![
        any::<u64>().prop_map(f64::from_bits),
        -1e3..1e3_f64,
        0.0..1.0_f64
    ]
}

fn sane<F: Float>(p: &Prediction<F>) -> bool {
    let time_ok = |t: Time<F>| t.seconds().is_none_or(|t| t.is_finite() && t >= F::ZERO);
    let count_ok = |n: Count<F>| n.value().is_none_or(|n| n.is_finite() && n >= F::ONE);
    time_ok(p.end_time)
        && time_ok(p.last_above_time)
        && count_ok(p.impacts_above)
        && count_ok(p.impacts_total)
        && p.expected_error
            .is_none_or(|e| e.is_finite() && e >= F::ZERO)
}

#[derive(Debug, Clone)]
struct Raw {
    frequency: (u8, f64, f64),
    offset: (bool, f64),
    restitution: (bool, f64),
    closing_speed: f64,
    threshold: (u8, f64),
    zeta: f64,
    kernel: Option<(f64, f64)>,
}

fn raw() -> impl Strategy<Value = Raw> {
    (
        (0u8..2, any_f64(), any_f64()),
        (any::<bool>(), any_f64()),
        (any::<bool>(), any_f64()),
        any_f64(),
        (0u8..3, any_f64()),
        any_f64(),
        proptest::option::of((any_f64(), any_f64())),
    )
        .prop_map(
            |(frequency, offset, restitution, closing_speed, threshold, zeta, kernel)| Raw {
                frequency,
                offset,
                restitution,
                closing_speed,
                threshold,
                zeta,
                kernel,
            },
        )
}

fn contact<F: Float>(r: &Raw) -> Contact<F> {
    let c = F::from_f64;
    Contact {
        frequency: if r.frequency.0 == 0 {
            Frequency::Omega(c(r.frequency.1))
        } else {
            Frequency::MassStiffness {
                mass: c(r.frequency.1),
                stiffness: c(r.frequency.2),
            }
        },
        offset: if r.offset.0 {
            Offset::Delta(c(r.offset.1))
        } else {
            Offset::PreloadForce(c(r.offset.1))
        },
        restitution: if r.restitution.0 {
            Restitution::Coefficient(c(r.restitution.1))
        } else {
            Restitution::Loss(c(r.restitution.1))
        },
        closing_speed: c(r.closing_speed),
        threshold: match r.threshold.0 {
            0 => Threshold::None,
            1 => Threshold::FractionOfFirst(c(r.threshold.1)),
            _ => Threshold::Impulse(c(r.threshold.1)),
        },
    }
}

fn values(r: &Raw) -> Vec<f64> {
    let mut v = vec![
        r.frequency.1,
        r.offset.1,
        r.restitution.1,
        r.closing_speed,
        r.zeta,
    ];
    if r.frequency.0 == 1 {
        v.push(r.frequency.2);
    }
    if r.threshold.0 > 0 {
        v.push(r.threshold.1);
    }
    if let Some((a, b)) = r.kernel {
        v.extend([a, b]);
    }
    v
}

fn check<F: Float>(r: &Raw) -> Result<(), TestCaseError> {
    let built = Viscous::optional(F::from_f64(r.zeta)).and_then(|viscous| {
        let kernel = r
            .kernel
            .map(|(k, t)| Hereditary::exponential(F::from_f64(k), F::from_f64(t)))
            .transpose()?;
        Scene::new(contact::<F>(r), (Some(viscous), kernel))
    });
    let non_finite = values(r).iter().any(|v| !F::from_f64(*v).is_finite());
    match built {
        Err(e) => {
            // A typed error that displays.
            prop_assert!(!e.to_string().is_empty());
        }
        Ok(scene) => {
            prop_assert!(!non_finite, "accepted a non-finite input: {:?}", r);
            for method in [
                Method::Closed,
                Method::Averaged(Nodes::N4),
                Method::Map { max_impacts: 500 },
                Method::Exact { max_impacts: 500 },
                Method::Auto(
                    Tolerance::new(F::from_f64(0.1))
                        .map_err(|e| TestCaseError::fail(e.to_string()))?,
                ),
            ] {
                let p = scene.predict(method);
                prop_assert!(sane(&p), "{method:?} on {r:?}: {p:?}");
            }
            let env = scene.averaged(Nodes::N2).envelope(F::from_f64(1e-3));
            prop_assert!(env.is_ok_and(|e| e.impulse.is_finite() && e.impulse >= F::ZERO));
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn scenes_from_arbitrary_bits_are_refused_or_predicted_f64(r in raw()) {
        check::<f64>(&r)?;
    }

    #[test]
    fn scenes_from_arbitrary_bits_are_refused_or_predicted_f32(r in raw()) {
        check::<f32>(&r)?;
    }

    #[test]
    fn two_body_reduction_never_panics(v in proptest::collection::vec(any_f64(), 6)) {
        let bodies = TwoBody { m1: v[0], c1: v[1], d1: v[2], m2: v[3], c2: v[4], d2: v[5] };
        match bodies.reduce() {
            Ok(r) => {
                prop_assert!(v.iter().all(|x| x.is_finite()));
                prop_assert!(r.omega.is_finite() && r.omega > 0.0 && r.zeta.is_finite() && r.zeta >= 0.0);
                prop_assert!(r.mass_fraction_1 >= 0.0 && r.mass_fraction_1 <= 1.0);
            }
            Err(e) => prop_assert!(!e.to_string().is_empty()),
        }
    }

    #[test]
    fn windows_and_tolerances_never_panic(a in any_f64(), b in any_f64(), c in any_f64(), d in any_f64()) {
        if let Ok(margin) = Margin::new(a, b) {
            match Window::from_seconds(c, &margin, d) {
                Ok(w) => prop_assert!(c.is_finite() && d.is_finite() && d > 0.0 && f64::from(w.ticks()) >= 0.0),
                Err(e) => prop_assert!(!e.to_string().is_empty()),
            }
        }
        prop_assert_eq!(Tolerance::new(a).is_ok(), a.is_finite() && a > 0.0);
        let leading = contact_bounce::debounce::window::preload_bounce_time(a, b, c, d, 0.5);
        prop_assert!(leading.is_err() || leading.is_ok_and(|l| l.seconds.is_finite() && l.seconds > 0.0));
        let ticks = contact_bounce::debounce::window::window_ticks(a, b, c);
        prop_assert!(ticks.is_err() || (a.is_finite() && b >= 1.0 && c > 0.0));
    }

    #[test]
    fn realistic_scenes_predict_sanely(
        log_omega in 1.0..7.0_f64,
        log_delta in -9.0..-1.0_f64,
        sign in prop_oneof![Just(-1.0), Just(0.0), Just(1.0)],
        r in 1e-4..0.99_f64,
        zeta in prop_oneof![Just(0.0), 1e-4..2.0_f64],
        log_j0 in -6.0..4.0_f64,
    ) {
        let omega = 10f64.powf(log_omega);
        let delta = sign * 10f64.powf(log_delta);
        let scale = if sign == 0.0 { omega * 1e-5 } else { omega * delta.abs() };
        let v0 = 10f64.powf(log_j0) * scale / (2.0 * (1.0 - r));
        let raw = Raw {
            frequency: (0, omega, 0.0),
            offset: (true, delta),
            restitution: (false, r),
            closing_speed: v0,
            threshold: (1, 1e-3),
            zeta,
            kernel: None,
        };
        let f64_scene = Scene::new(contact::<f64>(&raw), (Some(Viscous::optional(zeta).unwrap()), None::<Hereditary<f64>>));
        prop_assert!(f64_scene.is_ok(), "a realistic scene was refused: {:?}", f64_scene.err());
        check::<f64>(&raw)?;
        check::<f32>(&raw)?;
    }
}

//! Every invalid input of the core issue's item 1 returns its typed error, naming the parameter.

use contact_bounce::{
    scene::TwoBody, Contact, Error, Frequency, Hereditary, Margin, Offset, Parameter, Reason,
    Restitution, Scene, Threshold, Tolerance, Undamped, Viscous, Window,
};

const BAD: [(f64, Reason); 3] = [
    (f64::NAN, Reason::NotANumber),
    (f64::INFINITY, Reason::Infinite),
    (f64::NEG_INFINITY, Reason::Infinite),
];

fn good() -> Contact<f64> {
    Contact {
        frequency: Frequency::Omega(1000.0),
        offset: Offset::Delta(-1e-3),
        restitution: Restitution::Coefficient(0.7),
        closing_speed: 0.5,
        threshold: Threshold::None,
    }
}

fn err(contact: Contact<f64>) -> Error {
    match Scene::new(contact, Undamped) {
        Ok(s) => panic!("accepted an invalid scene: {contact:?} -> {:?}", s.regime()),
        Err(e) => e,
    }
}

fn expect(contact: Contact<f64>, parameter: Parameter, reason: Reason) {
    assert_eq!(err(contact), Error::new(parameter, reason), "{contact:?}");
}

/// A preloaded switch from its six numbers, in `Preloaded`'s order (the tests' shorthand).
fn lean_switch<F: contact_bounce::Float>(
    mass: F,
    stiffness: F,
    preload_force: F,
    closing_speed: F,
    restitution: F,
    damping_ratio: F,
) -> contact_bounce::Preloaded<F> {
    contact_bounce::Preloaded {
        mass,
        stiffness,
        preload_force,
        closing_speed,
        restitution,
        damping_ratio,
    }
}

#[test]
fn the_good_scene_is_accepted() {
    assert!(Scene::new(good(), Undamped).is_ok());
}

#[test]
fn omega_must_be_finite_and_positive() {
    for (v, reason) in BAD {
        expect(
            Contact {
                frequency: Frequency::Omega(v),
                ..good()
            },
            Parameter::Omega,
            reason,
        );
    }
    for v in [0.0, -0.0, -1.0] {
        expect(
            Contact {
                frequency: Frequency::Omega(v),
                ..good()
            },
            Parameter::Omega,
            Reason::NotPositive,
        );
    }
}

#[test]
fn mass_and_stiffness_must_be_finite_and_positive() {
    let ms = |mass, stiffness| Contact {
        frequency: Frequency::MassStiffness { mass, stiffness },
        ..good()
    };
    for (v, reason) in BAD {
        expect(ms(v, 1.0), Parameter::Mass, reason);
        expect(ms(1.0, v), Parameter::Stiffness, reason);
    }
    for v in [0.0, -2.0] {
        expect(ms(v, 1.0), Parameter::Mass, Reason::NotPositive);
        expect(ms(1.0, v), Parameter::Stiffness, Reason::NotPositive);
    }
    // Outside the physical domain of SI inputs, [1e-30, 1e30].
    expect(ms(1e-31, 1.0), Parameter::Mass, Reason::OutOfRange);
    expect(ms(1.0, 2e30), Parameter::Stiffness, Reason::OutOfRange);
    assert!(
        Scene::new(ms(1e-30, 1e30), Undamped).is_ok(),
        "Omega = 1e30 is inside the domain, and f64 holds its products"
    );
}

#[test]
fn delta_must_be_finite() {
    for (v, reason) in BAD {
        expect(
            Contact {
                offset: Offset::Delta(v),
                ..good()
            },
            Parameter::Delta,
            reason,
        );
    }
    // A non-zero |Delta| within the physical domain [1e-30, 1e30]; 0 is grazing.
    for d in [-1e-320, 2e30] {
        expect(
            Contact {
                offset: Offset::Delta(d),
                ..good()
            },
            Parameter::Delta,
            Reason::OutOfRange,
        );
    }
    // Inside the domain every product the model forms fits f64 (at most ~1e150): the corner
    // Omega = |Delta| = 1e30 is valid (f32 overflows first: see the f32 test).
    let fast = Contact {
        frequency: Frequency::Omega(1e30),
        offset: Offset::Delta(-1e30),
        ..good()
    };
    assert!(Scene::new(fast, Undamped).is_ok());
}

#[test]
fn preload_force_must_be_positive_and_needs_a_stiffness() {
    let with = |force| Contact {
        frequency: Frequency::MassStiffness {
            mass: 1e-4,
            stiffness: 100.0,
        },
        offset: Offset::PreloadForce(force),
        ..good()
    };
    for (v, reason) in BAD {
        expect(with(v), Parameter::PreloadForce, reason);
    }
    for v in [0.0, -1.0] {
        expect(with(v), Parameter::PreloadForce, Reason::NotPositive);
    }
    expect(
        Contact {
            offset: Offset::PreloadForce(1.0),
            ..good()
        },
        Parameter::PreloadForce,
        Reason::NeedsStiffness,
    );
    assert!(Scene::new(with(0.01), Undamped).is_ok());
}

#[test]
fn restitution_must_be_in_zero_one() {
    for (v, reason) in BAD {
        expect(
            Contact {
                restitution: Restitution::Coefficient(v),
                ..good()
            },
            Parameter::Restitution,
            reason,
        );
        expect(
            Contact {
                restitution: Restitution::Loss(v),
                ..good()
            },
            Parameter::OneMinusRestitution,
            reason,
        );
    }
    for v in [0.0, -0.1, 1.0 + 1e-15, 2.0] {
        expect(
            Contact {
                restitution: Restitution::Coefficient(v),
                ..good()
            },
            Parameter::Restitution,
            Reason::OutOfRange,
        );
    }
    for v in [1.0, 1.5, -1e-300] {
        expect(
            Contact {
                restitution: Restitution::Loss(v),
                ..good()
            },
            Parameter::OneMinusRestitution,
            Reason::OutOfRange,
        );
    }
    // R = 1 and r = 0 are valid (lossless impacts).
    assert!(Scene::new(
        Contact {
            restitution: Restitution::Coefficient(1.0),
            ..good()
        },
        Undamped
    )
    .is_ok());
    assert!(Scene::new(
        Contact {
            restitution: Restitution::Loss(0.0),
            ..good()
        },
        Undamped
    )
    .is_ok());
}

#[test]
fn closing_speed_must_be_finite_and_positive() {
    for (v, reason) in BAD {
        expect(
            Contact {
                closing_speed: v,
                ..good()
            },
            Parameter::ClosingSpeed,
            reason,
        );
    }
    for v in [0.0, -1.0] {
        expect(
            Contact {
                closing_speed: v,
                ..good()
            },
            Parameter::ClosingSpeed,
            Reason::NotPositive,
        );
    }
    for v in [f64::MAX, 1e-31] {
        expect(
            Contact {
                closing_speed: v,
                ..good()
            },
            Parameter::ClosingSpeed,
            Reason::OutOfRange,
        );
    }
}

#[test]
fn damping_ratio_must_be_finite_and_non_negative() {
    for (v, reason) in BAD {
        assert_eq!(
            Viscous::new(v),
            Err(Error::new(Parameter::DampingRatio, reason))
        );
    }
    assert_eq!(
        Viscous::new(-1e-9),
        Err(Error::new(Parameter::DampingRatio, Reason::Negative))
    );
    // Zero is no viscous damping: `Undamped`, or `None` where it is chosen at run time, so that
    // a scene typed `Viscous` is always damped (and links no undamped path).
    assert_eq!(
        Viscous::new(0.0),
        Err(Error::new(Parameter::DampingRatio, Reason::NotPositive))
    );
    assert_eq!(
        Viscous::new(-0.0),
        Err(Error::new(Parameter::DampingRatio, Reason::NotPositive))
    );
    assert_eq!(Viscous::optional(0.0), Ok(None));
    assert_eq!(Viscous::optional(-0.0), Ok(None));
    assert_eq!(
        Viscous::optional(-1e-9),
        Err(Error::new(Parameter::DampingRatio, Reason::Negative))
    );
    assert_eq!(
        Viscous::optional(f64::NAN).map_err(|e| e.reason()),
        Err(Reason::NotANumber)
    );
    assert_eq!(
        Viscous::optional(0.03).map(|v| v.map(|v| v.zeta())),
        Ok(Some(0.03))
    );
    // A preload without damping: Preloaded is damped, so it names the parameter.
    let undamped = lean_switch(5e-5, 5000.0, 1.0, 0.5, 0.7, 0.0);
    assert_eq!(
        undamped.scene().map(|_| ()),
        Err(Error::new(Parameter::DampingRatio, Reason::NotPositive))
    );
    assert!(Scene::new(undamped.contact(), contact_bounce::Undamped).is_ok());
}

#[test]
fn kernel_parameters_must_be_finite_and_positive() {
    for (v, reason) in BAD {
        assert_eq!(
            Hereditary::exponential(v, 1.0),
            Err(Error::new(Parameter::KernelAmplitude, reason))
        );
        assert_eq!(
            Hereditary::exponential(1.0, v),
            Err(Error::new(Parameter::KernelTimeConstant, reason))
        );
    }
    for v in [0.0, -1.0] {
        assert_eq!(
            Hereditary::exponential(v, 1.0),
            Err(Error::new(Parameter::KernelAmplitude, Reason::NotPositive))
        );
        assert_eq!(
            Hereditary::exponential(1.0, v),
            Err(Error::new(
                Parameter::KernelTimeConstant,
                Reason::NotPositive
            ))
        );
    }
    assert_eq!(
        Hereditary::exponential(1e300, 1e10),
        Err(Error::new(Parameter::KernelAmplitude, Reason::Overflow))
    );
    let k = Hereditary::exponential(1.0, 1.0).unwrap();
    for v in [0.0, 1e-20, 0.2, f64::NAN] {
        assert_eq!(
            k.with_tolerance(v).map(|_| ()).unwrap_err().parameter(),
            Parameter::HarmonicTolerance
        );
    }
}

#[test]
fn thresholds_must_be_valid_where_given_and_present_where_needed() {
    let with = |t| Contact {
        threshold: t,
        ..good()
    };
    for (v, reason) in BAD {
        expect(
            with(Threshold::FractionOfFirst(v)),
            Parameter::ThresholdFraction,
            reason,
        );
        expect(
            with(Threshold::Impulse(v)),
            Parameter::ThresholdImpulse,
            reason,
        );
    }
    for v in [0.0, -0.5, 1.0, 1.5] {
        expect(
            with(Threshold::FractionOfFirst(v)),
            Parameter::ThresholdFraction,
            Reason::OutOfRange,
        );
    }
    for v in [0.0, -1.0] {
        expect(
            with(Threshold::Impulse(v)),
            Parameter::ThresholdImpulse,
            Reason::NotPositive,
        );
    }
    // At or above the first impulse (1 + R) v0 = 0.85: no impact would count.
    expect(
        with(Threshold::Impulse(0.85)),
        Parameter::ThresholdImpulse,
        Reason::AboveFirstImpulse,
    );
    // An endless regime needs one: a gap without damping, R < 1.
    let endless = Contact {
        offset: Offset::Delta(1e-3),
        ..good()
    };
    expect(endless, Parameter::Threshold, Reason::Required);
    assert!(Scene::new(
        Contact {
            threshold: Threshold::FractionOfFirst(0.01),
            ..endless
        },
        Undamped
    )
    .is_ok());
    // ...and so does Delta = 0, and a preload with R = 1 and damping.
    expect(
        Contact {
            offset: Offset::Delta(0.0),
            ..good()
        },
        Parameter::Threshold,
        Reason::Required,
    );
    let r1 = Contact {
        restitution: Restitution::Coefficient(1.0),
        ..good()
    };
    assert_eq!(
        Scene::new(r1, Viscous::new(0.01).unwrap()).unwrap_err(),
        Error::new(Parameter::Threshold, Reason::Required)
    );
}

#[test]
fn two_body_parameters_are_named() {
    let ok = TwoBody {
        m1: 1e-3,
        c1: 100.0,
        d1: 0.0,
        m2: 2e-3,
        c2: 200.0,
        d2: 0.0,
    };
    assert!(ok.reduce().is_ok());
    type Set = fn(&mut TwoBody<f64>, f64);
    let fields: [(Set, Parameter, bool); 6] = [
        (|b, v| b.m1 = v, Parameter::Mass1, true),
        (|b, v| b.c1 = v, Parameter::Stiffness1, true),
        (|b, v| b.d1 = v, Parameter::Damping1, false),
        (|b, v| b.m2 = v, Parameter::Mass2, true),
        (|b, v| b.c2 = v, Parameter::Stiffness2, true),
        (|b, v| b.d2 = v, Parameter::Damping2, false),
    ];
    for (set, parameter, positive) in fields {
        for (v, reason) in BAD {
            let mut b = ok;
            set(&mut b, v);
            assert_eq!(b.reduce().unwrap_err(), Error::new(parameter, reason));
        }
        let mut b = ok;
        set(&mut b, -1.0);
        let reason = if positive {
            Reason::NotPositive
        } else {
            Reason::Negative
        };
        assert_eq!(b.reduce().unwrap_err(), Error::new(parameter, reason));
        let mut b = ok;
        set(&mut b, 0.0);
        assert_eq!(b.reduce().is_err(), positive, "{parameter}");
    }
    // The same errors come back through Scene::two_body.
    let mut bad = ok;
    bad.m2 = 0.0;
    let e = Scene::two_body(
        bad,
        Offset::Delta(-1e-3),
        Restitution::Coefficient(0.5),
        0.1,
        Threshold::None,
        None,
    );
    assert_eq!(
        e.unwrap_err(),
        Error::new(Parameter::Mass2, Reason::NotPositive)
    );
}

#[test]
fn tolerances_margins_and_windows_are_checked() {
    for (v, reason) in BAD {
        assert_eq!(
            Tolerance::new(v),
            Err(Error::new(Parameter::Tolerance, reason))
        );
        assert_eq!(
            Margin::new(v, 0.0),
            Err(Error::new(Parameter::MarginFactor, reason))
        );
        assert_eq!(
            Margin::new(1.0, v),
            Err(Error::new(Parameter::MarginExtra, reason))
        );
        assert_eq!(
            Window::from_seconds(v, &Margin::none(), 1e-3)
                .map(|w| w.ticks())
                .unwrap_err()
                .parameter(),
            Parameter::Time
        );
        assert_eq!(
            Window::from_seconds(1e-3, &Margin::none(), v)
                .map(|w| w.ticks())
                .unwrap_err()
                .parameter(),
            Parameter::SamplePeriod
        );
    }
    assert_eq!(
        Tolerance::new(0.0),
        Err(Error::new(Parameter::Tolerance, Reason::NotPositive))
    );
    assert_eq!(
        Margin::new(0.99, 0.0),
        Err(Error::new(Parameter::MarginFactor, Reason::OutOfRange))
    );
    assert_eq!(
        Margin::new(1.0, -1e-9),
        Err(Error::new(Parameter::MarginExtra, Reason::Negative))
    );
    assert_eq!(
        Window::from_seconds(-1.0, &Margin::none(), 1e-3),
        Err(Error::new(Parameter::Time, Reason::Negative))
    );
    assert_eq!(
        Window::from_seconds(1.0, &Margin::none(), 0.0),
        Err(Error::new(Parameter::SamplePeriod, Reason::NotPositive))
    );
}

#[test]
fn errors_display_the_parameter_and_the_reason() {
    let e = err(Contact {
        closing_speed: -1.0,
        ..good()
    });
    assert_eq!(e.to_string(), "closing_speed must be > 0");
    let e = err(Contact {
        offset: Offset::Delta(f64::NAN),
        ..good()
    });
    assert_eq!(e.to_string(), "gap is NaN");
    let boxed: Box<dyn std::error::Error> = Box::new(e);
    assert!(boxed.to_string().contains("gap"));
}

#[test]
fn out_of_range_errors_say_what_the_model_takes() {
    use contact_bounce::scene::{
        LARGEST_DAMPING, PHYSICAL_RANGE, SMALLEST_RATE, SMALLEST_RESTITUTION,
    };
    use contact_bounce::Windows;
    // The words name the limits the validation enforces (the constants, formatted as the
    // words write them).
    let (lo, hi) = PHYSICAL_RANGE;
    let physical = format!("[{lo:e}, {hi:e}]");
    let words = |p: Parameter| p.accepted().unwrap_or_else(|| panic!("{p} has no range"));
    for p in [
        Parameter::Omega,
        Parameter::Mass,
        Parameter::Stiffness,
        Parameter::ClosingSpeed,
        Parameter::ThresholdImpulse,
        Parameter::KernelTimeConstant,
        Parameter::PreloadForce,
        Parameter::Delta,
        Parameter::Damping1,
    ] {
        assert!(words(p).contains(&physical), "{p}: {}", words(p));
    }
    let restitution = words(Parameter::Restitution);
    assert!(restitution.contains(&format!("[{SMALLEST_RESTITUTION:e}, 1]")));
    assert!(restitution.contains(&format!("at least {SMALLEST_RATE:e}")));
    assert_eq!(
        words(Parameter::OneMinusRestitution),
        format!("0 or values in [{SMALLEST_RATE:e}, 1 - {SMALLEST_RESTITUTION:e}]")
    );
    assert_eq!(
        words(Parameter::DampingRatio),
        format!("0 or values in [{SMALLEST_RATE:e}, {LARGEST_DAMPING:e}]")
    );
    assert_eq!(Windows::MAX_TICKS, 32_767);
    assert!(words(Parameter::Time).contains("32,767"));

    // And the validation refuses just beyond them, accepts at them, and says so.
    let says = |e: Error, p: Parameter| {
        assert_eq!(e, Error::new(p, Reason::OutOfRange));
        let text = e.to_string();
        assert!(
            text.starts_with(&format!("{} is out of range: the model takes ", p.name()))
                && text.ends_with(words(p)),
            "{text}"
        );
    };
    let omega = |w| Contact {
        frequency: Frequency::Omega(w),
        ..good()
    };
    says(err(omega(hi * 1.01)), Parameter::Omega);
    says(err(omega(lo * 0.99)), Parameter::Omega);
    assert!(Scene::new(omega(lo), Undamped).is_ok() && Scene::new(omega(hi), Undamped).is_ok());
    let restitution = |r| Contact {
        restitution: Restitution::Coefficient(r),
        ..good()
    };
    says(
        err(restitution(SMALLEST_RESTITUTION * 0.99)),
        Parameter::Restitution,
    );
    says(err(restitution(1.2)), Parameter::Restitution);
    says(
        err(restitution(1.0 - SMALLEST_RATE * 0.5)),
        Parameter::Restitution,
    );
    assert!(Scene::new(restitution(SMALLEST_RESTITUTION), Undamped).is_ok());
    assert!(Scene::new(restitution(1.0 - SMALLEST_RATE * 1.01), Undamped).is_ok());
    assert!(Scene::new(restitution(1.0), Undamped).is_ok());
    let loss = |r| Contact {
        restitution: Restitution::Loss(r),
        ..good()
    };
    says(
        err(loss(SMALLEST_RATE * 0.5)),
        Parameter::OneMinusRestitution,
    );
    says(
        err(loss(1.0 - SMALLEST_RESTITUTION * 0.99)),
        Parameter::OneMinusRestitution,
    );
    assert!(Scene::new(loss(1.0 - SMALLEST_RESTITUTION * 1.01), Undamped).is_ok());
    for zeta in [SMALLEST_RATE * 0.5, LARGEST_DAMPING * 1.01] {
        let e = Scene::new(good(), Viscous::new(zeta).unwrap_or_else(|e| panic!("{e}")));
        says(e.map(|_| ()).unwrap_err(), Parameter::DampingRatio);
    }
    let fraction = |f| Contact {
        threshold: Threshold::FractionOfFirst(f),
        ..good()
    };
    says(err(fraction(1.0)), Parameter::ThresholdFraction);
    says(err(fraction(0.0)), Parameter::ThresholdFraction);
    // kappa tau at Omega^2 (1e6) leaves no restoring force; just below it is taken.
    let kernel = |kappa| Hereditary::exponential(kappa, 1e-3).unwrap_or_else(|e| panic!("{e}"));
    let e = Scene::new(good(), (None::<Viscous<f64>>, kernel(1e9)));
    says(e.map(|_| ()).unwrap_err(), Parameter::KernelAmplitude);
    assert!(Scene::new(good(), (None::<Viscous<f64>>, kernel(0.99e9))).is_ok());
    let tolerance = |t| kernel(1e6).with_tolerance(t).map(|_| ());
    says(tolerance(0.11).unwrap_err(), Parameter::HarmonicTolerance);
    says(
        tolerance(15.0 * f64::EPSILON).unwrap_err(),
        Parameter::HarmonicTolerance,
    );
    assert!(tolerance(0.1).is_ok() && tolerance(16.0 * f64::EPSILON).is_ok());
    says(
        Margin::new(0.99, 0.0).map(|_| ()).unwrap_err(),
        Parameter::MarginFactor,
    );
    let windows = |ticks| Windows::new(ticks, 1, contact_bounce::Mode::Confirm).map(|_| ());
    says(
        windows(Windows::MAX_TICKS + 1).unwrap_err(),
        Parameter::Time,
    );
    assert!(windows(Windows::MAX_TICKS).is_ok());
    // A reason other than the range says only itself.
    let e = err(Contact {
        closing_speed: -1.0,
        ..good()
    });
    assert_eq!(e.to_string(), "closing_speed must be > 0");
}

#[test]
fn f32_scenes_are_validated_the_same_way() {
    let c = Contact {
        frequency: Frequency::Omega(1000.0_f32),
        offset: Offset::Delta(-1e-3),
        restitution: Restitution::Coefficient(0.7),
        closing_speed: f32::NAN,
        threshold: Threshold::None,
    };
    assert_eq!(
        Scene::new(c, Undamped).unwrap_err(),
        Error::new(Parameter::ClosingSpeed, Reason::NotANumber)
    );
    // 2 Omega^2 ... overflows f32 long before f64.
    let c = Contact {
        frequency: Frequency::Omega(1e30_f32),
        closing_speed: 1.0,
        ..c
    };
    assert_eq!(
        Scene::new(c, Undamped).unwrap_err(),
        Error::new(Parameter::Delta, Reason::Overflow)
    );
}

#[test]
fn thresholds_below_the_resolvable_impulse_are_refused() {
    // 1e-300 of the first impulse at Omega |Delta| = 1: below 1e3 * MIN_POSITIVE * 2 Omega |Delta|.
    let c = Contact {
        threshold: Threshold::FractionOfFirst(1e-306),
        ..good()
    };
    expect(c, Parameter::ThresholdFraction, Reason::Overflow);
    let c = Contact {
        threshold: Threshold::Impulse(1e-306),
        ..good()
    };
    expect(c, Parameter::ThresholdImpulse, Reason::OutOfRange);
    assert!(Scene::new(
        Contact {
            threshold: Threshold::FractionOfFirst(1e-250),
            ..good()
        },
        Undamped
    )
    .is_ok());
}

#[test]
fn the_model_domain_is_enforced() {
    // r and zeta: 0, or at least 1e-12; zeta at most 1e3; R at least 1e-6.
    let loss = |r| Contact {
        restitution: Restitution::Loss(r),
        ..good()
    };
    expect(
        loss(1e-13),
        Parameter::OneMinusRestitution,
        Reason::OutOfRange,
    );
    assert!(Scene::new(loss(1e-12), Undamped).is_ok());
    // The same limit given as R names R, the parameter given (it named one_minus_restitution,
    // a field a scene file does not have).
    expect(
        Contact {
            restitution: Restitution::Coefficient(1.0 - 1e-13),
            ..good()
        },
        Parameter::Restitution,
        Reason::OutOfRange,
    );
    let coefficient = Contact {
        restitution: Restitution::Coefficient(1e-7),
        ..good()
    };
    expect(coefficient, Parameter::Restitution, Reason::OutOfRange);
    for zeta in [1e-13, 1.1e3] {
        let e = Scene::new(good(), Viscous::new(zeta).unwrap()).unwrap_err();
        assert_eq!(e, Error::new(Parameter::DampingRatio, Reason::OutOfRange));
    }
    assert!(Scene::new(good(), Viscous::new(1e3).unwrap()).is_ok());
    assert!(Scene::new(good(), Viscous::new(1e-12).unwrap()).is_ok());
    let e = Hereditary::exponential(1.0, 1e-31).unwrap_err();
    assert_eq!(
        e,
        Error::new(Parameter::KernelTimeConstant, Reason::OutOfRange)
    );
}

#[test]
fn the_lean_t_b1v_agrees_with_the_scenes_and_refuses_what_the_scene_refuses() {
    use contact_bounce::{scene::catalogue, tiers::preload_viscous_bounce_time};
    for d in catalogue::ALL {
        let lean = preload_viscous_bounce_time(&d.preloaded::<f64>()).expect("valid");
        let full = d.scene::<f64>().expect("valid").t_b1v().expect("a preload");
        assert!((lean.time / full.time - 1.0).abs() < 1e-12, "{}", d.name);
        assert_eq!(lean.expected_error.is_some(), full.expected_error.is_some());
        if let (Some(a), Some(b)) = (lean.expected_error, full.expected_error) {
            assert!((a / b - 1.0).abs() < 1e-9, "{}", d.name);
        }
        let narrow = preload_viscous_bounce_time(&d.preloaded::<f32>()).expect("valid in f32");
        assert!(
            (f64::from(narrow.time) / full.time - 1.0).abs() < 1e-5,
            "{}",
            d.name
        );
    }
    let d = catalogue::TACTILE_DOME;
    let refused = |m: f64, k: f64, f: f64, v: f64, r: f64, z: f64| {
        preload_viscous_bounce_time(&lean_switch(m, k, f, v, r, z))
            .map(|_| ())
            .map_err(|e| e.parameter())
    };
    let (m, k, f, v, r, z) = (
        d.mass,
        d.stiffness,
        d.preload_force,
        d.closing_speed,
        d.restitution,
        d.damping_ratio,
    );
    assert_eq!(refused(0.0, k, f, v, r, z), Err(Parameter::Mass));
    assert_eq!(refused(m, f64::NAN, f, v, r, z), Err(Parameter::Stiffness));
    assert_eq!(refused(m, k, -1.0, v, r, z), Err(Parameter::PreloadForce));
    assert_eq!(refused(m, k, f, 1e31, r, z), Err(Parameter::ClosingSpeed));
    assert_eq!(refused(m, k, f, v, 1.0, z), Err(Parameter::Restitution));
    assert_eq!(refused(m, k, f, v, 0.0, z), Err(Parameter::Restitution));
    assert_eq!(refused(m, k, f, v, r, -0.1), Err(Parameter::DampingRatio));
    assert_eq!(refused(m, k, f, v, r, 1e-13), Err(Parameter::DampingRatio));
    assert_eq!(refused(m, k, f, v, r, 0.0), Ok(()));
    // An acceleration scale Omega (1 + R) v0 beyond f32's largest value over 2^17 (Omega 2.6e16
    // rad/s at 1e30 m/s): both refuse it, naming the closing speed.
    let lean = preload_viscous_bounce_time(&lean_switch(1e-30_f32, 651.0, 1e-3, 1e30, 0.7, 0.01));
    assert_eq!(
        lean.map_err(|e| e.parameter()).map(|_| ()),
        Err(Parameter::ClosingSpeed)
    );
    let scene = Scene::new(
        Contact {
            frequency: Frequency::MassStiffness {
                mass: 1e-30_f32,
                stiffness: 651.0,
            },
            offset: Offset::PreloadForce(1e-3),
            restitution: Restitution::Coefficient(0.7),
            closing_speed: 1e30,
            threshold: Threshold::None,
        },
        Viscous::new(0.01).expect("valid"),
    );
    assert_eq!(
        scene.map(|_| ()).map_err(|e| e.parameter()),
        Err(Parameter::ClosingSpeed)
    );
}

#[test]
fn a_bounce_shorter_than_the_smallest_normal_float_is_refused() {
    // f32: a 6.6e-30 kg contact at Omega 2.6e11 rad/s, preloaded 0.86 m, closing at 4.2e-17
    // m/s with R 0.0046: its first flight, 2 R v0 / (Omega^2 |Delta|), is 6.6e-42 s, a
    // subnormal f32 with 12 significant bits (every tier answered 6.623e-42 s, 2e-4 from the
    // f64 answer, beyond the f32 rounding the exact tier states). Refused, naming the closing
    // speed; the lean paths refuse the time itself (not a normal number). In f64 the same
    // scene is fine and agrees with the closed form.
    use contact_bounce::tiers::{preload_restitution_bounce_seconds, preload_viscous_bounce_time};
    let (m, k, f, v, r, z) = (
        6.616_427e-30,
        4.555_134_6e-7,
        3.899_010_3e-7,
        4.216_672e-17,
        0.004_606_765,
        0.008_416_908,
    );
    fn preloaded<F: contact_bounce::Float>(m: F, k: F, f: F, v: F, r: F, z: F) -> Contact<F> {
        lean_switch(m, k, f, v, r, z).contact()
    }
    #[allow(clippy::cast_possible_truncation)]
    let narrow = |x: f64| x as f32;
    let (mf, kf, ff, vf, rf, zf) = (
        narrow(m),
        narrow(k),
        narrow(f),
        narrow(v),
        narrow(r),
        narrow(z),
    );
    let scene = Scene::new(
        preloaded(mf, kf, ff, vf, rf, zf),
        Viscous::new(zf).expect("valid"),
    );
    assert_eq!(
        scene.map(|_| ()),
        Err(Error::new(Parameter::ClosingSpeed, Reason::Overflow))
    );
    let lean = preload_viscous_bounce_time(&lean_switch(mf, kf, ff, vf, rf, zf)).map(|_| ());
    assert_eq!(
        lean,
        Err(Error::new(Parameter::PreloadForce, Reason::Overflow))
    );
    let lean =
        preload_restitution_bounce_seconds(&lean_switch(mf, kf, ff, vf, rf, 0.0)).map(|_| ());
    assert_eq!(
        lean,
        Err(Error::new(Parameter::PreloadForce, Reason::Overflow))
    );
    let wide = Scene::new(preloaded(m, k, f, v, r, z), Viscous::new(z).expect("valid"))
        .expect("normal in f64");
    let t_b1v = wide.t_b1v().expect("a preload").time;
    let lean = preload_viscous_bounce_time(&lean_switch(m, k, f, v, r, z))
        .expect("normal in f64")
        .time;
    assert!((t_b1v / 6.623_237_8e-42 - 1.0).abs() < 1e-6, "{t_b1v:e}");
    assert!((lean / t_b1v - 1.0).abs() < 1e-12);
}

#[test]
fn the_lean_t_b1v_alone_is_the_estimates_time_at_every_scale() {
    // m / k from 1e-58 to 1e58: inside f32's normal range one square root serves (of m / k),
    // outside it two (of m and of k); both agree with the f64 scene's t_b1v to f32's rounding,
    // and the time alone is bit for bit the estimate's, refusals included.
    use contact_bounce::tiers::{preload_viscous_bounce_seconds, preload_viscous_bounce_time};
    let exponents = [-29, -20, -8, -4, 0, 3, 8, 20, 29];
    let mut both_paths = (0, 0);
    for em in exponents {
        for ek in exponents {
            let (m, k) = (10f64.powi(em), 10f64.powi(ek));
            // A preload of 1 % of k times a metre-scale stroke, closing at 0.1 Omega |Delta|.
            let (f, r, z) = (1e-2 * k.min(1e28), 0.7, 0.03);
            let v = 0.1 * f / (k * m).sqrt();
            #[allow(clippy::cast_possible_truncation)]
            let narrow = |x: f64| x as f32;
            let (mf, kf, ff, vf) = (narrow(m), narrow(k), narrow(f), narrow(v));
            let lean = preload_viscous_bounce_time(&lean_switch(mf, kf, ff, vf, 0.7, 0.03));
            let alone = preload_viscous_bounce_seconds(&lean_switch(mf, kf, ff, vf, 0.7, 0.03));
            assert_eq!(lean.map(|e| e.time), alone, "m {m:e} k {k:e}");
            let Ok(time) = alone else { continue };
            let ratio = mf / kf;
            if ratio.is_normal() {
                both_paths.0 += 1;
            } else {
                both_paths.1 += 1;
            }
            let wide =
                preload_viscous_bounce_time(&lean_switch(m, k, f, v, r, z)).expect("valid in f64");
            assert!(
                (f64::from(time) / wide.time - 1.0).abs() < 1e-5,
                "m {m:e} k {k:e}: {time:e} against {:e}",
                wide.time
            );
        }
    }
    assert!(both_paths.0 > 0 && both_paths.1 > 0, "{both_paths:?}");
}

#[test]
fn the_lean_restitution_averaged_time_is_the_averaged_tiers_and_refuses_what_the_scene_refuses() {
    // The closed-form Ti2 time against Method::Averaged on the same contact as a
    // Scene<_, Undamped>, whose fall takes the same integral from the scene's own orbit (q =
    // 2 Omega Delta from Omega and Delta, not from sqrt(k m)): equal to rounding in f64, and in
    // f32 to f32's rounding of the inputs, on every catalogue switch and over m / k from 1e-58
    // to 1e58 (both square-root paths of the checks).
    use contact_bounce::{
        scene::catalogue, tiers::preload_restitution_bounce_seconds, Method, Nodes,
    };
    let averaged = |m: f64, k: f64, f: f64, v: f64, r: f64| {
        let contact = lean_switch(m, k, f, v, r, 0.0).contact();
        Scene::new(contact, Undamped)
            .expect("valid")
            .predict(Method::Averaged(Nodes::N8))
            .end_time
            .seconds()
            .expect("a preload ends")
    };
    #[allow(clippy::cast_possible_truncation)]
    let narrow = |x: f64| x as f32;
    for d in catalogue::ALL {
        let (m, k, f, v, r) = (
            d.mass,
            d.stiffness,
            d.preload_force,
            d.closing_speed,
            d.restitution,
        );
        let full = averaged(m, k, f, v, r);
        let lean =
            preload_restitution_bounce_seconds(&lean_switch(m, k, f, v, r, 0.0)).expect("valid");
        assert!(
            (lean / full - 1.0).abs() < 1e-12,
            "{}: {lean:e} vs {full:e}",
            d.name
        );
        let single = preload_restitution_bounce_seconds(&lean_switch(
            narrow(m),
            narrow(k),
            narrow(f),
            narrow(v),
            narrow(r),
            0.0,
        ))
        .expect("valid in f32");
        assert!((f64::from(single) / full - 1.0).abs() < 1e-5, "{}", d.name);
    }
    let exponents = [-29, -20, -8, 0, 8, 20, 29];
    let mut checked = 0;
    for em in exponents {
        for ek in exponents {
            let (m, k) = (10f64.powi(em), 10f64.powi(ek));
            let f = 1e-2 * k.min(1e28);
            // j0 from 0.2 (below the reflection of Ti2) to 20 (above it).
            for share in [0.1, 10.0] {
                let v = share * f / (k * m).sqrt();
                let single = preload_restitution_bounce_seconds(&lean_switch(
                    narrow(m),
                    narrow(k),
                    narrow(f),
                    narrow(v),
                    0.7,
                    0.0,
                ));
                let Ok(time) = single else { continue };
                let wide = averaged(m, k, f, v, 0.7);
                assert!(
                    (f64::from(time) / wide - 1.0).abs() < 1e-5,
                    "m {m:e} k {k:e} v {v:e}: {time:e} against {wide:e}"
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 40, "{checked}");
    let d = catalogue::TACTILE_DOME;
    let (m, k, f, v, r) = (
        d.mass,
        d.stiffness,
        d.preload_force,
        d.closing_speed,
        d.restitution,
    );
    let refused = |m: f64, k: f64, f: f64, v: f64, r: f64| {
        preload_restitution_bounce_seconds(&lean_switch(m, k, f, v, r, 0.0))
            .map(|_| ())
            .map_err(|e| e.parameter())
    };
    assert_eq!(refused(0.0, k, f, v, r), Err(Parameter::Mass));
    assert_eq!(refused(m, f64::NAN, f, v, r), Err(Parameter::Stiffness));
    assert_eq!(refused(m, k, -1.0, v, r), Err(Parameter::PreloadForce));
    assert_eq!(refused(m, k, f, 1e31, r), Err(Parameter::ClosingSpeed));
    assert_eq!(refused(m, k, f, v, 1.0), Err(Parameter::Restitution));
    assert_eq!(refused(m, k, f, v, 0.0), Err(Parameter::Restitution));
    assert_eq!(
        refused(m, k, f, v, f64::INFINITY),
        Err(Parameter::Restitution)
    );
    // A damping ratio the path would leave out of the time is refused, by name (a NaN too);
    // 0 is the path's own.
    for zeta in [0.03, 1e-12, f64::NAN] {
        let damped = preload_restitution_bounce_seconds(&lean_switch(m, k, f, v, r, zeta));
        assert_eq!(
            damped.map(|_| ()).map_err(|e| e.parameter()),
            Err(Parameter::DampingRatio),
            "zeta {zeta}"
        );
    }
    // The first impulse below the floor, as the scene (and the lean t_b1v) refuse it.
    let floor = preload_restitution_bounce_seconds(&lean_switch(
        1000.0_f32,
        1e-30,
        1.0,
        1e-30,
        1.0 - 4.335_312e-5,
        0.0,
    ));
    assert_eq!(
        floor.map_err(|e| e.parameter()),
        Err(Parameter::ClosingSpeed)
    );
}

#[test]
fn a_first_impulse_below_the_floor_is_refused() {
    // Found by the raw-bits harness (f32): v0 = 1e-30 m/s against 2 Omega |Delta| = 6e13 m/s,
    // a phase no float can hold; every tier returned a NaN time. Now refused, naming v0.
    let contact = Contact {
        frequency: Frequency::MassStiffness {
            mass: 1000.0_f32,
            stiffness: 1e-30,
        },
        offset: Offset::PreloadForce(1.0),
        restitution: Restitution::Loss(4.335_312e-5),
        closing_speed: 1e-30,
        threshold: Threshold::None,
    };
    let e = Scene::new(contact, contact_bounce::Undamped).expect_err("refused");
    assert_eq!(
        (e.parameter(), e.reason()),
        (Parameter::ClosingSpeed, Reason::Overflow)
    );
    // The lean closed form takes the same domain.
    let lean = contact_bounce::tiers::preload_viscous_bounce_time(&lean_switch(
        1000.0_f32,
        1e-30,
        1.0,
        1e-30,
        1.0 - 4.335_312e-5,
        0.0,
    ))
    .expect_err("refused");
    assert_eq!(lean.parameter(), Parameter::ClosingSpeed);
    // The same in f64 is well inside its range, and accepted.
    let wide = Contact {
        frequency: Frequency::MassStiffness {
            mass: 1000.0_f64,
            stiffness: 1e-30,
        },
        offset: Offset::PreloadForce(1.0),
        restitution: Restitution::Loss(4.335_312e-5),
        closing_speed: 1e-30,
        threshold: Threshold::None,
    };
    assert!(Scene::new(wide, contact_bounce::Undamped).is_ok());
}

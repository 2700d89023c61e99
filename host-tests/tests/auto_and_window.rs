//! `Method::Auto` picks the cheapest tier whose expected error meets the tolerance, and says
//! when none does; windows round up, check every conversion and refuse endless predictions.

use contact_bounce::{
    scene::catalogue, tiers::ClosedForm, tiers::Tier, Contact, Error, Frequency, Margin, Method,
    Nodes, Offset, Parameter, Reason, Restitution, Scene, Threshold, Tolerance, Undamped, Viscous,
    Window,
};

fn preload(r: f64, zeta: f64, j0: f64) -> Scene<f64, Option<Viscous<f64>>> {
    let v0 = j0 * 1000.0 * 1e-3 / (2.0 * r);
    let contact = Contact {
        frequency: Frequency::Omega(1000.0),
        offset: Offset::Delta(-1e-3),
        restitution: Restitution::Coefficient(r),
        closing_speed: v0,
        threshold: Threshold::None,
    };
    Scene::new(contact, Viscous::optional(zeta).unwrap()).unwrap()
}

fn auto(
    scene: &Scene<f64, Option<Viscous<f64>>>,
    tolerance: f64,
) -> contact_bounce::Prediction<f64> {
    scene.predict(Method::Auto(Tolerance::new(tolerance).unwrap()))
}

#[test]
fn auto_takes_the_exact_sums_when_there_is_no_damping() {
    let scene = preload(0.5, 0.0, 3.0);
    let p = auto(&scene, 1e-8);
    assert_eq!(p.tier, Tier::Closed(ClosedForm::Undamped));
    assert!(p.promises(Tolerance::new(1e-8).unwrap()));
}

#[test]
fn auto_takes_the_closed_form_when_its_error_fits() {
    // R = 0.5, zeta = 0.005, j0 = 0.5: t_b1v expected 2.5 % + 2.1 % (atan, x = 0.25) = 4.6 %.
    let scene = preload(0.5, 0.005, 0.5);
    let p = auto(&scene, 0.05);
    assert_eq!(p.tier, Tier::Closed(ClosedForm::Tb1v));
    assert!(p.expected_error.unwrap() <= 0.05);
}

#[test]
fn auto_takes_the_only_tier_that_fits() {
    // At 1 %: t_b1v (4.6 %) and the averaged model (0.7 % + 1 % for damping) do not fit; the
    // map (0.3 % for zeta <= 0.01) does.
    let scene = preload(0.5, 0.005, 0.5);
    let p = auto(&scene, 0.01);
    assert_eq!(p.tier, Tier::Map);
    assert!(p.promises(Tolerance::new(0.01).unwrap()));
}

#[test]
fn auto_weighs_the_exact_tier_by_its_cost() {
    let two = Tolerance::new(0.02).unwrap();
    let run =
        |scene: &Scene<f64, Option<Viscous<f64>>>, method| scene.predict(method).promises(two);
    let map = Method::Map {
        max_impacts: 100_000,
    };
    // Heavier damping: the map gives 2.5 %, the averaged model 1 % + its table's figure for
    // R = 0.7 at j0 <= 0.3, so of the cheaper tiers only the averaged model fits 2 %; but the
    // exact tier's few flights cost less than its 9 panels (0.56 against 1.5 us on this host),
    // and the exact tier is taken. (At R = 0.9, 15 flights against the same 9 panels, the two
    // cost about the same, 1.6 and 1.5 us.)
    let scene = preload(0.7, 0.05, 0.3);
    assert!(run(&scene, Method::Averaged(Nodes::N8)) && !run(&scene, map));
    assert_eq!(auto(&scene, 0.02).tier, Tier::Exact);
    // R = 0.98: the map (0.3 %) and the averaged model (1.1 %) both fit, and the exact tier
    // always does; the averaged model costs least (1.9 us against 10 us for the map's ~700
    // impacts and 12 us for the exact tier's ~150 flights).
    let scene = preload(0.98, 0.01, 1.0);
    assert!(run(&scene, Method::Averaged(Nodes::N8)) && run(&scene, map));
    assert_eq!(auto(&scene, 0.02).tier, Tier::Averaged(Nodes::N8));
}

#[test]
fn auto_answers_with_the_exact_tier_where_nothing_cheaper_promises() {
    // The tactile dome at 0.1 %: no closed form, map or averaged figure of docs/physics.md sec. 6
    // promises that with damping; the exact tier does, at the float's rounding.
    let dome = catalogue::TACTILE_DOME.scene::<f64>().unwrap();
    for tol in [1e-3, 1e-9] {
        let tolerance = Tolerance::new(tol).unwrap();
        let p = dome.predict(Method::Auto(tolerance));
        assert_eq!(p.tier, Tier::Exact);
        assert!(p.promises(tolerance), "{p:?}");
    }
    // At 10 % a cheaper tier promises, and is taken.
    let p = dome.predict(Method::Auto(Tolerance::new(0.1).unwrap()));
    assert_ne!(p.tier, Tier::Exact);
}

#[test]
fn the_exact_tier_states_its_work_bound_before_it_runs() {
    // Viscous damping with Delta != 0: flights are solved, at most (cap + 1) x (128 + 6)
    // evaluations. Without damping the closed tier's sums answer: no flight is solved.
    let dome = catalogue::TACTILE_DOME.scene::<f64>().unwrap();
    assert_eq!(dome.exact_work(1000), Some(1001 * 134));
    let undamped = Scene::new(catalogue::TACTILE_DOME.contact::<f64>(), Undamped).unwrap();
    assert_eq!(undamped.exact_work(1000), None);
    // A relaxation kernel: its flights are scanned for their return, 4096 evaluations each.
    let kernel = contact_bounce::Hereditary::exponential(1e6, 1e-3).unwrap();
    let kernelled = Scene::new(catalogue::TACTILE_DOME.contact::<f64>(), kernel).unwrap();
    assert_eq!(
        kernelled.exact_work(1000),
        Some(1001 * u64::from(contact_bounce::tiers::KERNEL_FLIGHT_STEPS))
    );
    // With a cap of 3 flights the averaged model finishes, and says so.
    let p = dome.predict(Method::Exact { max_impacts: 3 });
    assert!(p
        .approximations
        .contains(contact_bounce::tiers::Approximations::MAP_CONTINUED_AVERAGED));
}

#[test]
fn auto_answers_a_kernel_with_the_exact_tier() {
    // One relaxation kernel: the exact tier solves its flights, so even 1e-6 is promised.
    let contact = Contact {
        frequency: Frequency::Omega(1000.0),
        offset: Offset::Delta(-1e-3),
        restitution: Restitution::Coefficient(0.7),
        closing_speed: 0.5,
        threshold: Threshold::None,
    };
    let kernel = contact_bounce::Hereditary::exponential(1e6, 1e-3).unwrap();
    let scene = Scene::new(contact, kernel).unwrap();
    let tolerance = Tolerance::new(1e-6).unwrap();
    let p = scene.predict(Method::Auto(tolerance));
    assert_eq!(p.tier, Tier::Exact);
    assert!(p.promises(tolerance), "{p:?}");
}

#[test]
fn auto_says_when_it_cannot_promise() {
    // Two relaxation kernels: the exact tier solves one, so here it answers with the averaged
    // model, and at 1e-6 nothing promises.
    let kernel = contact_bounce::Hereditary::exponential(1e6, 1e-3).unwrap();
    let scene = Scene::new(
        Contact {
            frequency: Frequency::Omega(1000.0),
            offset: Offset::Delta(-1e-3),
            restitution: Restitution::Coefficient(0.7),
            closing_speed: 0.5,
            threshold: Threshold::None,
        },
        (kernel, kernel),
    )
    .unwrap();
    let tolerance = Tolerance::new(1e-6).unwrap();
    let p = scene.predict(Method::Auto(tolerance));
    assert!(!p.promises(tolerance));
    assert_eq!(scene.exact_work(1000), None);
    // It still answers, with the smallest expected error on offer.
    let candidates = [
        Method::Closed,
        Method::Averaged(Nodes::N8),
        Method::Map {
            max_impacts: 100_000,
        },
        Method::Exact {
            max_impacts: contact_bounce::tiers::EXACT_MAX_IMPACTS,
        },
    ];
    let best = candidates
        .iter()
        .filter_map(|m| scene.predict(*m).expected_error)
        .fold(f64::INFINITY, f64::min);
    assert_eq!(p.expected_error, Some(best));
}

#[test]
fn windows_round_up_and_check_every_conversion() {
    let margin = Margin::none();
    assert_eq!(
        Window::from_seconds(1.0e-3, &margin, 1.0e-3)
            .unwrap()
            .ticks(),
        1
    );
    assert_eq!(
        Window::from_seconds(1.000_001e-3, &margin, 1.0e-3)
            .unwrap()
            .ticks(),
        2
    );
    assert_eq!(
        Window::from_seconds(0.0, &margin, 1.0e-3).unwrap().ticks(),
        0
    );
    // u32::MAX ticks fit; one more does not, and that is an error, not a wrap or a saturation.
    assert_eq!(
        Window::from_seconds(4_294_967_295.0, &margin, 1.0)
            .unwrap()
            .ticks(),
        u32::MAX
    );
    assert_eq!(
        Window::from_seconds(4_294_967_296.0, &margin, 1.0),
        Err(Error::new(Parameter::SamplePeriod, Reason::Overflow))
    );
    // The margin multiplies, then adds.
    let margin = Margin::new(2.0, 0.5e-3).unwrap();
    assert_eq!(
        Window::from_seconds(1.0e-3, &margin, 0.25e-3)
            .unwrap()
            .ticks(),
        10
    );
}

#[test]
fn an_endless_prediction_has_no_window() {
    let periodic = Scene::new(
        Contact {
            frequency: Frequency::Omega(1000.0),
            offset: Offset::Delta(-1e-3),
            restitution: Restitution::Coefficient(1.0),
            closing_speed: 0.1,
            threshold: Threshold::None,
        },
        Undamped,
    )
    .unwrap();
    let p = periodic.predict(Method::Closed);
    assert_eq!(
        Window::from_prediction(&p, &Margin::none(), 1e-3),
        Err(Error::new(Parameter::Time, Reason::Endless))
    );
}

#[test]
fn the_expected_error_widens_the_window() {
    let dome = catalogue::TACTILE_DOME.scene::<f64>().unwrap();
    let p = dome.predict(Method::Closed);
    let plain = Window::from_prediction(&p, &Margin::none(), 1e-6)
        .unwrap()
        .ticks();
    let widened = Window::from_prediction(&p, &Margin::none().with_expected_error(&p), 1e-6)
        .unwrap()
        .ticks();
    let expected = p.expected_error.unwrap();
    assert!(f64::from(widened) >= f64::from(plain) * (1.0 + expected) - 1.0);
    assert!(widened > plain);
}

#[test]
fn const_window_matches_the_runtime_one() {
    const T: f64 =
        match contact_bounce::debounce::window::preload_bounce_time(5e-5, 5000.0, 1.0, 0.5, 0.7) {
            Ok(t) => t.seconds,
            Err(_) => panic!(),
        };
    let dome = Scene::new(catalogue::TACTILE_DOME.contact::<f64>(), Undamped).unwrap();
    assert!((T / dome.t_b1().unwrap().time - 1.0).abs() < 1e-14);
    for (seconds, factor, period) in [(T, 1.5, 1e-5), (1e-3, 1.0, 1e-3), (0.37, 2.0, 1e-4)] {
        let runtime =
            Window::from_seconds(seconds, &Margin::new(factor, 0.0).unwrap(), period).unwrap();
        assert_eq!(
            contact_bounce::debounce::window::window_ticks(seconds, factor, period),
            Ok(runtime.ticks())
        );
    }
    assert_eq!(
        contact_bounce::debounce::window::window_ticks(1e10, 1.0, 1e-3),
        Err(Error::new(Parameter::SamplePeriod, Reason::Overflow))
    );
    assert_eq!(
        contact_bounce::debounce::window::preload_bounce_time(5e-5, 5000.0, 1.0, 0.5, 1.0)
            .unwrap_err()
            .parameter(),
        Parameter::Restitution
    );
    assert_eq!(
        contact_bounce::debounce::window::preload_bounce_time(f64::NAN, 5000.0, 1.0, 0.5, 0.5)
            .unwrap_err(),
        Error::new(Parameter::Mass, Reason::NotANumber)
    );
}

/// `Preloaded` is the long path in one call: the same window as building the scene, predicting
/// and widening by hand, for every catalogue switch, tier and float; and every invalid input
/// is the typed error the long path gives.
#[test]
fn a_preloaded_switch_gives_the_long_paths_window_and_errors() {
    use contact_bounce::{scene::catalogue, Margin, Method, Nodes, Parameter, Preloaded, Window};
    fn long<F: contact_bounce::Float>(
        p: &Preloaded<F>,
        method: Method<F>,
    ) -> Result<Window, contact_bounce::Error> {
        let scene = contact_bounce::Scene::new(
            p.contact(),
            contact_bounce::Viscous::optional(p.damping_ratio)?,
        )?;
        let prediction = scene.predict(method);
        let margin = Margin::new(F::from_f64(1.5), F::ZERO)?.with_expected_error(&prediction);
        Window::from_prediction(&prediction, &margin, F::from_f64(1e-6))
    }
    for s in catalogue::ALL {
        for method in [
            Method::Closed,
            Method::Averaged(Nodes::N8),
            Method::Map {
                max_impacts: 100_000,
            },
        ] {
            let p = s.preloaded::<f64>();
            assert_eq!(p.window(method, 1.5, 1e-6), long(&p, method), "{}", s.name);
            let method32 = match method {
                Method::Closed => Method::Closed,
                Method::Averaged(n) => Method::Averaged(n),
                _ => Method::Map {
                    max_impacts: 100_000,
                },
            };
            let p32 = s.preloaded::<f32>();
            assert_eq!(
                p32.window(method32, 1.5, 1e-6),
                long(&p32, method32),
                "{}",
                s.name
            );
        }
    }
    let dome = catalogue::TACTILE_DOME.preloaded::<f32>();
    let cases = [
        (
            Preloaded {
                preload_force: -1.0,
                ..dome
            },
            Parameter::PreloadForce,
        ),
        (
            Preloaded {
                damping_ratio: f32::NAN,
                ..dome
            },
            Parameter::DampingRatio,
        ),
        (
            Preloaded {
                restitution: 1.5,
                ..dome
            },
            Parameter::Restitution,
        ),
        (Preloaded { mass: 0.0, ..dome }, Parameter::Mass),
    ];
    for (p, parameter) in cases {
        let e = p.window(Method::Closed, 1.5, 1e-5).expect_err("invalid");
        assert_eq!(e.parameter(), parameter, "{p:?}: {e}");
    }
    let margin = dome
        .window(Method::Closed, 0.5, 1e-5)
        .expect_err("margin below 1");
    assert_eq!(margin.parameter(), Parameter::MarginFactor);
    let period = dome
        .window(Method::Closed, 1.5, 0.0)
        .expect_err("no period");
    assert_eq!(period.parameter(), Parameter::SamplePeriod);
}

/// Regime and tier names come from the core alone (`name`, `Display`), as every report writes
/// them; the reference's regimes are named the same.
#[test]
fn regimes_and_tiers_have_one_name_each() {
    use contact_bounce::scene::Regime;
    use contact_bounce::tiers::{ClosedForm, Tier};
    use contact_bounce::Nodes;
    use host_tests::reference::Regime as Exact;
    let pairs = [
        (
            Regime::ZenoAccumulation,
            Exact::ZenoAccumulation,
            "zeno_accumulation",
        ),
        (Regime::LastImpact, Exact::LastImpact, "last_impact"),
        (Regime::Endless, Exact::Endless, "endless"),
        (Regime::Periodic, Exact::Periodic, "periodic"),
        (Regime::SingleImpact, Exact::SingleImpact, "single_impact"),
    ];
    for (core, exact, name) in pairs {
        assert_eq!(
            (core.name(), core.to_string(), exact.name()),
            (name, name.to_owned(), name)
        );
    }
    let tiers = [
        (Tier::Regime, "regime"),
        (Tier::Closed(ClosedForm::Tb1v), "closed (Tb1v)"),
        (Tier::Closed(ClosedForm::Tb2r), "closed (Tb2r)"),
        (Tier::Averaged(Nodes::N8), "averaged N8"),
        (Tier::Map, "map"),
        (Tier::Exact, "exact"),
    ];
    for (tier, name) in tiers {
        assert_eq!(tier.to_string(), name);
    }
}

#[test]
fn a_tier_is_named_by_its_closed_form_or_its_nodes() {
    let forms = [
        ClosedForm::Tb1v,
        ClosedForm::Tb2,
        ClosedForm::Tb2r,
        ClosedForm::Asymptotic,
        ClosedForm::Grazing,
        ClosedForm::Undamped,
    ];
    for form in forms {
        let tier = Tier::Closed(form);
        assert_eq!(tier.name(), format!("closed ({})", form.name()));
        assert_eq!(tier.to_string(), tier.name());
    }
    for nodes in Nodes::ALL {
        let tier = Tier::Averaged(nodes);
        assert_eq!(tier.name(), format!("averaged N{}", nodes.count()));
        assert_eq!(tier.to_string(), tier.name());
    }
    for (tier, name) in [
        (Tier::Regime, "regime"),
        (Tier::Map, "map"),
        (Tier::Exact, "exact"),
    ] {
        assert_eq!(tier.name(), name);
        assert_eq!(tier.to_string(), name);
    }
}

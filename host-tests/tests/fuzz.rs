//! A seeded random harness over the public API (the start of the fuzzing harness): scenes drawn
//! across the whole accepted domain (log-uniform Omega 1e-2..1e9 rad/s, |Delta| 1e-15..1 m on
//! both sides and 0, R from 0 to 1 - 1e-12 and 1, closing speeds 1e-9..1e6 m/s, zeta 0 and
//! 1e-12..1e3, with and without a threshold), in f32 and f64, through every tier and Auto;
//! and the debouncer and the learner on random samples and windows. Each call is checked for
//! no panic, no NaN or negative time or count, and consistency (the last impact above the
//! threshold not after the end, impacts above not more than all). Each scene is also tried
//! with an exponential kernel and as two bodies of unequal partial frequencies. `FUZZ_SCENES`
//! sets the number of scenes per float (CI: the default, 10,000; `scripts/fuzz.sh`: millions).

use contact_bounce::{
    Averaged, Bodies, Contact, Count, Float, Frequency, Hereditary, LearningState, MapImpacts,
    Method, Mode, Nodes, Offset, Prediction, Restitution, Scene, State, Threshold, Time, Tolerance,
    TwoBody, Viscous, Windows,
};

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    #[allow(clippy::cast_precision_loss)]
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1_u64 << 53) as f64
    }
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + self.unit() * (hi.ln() - lo.ln())).exp()
    }
}

fn scenes() -> usize {
    std::env::var("FUZZ_SCENES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(10_000)
}

/// What is wrong with a prediction, if anything.
fn fault<F: Float>(p: &Prediction<F>) -> Option<&'static str> {
    let bad = |x: F| !x.is_finite() || x < F::ZERO;
    for t in [p.end_time, p.last_above_time] {
        if matches!(t, Time::At(t) if bad(t)) {
            return Some("a time NaN, infinite or negative");
        }
    }
    for n in [p.impacts_above, p.impacts_total] {
        if matches!(n, Count::Finite(n) if bad(n)) {
            return Some("a count NaN, infinite or negative");
        }
    }
    if p.expected_error.is_some_and(bad) {
        return Some("an expected error NaN, infinite or negative");
    }
    if let (Time::At(a), Time::At(e)) = (p.last_above_time, p.end_time) {
        if a > e {
            return Some("last_above_time > end_time");
        }
    }
    if let (Count::Finite(a), Count::Finite(t)) = (p.impacts_above, p.impacts_total) {
        if a > t {
            return Some("impacts_above > impacts_total");
        }
    }
    None
}

fn predictions<F: Float + std::fmt::Debug>(rng: &mut Rng, n: usize) -> (usize, Vec<String>) {
    let mut checked = 0;
    let mut faults = Vec::new();
    for _ in 0..n {
        let omega = rng.log_uniform(1e-2, 1e9);
        let delta = match rng.next() % 3 {
            0 => -rng.log_uniform(1e-15, 1.0),
            1 => rng.log_uniform(1e-15, 1.0),
            _ => 0.0,
        };
        let r = match rng.next() % 3 {
            0 => 1.0 - rng.log_uniform(1e-12, 1.0),
            1 => rng.unit(),
            _ => 1.0,
        };
        let v0 = rng.log_uniform(1e-9, 1e6);
        let zeta = match rng.next() % 3 {
            0 => 0.0,
            1 => rng.log_uniform(1e-12, 1e3),
            _ => rng.unit() * 2.0,
        };
        let threshold = if rng.next().is_multiple_of(2) {
            Threshold::FractionOfFirst(F::from_f64(rng.log_uniform(1e-9, 0.99)))
        } else {
            Threshold::None
        };
        let contact = Contact {
            frequency: Frequency::Omega(F::from_f64(omega)),
            offset: Offset::Delta(F::from_f64(delta)),
            restitution: Restitution::Coefficient(F::from_f64(r)),
            closing_speed: F::from_f64(v0),
            threshold,
        };
        let Ok(viscous) = Viscous::new(F::from_f64(zeta)) else {
            continue;
        };
        // Refused scenes are fine: a typed error, which is what the harness wants.
        let Ok(scene) = Scene::new(contact, viscous) else {
            continue;
        };
        let what =
            format!("omega {omega:e} delta {delta:e} r {r} v0 {v0:e} zeta {zeta:e} {threshold:?}");
        check_scene(&scene, &what, &mut checked, &mut faults);
        // The same contact with an exponential kernel below the spring's stiffness.
        let tau = rng.log_uniform(1e-3, 1e3) / omega;
        let kappa = rng.unit() * 0.9 * omega * omega / tau;
        if let (Ok(viscous), Ok(kernel)) = (
            Viscous::new(F::from_f64(zeta)),
            Hereditary::exponential(F::from_f64(kappa), F::from_f64(tau)),
        ) {
            if let Ok(scene) = Scene::new(contact, (viscous, kernel)) {
                check_scene(
                    &scene,
                    &format!("{what} kappa {kappa:e} tau {tau:e}"),
                    &mut checked,
                    &mut faults,
                );
            }
        }
        // Two bodies whose partial frequencies differ by up to 2x each way.
        let (m1, m2) = (rng.log_uniform(1e-9, 10.0), rng.log_uniform(1e-9, 10.0));
        let (f1, f2) = (rng.log_uniform(0.5, 2.0), rng.log_uniform(0.5, 2.0));
        let (c1, c2) = (m1 * omega * omega * f1, m2 * omega * omega * f2);
        let bodies = TwoBody {
            m1: F::from_f64(m1),
            c1: F::from_f64(c1),
            d1: F::from_f64(2.0 * zeta * (c1 * m1).sqrt()),
            m2: F::from_f64(m2),
            c2: F::from_f64(c2),
            d2: F::from_f64(2.0 * zeta * (c2 * m2).sqrt()),
        };
        if let Ok(scene) = Scene::two_body(
            bodies,
            Offset::Delta(F::from_f64(delta)),
            Restitution::Coefficient(F::from_f64(r)),
            F::from_f64(v0),
            threshold,
            None,
        ) {
            check_scene(
                &scene,
                &format!("{what} two bodies {bodies:?}"),
                &mut checked,
                &mut faults,
            );
        }
    }
    (checked, faults)
}

/// Every check on one accepted scene: the map walked impact by impact, the closed forms, the
/// envelope and the laws of motion at times from 0 to far past the end, and every tier.
fn check_scene<F: Float + std::fmt::Debug, D: contact_bounce::Dissipation<F>>(
    scene: &Scene<F, D>,
    what: &str,
    checked: &mut usize,
    faults: &mut Vec<String>,
) {
    let scene = *scene;
    let auto = Tolerance::new(F::from_f64(0.01)).unwrap_or_else(|_| unreachable!());
    // The map walked impact by impact, the closed forms, the envelope and the laws of
    // motion, at times from 0 to far past the end.
    let mut walk = MapImpacts::new(&scene, 200);
    let mut previous = F::ZERO;
    for impact in walk.by_ref() {
        if !(impact.time.is_finite() && impact.time >= previous && impact.impulse.is_finite())
            || impact.impulse < F::ZERO
        {
            faults.push(format!("MapImpacts {impact:?} after {previous:?}, {what}"));
            break;
        }
        previous = impact.time;
    }
    if walk
        .zeno_tail_time()
        .is_some_and(|t| !t.is_finite() || t < F::ZERO)
    {
        faults.push(format!("zeno tail {:?}, {what}", walk.zeno_tail_time()));
    }
    for e in [
        scene.t_b1(),
        scene.t_b1v(),
        scene.t_b2(),
        scene.t_b2r(),
        scene.t_grazing(),
    ]
    .into_iter()
    .flatten()
    {
        if !e.time.is_finite() || e.time < F::ZERO {
            faults.push(format!(
                "closed form {} {e:?}, {what}",
                std::any::type_name::<F>()
            ));
        }
    }
    let averaged = Averaged::new(&scene, Nodes::N4);
    let end = scene
        .predict(Method::Averaged(Nodes::N4))
        .bounce_time()
        .unwrap_or(F::ONE);
    for t in [
        F::ZERO,
        end * F::HALF,
        end,
        end * F::from_f64(10.0),
        F::from_f64(1e30),
    ] {
        // An error is a typed refusal; a value must be a number.
        if let Ok(p) = averaged.envelope(t) {
            if !p.impulse.is_finite()
                || p.impulse < F::ZERO
                || matches!(p.impacts, Count::Finite(n) if !n.is_finite())
            {
                faults.push(format!("envelope at {t:?}: {p:?}, {what}"));
            }
        }
        if let Ok(m) = averaged.motion(t, &Bodies::equal_at_rest()) {
            if !(m.relative.is_finite() && m.body1.is_finite() && m.body2.is_finite()) {
                faults.push(format!("motion at {t:?}: {m:?}, {what}"));
            }
        }
    }
    for method in [
        Method::Closed,
        Method::Averaged(Nodes::N4),
        Method::Map {
            max_impacts: 10_000,
        },
        Method::Exact {
            max_impacts: 10_000,
        },
        Method::Auto(auto),
    ] {
        let p = scene.predict(method);
        *checked += 1;
        if let Some(why) = fault(&p) {
            faults.push(format!("{why}: {method:?}, {what}: {p:?}"));
        }
    }
}

#[test]
fn predictions_on_random_scenes_are_finite_and_consistent() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let n = scenes();
    let (a, mut faults) = predictions::<f64>(&mut rng, n);
    let (b, more) = predictions::<f32>(&mut rng, n);
    faults.extend(more);
    eprintln!("{} predictions checked, {} faults", a + b, faults.len());
    let mut classes = std::collections::BTreeMap::new();
    for f in &faults {
        let class: String = f
            .split([',', ':'])
            .next()
            .unwrap_or("")
            .chars()
            .take(40)
            .collect();
        classes.entry(class).or_insert((0, f.clone())).0 += 1;
    }
    for (class, (count, example)) in &classes {
        eprintln!(
            "{count:7} {class}\n        {}",
            &example[..example.len().min(300)]
        );
    }
    assert!(
        a + b > n,
        "too few scenes were accepted to mean anything: {}",
        a + b
    );
    assert!(
        faults.is_empty(),
        "{} faults, first: {}",
        faults.len(),
        faults[0]
    );
}

#[test]
fn the_debouncers_on_random_samples_and_windows_report_alternating_edges() {
    let mut rng = Rng(0xD1B5_4A32_D192_ED03);
    for _ in 0..scenes() / 20 {
        let press = u16::try_from(rng.next() % 40).unwrap_or(0);
        let release = u16::try_from(rng.next() % 40).unwrap_or(0);
        let mode = if rng.next().is_multiple_of(2) {
            Mode::Confirm
        } else {
            Mode::HoldOff
        };
        let windows = Windows::new(press, release, mode).unwrap_or_else(|_| unreachable!());
        let closed = rng.next().is_multiple_of(2);
        let (mut state, mut key) = (State::new(closed), LearningState::new(closed));
        let (mut level, mut learned_level) = (closed, closed);
        // Runs of random lengths, some a single sample (noise faster than the sampling).
        let mut sample = closed;
        for _ in 0..200 {
            let run = 1 + rng.next() % 30;
            sample = !sample;
            for _ in 0..run {
                if let Some(edge) = state.update(sample, &windows) {
                    let to = edge == contact_bounce::Edge::Press;
                    assert_ne!(to, level, "the debouncer reported the level it had");
                    level = to;
                }
                if let Some(edge) = key.update(sample, &windows) {
                    let to = edge == contact_bounce::Edge::Press;
                    assert_ne!(to, learned_level, "the learner reported the level it had");
                    learned_level = to;
                }
            }
        }
        let (p, r) = key.learned().windows(&windows);
        assert!(p >= 1 && r >= 1 && p <= Windows::MAX_TICKS && r <= Windows::MAX_TICKS);
        assert_eq!(state.is_closed(), level);
        assert_eq!(key.is_closed(), learned_level);
    }
}

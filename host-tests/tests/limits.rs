//! The analytic limits of docs/physics.md sec. 4-5: small-J limits of E1, the Delta = 0
//! exponential, the bouncing-ball limit, the exact zeta = 0 sums against brute force, and the
//! hereditary sum reducing to the viscous formula when Gs = 2 zeta Omega nu.

use contact_bounce::{
    physics::Orbit, scene::Dissipation, tiers::Count, tiers::Time, Contact, Frequency, Hereditary,
    Method, Nodes, Offset, Restitution, Scene, Threshold, Undamped, Viscous,
};

const OMEGA: f64 = 1000.0;

fn contact(delta: f64, r: f64, v0: f64, threshold: Threshold<f64>) -> Contact<f64> {
    Contact {
        frequency: Frequency::Omega(OMEGA),
        offset: Offset::Delta(delta),
        restitution: Restitution::Loss(r),
        closing_speed: v0,
        threshold,
    }
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Kahan-summed brute force of sum_{n < count} (2/Omega) atan2(R^{n+1} v0, -Omega Delta),
/// until the terms stop mattering (1e-19 of the sum) when `count` is None.
fn brute_flights(delta: f64, restitution: f64, v0: f64, count: Option<u64>) -> f64 {
    let (mut sum, mut carry) = (0.0_f64, 0.0_f64);
    let mut v = restitution * v0;
    let mut n = 0_u64;
    loop {
        if count.is_some_and(|c| n >= c) {
            break;
        }
        let term = 2.0 / OMEGA * v.atan2(-OMEGA * delta);
        if count.is_none() && term < 1e-19 * sum {
            break;
        }
        let y = term - carry;
        let t = sum + y;
        carry = (t - sum) - y;
        sum = t;
        v *= restitution;
        n += 1;
    }
    sum
}

#[test]
fn small_impulse_limits_of_e1_preload() {
    // E1 -> -r Omega^2 |Delta| - (2/3) zeta Omega J; next terms are O(j^2) relative
    // (theta = atan(j/2) = j/2 (1 - j^2/12 + ...)), so |E1/limit - 1| <= j^2.
    let delta: f64 = -1e-3;
    for (r, zeta) in [(0.3, 0.0), (0.01, 0.05), (1e-4, 0.2)] {
        let scene = Scene::new(
            contact(delta, r, 1.0, Threshold::None),
            Viscous::optional(zeta).unwrap(),
        )
        .unwrap();
        for j in [1e-2, 1e-3, 1e-5] {
            let impulse = j * OMEGA * delta.abs();
            let limit = -r * OMEGA * OMEGA * delta.abs() - 2.0 / 3.0 * zeta * OMEGA * impulse;
            let e1 = scene.rate(impulse);
            assert!(
                rel(e1, limit) <= j * j,
                "r {r} zeta {zeta} j {j}: {e1} vs {limit}"
            );
            let a = scene.asymptote();
            assert!(rel(-a.magnitude(impulse), limit) < 1e-14);
        }
    }
}

#[test]
fn small_impulse_limits_of_e1_gap() {
    // E1 -> -r Omega J / (2 pi) - 4 zeta Omega^3 Delta^2 / J; the next terms are O(j) relative
    // (pi - theta = atan(j/2) enters at first order), so |E1/limit - 1| <= j.
    let delta = 2e-3;
    for (r, zeta) in [(0.3, 0.0), (0.01, 0.05), (0.0, 0.2)] {
        let scene = Scene::new(
            contact(delta, r, 1.0, Threshold::FractionOfFirst(0.01)),
            Viscous::optional(zeta).unwrap(),
        )
        .unwrap();
        for j in [1e-2, 1e-3, 1e-5] {
            let impulse = j * OMEGA * delta;
            let limit = -r * OMEGA * impulse / (2.0 * std::f64::consts::PI)
                - 4.0 * zeta * OMEGA.powi(3) * delta * delta / impulse;
            let e1 = scene.rate(impulse);
            assert!(
                rel(e1, limit) <= j,
                "r {r} zeta {zeta} j {j}: {e1} vs {limit}"
            );
        }
    }
}

#[test]
fn grazing_rate_is_exactly_linear() {
    // Delta = 0: E1 = -(r/pi + zeta) Omega J for every J, to rounding.
    for (r, zeta) in [(0.3, 0.0), (0.01, 0.05), (0.5, 0.3)] {
        let scene = Scene::new(
            contact(0.0, r, 1.0, Threshold::FractionOfFirst(0.01)),
            Viscous::optional(zeta).unwrap(),
        )
        .unwrap();
        for impulse in [1e-9, 1e-3, 1.0, 1e6] {
            let exact = -(r / std::f64::consts::PI + zeta) * OMEGA * impulse;
            assert!(
                rel(scene.rate(impulse), exact) < 1e-14,
                "{r} {zeta} {impulse}"
            );
        }
    }
}

#[test]
fn grazing_averaged_is_the_exponential_and_closed_is_the_discrete_decay() {
    for (r, zeta, fraction) in [(0.1, 0.01, 1e-2), (0.5, 0.0, 1e-4), (0.02, 0.2, 1e-6)] {
        let scene = Scene::new(
            contact(0.0, r, 0.3, Threshold::FractionOfFirst(fraction)),
            Viscous::optional(zeta).unwrap(),
        )
        .unwrap();
        // The averaged model integrates a constant in ln J: it is the exponential of sec. 5.
        let exponential = scene.t_grazing().unwrap().time;
        for nodes in [Nodes::N2, Nodes::N8] {
            let p = scene.predict(Method::Averaged(nodes));
            assert!(rel(p.last_above_time.seconds().unwrap(), exponential) < 1e-12);
        }
        // The closed tier is the exact discrete decay: flights pi / Omega_d, impulses times
        // R exp(-zeta Omega pi / Omega_d); count them by brute force.
        let restitution = 1.0 - r;
        let damped = OMEGA * (1.0 - zeta * zeta).sqrt();
        let factor = restitution * (-zeta * OMEGA * std::f64::consts::PI / damped).exp();
        let p_end = fraction * (1.0 + restitution) * 0.3;
        let (mut impulse, mut n) = ((1.0 + restitution) * 0.3, 0_u32);
        while impulse * factor >= p_end {
            impulse *= factor;
            n += 1;
        }
        let p = scene.predict(Method::Closed);
        assert_eq!(p.impacts_above, Count::Finite(f64::from(n + 1)));
        let t = p.last_above_time.seconds().unwrap();
        assert!(
            rel(t, f64::from(n) * std::f64::consts::PI / damped) < 1e-13,
            "{t}"
        );
    }
}

#[test]
fn exact_undamped_accumulation_matches_brute_force() {
    // Direct sums (ln(1/R) >= 0.05) and Euler-Maclaurin (R closer to 1) alike.
    let delta: f64 = -1e-3;
    for r in [0.95, 0.5, 0.1, 0.03, 0.01, 1e-3, 1e-4] {
        for j0 in [1e-3, 0.1, 1.0, 10.0, 1e3] {
            let restitution = 1.0 - r;
            let v0 = j0 * OMEGA * delta.abs() / (2.0 * restitution);
            let scene = Scene::new(contact(delta, r, v0, Threshold::None), Undamped).unwrap();
            let exact = brute_flights(delta, restitution, v0, None);
            let closed = scene.undamped_accumulation_time().unwrap();
            assert!(
                rel(closed, exact) < 1e-11,
                "r {r} j0 {j0}: {closed} vs {exact}"
            );
            let p = scene.predict(Method::Closed);
            assert_eq!(p.end_time, Time::At(closed));
        }
    }
}

#[test]
fn exact_undamped_partial_sums_match_brute_force_for_gap_and_preload() {
    for delta in [-1e-3, 1e-3] {
        for r in [0.5, 0.03, 1e-3] {
            for n in [1_u64, 2, 10, 255, 256, 257, 1000, 20_000] {
                let restitution = 1.0 - r;
                let scene = Scene::new(
                    contact(delta, r, 0.7, Threshold::FractionOfFirst(0.5)),
                    Undamped,
                )
                .unwrap();
                #[allow(clippy::cast_precision_loss)]
                let closed = scene.undamped_flights_until(n as f64);
                let exact = brute_flights(delta, restitution, 0.7, Some(n));
                assert!(
                    rel(closed, exact) < 1e-11,
                    "delta {delta} r {r} n {n}: {closed} vs {exact}"
                );
            }
        }
    }
}

#[test]
fn impacts_above_threshold_follow_the_geometric_count() {
    // floor(ln(P0/P_end) / ln(1/R)) + 1, for preload and gap, closed and map alike.
    for delta in [-1e-3, 1e-3] {
        for (r, fraction) in [(0.3, 0.01), (0.01, 1e-3), (1e-3, 0.5)] {
            let scene = Scene::new(
                contact(delta, r, 0.2, Threshold::FractionOfFirst(fraction)),
                Undamped,
            )
            .unwrap();
            let expected = ((1.0 / fraction).ln() / -(-r).ln_1p()).floor() + 1.0;
            for method in [
                Method::Closed,
                Method::Map {
                    max_impacts: 1_000_000,
                },
            ] {
                let p = scene.predict(method);
                assert_eq!(
                    p.impacts_above,
                    Count::Finite(expected),
                    "{delta} {r} {method:?}"
                );
            }
            // The map iterates what the closed form sums: same time to rounding.
            let closed = scene
                .predict(Method::Closed)
                .last_above_time
                .seconds()
                .unwrap();
            let map = scene
                .predict(Method::Map {
                    max_impacts: 1_000_000,
                })
                .last_above_time
                .seconds()
                .unwrap();
            assert!(rel(map, closed) < 1e-11, "{delta} {r}: {map} vs {closed}");
        }
    }
}

#[test]
fn bouncing_ball_limit() {
    // As v0 -> 0 the accumulation time tends to t_b1 = 2 R v0 / (r Omega^2 |Delta|), with
    // relative error at most x^2/3 (x = j0/2: atan(y) >= y - y^3/3); every tier follows.
    let delta: f64 = -1e-3;
    for r in [0.9, 0.3, 0.01] {
        for j0 in [1e-2, 1e-4] {
            let restitution = 1.0 - r;
            let v0 = j0 * OMEGA * delta.abs() / (2.0 * restitution);
            let scene = Scene::new(contact(delta, r, v0, Threshold::None), Undamped).unwrap();
            let ball = 2.0 * restitution * v0 / (r * OMEGA * OMEGA * delta.abs());
            assert!(rel(scene.t_b1().unwrap().time, ball) < 1e-14);
            let bound = (j0 / 2.0) * (j0 / 2.0) / 3.0;
            for method in [
                Method::Closed,
                Method::Averaged(Nodes::N8),
                Method::Map {
                    max_impacts: 100_000,
                },
            ] {
                let t = scene.predict(method).end_time.seconds().unwrap();
                assert!(
                    rel(t, ball) <= bound * 1.0001 + 1e-13,
                    "{method:?} r {r} j0 {j0}: {t} vs {ball}"
                );
            }
        }
    }
}

#[test]
fn hereditary_sum_reduces_to_viscous() {
    // Gs(nu) = 2 zeta Omega nu is the kernel kappa exp(-t/tau) with tau -> 0 and
    // kappa tau^2 = 2 zeta Omega. The kernel departs from it by (k omega tau)^2, with
    // omega = pi Omega / theta up to 6e7 rad/s here (preload, J = 1e-4: theta = 5e-5) and k up
    // to the ~1e3 harmonics a 1e-6 tolerance needs: tau = 1e-16 s keeps that below 1e-10.
    let zeta = 0.05;
    let tau = 1e-16;
    let kernel = Hereditary::exponential(2.0 * zeta * OMEGA / (tau * tau), tau)
        .unwrap()
        .with_tolerance(1e-6)
        .unwrap();
    let viscous = Viscous::optional(zeta).unwrap();
    for delta in [-1e-3, 0.0, 1e-3] {
        let orbit = Orbit::new(OMEGA, delta);
        for impulse in [1e-4, 1e-2, 1.0, 100.0] {
            let p = orbit.at(impulse);
            let sum = kernel.harmonic_sum(&p);
            assert!(sum.relative_error <= 1e-6);
            let (h, v) = (kernel.rate(&p), viscous.rate(&p));
            assert!(rel(h, v) < 2e-6, "delta {delta} J {impulse}: {h} vs {v}");
        }
    }
}

#[test]
fn hereditary_sum_matches_a_long_direct_sum() {
    // The truncated sum with its integral tail against 2e6 explicit harmonics (whose own
    // remaining tail is below 1e-7 of the sum for these kernels).
    for (omega_tau, delta) in [(1e-3, -1e-3), (0.1, 1e-3), (10.0, -1e-4), (1.0, 1e-3)] {
        let tau = omega_tau / OMEGA;
        let kernel = Hereditary::exponential(1e6, tau)
            .unwrap()
            .with_tolerance(1e-7)
            .unwrap();
        let p = Orbit::new(OMEGA, delta).at(0.3);
        let (theta, omega) = (p.phase(), p.frequency());
        let mut direct = 0.0_f64;
        for k in (1..=2_000_000_u32).rev() {
            let k = f64::from(k);
            let g = kernel.sine_transform(k * omega) / (k * omega);
            let den = (std::f64::consts::PI * k).powi(2) - theta * theta;
            direct += k * k * g / (den * den);
        }
        let sum = kernel.harmonic_sum(&p);
        assert!(
            rel(sum.value, direct) < 1e-6,
            "Omega tau {omega_tau}: {} vs {direct} ({} harmonics)",
            sum.value,
            sum.harmonics
        );
    }
}

#[test]
fn the_harmonic_tail_estimate_is_far_inside_its_bound() {
    // At the default tolerance (1e-4) the sum stops after 2-16 harmonics. The tail used to be
    // the midpoint of its integral bracket, off by up to 3.5e-6 of the sum (theta near pi in a
    // gap, or 8 harmonics on a preload); the Euler-Maclaurin estimate with theta to first
    // order is within 1e-7 (measured: 9e-8 at most), against a sum to 1e-13.
    let kernel = Hereditary::exponential(1e8, 1e-4).unwrap();
    let tight = kernel
        .with_tolerance(1e-13)
        .unwrap()
        .with_max_harmonics(1 << 24);
    for delta in [1e-3, -1e-3] {
        for j in [0.01, 0.1, 1.0, 3.0, 10.0] {
            let p = Orbit::new(OMEGA, delta).at(j * OMEGA * delta.abs());
            let (a, b) = (kernel.harmonic_sum(&p), tight.harmonic_sum(&p));
            assert!(b.relative_error <= 1e-13);
            let error = rel(a.value, b.value);
            assert!(
                error < 1e-7 && error <= a.relative_error,
                "{delta} {j}: {error:e} after {} harmonics",
                a.harmonics
            );
        }
    }
}

#[test]
fn the_averaged_hereditary_end_is_not_limited_by_the_harmonic_cut() {
    // Gaps with a kernel alone (R 0.9-1, j0 3-10) and a preload: the averaged tier at 8 and
    // 20 nodes against itself with the harmonic sum to 1e-11. With the tail at its bracket's
    // midpoint they differed by 1.4e-6 to 3.6e-6, whatever the nodes; now within 1e-7
    // (measured: 3e-8 at most). (An independent mpmath quadrature of the averaged equation
    // agrees with the 1e-11 sums to 1e-13.)
    for (delta, r, j0) in [
        (1e-3, 0.9, 3.0),
        (1e-3, 0.95, 10.0),
        (1e-3, 1.0, 3.0),
        (-1e-3, 0.7, 1.0),
    ] {
        let kernel = Hereditary::exponential(1e8, 1e-4).unwrap();
        let end = |k: Hereditary<f64>, nodes| {
            let c = Contact {
                restitution: Restitution::Coefficient(r),
                ..contact(
                    delta,
                    0.0,
                    j0 * OMEGA * delta.abs() / (2.0 * r),
                    Threshold::None,
                )
            };
            Scene::new(c, k)
                .unwrap()
                .predict(Method::Averaged(nodes))
                .end_time
                .seconds()
                .unwrap()
        };
        let tight = kernel
            .with_tolerance(1e-11)
            .unwrap()
            .with_max_harmonics(1 << 24);
        let want = end(tight, Nodes::N20);
        for nodes in [Nodes::N8, Nodes::N20] {
            let got = end(kernel, nodes);
            assert!(
                rel(got, want) < 1e-7,
                "{delta} {r} {nodes:?}: {got} vs {want}: {:e}",
                rel(got, want)
            );
        }
    }
}

#[test]
fn regimes_follow_the_table_of_section_4() {
    use contact_bounce::scene::Regime::*;
    let th = Threshold::FractionOfFirst(0.01);
    let cases: [(f64, f64, f64, contact_bounce::scene::Regime); 10] = [
        (-1e-3, 0.3, 0.0, ZenoAccumulation),
        (-1e-3, 0.3, 0.5, ZenoAccumulation),
        (-1e-3, 0.3, 1.5, ZenoAccumulation),
        (-1e-3, 0.0, 0.1, Endless),
        (-1e-3, 0.0, 0.0, Periodic),
        (1e-3, 0.3, 0.1, LastImpact),
        (1e-3, 0.0, 0.1, LastImpact),
        (1e-3, 0.3, 0.0, Endless),
        (0.0, 0.3, 0.5, Endless),
        (1e-3, 0.3, 1.0, SingleImpact),
    ];
    for (delta, r, zeta, regime) in cases {
        let s = Scene::new(contact(delta, r, 0.1, th), Viscous::optional(zeta).unwrap()).unwrap();
        assert_eq!(s.regime(), regime, "{delta} {r} {zeta}");
        let endless = s.predict(Method::Closed).end_time == Time::Never;
        assert_eq!(endless, regime.is_endless(), "{delta} {r} {zeta}");
    }
    let single = Scene::new(contact(0.0, 0.3, 0.1, th), Viscous::optional(2.0).unwrap()).unwrap();
    assert_eq!(single.regime(), SingleImpact);
    // A kernel alone ends a gap's bounce.
    let k = Hereditary::exponential(1e6, 1e-4).unwrap();
    assert_eq!(
        Scene::new(contact(1e-3, 0.0, 0.1, Threshold::None), k)
            .unwrap()
            .regime(),
        LastImpact
    );
}

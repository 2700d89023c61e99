//! The exact reference (std, f64): event-driven simulation that the core is checked against
//! (`host-tests`) and that the desk tool falls back on (`bounce-table`), kept in a crate of its
//! own so that the tool does not depend on the test crate.
//!
//! Definitions every output uses (P_n = (1 + R) v_n is impact n's impulse per unit reduced
//! mass, impact 0 at t = 0; P_end the threshold impulse):
//! - `impacts_above`: impacts with P >= P_end, impact 0 included (`None`: infinitely many);
//!   with two bodies whose stuck pair reopens, counted over every burst (the impulses of a
//!   burst after a separation may rise above P_end again, after a tail below it);
//! - `last_above_time`: time of the last impact with P >= P_end, in any burst (`None`: never
//!   ends);
//! - `end_time`: the last impact when impacts stop (gap with damping, single impact), the
//!   accumulation time of a Zeno preload; `None` when endless;
//! - `impacts_total`: the total when finite, `None` when infinite (Zeno or endless).

pub mod brent;
pub mod compliant;
pub mod hereditary;
pub mod one_body;
pub mod stats;
pub mod two_body;

use one_body::{Oscillator, ZENO_TAIL};

/// The drift of the ratio of successive flights below which a Zeno tail is summed as
/// geometric (its error is about half of it, on the tail).
pub const TAIL_DRIFT: f64 = 1e-13;

/// One body against a stop (docs/physics.md sec. 1), f64, SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OneBody {
    /// Omega (rad/s).
    pub omega: f64,
    /// Delta (m): gap > 0, preload < 0.
    pub delta: f64,
    /// R.
    pub restitution: f64,
    /// zeta.
    pub zeta: f64,
    /// v0 (m/s).
    pub closing_speed: f64,
    /// P_end (m/s), if any.
    pub threshold: Option<f64>,
}

impl OneBody {
    /// A catalogue switch as the reference models it: Omega = sqrt(c / m), the preload
    /// Delta = -F / c, no threshold.
    #[must_use]
    pub fn typical(s: &contact_bounce::scene::catalogue::Typical) -> Self {
        Self {
            omega: (s.stiffness / s.mass).sqrt(),
            delta: -s.preload_force / s.stiffness,
            restitution: s.restitution,
            zeta: s.damping_ratio,
            closing_speed: s.closing_speed,
            threshold: None,
        }
    }
}

/// How the bounce ends (docs/physics.md sec. 4).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Regime {
    /// Preload, R < 1.
    ZenoAccumulation,
    /// Finitely many impacts.
    LastImpact,
    /// Decays without end.
    Endless,
    /// No loss at all.
    Periodic,
    /// Overdamped with Delta >= 0.
    SingleImpact,
}

impl Regime {
    /// The core's regime of the same name.
    #[must_use]
    pub const fn core(self) -> contact_bounce::scene::Regime {
        use contact_bounce::scene::Regime as Core;
        match self {
            Self::ZenoAccumulation => Core::ZenoAccumulation,
            Self::LastImpact => Core::LastImpact,
            Self::Endless => Core::Endless,
            Self::Periodic => Core::Periodic,
            Self::SingleImpact => Core::SingleImpact,
        }
    }

    /// Its name in reports and files: the core's ([`contact_bounce::scene::Regime::name`]).
    #[must_use]
    pub const fn name(self) -> &'static str {
        self.core().name()
    }
}

/// What a simulation found.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    /// The regime.
    pub regime: Regime,
    /// See the module docs.
    pub end_time: Option<f64>,
    /// See the module docs.
    pub impacts_total: Option<u64>,
    /// See the module docs.
    pub last_above_time: Option<f64>,
    /// See the module docs.
    pub impacts_above: Option<u64>,
    /// The first impacts (up to 5), as (time, impulse P).
    pub first_impacts: Vec<(f64, f64)>,
}

impl Outcome {
    /// A bounce that ends in a Zeno accumulation at `end` (countless impacts): with a threshold,
    /// the last impact above it and their count; without one, the accumulation itself.
    pub(crate) fn accumulated(
        regime: Regime,
        end: f64,
        threshold: bool,
        last_above: f64,
        count_above: u64,
        first_impacts: Vec<(f64, f64)>,
    ) -> Self {
        Self {
            regime,
            end_time: Some(end),
            impacts_total: None,
            last_above_time: Some(if threshold { last_above } else { end }),
            impacts_above: threshold.then_some(count_above),
            first_impacts,
        }
    }
}

/// Why a simulation could not answer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Failure {
    /// The bounce never ends by itself, and no threshold was given.
    NeedsThreshold,
    /// More impacts than the budget allows.
    Budget(u64),
    /// A parameter is outside the model (named).
    Invalid(&'static str),
    /// The event search lost an event it knows exists (named), in floating point.
    Unresolved(&'static str),
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::NeedsThreshold => {
                f.write_str("the bounce never ends by itself: a threshold is required")
            }
            Self::Budget(n) => write!(
                f,
                "more than {n} impacts: raise the budget or the threshold"
            ),
            Self::Invalid(p) => write!(f, "{p} is invalid"),
            Self::Unresolved(e) => write!(f, "{e} could not be resolved in floating point"),
        }
    }
}

impl std::error::Error for Failure {}

/// Neumaier's compensated sum.
#[derive(Debug, Clone, Copy, Default)]
struct Sum {
    sum: f64,
    carry: f64,
}

impl Sum {
    fn add(&mut self, x: f64) {
        let t = self.sum + x;
        if self.sum.abs() >= x.abs() {
            self.carry += (self.sum - t) + x;
        } else {
            self.carry += (x - t) + self.sum;
        }
        self.sum = t;
    }
    fn value(self) -> f64 {
        self.sum + self.carry
    }
}

/// Impacts a simulation may make before it gives up.
pub const DEFAULT_BUDGET: u64 = 50_000_000;

/// A summed Zeno tail's impacts at or above `threshold`: the tail's impulses are `first`,
/// `first q`, `first q^2`, ... and its flights `flight`, `flight q`, ... (0 < q < 1). Returns
/// how many impulses are at or above the threshold and the time from the tail's start to the
/// last of them (the flights before it), or `None` where the first is already below. The one
/// body, the kernel and the two-body references count a threshold through their tails alike.
pub(crate) fn tail_above(first: f64, q: f64, flight: f64, threshold: f64) -> Option<(u64, f64)> {
    if first < threshold {
        return None;
    }
    let more = ((first / threshold).ln() / -q.ln()).floor() + 1.0;
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let count = more as u64;
    Some((count, flight * (1.0 - q.powf(more)) / (1.0 - q)))
}

/// Simulates one body exactly (see [`one_body`]).
///
/// # Errors
/// [`Failure::Invalid`] for parameters outside the model, [`Failure::NeedsThreshold`] for an
/// endless regime without a threshold, [`Failure::Budget`] past `budget` impacts.
pub fn simulate(scene: &OneBody, budget: u64) -> Result<Outcome, Failure> {
    simulate_observed(scene, budget, |_, _| {})
}

/// [`simulate`], calling `on_impact(time, impulse)` at every impact it resolves (impact 0
/// first; not the impacts of a summed Zeno tail), e.g. to record a bounce trace.
///
/// # Errors
/// As [`simulate`].
#[allow(clippy::too_many_lines)]
pub fn simulate_observed(
    scene: &OneBody,
    budget: u64,
    mut on_impact: impl FnMut(f64, f64),
) -> Result<Outcome, Failure> {
    let OneBody {
        omega,
        delta,
        restitution,
        zeta,
        closing_speed,
        threshold,
    } = *scene;
    let positive = |x: f64| x.is_finite() && x > 0.0;
    if !positive(omega) {
        return Err(Failure::Invalid("omega"));
    }
    if !delta.is_finite() {
        return Err(Failure::Invalid("gap"));
    }
    if !(restitution > 0.0 && restitution <= 1.0) {
        return Err(Failure::Invalid("restitution"));
    }
    if !(zeta.is_finite() && zeta >= 0.0) {
        return Err(Failure::Invalid("damping_ratio"));
    }
    if !positive(closing_speed) {
        return Err(Failure::Invalid("closing_speed"));
    }
    if threshold.is_some_and(|p| !positive(p)) {
        return Err(Failure::Invalid("threshold"));
    }
    let regime = if delta >= 0.0 && zeta >= 1.0 {
        Regime::SingleImpact
    } else if restitution == 1.0 && zeta == 0.0 {
        Regime::Periodic
    } else if delta < 0.0 && restitution < 1.0 {
        Regime::ZenoAccumulation
    } else if delta > 0.0 && zeta > 0.0 {
        Regime::LastImpact
    } else {
        Regime::Endless
    };
    if regime == Regime::Endless && threshold.is_none() {
        return Err(Failure::NeedsThreshold);
    }
    let osc = Oscillator { omega, zeta, delta };
    let impulse = |v: f64| (1.0 + restitution) * v;
    let above = |p: f64| threshold.is_none_or(|end| p >= end);
    let mut first = vec![(0.0, impulse(closing_speed))];
    on_impact(0.0, impulse(closing_speed));
    let mut time = Sum::default();
    let mut speed = closing_speed;
    let mut impacts: u64 = 1;
    let mut last_above = 0.0;
    let mut count_above: u64 = 1;
    let mut still_above = true;
    let scale = omega * delta.abs();

    if regime == Regime::Periodic {
        // Every flight equals the first: record a few, and report the endless answer.
        let (flight, _) = osc
            .leave(restitution * speed)
            .land()
            .ok_or(Failure::Invalid("gap"))?;
        for k in 1..5_u32 {
            first.push((f64::from(k) * flight, impulse(speed)));
        }
        let all_above = above(impulse(speed));
        return Ok(Outcome {
            regime,
            end_time: None,
            impacts_total: None,
            last_above_time: if all_above { None } else { Some(0.0) },
            impacts_above: if all_above { None } else { Some(1) },
            first_impacts: first,
        });
    }

    let (end_time, impacts_total) = loop {
        if impacts > budget {
            return Err(Failure::Budget(budget));
        }
        let departure = restitution * speed;
        let flight = osc.leave(departure);
        // The tail is summed as geometric once the departures are small (their flights then
        // scale with them) and damping no longer drifts the ratio of successive flights: that
        // drift, about 4 zeta a / (3 r Omega |Delta|), would put an error of half of it on the
        // sum. The first 5 impacts are always resolved (they are listed).
        let drift = zeta * departure / ((1.0 - restitution) * scale);
        if regime == Regime::ZenoAccumulation
            && departure < ZENO_TAIL * scale
            && drift < TAIL_DRIFT
            && first.len() >= 5
        {
            // Geometric tail: departures a q^k, flights t_f q^k.
            let (t_f, returned) = flight.land().ok_or(Failure::Invalid("gap"))?;
            let q = restitution * returned / departure;
            let start = time.value();
            if still_above {
                if let Some((more, flights)) =
                    threshold.and_then(|end| tail_above(impulse(returned), q, t_f, end))
                {
                    last_above = start + flights;
                    count_above += more;
                }
            }
            break (Some(start + t_f / (1.0 - q)), None);
        }
        match flight.land() {
            None => break (Some(time.value()), Some(impacts)),
            Some((t_f, returned)) => {
                time.add(t_f);
                speed = returned;
                impacts += 1;
                let p = impulse(speed);
                on_impact(time.value(), p);
                if first.len() < 5 {
                    first.push((time.value(), p));
                }
                if still_above {
                    if above(p) {
                        last_above = time.value();
                        count_above = impacts;
                    } else {
                        still_above = false;
                        if regime == Regime::Endless {
                            break (None, None);
                        }
                    }
                }
            }
        }
    };
    let (last_above_time, impacts_above) = match threshold {
        Some(_) => (Some(last_above), Some(count_above)),
        None => (end_time, impacts_total),
    };
    Ok(Outcome {
        regime,
        end_time,
        impacts_total,
        last_above_time,
        impacts_above,
        first_impacts: first,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn preload(r: f64, zeta: f64, v0: f64) -> OneBody {
        OneBody {
            omega: 1000.0,
            delta: -1e-3,
            restitution: r,
            zeta,
            closing_speed: v0,
            threshold: None,
        }
    }

    #[test]
    fn light_damping_tends_to_the_undamped_flight() {
        // zeta = 1e-9 goes through the root finder: its flights differ from the undamped closed
        // form by O(zeta). (In the gap the body must clear the stop by more than the damping
        // takes: Delta j^2 / 8 > pi zeta Delta, so j >= 1e-2 here.)
        for delta in [-1e-3, 0.0, 1e-3] {
            for a in [1e-2, 0.3, 1.0, 50.0] {
                let osc = Oscillator {
                    omega: 1000.0,
                    zeta: 1e-9,
                    delta,
                };
                let (t, v) = osc.leave(a).land().unwrap();
                let exact = 2.0 / 1000.0 * a.atan2(-1000.0 * delta);
                // Near grazing the return's kinetic energy is the clearance Delta j^2 / 8 less
                // the ~2 pi zeta Delta that damping takes: sensitivity O(zeta / j^2),
                // j = a / (Omega |Delta|).
                let j = a / (1000.0 * delta.abs()).max(1e-300);
                let bound = 1e-8 + 10.0 * 1e-9 / (j * j).min(1.0);
                assert!(
                    (t / exact - 1.0).abs() < bound,
                    "{delta} {a}: {t} vs {exact}"
                );
                assert!((v / a - 1.0).abs() < bound, "{delta} {a}: {v}");
            }
        }
    }

    #[test]
    fn energy_lost_in_flight_is_the_viscous_integral() {
        for (delta, zeta, a) in [
            (-1e-3, 0.05, 1.0),
            (-1e-3, 0.3, 1e-3),
            (1e-3, 0.01, 2.0),
            (0.0, 0.2, 0.5),
            (-1e-3, 1.5, 0.2),
            (-1e-3, 1.0, 0.2),
        ] {
            let osc = Oscillator {
                omega: 1000.0,
                zeta,
                delta,
            };
            let (t, v) = osc.leave(a).land().unwrap();
            let lost = (a * a - v * v) / 2.0;
            let integral = osc.viscous_loss(a, t);
            assert!(
                (lost / integral - 1.0).abs() < 1e-9,
                "{delta} {zeta} {a}: {lost} vs {integral}"
            );
        }
    }

    #[test]
    fn tiny_zeno_flights_keep_their_digits() {
        // a = 1e-9 Omega |Delta|: flight ~ 2a / (Omega^2 |Delta|) (1 + O(a)); the series form
        // keeps it to rounding where the closed form would lose ~9 digits.
        let osc = Oscillator {
            omega: 1000.0,
            zeta: 0.3,
            delta: -1e-3,
        };
        let a = 1e-9;
        let (t, v) = osc.leave(a).land().unwrap();
        let ball = 2.0 * a / (1000.0 * 1000.0 * 1e-3);
        assert!((t / ball - 1.0).abs() < 1e-8, "{t} vs {ball}");
        assert!((v / a - 1.0).abs() < 1e-8);
    }

    #[test]
    fn zeno_accumulation_matches_the_exact_undamped_sum() {
        let s = preload(0.8, 0.0, 0.3);
        let out = simulate(&s, DEFAULT_BUDGET).unwrap();
        // sum_{n>=0} (2/Omega) atan(R^{n+1} v0 / (Omega |Delta|)), brute force.
        let mut exact = 0.0;
        let mut y: f64 = 0.8 * 0.3;
        while y > 1e-30 {
            exact += 2.0 / 1000.0 * y.atan();
            y *= 0.8;
        }
        assert_eq!(out.regime, Regime::ZenoAccumulation);
        assert!((out.end_time.unwrap() / exact - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_gap_with_damping_ends_and_overdamped_is_single() {
        // j = R v0 / (Omega Delta) = 4.5: the amplitude outlasts several decays.
        let gap = OneBody {
            delta: 1e-3,
            ..preload(0.9, 0.05, 5.0)
        };
        let out = simulate(&gap, DEFAULT_BUDGET).unwrap();
        assert_eq!(out.regime, Regime::LastImpact);
        assert!(out.impacts_total.unwrap() > 1 && out.end_time.unwrap() > 0.0);
        let single = OneBody { zeta: 1.2, ..gap };
        let out = simulate(&single, DEFAULT_BUDGET).unwrap();
        assert_eq!(
            (out.regime, out.end_time, out.impacts_total),
            (Regime::SingleImpact, Some(0.0), Some(1))
        );
        // Endless needs a threshold.
        let endless = OneBody { zeta: 0.0, ..gap };
        assert_eq!(
            simulate(&endless, DEFAULT_BUDGET),
            Err(Failure::NeedsThreshold)
        );
        assert!(simulate(
            &OneBody {
                threshold: Some(0.01),
                ..endless
            },
            DEFAULT_BUDGET
        )
        .is_ok());
    }
}

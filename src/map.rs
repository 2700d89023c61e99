//! The semi-discrete map: physics.md sec. 6.
//!
//! Per impact: exact restitution (v -> R v), the conservative flight time T(2a) of a flight
//! leaving at a, and the first-order loss of the other mechanisms over that flight
//! (Delta J = E1_damping(J) T(J)); no root finding. Exact for zeta = 0; preload within 0.3 %
//! for zeta <= 0.01 and 2.5 % for zeta <= 0.1; gap end within ~2 % for zeta <= 1e-3, -12 % at
//! zeta = 0.01, unreliable for a gap with zeta >= 0.1 (it cannot decide the last return).
//!
//! Iterations are bounded: a preload's Zeno tail is summed on the small-impulse asymptote once
//! J < [`Float::TAIL_CUTOFF`] Omega |Delta|; past `max_impacts` the averaged model finishes
//! the sum (flagged [`Approximations::MAP_CONTINUED_AVERAGED`]).

use crate::averaged::Averaged;
use crate::closed::{asymptotic_count, asymptotic_time, by_regime};
use crate::mechanisms::Dissipation;
use crate::prediction::{Approximations, Count, Prediction, Tier, Time};
use crate::quadrature::{Compensated, Nodes};
use crate::regime::Regime;
use crate::{accuracy, Float, Scene};

/// The map's default cap on iterated impacts.
pub const DEFAULT_MAX_IMPACTS: u32 = 100_000;

/// Where the iteration stopped and what remains to be summed.
enum Stop<F> {
    /// The bounce ended at this impact (time, impacts so far).
    Ended(F, F),
    /// Below the threshold in an endless regime: nothing more to sum.
    BelowThreshold,
    /// Hand the rest over, from generating impulse `j` at time `t` after `n` impacts.
    Rest { j: F, t: F, n: F, averaged: bool },
}

/// The map's prediction, iterating at most `max_impacts` impacts.
#[allow(clippy::too_many_lines)] // one loop and its hand-over; splitting it would hide the state
pub(crate) fn predict<F: Float, D: Dissipation<F>>(
    scene: &Scene<F, D>,
    max_impacts: u32,
) -> Prediction<F> {
    if let Some(p) = by_regime(scene) {
        return p;
    }
    let orbit = scene.orbit();
    let restitution = scene.restitution();
    let threshold = scene.threshold_impulse();
    let preload = scene.delta() < F::ZERO;
    let tail = F::TAIL_CUTOFF * scene.omega() * scene.delta().abs();
    let endless = scene.regime() == Regime::Endless;

    let mut speed = scene.closing_speed();
    let mut time = Compensated::new();
    let mut impacts: u32 = 1;
    let mut last_above = F::ZERO;
    let mut above = F::ONE;
    let mut still_above = true;

    let stop = loop {
        let j = F::TWO * restitution * speed;
        if preload && j <= tail {
            break Stop::Rest {
                j,
                t: time.value(),
                n: F::from_u32(impacts),
                averaged: false,
            };
        }
        if impacts > max_impacts {
            break Stop::Rest {
                j,
                t: time.value(),
                n: F::from_u32(impacts),
                averaged: true,
            };
        }
        let point = orbit.at(j);
        let period = point.period();
        let returning = j + scene.dissipation().rate(&point) * period;
        if returning <= F::ZERO {
            // The first-order loss exceeds the flight's impulse (heavy damping). In a gap the
            // impact just made was the last; a preload always returns, with a vanishing
            // impulse: the bounce ends after this flight, or, in an endless regime, the next
            // impact is below any threshold.
            if endless {
                break Stop::BelowThreshold;
            }
            let end = if preload {
                time.value() + period
            } else {
                time.value()
            };
            break Stop::Ended(end, F::from_u32(impacts));
        }
        time.add(period);
        impacts = impacts.saturating_add(1);
        speed = returning * F::HALF;
        if still_above {
            let impulse = (F::ONE + restitution) * speed;
            if threshold.is_some_and(|p_end| impulse < p_end) {
                still_above = false;
                if endless {
                    break Stop::BelowThreshold;
                }
            } else {
                last_above = time.value();
                above = F::from_u32(impacts);
            }
        }
    };

    let mut approximations = accuracy::reduction_flags(scene);
    let (end_time, impacts_total) = match stop {
        Stop::Ended(t, n) => (Time::At(t), Count::Finite(n)),
        Stop::BelowThreshold => (Time::Never, Count::Infinite),
        Stop::Rest { j, t, n, averaged } => {
            if averaged {
                approximations = approximations.with(Approximations::MAP_CONTINUED_AVERAGED);
            }
            let averaged_model = Averaged::new(scene, Nodes::N8);
            // The rest of the threshold count, if the threshold was not crossed yet.
            if still_above {
                if let Some(j_end) = scene.threshold_generating() {
                    let (dt, dn, _) = if averaged {
                        averaged_model.fall(j, j_end)
                    } else {
                        let a = scene.asymptote();
                        (
                            asymptotic_time(a, j, j_end),
                            asymptotic_count(a, orbit, j, j_end),
                            false,
                        )
                    };
                    if let (Time::At(dt), Count::Finite(dn)) = (dt, dn) {
                        last_above = t + dt;
                        above = n + dn;
                    }
                }
            }
            if endless {
                (Time::Never, Count::Infinite)
            } else {
                let (dt, dn, _) = if averaged {
                    averaged_model.fall(j, F::ZERO)
                } else {
                    let a = scene.asymptote();
                    (
                        asymptotic_time(a, j, F::ZERO),
                        asymptotic_count(a, orbit, j, F::ZERO),
                        false,
                    )
                };
                (
                    dt.seconds().map_or(Time::Never, |dt| Time::At(t + dt)),
                    dn.value()
                        .map_or(Count::Infinite, |dn| Count::Finite(n + dn)),
                )
            }
        }
    };
    let (last_above_time, impacts_above) = if threshold.is_some() {
        (Time::At(last_above), Count::Finite(above))
    } else {
        (end_time, impacts_total)
    };
    let mut expected = accuracy::with_reduction(scene, accuracy::map(scene, impacts_total.value()));
    if approximations.contains(Approximations::MAP_CONTINUED_AVERAGED) {
        let averaged = accuracy::averaged(scene, impacts_total.value());
        expected = match (expected, averaged) {
            (Some(a), Some(b)) => Some(a.max(b)),
            _ => None,
        };
    }
    if expected.is_none() {
        approximations = approximations.with(Approximations::OUTSIDE_VALIDITY);
    }
    Prediction {
        regime: scene.regime(),
        end_time,
        last_above_time,
        impacts_above,
        impacts_total,
        tier: Tier::Map,
        approximations,
        expected_error: expected,
    }
}

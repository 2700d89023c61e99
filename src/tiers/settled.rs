//! Predictions that need no tier: a single impact, periodic motion, or a gap's bounce that
//! ends at the first contact. Every tier answers these first.

use crate::physics::duration::{Count, Time};
use crate::physics::flight::{surely_returns, Damping, Oscillator};
use crate::physics::mechanisms::restitution::rebound;
use crate::physics::mechanisms::Dissipation;
use crate::physics::regime::Regime;
use crate::scene::OffsetSign;
use crate::tiers::accuracy;
use crate::tiers::approximations::Approximations;
use crate::tiers::prediction::{Course, Prediction, Tier};
use crate::{Float, Scene};

/// A prediction that needs no tier: a single impact, periodic motion, or a gap's bounce that
/// ends at the first contact (decided exactly: [`ends_at_first_contact`]). Every
/// tier answers these first.
pub(crate) fn answer<F: Float, D: Dissipation<F>, S: OffsetSign>(
    scene: &Scene<F, D, S>,
) -> Option<Prediction<F>> {
    by_regime(scene).or_else(|| ends_at_first_contact(scene))
}

/// A prediction that needs no model: single impact or periodic.
fn by_regime<F: Float, D: Dissipation<F>, S: OffsetSign>(
    scene: &Scene<F, D, S>,
) -> Option<Prediction<F>> {
    let course = match scene.regime() {
        Regime::SingleImpact => Course::single_impact(),
        Regime::Periodic => Course {
            end_time: Time::Never,
            last_above_time: Time::Never,
            impacts_above: Count::Infinite,
            impacts_total: Count::Infinite,
        },
        _ => return None,
    };
    Some(Prediction::of_tier(
        scene,
        course,
        Tier::Regime,
        Approximations::NONE,
        Some(F::ZERO),
    ))
}

/// A gap's bounce that ends at the first contact: the first flight (leaving at R v0) does not
/// come back to the stop, decided exactly by the top of its first swing (one `atan2`, one `exp`
/// and a sine: no root is solved). Then every tier answers exactly: one impact, at t = 0.
/// `None` otherwise, and where it does not apply (no viscous damping, a kernel, Delta <= 0).
pub(crate) fn ends_at_first_contact<F: Float, D: Dissipation<F>, S: OffsetSign>(
    scene: &Scene<F, D, S>,
) -> Option<Prediction<F>> {
    let dissipation = scene.dissipation();
    // (`dissipates` first: a scene type without damping links none of this.)
    if !dissipation.dissipates() || scene.regime() != Regime::LastImpact || dissipation.has_kernel()
    {
        return None;
    }
    let zeta = dissipation.damping_ratio();
    let departure = rebound(scene.closing_speed(), scene.restitution(), scene.loss());
    if surely_returns(scene.omega(), zeta, scene.delta(), departure) {
        return None;
    }
    let oscillator = Oscillator::<F, S>::signed(scene.omega(), zeta, scene.delta());
    let Damping::Under { w, .. } = oscillator.damping else {
        return None; // over-damped gaps are the single-impact regime
    };
    let low = oscillator.first_minimum(departure)?;
    let top = oscillator.eval(departure, low + F::PI / w).0;
    if top >= F::ZERO || oscillator.grazes(top) {
        return None;
    }
    Some(Prediction::of_tier(
        scene,
        Course::single_impact(),
        Tier::Regime,
        Approximations::NONE,
        accuracy::with_reduction(scene, Some(F::ZERO)),
    ))
}

//! Loss at the impacts: the restitution term of E1 (docs/physics.md sec. 3).

use super::Asymptote;
use crate::physics::orbit::{Orbit, OrbitPoint};
use crate::physics::sign::OffsetSign;
use crate::physics::sign::{offset_class, OffsetClass};
use crate::Float;

/// The restitution term of E1: -(1 - R) J / T(J) (m/s^2), with `one_minus_r` = 1 - R.
///
/// The paper's preload form needs arctg(J/(2 Omega |Delta|)) (docs/physics.md sec. 4, errata); with
/// T = 2 theta / Omega this is that form for every sign of Delta.
///
/// ```
/// use contact_bounce::{physics::restitution_rate, physics::Orbit};
/// let orbit = Orbit::new(100.0_f64, 0.0); // Delta = 0: T = pi / Omega
/// let rate = restitution_rate(0.1, &orbit.at(2.0));
/// assert!((rate + 0.1 * 2.0 * 100.0 / core::f64::consts::PI).abs() < 1e-12);
/// ```
#[must_use]
pub fn restitution_rate<F: Float>(one_minus_r: F, point: &OrbitPoint<F>) -> F {
    -one_minus_r * point.impulse() / point.period()
}

/// The speed R v an impact leaves at `speed` (m/s), from R and 1 - R both: R v below R = 1/2,
/// v - (1 - R) v above it, so that neither end cancels (in f32, v - (1 - R) v at R = 4.9e-5
/// kept 3 digits of R v, and the map's first flight was 1e-3 off; R v at R within an epsilon
/// of 1 loses the loss).
#[inline]
pub(crate) fn rebound<F: Float>(speed: F, restitution: F, loss: F) -> F {
    if restitution < F::HALF {
        restitution * speed
    } else {
        speed - loss * speed
    }
}

/// Small-J asymptote of the restitution term (docs/physics.md sec. 4): preload r Omega^2 |Delta|,
/// gap r Omega J / (2 pi), Delta = 0 exactly r Omega J / pi.
pub(crate) fn restitution_asymptote<F: Float, S: OffsetSign>(
    one_minus_r: F,
    orbit: &Orbit<F>,
) -> Asymptote<F> {
    let omega = orbit.omega();
    let mut out = Asymptote::zero();
    match crate::physics::sign::class_of::<S>(offset_class(orbit)) {
        OffsetClass::Preload => out.constant = one_minus_r * omega * omega * orbit.delta().abs(),
        OffsetClass::Gap => out.linear = one_minus_r * omega / (F::TWO * F::PI),
        OffsetClass::Grazing => out.linear = one_minus_r * omega / F::PI,
    }
    out
}

//! Viscous damping: docs/physics.md sec. 3.

use super::{sealed, Asymptote, Dissipation};
use crate::physics::error::{non_negative, Error, Parameter, Reason};
use crate::physics::orbit::{Orbit, OrbitPoint};
use crate::physics::sign::OffsetSign;
use crate::physics::sign::{offset_class, OffsetClass};
use crate::Float;

/// Viscous damping of ratio zeta (x'' + 2 zeta Omega x' + Omega^2 x = 0 in flight).
///
/// E1 term: -zeta Omega (J^2 + 4 Omega^2 Delta^2) / J * (1 - sin(2 theta) / (2 theta)),
/// evaluated as -zeta Omega ((2 theta)^2 J + (2 theta q)(2 theta q / J)) (1 - sinc(2 theta)) /
/// (2 theta)^2, q = 2 Omega Delta, with the series of docs/physics.md sec. 3 below
/// [`Tuning::SINC_SERIES_LIMIT`](crate::numeric::Tuning::SINC_SERIES_LIMIT) and sin(2 theta) = -2 J
/// q / (J^2 + q^2) algebraically (one
/// atan per evaluation, for theta; no sine, no hypot), so it is accurate to a few ULP for every
/// J > 0 and does not underflow before J does.
///
/// ```
/// use contact_bounce::{scene::Dissipation, physics::Orbit, Viscous};
/// let viscous = Viscous::new(0.01_f64)?;
/// // Delta = 0: theta = pi/2 and the rate is exactly -zeta Omega J.
/// let rate = viscous.rate(&Orbit::new(100.0, 0.0).at(3.0));
/// assert!((rate + 0.01 * 100.0 * 3.0).abs() < 1e-12);
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Viscous<F> {
    zeta: F,
}

impl<F: Float> Viscous<F> {
    /// Viscous damping of ratio `zeta` (finite, > 0). A switch without it is a
    /// `Scene<F, Undamped>`, or, chosen at run time, `Option<Viscous<F>>` (`None`): so a scene
    /// typed `Viscous` is damped, and its firmware links none of the undamped paths (the exact
    /// sums of zeta = 0: 3.5 KB of the closed tier and 3.8 KB of the exact one on the Uno; 1.5 KB
    /// of the closed tier and 1.4 KB of the exact one on a Cortex-M4F, `docs/reports/cost-report.md`).
    ///
    /// # Errors
    /// [`Parameter::DampingRatio`] when zeta is NaN, infinite, negative ([`Reason::Negative`])
    /// or 0 ([`Reason::NotPositive`]). [`Scene::new`](crate::Scene::new) also refuses zeta below
    /// [`SMALLEST_RATE`](crate::scene::SMALLEST_RATE) or above
    /// [`LARGEST_DAMPING`](crate::scene::LARGEST_DAMPING).
    pub fn new(zeta: F) -> Result<Self, Error> {
        let zeta = non_negative(zeta, Parameter::DampingRatio)?;
        if zeta == F::ZERO {
            return Err(Error::new(Parameter::DampingRatio, Reason::NotPositive));
        }
        Ok(Self { zeta })
    }
    /// The damping of a switch whose damping ratio is known only at run time: `None` for
    /// zeta = 0 (no viscous damping), else as [`Viscous::new`]. A scene of
    /// `Option<Viscous<F>>` links both the damped and the undamped paths.
    ///
    /// ```
    /// use contact_bounce::Viscous;
    /// assert_eq!(Viscous::optional(0.0_f32)?, None);
    /// assert_eq!(Viscous::optional(0.03_f32)?.map(|v| v.zeta()), Some(0.03));
    /// assert!(Viscous::optional(-0.03_f32).is_err());
    /// # Ok::<(), contact_bounce::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Parameter::DampingRatio`] when zeta is NaN, infinite or negative.
    pub fn optional(zeta: F) -> Result<Option<Self>, Error> {
        let zeta = non_negative(zeta, Parameter::DampingRatio)?;
        Ok((zeta != F::ZERO).then_some(Self { zeta }))
    }
    /// The damping ratio zeta.
    #[must_use]
    pub const fn zeta(&self) -> F {
        self.zeta
    }
}

/// (1 - sin(y)/y) / y^2 for y in (0, 2 pi), given sin(y) computed stably by the caller: the
/// series 1/6 (1 - y^2/20 (1 - y^2/42 (1 - y^2/72))) below
/// [`Tuning::SINC_SERIES_LIMIT`](crate::numeric::Tuning::SINC_SERIES_LIMIT)
/// (docs/physics.md sec. 3), the direct form above. Dividing by y^2 keeps the loss from underflowing
/// where y^2 would (y < 1e-154 in f64, 1e-19 in f32).
pub(crate) fn one_minus_sinc_over_square<F: Float>(y: F, sin_y: F) -> F {
    if y.abs() < F::SINC_SERIES_LIMIT {
        let y2 = y * y;
        let c = |n: f64| F::from_f64(n);
        (F::ONE - y2 / c(20.0) * (F::ONE - y2 / c(42.0) * (F::ONE - y2 / c(72.0)))) / c(6.0)
    } else {
        (F::ONE - sin_y / y) / (y * y)
    }
}

impl<F> sealed::Sealed for Viscous<F> {}

impl<F: Float> Dissipation<F> for Viscous<F> {
    fn damping_ratio(&self) -> F {
        self.zeta
    }
    /// Always: zeta > 0 is checked when it is built.
    #[inline]
    fn dissipates(&self) -> bool {
        true
    }
    fn has_kernel(&self) -> bool {
        false
    }
    fn rate(&self, point: &OrbitPoint<F>) -> F {
        let two_theta = F::TWO * point.phase();
        // sin(2 theta) algebraically from J and 2 Omega Delta (no sine).
        let loss = one_minus_sinc_over_square(two_theta, point.sin_twice_phase());
        // (h^2 / J) (2 theta)^2 = 2 theta (2 theta J) + (2 theta q)(2 theta q / J), q = 2 Omega
        // Delta, with no hypot: for a small phase (preload, small J) 2 theta q / J stays near
        // 2 and 2 theta q near 2 J, so nothing overflows or underflows before J itself does.
        let (j, q) = (point.impulse(), point.offset_impulse());
        let scaled = two_theta * q;
        let h2_over_j = two_theta * (two_theta * j) + scaled * (scaled / j);
        -self.zeta * point.natural_frequency() * h2_over_j * loss
    }
    fn asymptote_for<S: OffsetSign>(&self, orbit: &Orbit<F>, _: sealed::Private) -> Asymptote<F> {
        let omega = orbit.omega();
        let mut out = Asymptote::zero();
        match crate::physics::sign::class_of::<S>(offset_class(orbit)) {
            // -(2/3) zeta Omega J
            OffsetClass::Preload => out.linear = F::TWO * self.zeta * omega / F::from_f64(3.0),
            // -4 zeta Omega^3 Delta^2 / J = -zeta Omega q^2 / J
            OffsetClass::Gap => {
                let q = orbit.offset_impulse();
                out.inverse = self.zeta * omega * q * q;
            }
            OffsetClass::Grazing => out.linear = self.zeta * omega,
        }
        out
    }
}

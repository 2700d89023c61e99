//! What every mechanism is: a [`Dissipation`], with the [`Asymptote`] of its rate at small
//! impulses; and [`Undamped`], the scene with restitution alone.

use core::fmt::Debug;

use crate::numeric::float::{ln1p_ratio, log_growth_of_ratio};
use crate::physics::duration::{Count, Time};
use crate::physics::orbit::{Orbit, OrbitPoint};
use crate::physics::sign::{offset_class, AnySign, OffsetClass, OffsetSign};
use crate::Float;

pub(crate) mod sealed {
    pub trait Sealed {}
    /// A token only this crate can make: a trait method that takes one cannot be called from
    /// outside it.
    #[derive(Debug, Clone, Copy)]
    pub struct Private(pub(crate) ());
}

/// The small-impulse asymptote of an averaged rate: E1(J) -> -(constant + linear J + inverse / J)
/// as J -> 0 (docs/physics.md sec. 4, "small-J limits of E1"). Each mechanism contributes to one
/// term, depending on the sign of Delta.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Asymptote<F> {
    /// The J-independent part (m/s^2): restitution with a preload.
    pub constant: F,
    /// The part linear in J (1/s): viscous with a preload; restitution in a gap or at Delta = 0.
    pub linear: F,
    /// The part in 1/J (m^2/s^3): viscous or hereditary in a gap.
    pub inverse: F,
}

impl<F: Float> Asymptote<F> {
    /// Where a tier leaves the small-impulse tail to the asymptote on the way to J = 0,
    /// relative to Omega |Delta|: [`Tuning::DAMPED_TAIL_CUTOFF`](crate::numeric::Tuning) where
    /// the scene `dissipates` between impacts, else [`Tuning::TAIL_CUTOFF`](crate::numeric::Tuning),
    /// exact to rounding. (In f32 the two are one constant, and the test folds away.)
    #[inline]
    pub(crate) fn tail_cutoff(dissipates: bool) -> F {
        if F::DAMPED_TAIL_CUTOFF > F::TAIL_CUTOFF && dissipates {
            F::DAMPED_TAIL_CUTOFF
        } else {
            F::TAIL_CUTOFF
        }
    }

    /// No contribution.
    pub const fn zero() -> Self {
        Self {
            constant: F::ZERO,
            linear: F::ZERO,
            inverse: F::ZERO,
        }
    }
    /// Sum of two asymptotes.
    #[must_use]
    pub fn plus(self, other: Self) -> Self {
        Self {
            constant: self.constant + other.constant,
            linear: self.linear + other.linear,
            inverse: self.inverse + other.inverse,
        }
    }
    /// -E1 on the asymptote at impulse `impulse` (m/s^2, >= 0).
    #[must_use]
    pub fn magnitude(&self, impulse: F) -> F {
        self.constant + self.linear * impulse + self.inverse / impulse
    }
    /// Time for J to fall from `j1` to `j2` (0 <= j2 <= j1) on the asymptote
    /// J' = -(constant + linear J + inverse / J) (at most two terms are non-zero).
    pub(crate) fn fall_time(&self, j1: F, j2: F) -> Time<F> {
        let a = self;
        if j1 <= j2 {
            return Time::At(F::ZERO);
        }
        let drop = j1 - j2;
        if a.inverse > F::ZERO {
            // integral of J dJ / (B J^2 + C): t_b2r, and t_b2 when B = 0.
            let squares = drop * (j1 + j2);
            let base = a.linear * j2 * j2 + a.inverse;
            Time::At(log_growth_of_ratio(squares, base, a.linear) * F::HALF)
        } else if a.constant > F::ZERO {
            // integral of dJ / (A + B J): t_b1v, and t_b1 when B = 0.
            let base = a.constant + a.linear * j2;
            Time::At(log_growth_of_ratio(drop, base, a.linear))
        } else if a.linear > F::ZERO && j2 > F::ZERO {
            Time::At((j1.ln() - j2.ln()) / a.linear)
        } else {
            Time::Never
        }
    }

    /// Impacts while J falls from `j1` to `j2` on the asymptote: the integral of dJ / (|E1| T)
    /// with the small-J period (preload J / (Omega^2 |Delta|), gap 2 pi / Omega, Delta = 0 pi / Omega).
    /// `S` is the scene's sign type: where it fixes the sign, the other classes' code is left
    /// out.
    pub(crate) fn fall_count<S: OffsetSign>(&self, orbit: &Orbit<F>, j1: F, j2: F) -> Count<F> {
        let a = self;
        if j1 <= j2 {
            return Count::Finite(F::ZERO);
        }
        let omega = orbit.omega();
        let class = crate::physics::sign::class_of::<S>(offset_class(orbit));
        match class {
            OffsetClass::Preload => {
                let k = omega * omega * orbit.delta().abs();
                if j2 <= F::ZERO {
                    Count::Infinite
                } else if a.constant > F::ZERO {
                    // (k/A) ln(j1 (A + B j2) / (j2 (A + B j1))) = (k/A) ln1p(u),
                    // u = A (j1 - j2) / (j2 (A + B j1)): no cancellation as A -> 0. The ratio
                    // (j1 - j2) / j2 first, so that j2 (A + B j1) cannot underflow (f32).
                    let rate = a.constant + a.linear * j1;
                    let scale = (j1 - j2) / j2 / rate;
                    let u = a.constant * scale;
                    if scale.is_finite() && u.is_finite() {
                        Count::Finite(k * scale * ln1p_ratio(u))
                    } else {
                        // The ratio beyond the float's range: u in logarithms (k / A stays near
                        // 1 / r). u itself may still be small (A tiny: f32, r = 4e-10 and
                        // v0 = 1e30 gave u = 0.02 and a negative count when ln1p(u) was taken as
                        // ln u), so ln1p(u) exactly where u is a number, and ln u only beyond.
                        let ln_u = a.constant.ln() + (j1 - j2).ln() - j2.ln() - rate.ln();
                        let u = ln_u.exp();
                        let ln1p_u = if u.is_finite() { u.ln_1p() } else { ln_u };
                        let n = k / a.constant * ln1p_u;
                        if n.is_finite() {
                            Count::Finite(n)
                        } else {
                            Count::Infinite
                        }
                    }
                } else if a.linear > F::ZERO {
                    Count::Finite(k / a.linear * (F::ONE / j2 - F::ONE / j1))
                } else {
                    Count::Infinite
                }
            }
            OffsetClass::Gap | OffsetClass::Grazing => {
                let period = if class == OffsetClass::Gap {
                    F::TWO * F::PI / omega
                } else {
                    F::PI / omega
                };
                match a.fall_time(j1, j2) {
                    Time::At(t) => Count::Finite(t / period),
                    Time::Never => Count::Infinite,
                }
            }
        }
    }
}

/// A dissipation mechanism acting between impacts (sealed: implemented by [`Undamped`],
/// [`Viscous`](super::Viscous), [`Hereditary`](super::Hereditary), tuples and `Option`s of them).
pub trait Dissipation<F: Float>: sealed::Sealed + Copy + Debug {
    /// True for a type that never dissipates whatever its value ([`Undamped`]): code for the
    /// other mechanisms is then left out at compile time. ([`Viscous`](super::Viscous) is the converse: it
    /// always dissipates, zeta > 0 being checked when it is built, so a `Viscous` scene links
    /// none of the undamped paths.)
    const NEVER_DISSIPATES: bool = false;
    /// The viscous damping ratio zeta (0 without viscous damping): it decides the
    /// single-impact regime (zeta >= 1 with Delta >= 0).
    fn damping_ratio(&self) -> F;
    /// True when energy is lost between impacts.
    fn dissipates(&self) -> bool;
    /// True when a hereditary kernel is present.
    fn has_kernel(&self) -> bool;
    /// This mechanism's contribution to E1(J) at an orbit point (m/s^2, <= 0).
    fn rate(&self, point: &OrbitPoint<F>) -> F;
    /// This mechanism's small-impulse asymptote on `orbit`.
    fn asymptote(&self, orbit: &Orbit<F>) -> Asymptote<F> {
        self.asymptote_for::<AnySign>(orbit, sealed::Private(()))
    }
    /// [`Dissipation::asymptote`] for the orbit of a scene of sign type `S`, whose Delta has the
    /// sign `S` admits (the same value): where `S` fixes the sign, the other sides' terms are
    /// left out of the code. Only the crate can call it (its scenes' build): an orbit of the
    /// other sign would get the wrong side's terms.
    #[doc(hidden)]
    fn asymptote_for<S: OffsetSign>(&self, orbit: &Orbit<F>, _: sealed::Private) -> Asymptote<F>;
    /// The static stiffness it takes from the spring, per unit mass (1/s^2): kappa tau for a
    /// relaxation kernel (its force kappa y tends to kappa tau x for slow motion), 0 otherwise.
    /// The averaged model keeps only the dissipative part; this is the part it leaves out.
    fn static_stiffness(&self) -> F {
        F::ZERO
    }
    /// The one relaxation kernel's (kappa, tau), which the exact tier solves with: `None`
    /// without a kernel, and where two kernels act (that tier then answers with the averaged
    /// model).
    fn kernel(&self) -> Option<(F, F)> {
        None
    }
    /// The longest relaxation time of its kernels, tau (s; 0 without a kernel): how long the
    /// kernel's force remembers the motion.
    fn longest_relaxation(&self) -> F {
        F::ZERO
    }
}

/// No dissipation between impacts: restitution only.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Undamped;

impl sealed::Sealed for Undamped {}

impl<F: Float> Dissipation<F> for Undamped {
    const NEVER_DISSIPATES: bool = true;
    #[inline]
    fn damping_ratio(&self) -> F {
        F::ZERO
    }
    #[inline]
    fn dissipates(&self) -> bool {
        false
    }
    #[inline]
    fn has_kernel(&self) -> bool {
        false
    }
    #[inline]
    fn rate(&self, _point: &OrbitPoint<F>) -> F {
        F::ZERO
    }
    #[inline]
    fn asymptote_for<S: OffsetSign>(&self, _: &Orbit<F>, _: sealed::Private) -> Asymptote<F> {
        Asymptote::zero()
    }
}

impl<A: sealed::Sealed> sealed::Sealed for Option<A> {}

impl<F: Float, A: Dissipation<F>> Dissipation<F> for Option<A> {
    const NEVER_DISSIPATES: bool = A::NEVER_DISSIPATES;
    fn damping_ratio(&self) -> F {
        self.as_ref().map_or(F::ZERO, Dissipation::damping_ratio)
    }
    fn dissipates(&self) -> bool {
        self.as_ref().is_some_and(Dissipation::dissipates)
    }
    fn has_kernel(&self) -> bool {
        self.as_ref().is_some_and(Dissipation::has_kernel)
    }
    fn rate(&self, point: &OrbitPoint<F>) -> F {
        self.as_ref().map_or(F::ZERO, |m| m.rate(point))
    }
    fn asymptote_for<S: OffsetSign>(&self, orbit: &Orbit<F>, p: sealed::Private) -> Asymptote<F> {
        self.as_ref()
            .map_or(Asymptote::zero(), |m| m.asymptote_for::<S>(orbit, p))
    }
    fn static_stiffness(&self) -> F {
        self.as_ref().map_or(F::ZERO, Dissipation::static_stiffness)
    }
    fn kernel(&self) -> Option<(F, F)> {
        self.as_ref().and_then(Dissipation::kernel)
    }
    fn longest_relaxation(&self) -> F {
        self.as_ref()
            .map_or(F::ZERO, Dissipation::longest_relaxation)
    }
}

impl<A: sealed::Sealed, B: sealed::Sealed> sealed::Sealed for (A, B) {}

impl<F: Float, A: Dissipation<F>, B: Dissipation<F>> Dissipation<F> for (A, B) {
    const NEVER_DISSIPATES: bool = A::NEVER_DISSIPATES && B::NEVER_DISSIPATES;
    fn damping_ratio(&self) -> F {
        self.0.damping_ratio() + self.1.damping_ratio()
    }
    fn dissipates(&self) -> bool {
        self.0.dissipates() || self.1.dissipates()
    }
    fn has_kernel(&self) -> bool {
        self.0.has_kernel() || self.1.has_kernel()
    }
    fn rate(&self, point: &OrbitPoint<F>) -> F {
        self.0.rate(point) + self.1.rate(point)
    }
    fn asymptote_for<S: OffsetSign>(&self, orbit: &Orbit<F>, p: sealed::Private) -> Asymptote<F> {
        self.0
            .asymptote_for::<S>(orbit, p)
            .plus(self.1.asymptote_for::<S>(orbit, p))
    }
    fn static_stiffness(&self) -> F {
        self.0.static_stiffness() + self.1.static_stiffness()
    }
    fn kernel(&self) -> Option<(F, F)> {
        if self.0.has_kernel() && self.1.has_kernel() {
            None
        } else {
            self.0.kernel().or_else(|| self.1.kernel())
        }
    }
    fn longest_relaxation(&self) -> F {
        let (a, b) = (self.0.longest_relaxation(), self.1.longest_relaxation());
        if a > b {
            a
        } else {
            b
        }
    }
}

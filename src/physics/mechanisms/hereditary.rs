//! Hereditary (viscoelastic) damping with an exponential relaxation kernel: docs/physics.md sec. 3.

use super::{sealed, Asymptote, Dissipation};
use crate::physics::error::{derived, physical, positive, Error, Parameter, Reason};
use crate::physics::orbit::{Orbit, OrbitPoint};
use crate::physics::sign::OffsetSign;
use crate::physics::sign::{offset_class, OffsetClass};
use crate::Float;

/// Hereditary damping by the relaxation kernel Gamma(t) = kappa exp(-t / tau).
///
/// E1 term (docs/physics.md sec. 3, the paper's formula corrected: coefficient 2, every harmonic):
///
/// -(2 J omega^3 / pi^2) sum_{k>=1} k Gs(k omega) / (Omega^2 - k^2 omega^2)^2,
/// Gs(nu) = kappa nu tau^2 / (1 + nu^2 tau^2),
///
/// evaluated as -2 pi^2 J sum_k k^2 g(k omega) / (pi^2 k^2 - theta^2)^2 with g = Gs/nu, the
/// k = 1 denominator as (pi - theta)(pi + theta) (no cancellation near grazing in a gap).
///
/// **Accuracy.** The sum is truncated after K harmonics, K doubling from 2, once the remaining
/// tail, bracketed by integrals (terms are positive and decreasing), is known to within the
/// relative `tolerance` (default 1e-4) of the total; the tail's Euler-Maclaurin estimate,
/// kept inside that bracket, is added (in practice far closer than the bound). So the
/// returned rate is within `tolerance` of the full infinite sum unless `max_harmonics` (default
/// 4096) stops it first, in which case [`HarmonicSum::relative_error`] says how far. The
/// averaging itself is within ~0.3 % of exact simulation (docs/physics.md sec. 6).
///
/// ```
/// use contact_bounce::{scene::Dissipation, Hereditary, physics::Orbit, Viscous};
/// // A kernel with tau -> 0 and kappa tau^2 = 2 zeta Omega acts as viscous damping (it departs
/// // from it by (k omega tau)^2 over the ~2000 harmonics a 1e-7 tolerance sums).
/// let (omega, zeta, tau) = (1000.0_f64, 0.02, 1e-12);
/// let kernel = Hereditary::exponential(2.0 * zeta * omega / (tau * tau), tau)?
///     .with_tolerance(1e-7)?;
/// let p = Orbit::new(omega, -1e-3).at(1.0);
/// let (h, v) = (kernel.rate(&p), Viscous::new(zeta)?.rate(&p));
/// assert!((h / v - 1.0).abs() < 1e-6);
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Hereditary<F> {
    kappa: F,
    tau: F,
    /// kappa tau^2 = g(0) (1/s).
    low_frequency: F,
    tolerance: F,
    max_harmonics: u32,
}

/// A truncated harmonic sum with its error bound.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct HarmonicSum<F> {
    /// The sum, tail estimate included: sum_k k^2 g(k omega) / (pi^2 k^2 - theta^2)^2 (s/1).
    pub value: F,
    /// A bound on |value - full sum| / value.
    pub relative_error: F,
    /// The harmonics summed explicitly.
    pub harmonics: u32,
}

impl<F: Float> Hereditary<F> {
    /// The kernel kappa exp(-t / tau): `kappa` > 0 (1/s^3, per unit reduced mass), `tau` > 0 (s).
    ///
    /// # Errors
    /// [`Parameter::KernelAmplitude`] or [`Parameter::KernelTimeConstant`] when NaN, infinite
    /// or not positive; [`Parameter::KernelAmplitude`] with [`Reason::Overflow`] when
    /// kappa tau^2 overflows or underflows.
    pub fn exponential(kappa: F, tau: F) -> Result<Self, Error> {
        let kappa = positive(kappa, Parameter::KernelAmplitude)?;
        let tau = physical(tau, Parameter::KernelTimeConstant)?;
        let low_frequency = derived(kappa * tau * tau, Parameter::KernelAmplitude)?;
        Ok(Self {
            kappa,
            tau,
            low_frequency,
            tolerance: F::from_f64(1e-4),
            max_harmonics: 4096,
        })
    }

    /// Sets the relative tolerance of the harmonic sum, in [16 epsilon, 0.1].
    ///
    /// # Errors
    /// [`Parameter::HarmonicTolerance`] outside that interval or NaN.
    pub fn with_tolerance(mut self, tolerance: F) -> Result<Self, Error> {
        let lowest = F::from_f64(16.0) * F::EPSILON;
        let tolerance = positive(tolerance, Parameter::HarmonicTolerance)?;
        if tolerance < lowest || tolerance > F::from_f64(0.1) {
            return Err(Error::new(Parameter::HarmonicTolerance, Reason::OutOfRange));
        }
        self.tolerance = tolerance;
        Ok(self)
    }

    /// Caps the harmonics summed explicitly (at least 2).
    #[must_use]
    pub fn with_max_harmonics(mut self, max_harmonics: u32) -> Self {
        self.max_harmonics = max_harmonics.max(2);
        self
    }

    /// kappa (1/s^3).
    #[must_use]
    pub const fn kappa(&self) -> F {
        self.kappa
    }
    /// tau (s).
    #[must_use]
    pub const fn tau(&self) -> F {
        self.tau
    }

    /// The kernel's sine transform Gs(nu) = kappa nu tau^2 / (1 + nu^2 tau^2) (1/s^2).
    #[must_use]
    pub fn sine_transform(&self, nu: F) -> F {
        nu * self.per_frequency(nu)
    }

    /// g(nu) = Gs(nu) / nu = kappa tau^2 / (1 + (nu tau)^2): positive, decreasing.
    fn per_frequency(&self, nu: F) -> F {
        let x = nu * self.tau;
        self.low_frequency / (F::ONE + x * x)
    }

    /// The integral of g(x omega) / x^2 over [m, inf): kappa tau^2 (1 - u atan(1/u)) / m,
    /// u = omega tau m; the bracket of the harmonic tail.
    fn tail_integral(&self, omega: F, m: F) -> F {
        let u = omega * self.tau * m;
        let c = |x: f64| F::from_f64(x);
        let q = if u <= c(4.0) {
            F::ONE - u * (F::ONE / u).atan()
        } else {
            // 1 - u atan(1/u) = w/3 - w^2/5 + ... with w = 1/u^2 <= 1/16; six terms leave a
            // relative error below 1e-8 of a tail that is itself a small part of the sum.
            let w = F::ONE / (u * u);
            w * (F::ONE / c(3.0)
                - w * (F::ONE / c(5.0)
                    - w * (F::ONE / c(7.0)
                        - w * (F::ONE / c(9.0) - w * (F::ONE / c(11.0) - w / c(13.0))))))
        };
        self.low_frequency * q / m
    }

    /// The integral of g(x omega) / x^4 over [m, inf): kappa tau^2 q(u) / m^3 with
    /// q(u) = 1/3 - u^2 + u^3 atan(1/u), u = omega tau m (the tail's theta correction).
    fn tail_integral_4(&self, omega: F, m: F) -> F {
        let u = omega * self.tau * m;
        let c = |x: f64| F::from_f64(x);
        let q = if u <= F::TWO {
            // (At most two digits cancel, at u = 2.)
            F::ONE / c(3.0) - u * u + u * u * u * (F::ONE / u).atan()
        } else {
            // w/5 - w^2/7 + ... with w = 1/u^2 <= 1/4: eight terms leave below 1e-6 of a
            // correction that is itself O(1/m^2) of the tail.
            let w = F::ONE / (u * u);
            w * (F::ONE / c(5.0)
                - w * (F::ONE / c(7.0)
                    - w * (F::ONE / c(9.0)
                        - w * (F::ONE / c(11.0)
                            - w * (F::ONE / c(13.0)
                                - w * (F::ONE / c(15.0) - w * (F::ONE / c(17.0) - w / c(19.0))))))))
        };
        self.low_frequency * q / (m * m * m)
    }

    /// The harmonic sum at an orbit point, to the kernel's tolerance (see the type docs).
    #[must_use]
    pub fn harmonic_sum(&self, point: &OrbitPoint<F>) -> HarmonicSum<F> {
        let pi = F::PI;
        let theta = point.phase();
        let omega = point.frequency();
        let a2 = (theta / pi) * (theta / pi);
        let pi4 = pi * pi * pi * pi;
        // k = 1: pi^2 - theta^2 = (pi - theta)(pi + theta), cancellation-free.
        let first = point.supplement() * (pi + theta);
        let mut sum = self.per_frequency(omega) / (first * first);
        let mut k: u32 = 1;
        loop {
            k += 1;
            let kf = F::from_u32(k);
            let den = (pi * kf - theta) * (pi * kf + theta);
            sum += kf * kf * self.per_frequency(kf * omega) / (den * den);
            let checkpoint = k.is_power_of_two() || k >= self.max_harmonics;
            if !checkpoint {
                continue;
            }
            let next = kf + F::ONE;
            let lower = self.tail_integral(omega, next) / pi4;
            let shrink = F::ONE - a2 / (next * next);
            let upper = self.tail_integral(omega, kf) / (shrink * shrink * pi4);
            // The estimate inside the bracket: the midpoint rule of Euler-Maclaurin,
            // sum_{k > K} f(k) ~ integral of f from K + 1/2 (error ~ f'(K) / 24), with
            // f = g / (pi^4 x^2) (1 - a^2 / x^2)^-2 to first order in a^2 / x^2. Where theta
            // is near pi (a gap) the bracket's midpoint was off by a sizeable share of its
            // width; this is O(1 / K^3) of the tail's scale.
            let half = kf + F::HALF;
            // + f'(M) / 24 (f' < 0), with f ~ g(x omega) / (pi^4 x^2):
            // f' = -2 f (1/x + x b^2 / (1 + x^2 b^2)),
            // b = omega tau.
            let b = omega * self.tau;
            let hb = half * b;
            let slope = self.per_frequency(half * omega) / (half * half)
                * (F::ONE / half + half * b * b / (F::ONE + hb * hb));
            let estimate = (self.tail_integral(omega, half)
                + F::TWO * a2 * self.tail_integral_4(omega, half)
                - slope / F::from_f64(12.0))
                / pi4;
            let value = sum + estimate.max(lower).min(upper);
            let half_width = (upper - lower) * F::HALF;
            if half_width <= self.tolerance * value || k >= self.max_harmonics {
                return HarmonicSum {
                    value,
                    relative_error: half_width / value,
                    harmonics: k,
                };
            }
        }
    }
}

impl<F> sealed::Sealed for Hereditary<F> {}

impl<F: Float> Dissipation<F> for Hereditary<F> {
    fn damping_ratio(&self) -> F {
        F::ZERO
    }
    fn dissipates(&self) -> bool {
        true
    }
    fn has_kernel(&self) -> bool {
        true
    }
    fn static_stiffness(&self) -> F {
        self.kappa * self.tau
    }
    fn kernel(&self) -> Option<(F, F)> {
        Some((self.kappa, self.tau))
    }
    fn longest_relaxation(&self) -> F {
        self.tau
    }
    fn rate(&self, point: &OrbitPoint<F>) -> F {
        let two_pi2 = F::TWO * F::PI * F::PI;
        -two_pi2 * point.impulse() * self.harmonic_sum(point).value
    }
    fn asymptote_for<S: OffsetSign>(&self, orbit: &Orbit<F>, _: sealed::Private) -> Asymptote<F> {
        let mut out = Asymptote::zero();
        match crate::physics::sign::class_of::<S>(offset_class(orbit)) {
            // theta -> 0: the rate vanishes faster than J (like J theta^2).
            OffsetClass::Preload => {}
            // theta -> pi: the k = 1 term gives -2 Omega^2 Delta^2 g(Omega) / J.
            OffsetClass::Gap => {
                let q = orbit.offset_impulse();
                out.inverse = q * q * self.per_frequency(orbit.omega()) * F::HALF;
            }
            // theta = pi/2 for every J: the rate is exactly linear in J.
            OffsetClass::Grazing => out.linear = -self.rate(&orbit.at(F::ONE)),
        }
        out
    }
}

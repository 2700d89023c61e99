//! The generating (conservative) orbit: docs/physics.md sec. 2 (the paper's Eq. 3, with its errata).
//!
//! Between impacts the contact moves on the undamped orbit of period T(J), where J is the
//! generating impulse: twice the impact speed. Everything here is in the stable forms of
//! docs/physics.md sec. 2: sin(theta) = J/h and cos(theta) = -2 Omega Delta / h with
//! h = hypot(J, 2 Omega Delta); for a gap, pi - theta = atan2(J, 2 Omega Delta) is computed
//! directly, never as a difference.

use crate::Float;

/// The generating orbit of a contact with natural frequency Omega and offset Delta.
///
/// ```
/// use contact_bounce::physics::Orbit;
/// // A preload of 1 mm at Omega = 1000 rad/s, generating impulse 1 m/s (j = J/(Omega|Delta|) = 1).
/// let orbit = Orbit::new(1000.0_f64, -1e-3);
/// let p = orbit.at(1.0);
/// // theta = atan(J / (2 Omega |Delta|)) = atan(0.5)
/// assert!((p.phase() - 0.5_f64.atan()).abs() < 1e-15);
/// assert!((p.period() - 2.0 * 0.5_f64.atan() / 1000.0).abs() < 1e-18);
/// // The orbit starts and ends at the stop: x(0+) = x(T) = Delta.
/// assert!((orbit.position(1.0, p.period()) + 1e-3).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Orbit<F> {
    omega: F,
    delta: F,
}

/// The generating orbit at one impulse J: the phase theta, its supplement and the period.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct OrbitPoint<F> {
    impulse: F,
    /// 2 Omega Delta (m/s).
    offset: F,
    phase: F,
    supplement: F,
    omega: F,
}

/// The phase atan2(y, x) of the orbit for y >= 0 and x = +-0 or positive, finite, from `atan`
/// alone: atan(y / x), which is what libm's `atan2` computes in this quadrant after its checks
/// of signs, zeros, infinities and exponent gaps; y / x beyond the float's range (x = 0) is
/// pi/2, as `atan2` gives it. Bit for bit libm's `atan2` (tested over random bits and edges in
/// f32 and f64), except:
/// - in f32 where y / x >= 2^26, where `atanf` returns its table's pi/2, one ulp below the pi/2
///   `atan2f` returns;
/// - at y = 0 and x = +-0 (J = 0 at Delta = 0, outside [`Orbit::at`]'s domain), where it is pi/2,
///   the phase at every J > 0 there, where `atan2` gives 0 or pi.
///
/// The tiers that need no flight of their own (the closed forms, the averaged model) then link
/// no `atan2` (726 bytes of the Uno's averaged tier), and the host skips its checks (a third of
/// the map's instructions, where its impacts call this once each).
#[inline]
fn first_quadrant<F: Float>(y: F, x: F) -> F {
    let ratio = y / x;
    if ratio.abs() <= F::MAX {
        ratio.atan()
    } else {
        // +-inf, or 0 / 0.
        F::PI * F::HALF
    }
}

impl<F: Float> Orbit<F> {
    /// The orbit of natural frequency `omega` (rad/s, > 0) and offset `delta` (m; gap > 0,
    /// preload < 0). The caller guarantees finite inputs and omega > 0 (a
    /// [`Scene`](crate::Scene) does).
    #[must_use]
    pub const fn new(omega: F, delta: F) -> Self {
        Self { omega, delta }
    }

    /// Natural frequency Omega (rad/s).
    #[must_use]
    pub const fn omega(&self) -> F {
        self.omega
    }

    /// Offset Delta (m): gap > 0, preload < 0.
    #[must_use]
    pub const fn delta(&self) -> F {
        self.delta
    }

    /// 2 Omega Delta (m/s), the impulse scale of the offset (signed).
    #[must_use]
    pub fn offset_impulse(&self) -> F {
        F::TWO * self.omega * self.delta
    }

    /// The orbit at generating impulse `impulse` (J > 0, m/s). Accurate to a few ULP for every
    /// J > 0 and Delta of either sign, including J/(Omega |Delta|) down to 1e-30 and up to 1e30.
    #[must_use]
    pub fn at(&self, impulse: F) -> OrbitPoint<F> {
        let q = self.offset_impulse();
        let (phase, supplement) = if q > F::ZERO {
            // Gap: theta in (pi/2, pi); its supplement is small for small J, so compute it first.
            let d = first_quadrant(impulse, q);
            (F::PI - d, d)
        } else {
            // Preload or grazing: theta in (0, pi/2]. `-q` is +0.0 or positive.
            let theta = first_quadrant(impulse, -q);
            (theta, F::PI - theta)
        };
        OrbitPoint {
            impulse,
            offset: q,
            phase,
            supplement,
            omega: self.omega,
        }
    }

    /// The generating orbit's position x(t) = -J chi(t) (docs/physics.md sec. 2), for any t >= 0
    /// (T-periodic): x(t) = -(h / (2 Omega)) cos(Omega t' - theta), t' = t mod T in (0, T]
    /// (the argument stays in [-theta, theta], so the series of [`Float::cos_within_pi`] serves).
    #[must_use]
    pub fn position(&self, impulse: F, t: F) -> F {
        let p = self.at(impulse);
        let local = p.time_in_period(t);
        -(p.hypot() / (F::TWO * self.omega)) * (self.omega * local - p.phase).cos_within_pi()
    }

    /// The generating orbit's velocity x'(t) (m/s), for any t >= 0 (T-periodic).
    #[must_use]
    pub fn velocity(&self, impulse: F, t: F) -> F {
        let p = self.at(impulse);
        let local = p.time_in_period(t);
        p.hypot() * F::HALF * (self.omega * local - p.phase).sin_within_pi()
    }
}

impl<F: Float> OrbitPoint<F> {
    /// The generating impulse J (m/s).
    #[must_use]
    pub const fn impulse(&self) -> F {
        self.impulse
    }
    /// h = hypot(J, 2 Omega Delta) (m/s).
    #[must_use]
    pub fn hypot(&self) -> F {
        self.impulse.hypot(self.offset)
    }
    /// sin(2 theta) = -2 J (2 Omega Delta) / h^2, algebraically (no sine, no hypot): as
    /// -2 t / (1 + t^2) with t the smaller of the ratios of J and 2 Omega Delta, so it is
    /// within a few ULP for every J and never overflows.
    #[must_use]
    pub fn sin_twice_phase(&self) -> F {
        let (j, q) = (self.impulse, self.offset);
        let t = if j.abs() >= q.abs() { q / j } else { j / q };
        -(t + t) / (F::ONE + t * t)
    }
    /// theta(J) = atan2(J, -2 Omega Delta), in (0, pi): preload (0, pi/2), grazing pi/2, gap
    /// (pi/2, pi).
    #[must_use]
    pub const fn phase(&self) -> F {
        self.phase
    }
    /// pi - theta, computed without cancellation for a gap (it is the small one there).
    #[must_use]
    pub const fn supplement(&self) -> F {
        self.supplement
    }
    /// sin(theta) = J / h.
    #[must_use]
    pub fn sin_phase(&self) -> F {
        self.impulse / self.hypot()
    }
    /// 2 Omega Delta (m/s), the offset's impulse scale (signed: gap > 0).
    #[must_use]
    pub const fn offset_impulse(&self) -> F {
        self.offset
    }
    /// The period between impacts T(J) = 2 theta / Omega (s): the exact flight time of an
    /// undamped flight that leaves the stop at J/2.
    #[must_use]
    pub fn period(&self) -> F {
        F::TWO * self.phase / self.omega
    }
    /// The impact frequency omega(J) = 2 pi / T = pi Omega / theta (rad/s).
    #[must_use]
    pub fn frequency(&self) -> F {
        F::PI * self.omega / self.phase
    }
    /// Natural frequency Omega of the orbit (rad/s).
    #[must_use]
    pub const fn natural_frequency(&self) -> F {
        self.omega
    }
    /// t reduced into (0, T] (for t <= 0, returns t unchanged: the orbit before impact 0).
    fn time_in_period(&self, t: F) -> F {
        let period = self.period();
        if t <= F::ZERO {
            return t;
        }
        let cycles = (t / period).floor();
        let local = t - cycles * period;
        if local <= F::ZERO {
            period
        } else {
            local
        }
    }
}

#[cfg(test)]
mod tests {
    use super::first_quadrant;

    /// splitmix64 (a bare LCG's consecutive high bits left y / x near 1).
    fn random(state: &mut u64) -> u64 {
        *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let z = (*state ^ (*state >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        let z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Random finite bit patterns with y >= 0 and x >= +0 (subnormals and zeros among them;
    /// half the pairs with exponents near each other), and the edges: `first_quadrant` is libm's
    /// `atan2` there, bit for bit.
    #[test]
    fn the_first_quadrant_is_atan2_bit_for_bit_in_f64() {
        let mut state = 1;
        let mut checked = 0;
        for _ in 0..200_000 {
            let (a, b) = (random(&mut state), random(&mut state));
            let y = f64::from_bits(a >> 1);
            let x = f64::from_bits(if a & 1 == 0 {
                b >> 1
            } else {
                (a >> 1) ^ (b >> 44)
            });
            if y.is_finite() && x.is_finite() {
                assert_eq!(
                    first_quadrant(y, x).to_bits(),
                    libm::atan2(y, x).to_bits(),
                    "{y:e} {x:e}"
                );
                checked += 1;
            }
        }
        let edges = [
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            5e-324,
            1e-300,
            1.0,
            1e300,
            f64::MAX,
        ];
        for y in edges.into_iter().filter(|y| *y > 0.0) {
            for x in edges {
                assert_eq!(first_quadrant(y, x).to_bits(), libm::atan2(y, x).to_bits());
            }
            assert_eq!(first_quadrant(0.0, y).to_bits(), 0);
        }
        // J = 0 at Delta = 0: the phase of every J > 0 there.
        for x in [0.0, -0.0] {
            assert_eq!(first_quadrant(0.0, x), core::f64::consts::FRAC_PI_2);
        }
        assert!(checked > 150_000, "{checked}");
    }

    /// As in f64, but for f32's pi/2 where y / x >= 2^26 (one ulp below `atan2f`'s).
    #[cfg(not(feature = "micromath"))]
    #[test]
    fn the_first_quadrant_is_atan2_bit_for_bit_in_f32() {
        let same = |y: f32, x: f32| {
            let (got, want) = (first_quadrant(y, x).to_bits(), libm::atan2f(y, x).to_bits());
            let half_pi = (core::f32::consts::PI / 2.0).to_bits();
            let saturated = y / x >= 67_108_864.0 && got + 1 == want && want == half_pi;
            assert!(got == want || saturated, "{y:e} {x:e}: {got:#x} {want:#x}");
        };
        let mut state = 2;
        let mut checked = 0;
        for _ in 0..200_000 {
            let (a, b) = (random(&mut state), random(&mut state));
            let (a, b) = (
                u32::try_from(a >> 33).unwrap_or(0),
                u32::try_from(b >> 33).unwrap_or(0),
            );
            let y = f32::from_bits(a);
            let x = f32::from_bits(if b & 1 == 0 { b } else { a ^ (b >> 20) });
            if y.is_finite() && x.is_finite() {
                same(y, x);
                checked += 1;
            }
        }
        let edges = [
            0.0,
            -0.0,
            f32::MIN_POSITIVE,
            1e-45,
            1e-30,
            1.0,
            1e30,
            f32::MAX,
        ];
        for y in edges.into_iter().filter(|y| *y > 0.0) {
            for x in edges {
                same(y, x);
            }
            same(0.0, y);
        }
        for x in [0.0, -0.0] {
            assert_eq!(first_quadrant(0.0_f32, x), core::f32::consts::FRAC_PI_2);
        }
        assert!(checked > 150_000, "{checked}");
    }
}

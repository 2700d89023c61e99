//! The small float trait the model is generic over, with its math backends.
//!
//! One code path serves `f32` and `f64`. The trait is sealed: the numerical choices in this
//! crate (series cut-offs, tail thresholds, tolerances: [`crate::numeric::Tuning`], which it
//! requires) are tuned for exactly these two types. `Float` itself holds float operations only.
//!
//! # Backends (by precedence, never mutually exclusive)
//! - `f64`: always [`libm`].
//! - `f32`: [`micromath`] when the `micromath` feature is on (small and fast: sqrt relative error
//!   up to 6.1 %, atan2 absolute error up to 2.1e-3 rad, measured by this module's tests; `ln_1p`
//!   still comes from libm, which micromath lacks), otherwise [`libm`] (within 1-2 ULP), but
//!   for the square root: the crate's own, correctly rounded like libm's `sqrtf` (the same
//!   bits) and without its table (288 bytes less flash on a Cortex-M4F).
//!
//! Enabling `micromath` changes `f32` results by up to the errors above; it never changes `f64`.

use core::fmt::Debug;
use core::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

use crate::numeric::tuning::sealed;

/// A floating-point type the model can run in: `f32` or `f64` (sealed).
///
/// Every function states the backend it uses in the module docs; all are total (they return
/// NaN or infinity for out-of-domain input rather than panic), and the model never calls them
/// outside their domain after a [`Scene`](crate::Scene) has been validated.
pub trait Float:
    sealed::Sealed
    + crate::numeric::tuning::Tuning
    + 'static
    + Copy
    + Debug
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
{
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// 2.
    const TWO: Self;
    /// 1/2.
    const HALF: Self;
    /// pi.
    const PI: Self;
    /// Machine epsilon.
    const EPSILON: Self;
    /// Largest finite value.
    const MAX: Self;
    /// Smallest positive normal value.
    const MIN_POSITIVE: Self;

    /// Converts an `f64` (rounds to nearest for `f32`).
    fn from_f64(x: f64) -> Self;
    /// Converts to `f64` (exact).
    fn to_f64(self) -> f64;
    /// Converts an `f32` (exact).
    fn from_f32(x: f32) -> Self;
    /// Converts a count (rounds to nearest for `f32` above 2^24).
    fn from_u32(n: u32) -> Self;

    /// |x|.
    fn abs(self) -> Self;
    /// Square root.
    fn sqrt(self) -> Self;
    /// Natural logarithm.
    fn ln(self) -> Self;
    /// ln(1 + x), accurate for small x.
    fn ln_1p(self) -> Self;
    /// ln(1 + x) / x for x > -1, x != 0, to the accuracy of [`Float::ln_1p`] (the crate takes a
    /// series for |x| < 1e-4). One division in `f32`, where `ln_1p` and the quotient would be
    /// two (Kahan's form divides already).
    #[inline]
    fn ln_1p_ratio(self) -> Self {
        self.ln_1p() / self
    }
    /// e^x.
    fn exp(self) -> Self;
    /// Arc tangent.
    fn atan(self) -> Self;
    /// Four-quadrant arc tangent of self / x.
    fn atan2(self, x: Self) -> Self;
    /// Sine.
    fn sin(self) -> Self;
    /// Cosine.
    fn cos(self) -> Self;
    /// sqrt(self^2 + y^2) without undue overflow.
    fn hypot(self, y: Self) -> Self;
    /// e^x - 1, accurate for small x (libm for both types).
    fn exp_m1(self) -> Self;
    /// Largest integer not above self.
    fn floor(self) -> Self;
    /// Smallest integer not below self.
    fn ceil(self) -> Self;
    /// `self` rounded up to a `u32`, or `None` if NaN, negative or above `u32::MAX`.
    fn ceil_u32(self) -> Option<u32>;
    /// True unless NaN or infinite.
    fn is_finite(self) -> bool;
    /// True if NaN.
    fn is_nan(self) -> bool;
    /// True if `low <= self <= high`, for bounds `0 < low <= high` that are finite: one integer
    /// comparison of the bit patterns (positive floats order as their bits do; NaN, the
    /// infinities, zeros and negative values all fall outside), where a soft-float target
    /// (AVR) would call its comparison routine twice.
    fn within_positive(self, low: Self, high: Self) -> bool;

    /// sin(x) for |x| <= pi, without range reduction: reflected into |y| <= pi/2
    /// (sin(pi - y) = sin y) and summed as a Taylor series in y^2
    /// ([`Tuning::SIN_COEFFICIENTS`](crate::numeric::Tuning::SIN_COEFFICIENTS), through the
    /// crate's one polynomial routine, outlined on bare metal). Absolute error a few ULP; no libm
    /// `sin` (whose range reduction costs ~3-7 KB of flash and does not fit the Uno). Used
    /// where the model's arguments are bounded by construction.
    #[inline]
    fn sin_within_pi(self) -> Self {
        let a = self.abs();
        let quarter = Self::PI * Self::HALF;
        let y = if a > quarter { Self::PI - a } else { a };
        let s = y + y * power_series(Self::SIN_COEFFICIENTS, y * y);
        if self < Self::ZERO {
            -s
        } else {
            s
        }
    }
    /// cos(x) for |x| <= pi: sin(pi/2 - |x|), see [`Float::sin_within_pi`].
    #[inline]
    fn cos_within_pi(self) -> Self {
        (Self::PI * Self::HALF - self.abs()).sin_within_pi()
    }
    /// The larger of two (NaN-free inputs).
    #[inline]
    fn max(self, other: Self) -> Self {
        if self > other {
            self
        } else {
            other
        }
    }
    /// The smaller of two (NaN-free inputs).
    #[inline]
    fn min(self, other: Self) -> Self {
        if self < other {
            self
        } else {
            other
        }
    }
}

/// The math backend of `f32` in this build: "micromath" or "libm" (`f64` always uses libm).
pub const F32_BACKEND: &str = if cfg!(feature = "micromath") {
    "micromath"
} else {
    "libm"
};

impl Float for f64 {
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    const TWO: Self = 2.0;
    const HALF: Self = 0.5;
    const PI: Self = core::f64::consts::PI;
    const EPSILON: Self = f64::EPSILON;
    const MAX: Self = f64::MAX;
    const MIN_POSITIVE: Self = f64::MIN_POSITIVE;

    #[inline]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self
    }
    #[inline]
    fn from_f32(x: f32) -> Self {
        f64::from(x)
    }
    #[inline]
    fn from_u32(n: u32) -> Self {
        f64::from(n)
    }
    #[inline]
    fn abs(self) -> Self {
        libm::fabs(self)
    }
    #[inline]
    fn sqrt(self) -> Self {
        libm::sqrt(self)
    }
    #[inline]
    fn ln(self) -> Self {
        libm::log(self)
    }
    #[inline]
    fn ln_1p(self) -> Self {
        libm::log1p(self)
    }
    #[inline]
    fn exp(self) -> Self {
        libm::exp(self)
    }
    #[inline]
    fn atan(self) -> Self {
        libm::atan(self)
    }
    #[inline]
    fn atan2(self, x: Self) -> Self {
        libm::atan2(self, x)
    }
    #[inline]
    fn sin(self) -> Self {
        libm::sin(self)
    }
    #[inline]
    fn cos(self) -> Self {
        libm::cos(self)
    }
    #[inline]
    fn hypot(self, y: Self) -> Self {
        libm::hypot(self, y)
    }
    #[inline]
    fn exp_m1(self) -> Self {
        libm::expm1(self)
    }
    #[inline]
    fn floor(self) -> Self {
        libm::floor(self)
    }
    #[inline]
    fn ceil(self) -> Self {
        libm::ceil(self)
    }
    fn ceil_u32(self) -> Option<u32> {
        let up = libm::ceil(self);
        if up >= 0.0 && up <= f64::from(u32::MAX) {
            // In range and integral: the conversion is exact.
            #[allow(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                clippy::as_conversions
            )]
            let n = up as u32;
            Some(n)
        } else {
            None
        }
    }
    #[inline]
    fn is_finite(self) -> bool {
        f64::is_finite(self)
    }
    #[inline]
    fn is_nan(self) -> bool {
        f64::is_nan(self)
    }
    #[inline]
    fn within_positive(self, low: Self, high: Self) -> bool {
        (low.to_bits()..=high.to_bits()).contains(&self.to_bits())
    }
}

/// Calls micromath when the feature is on, libm otherwise.
macro_rules! f32_backend {
    ($micromath:ident, $libm:ident $(, $arg:expr)*) => {{
        #[cfg(feature = "micromath")]
        {
            micromath::F32Ext::$micromath($($arg),*)
        }
        #[cfg(not(feature = "micromath"))]
        {
            libm::$libm($($arg),*)
        }
    }};
}

impl Float for f32 {
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    const TWO: Self = 2.0;
    const HALF: Self = 0.5;
    const PI: Self = core::f32::consts::PI;
    const EPSILON: Self = f32::EPSILON;
    const MAX: Self = f32::MAX;
    const MIN_POSITIVE: Self = f32::MIN_POSITIVE;

    #[inline]
    fn from_f64(x: f64) -> Self {
        #[allow(clippy::cast_possible_truncation, clippy::as_conversions)]
        let narrowed = x as f32;
        narrowed
    }
    #[inline]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    #[inline]
    fn from_f32(x: f32) -> Self {
        x
    }
    #[inline]
    fn from_u32(n: u32) -> Self {
        #[allow(clippy::cast_precision_loss, clippy::as_conversions)]
        let rounded = n as f32;
        rounded
    }
    #[inline]
    fn abs(self) -> Self {
        libm::fabsf(self)
    }
    #[inline]
    fn sqrt(self) -> Self {
        #[cfg(feature = "micromath")]
        {
            micromath::F32Ext::sqrt(self)
        }
        #[cfg(all(not(feature = "micromath"), target_arch = "avr"))]
        {
            core::f32::math::sqrt(self)
        }
        #[cfg(all(
            not(feature = "micromath"),
            not(target_arch = "avr"),
            target_os = "none"
        ))]
        {
            sqrt_f32(self)
        }
        // Hosts: libm's, the same correctly rounded value, by the instruction where the host
        // has one.
        #[cfg(all(not(feature = "micromath"), not(target_os = "none")))]
        {
            libm::sqrtf(self)
        }
    }
    #[inline]
    fn ln(self) -> Self {
        f32_backend!(ln, logf, self)
    }
    #[inline]
    fn ln_1p(self) -> Self {
        // (micromath's ln is too coarse near 1 for Kahan's form: its own log1pf then.)
        #[cfg(feature = "micromath")]
        {
            libm::log1pf(self)
        }
        #[cfg(not(feature = "micromath"))]
        {
            ln_1p_f32(self)
        }
    }
    #[cfg(not(feature = "micromath"))]
    #[inline]
    fn ln_1p_ratio(self) -> Self {
        // Kahan's form: with u = 1 + x rounded, ln(u) / (u - 1) is ln(1 + y) / y at y = u - 1
        // (exact), and ln(1 + y) / y changes slowly: within 3 ULP of f64's log1p(x) / x, as
        // the two-division form (tested below).
        let u = 1.0 + self;
        if u == 1.0 {
            1.0
        } else {
            libm::logf(u) / (u - 1.0)
        }
    }
    #[inline]
    fn exp(self) -> Self {
        f32_backend!(exp, expf, self)
    }
    #[inline]
    fn atan(self) -> Self {
        f32_backend!(atan, atanf, self)
    }
    #[inline]
    fn atan2(self, x: Self) -> Self {
        f32_backend!(atan2, atan2f, self, x)
    }
    #[inline]
    fn sin(self) -> Self {
        f32_backend!(sin, sinf, self)
    }
    #[inline]
    fn cos(self) -> Self {
        f32_backend!(cos, cosf, self)
    }
    /// With libm: |big| sqrt(1 + (small/big)^2), within 2 ULP and without overflow (libm's
    /// hypotf works in f64, which drags soft-float f64 routines into f32 firmware).
    #[inline]
    fn hypot(self, y: Self) -> Self {
        #[cfg(feature = "micromath")]
        {
            micromath::F32Ext::hypot(self, y)
        }
        #[cfg(not(feature = "micromath"))]
        {
            let (a, b) = (libm::fabsf(self), libm::fabsf(y));
            let (big, small) = if a >= b { (a, b) } else { (b, a) };
            if big == 0.0 || !big.is_finite() {
                return big + small;
            }
            let ratio = small / big;
            big * libm::sqrtf(1.0 + ratio * ratio)
        }
    }
    #[inline]
    fn exp_m1(self) -> Self {
        // (Beyond |x| = 1/2 e^x - 1 carries exp's error, which micromath's is too coarse for:
        // libm's expm1f then.)
        #[cfg(feature = "micromath")]
        {
            libm::expm1f(self)
        }
        #[cfg(not(feature = "micromath"))]
        {
            exp_m1_f32(self)
        }
    }
    #[inline]
    fn floor(self) -> Self {
        libm::floorf(self)
    }
    #[inline]
    fn ceil(self) -> Self {
        libm::ceilf(self)
    }
    fn ceil_u32(self) -> Option<u32> {
        // 4_294_967_040 = 2^32 - 256 is the largest f32 not above u32::MAX; above -1 the
        // ceiling is 0 or more. (NaN fails both.)
        if self > -1.0 && self <= 4_294_967_040.0 {
            // Truncated toward zero (-0.x to 0): exact, as every f32 at or above 2^23 is an
            // integer. Below 2^24 the truncation converts back exactly, so the comparison
            // says whether a fraction was cut; above, there is none. No `ceilf` linked.
            #[allow(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                clippy::as_conversions
            )]
            let n = self as u32;
            #[allow(clippy::cast_precision_loss, clippy::as_conversions)]
            let cut = (n as f32) < self;
            Some(n + u32::from(cut))
        } else {
            None
        }
    }
    #[inline]
    fn is_finite(self) -> bool {
        f32::is_finite(self)
    }
    #[inline]
    fn is_nan(self) -> bool {
        f32::is_nan(self)
    }
    #[inline]
    fn within_positive(self, low: Self, high: Self) -> bool {
        (low.to_bits()..=high.to_bits()).contains(&self.to_bits())
    }
}

/// The square root of an `f32`, correctly rounded (the IEEE result, which libm's `sqrtf` also
/// gives: tested equal over two whole binades and the subnormals), by digit-by-digit extraction
/// of the significand in 32-bit integers: 24 steps of a compare, a subtraction and shifts, no
/// table and no division. libm's `sqrtf` linked 480 bytes with its table on a Cortex-M4F, where
/// `core` offers no way to the FPU's square root without `unsafe`.
///
/// Negative numbers and NaN give NaN; +-0 and +inf give themselves. On AVR (a nightly target)
/// the square root goes through `core::f32::math::sqrt` instead: a call to `sqrtf`, which
/// `.cargo/config.toml`'s flags resolve to avr-libc's assembly (140 bytes; `scripts/uno.sh`
/// checks that the Uno prints the host's lines). avr-libc has no `floorf` or `ceilf` (only
/// `floor` and `ceil`), so floor and ceiling stay libm's. Hosts take libm's `sqrtf`, the same
/// value by the instruction where there is one: these 24 steps made the closed tier in `f32`
/// slower on x86-64 than in `f64`. Built on hosts for the tests that hold it to `sqrtf`.
#[cfg(all(
    not(feature = "micromath"),
    not(target_arch = "avr"),
    any(test, target_os = "none")
))]
fn sqrt_f32(x: f32) -> f32 {
    if x.is_nan() || x < 0.0 {
        return f32::NAN;
    }
    if x == 0.0 || x == f32::INFINITY {
        return x;
    }
    let bits = x.to_bits();
    // x = significand 2^k with the significand in [2^23, 2^24) (subnormals normalised).
    let mut significand = bits & 0x007f_ffff;
    let biased = i32::try_from(bits >> 23).unwrap_or(0);
    let mut k = if biased == 0 {
        let shift = significand.leading_zeros() - 8;
        significand <<= shift;
        1 - i32::try_from(shift).unwrap_or(0) - 150
    } else {
        significand |= 0x0080_0000;
        biased - 150
    };
    // An odd k, so that x = n 2^(k - 23) with k - 23 even and n = significand 2^23 in
    // [2^46, 2^48): its root has exactly 24 bits.
    if k % 2 == 0 {
        significand <<= 1;
        k -= 1;
    }
    // The root of n = significand 2^23 (< 2^48), two bits of n per step from the top: the
    // remainder n' - root^2 of the bits taken so far stays below 2^27, so it all fits in u32
    // (n's low 16 bits are zeros: the source runs dry after 16 steps).
    let mut source = significand << 7;
    let (mut root, mut remainder) = (0_u32, 0_u32);
    for _ in 0..24 {
        remainder = (remainder << 2) | (source >> 30);
        source <<= 2;
        let trial = (root << 2) | 1;
        root <<= 1;
        if remainder >= trial {
            remainder -= trial;
            root |= 1;
        }
    }
    // Round to nearest: up when sqrt(n) > root + 1/2, i.e. n - root^2 > root (no ties: the
    // square of a half-integer is not an integer). A carry out of 24 bits moves the exponent.
    if remainder > root {
        root += 1;
    }
    let exponent = u32::try_from((k - 23) / 2 + 150).unwrap_or(0);
    f32::from_bits((exponent << 23) + (root - 0x0080_0000))
}

/// ln(1 + x) for `f32` from the backend's `ln` alone (Kahan): with u = 1 + x rounded,
/// ln(u) x / (u - 1) is exact to the accuracy of `ln` however small x is (the rounding of u
/// cancels between ln(u) and u - 1), so libm's `log1pf` is not linked beside `logf`. Within
/// 2 ULP of libm's `log1pf` (tested over x from 1e-30 to 1e30 and down to -1).
#[cfg(not(feature = "micromath"))]
fn ln_1p_f32(x: f32) -> f32 {
    let u = 1.0 + x;
    if u == 1.0 {
        x
    } else if u == f32::INFINITY {
        u
    } else {
        libm::logf(u) * (x / (u - 1.0))
    }
}

/// (e^x, e^x - 1), each to its own relative accuracy: e^x - 1 from its Taylor series where
/// |x| <= 1/2 ([`power_series`] of [`Tuning::EXP_COEFFICIENTS`](crate::numeric::Tuning), and e^x
/// is then at least 0.6, so adding 1 keeps its digits), from `exp` beyond (where e^x - 1 is at
/// least 0.39 in size, so the subtraction keeps its digits). No `expm1` is linked for it: the
/// exact tier's flights take both (1 + expm1(x) for e^x lost eps / e^x of it: 20 epsilons at
/// e^x = 0.05), and f32's [`Float::exp_m1`] is its second half.
pub(crate) fn exp_and_m1<F: Float>(x: F) -> (F, F) {
    if x.abs() <= F::HALF {
        let m = power_series(F::EXP_COEFFICIENTS, x);
        (F::ONE + m, m)
    } else {
        let e = x.exp();
        (e, e - F::ONE)
    }
}

/// e^x - 1 for `f32`, as [`exp_and_m1`] gives it: libm's `expf` beyond |x| = 1/2, so that
/// libm's `expm1f` (several hundred bytes) is not linked beside it. Within 2 ULP of f64's
/// `expm1` rounded to f32, where `expm1f` is within 1 (tested over |x| from 1e-30 to 88).
#[cfg(not(feature = "micromath"))]
fn exp_m1_f32(x: f32) -> f32 {
    exp_and_m1(x).1
}

/// sum_m c_m x^m, m from 1, of `coefficients` (c_1 first), by Horner's rule, on bare metal
/// (`target_os = "none"`: Cortex-M, AVR). Outlined there, where flash is short and, on AVR,
/// each float operation is a call: the sine's, e^x - 1's and the exact tier's series then share
/// one copy (the Uno's exact-tier firmware has little room to spare). There the fewest
/// operations win: the split below costs a few more multiplications and an unrolled copy per
/// call site.
#[cfg(target_os = "none")]
#[inline(never)]
pub(crate) fn power_series<F: Float>(coefficients: &[F], x: F) -> F {
    coefficients
        .iter()
        .rev()
        .fold(F::ZERO, |s, coefficient| (s + *coefficient) * x)
}

/// sum_m c_m x^m, m from 1, of `coefficients` (c_1 first), on hosts: four Horner chains in x^4
/// (the coefficients of x^(4j + 1), x^(4j + 2), ...) that run side by side, joined at the end.
/// An out-of-order core waits on each step of a single chain (an add and a multiply, about 8
/// cycles on x86-64 without FMA); the exact tier's flights are such chains end to end (the
/// tail's 12-term flight, e^x - 1's 15 terms): split four ways the catalogue's exact
/// predictions took 13 % less time in f64 for 5 % more instructions (paired runs). The chains'
/// sums are joined by Horner's rule, leading terms last, as a single chain ends: the same values
/// to an ULP or two (joined pairwise, f32's e^x - 1 was 3 ULP from f64's, where the test allows
/// 2). Always inlined: each call site's table is then unrolled.
#[cfg(not(target_os = "none"))]
#[inline(always)]
#[allow(clippy::inline_always)] // measured: see above
pub(crate) fn power_series<F: Float>(coefficients: &[F], x: F) -> F {
    let x2 = x * x;
    let x4 = x2 * x2;
    let (p1, p2, p3, p4) = coefficients.chunks(4).rev().fold(
        (F::ZERO, F::ZERO, F::ZERO, F::ZERO),
        |(a, b, c, d), four| {
            let mut next = four.iter().copied();
            let mut term = || next.next().unwrap_or(F::ZERO);
            (
                a * x4 + term(),
                b * x4 + term(),
                c * x4 + term(),
                d * x4 + term(),
            )
        },
    );
    x * (p1 + x * (p2 + x * (p3 + x * p4)))
}

/// ln(1 + z) / z for z > -1, accurate as z -> 0 (series below |z| = 1e-4).
pub(crate) fn ln1p_ratio<F: Float>(z: F) -> F {
    if z.abs() < F::from_f64(1e-4) {
        F::ONE - z * (F::HALF - z * (F::ONE / F::from_f64(3.0) - z / F::from_f64(4.0)))
    } else {
        z.ln_1p_ratio()
    }
}

/// s ln(1 + k s) / (k s) for k >= 0, s > 0 (a closed-form fall time): accurate as k s -> 0
/// (series) and finite when k s overflows (ln(k s) = ln k + ln s).
pub(crate) fn log_growth<F: Float>(s: F, k: F) -> F {
    if k <= F::ZERO {
        return s;
    }
    let z = k * s;
    if z.is_finite() {
        s * ln1p_ratio(z)
    } else {
        (k.ln() + s.ln()) / k
    }
}

/// [`log_growth`] of s = `num / den` (both > 0), still finite where that ratio overflows
/// (ln s = ln num - ln den): f32, j0 / r with r = 4e-10 and v0 = 1e30 overflowed, and t_b1v
/// became `Never` where it is 3.3 s.
pub(crate) fn log_growth_of_ratio<F: Float>(num: F, den: F, k: F) -> F {
    let s = num / den;
    if s.is_finite() || k <= F::ZERO {
        log_growth(s, k)
    } else {
        (k.ln() + num.ln() - den.ln()) / k
    }
}

#[cfg(test)]
mod tests {
    #[cfg(not(feature = "micromath"))]
    use super::sqrt_f32;
    use super::Float;

    /// The f32 backend's sqrt and atan2 against f64 libm over a log sweep of magnitudes and
    /// every quadrant: the figures the module docs state (micromath is approximate; libm within
    /// an ULP or two).
    #[test]
    fn the_f32_backend_is_as_accurate_as_documented() {
        let (mut sqrt_rel, mut atan2_abs) = (0.0_f64, 0.0_f64);
        for i in 0..=4000 {
            let x = 10_f64.powf(-30.0 + 60.0 * f64::from(i) / 4000.0);
            let xf = f32::from_f64(x);
            let exact = libm::sqrt(f64::from(xf));
            sqrt_rel = sqrt_rel.max((f64::from(Float::sqrt(xf)) - exact).abs() / exact);
            for k in 0..16 {
                let angle = core::f64::consts::PI * (f64::from(k) / 8.0 - 1.0) + 1e-3;
                let (y, x) = (
                    f32::from_f64(libm::sin(angle)),
                    f32::from_f64(libm::cos(angle)),
                );
                let exact = libm::atan2(f64::from(y), f64::from(x));
                atan2_abs = atan2_abs.max((f64::from(Float::atan2(y, x)) - exact).abs());
            }
        }
        let (sqrt_bound, atan2_bound) = if cfg!(feature = "micromath") {
            (0.065, 3e-3)
        } else {
            (2.0 * f64::from(f32::EPSILON), 4.0 * f64::from(f32::EPSILON))
        };
        assert!(sqrt_rel < sqrt_bound, "sqrt relative error {sqrt_rel:e}");
        assert!(
            atan2_abs < atan2_bound,
            "atan2 absolute error {atan2_abs:e}"
        );
    }

    #[test]
    fn bounded_sine_and_cosine_match_libm() {
        let mut worst = (0.0_f64, 0.0_f32);
        for i in -2000..=2000 {
            let x = f64::from(i) / 2000.0 * core::f64::consts::PI;
            worst.0 = worst
                .0
                .max((x.sin_within_pi() - libm::sin(x)).abs())
                .max((x.cos_within_pi() - libm::cos(x)).abs());
            let y = f32::from_f64(x);
            worst.1 = worst
                .1
                .max((y.sin_within_pi() - libm::sinf(y)).abs())
                .max((y.cos_within_pi() - libm::cosf(y)).abs());
        }
        // A few ULP of 1.
        assert!(worst.0 < 4.0 * f64::EPSILON, "f64 {}", worst.0);
        assert!(worst.1 < 4.0 * f32::EPSILON, "f32 {}", worst.1);
        // Relative accuracy near 0, where the viscous loss needs it.
        for x in [1e-30_f64, 1e-8, 1e-3, 0.05] {
            assert!((x.sin_within_pi() / libm::sin(x) - 1.0).abs() < 2.0 * f64::EPSILON);
        }
    }

    #[test]
    fn native_f32_hypot_is_close_and_does_not_overflow() {
        for (a, b) in [
            (3.0_f32, 4.0),
            (1e30, 1e30),
            (1e-30, 3e-31),
            (0.0, 0.0),
            (0.0, -2.0),
        ] {
            let exact = libm::hypot(f64::from(a), f64::from(b));
            let ours = f64::from(a.hypot(b));
            assert!(
                (ours - exact).abs() <= 2.5 * f64::from(f32::EPSILON) * exact,
                "{a} {b}"
            );
        }
    }

    #[test]
    fn ceil_u32_is_checked() {
        assert_eq!(2.1_f32.ceil_u32(), Some(3));
        assert_eq!(0.0_f64.ceil_u32(), Some(0));
        assert_eq!(4_294_967_295.0_f64.ceil_u32(), Some(u32::MAX));
        assert_eq!(4_294_967_295.5_f64.ceil_u32(), None);
        assert_eq!(5e9_f32.ceil_u32(), None);
        assert_eq!((-1.0_f32).ceil_u32(), None);
        assert_eq!(f64::NAN.ceil_u32(), None);
    }

    /// The f32 ceiling without `ceilf` is libm's `ceilf` converted, with the same range: on
    /// every 7th f32 from -1 to 2^25 (every binade, fractions and all), on the integers and
    /// halves below 2^24 and their neighbours, at the ends of the range and on NaN and the
    /// infinities.
    #[test]
    fn the_f32_ceiling_to_u32_is_ceilfs() {
        let reference = |x: f32| {
            let up = libm::ceilf(x);
            #[allow(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                clippy::as_conversions
            )]
            (0.0..=4_294_967_040.0).contains(&up).then_some(up as u32)
        };
        let check = |x: f32| assert_eq!(x.ceil_u32(), reference(x), "{x:e}");
        // -0 to -1, and +0 to 2^25.
        (0x8000_0000_u32..=0xbf80_0000)
            .step_by(7)
            .for_each(|b| check(f32::from_bits(b)));
        (0_u32..=0x4c00_0000)
            .step_by(7)
            .for_each(|b| check(f32::from_bits(b)));
        for k in (0..16_777_216_u32).step_by(251) {
            #[allow(clippy::cast_precision_loss, clippy::as_conversions)]
            let x = k as f32;
            for y in [x, x + 0.5] {
                check(y);
                check(f32::from_bits(y.to_bits() + 1));
                if y > 0.0 {
                    check(f32::from_bits(y.to_bits() - 1));
                }
            }
        }
        for x in [
            -1.0_f32,
            -0.999_999_9,
            -0.5,
            -0.0,
            0.0,
            1e-45,
            0.5,
            1.0,
            8_388_607.5,
            8_388_608.0,
            16_777_215.0,
            16_777_216.0,
            4_294_967_040.0,
            4_294_967_296.0,
            f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ] {
            check(x);
        }
    }

    #[cfg(not(feature = "micromath"))]
    #[test]
    fn the_f32_square_root_is_libms_correctly_rounded_one() {
        // Every f32 of [1, 4) (two binades: both parities of the exponent, which is all the
        // digit extraction sees of it), every 7th subnormal, and the edges.
        let mut checked = 0_u32;
        for bits in 0x3f80_0000_u32..0x4080_0000 {
            let x = f32::from_bits(bits);
            assert_eq!(sqrt_f32(x).to_bits(), libm::sqrtf(x).to_bits(), "{x:e}");
            checked += 1;
        }
        for bits in (1_u32..0x0080_0000).step_by(7) {
            let x = f32::from_bits(bits);
            assert_eq!(sqrt_f32(x).to_bits(), libm::sqrtf(x).to_bits(), "{x:e}");
        }
        for x in [f32::MIN_POSITIVE, f32::MAX, 1e-45, 3e38, 0.25, 1e30, 7e-20] {
            assert_eq!(sqrt_f32(x).to_bits(), libm::sqrtf(x).to_bits(), "{x:e}");
        }
        assert_eq!(checked, 1 << 24);
        assert!(sqrt_f32(-1.0).is_nan() && sqrt_f32(f32::NAN).is_nan());
        assert_eq!(sqrt_f32(-0.0).to_bits(), (-0.0_f32).to_bits());
        assert_eq!(sqrt_f32(0.0), 0.0);
        assert_eq!(sqrt_f32(f32::INFINITY), f32::INFINITY);
        assert!(sqrt_f32(f32::NEG_INFINITY).is_nan());
    }

    #[cfg(not(feature = "micromath"))]
    #[test]
    fn the_f32_ln_1p_is_within_two_ulp_of_libms() {
        extern crate std;
        // (Both of one sign here: the distance of their bit patterns counts the ULP between.)
        let ulps = |a: f32, b: f32| a.to_bits().abs_diff(b.to_bits());
        let mut worst = 0;
        let mut x = 1e-30_f32;
        while x < 1e30 {
            for v in [x, -x.min(1.0)] {
                let d = ulps(super::ln_1p_f32(v), libm::log1pf(v));
                worst = worst.max(d);
            }
            x *= 1.0001;
        }
        std::eprintln!("ln_1p_f32: worst {worst} ULP from log1pf");
        assert!(worst <= 2, "{worst} ULP");
        assert_eq!(super::ln_1p_f32(0.0), 0.0);
        assert_eq!(super::ln_1p_f32(-1.0), f32::NEG_INFINITY);
        assert_eq!(super::ln_1p_f32(f32::INFINITY), f32::INFINITY);
        assert!(super::ln_1p_f32(-2.0).is_nan() && super::ln_1p_f32(f32::NAN).is_nan());
    }

    #[cfg(not(feature = "micromath"))]
    #[test]
    fn the_f32_exp_m1_is_within_two_ulp_of_f64s() {
        extern crate std;
        let ulps = |a: f32, b: f32| a.to_bits().abs_diff(b.to_bits());
        let (mut worst, mut libm_worst) = (0, 0);
        let mut x = 1e-30_f32;
        while x < 88.0 {
            for v in [x, -x] {
                #[allow(clippy::cast_possible_truncation, clippy::as_conversions)]
                let reference = libm::expm1(f64::from(v)) as f32;
                let d = ulps(super::exp_m1_f32(v), reference);
                worst = worst.max(d);
                libm_worst = libm_worst.max(ulps(libm::expm1f(v), reference));
            }
            x *= 1.0001;
        }
        std::eprintln!("exp_m1_f32: worst {worst} ULP from expm1; expm1f {libm_worst}");
        assert!(worst <= 2, "{worst} ULP");
        assert_eq!(super::exp_m1_f32(0.0), 0.0);
        assert_eq!(super::exp_m1_f32(-200.0), -1.0);
        assert_eq!(super::exp_m1_f32(f32::INFINITY), f32::INFINITY);
        assert!(super::exp_m1_f32(f32::NAN).is_nan());
    }

    /// The one-division ratio ln(1 + x) / x of f32 against f64's log1p(x) / x rounded to f32,
    /// over x from 1e-30 to 1e30 and down to -1 + 2^-24: within 3 ULP (of the ratio), as the
    /// two-division `ln_1p(x) / x` it replaces (measured: 3 for both).
    #[cfg(not(feature = "micromath"))]
    #[test]
    fn the_f32_ln_1p_ratio_is_as_accurate_as_ln_1p_over_x() {
        extern crate std;
        let ulps = |a: f32, b: f32| a.to_bits().abs_diff(b.to_bits());
        let reference = |v: f32| f32::from_f64(libm::log1p(f64::from(v)) / f64::from(v));
        let (mut worst, mut old) = (0, 0);
        let mut x = 1e-30_f32;
        while x < 1e30 {
            for v in [x, -x.min(1.0 - f32::EPSILON / 2.0)] {
                worst = worst.max(ulps(Float::ln_1p_ratio(v), reference(v)));
                old = old.max(ulps(super::ln_1p_f32(v) / v, reference(v)));
            }
            x *= 1.0001;
        }
        std::eprintln!("ln_1p_ratio (f32): worst {worst} ULP; ln_1p / x: {old}");
        assert!(worst <= 3 && worst <= old, "{worst} ULP against {old}");
    }

    /// The bit comparison of `within_positive` is the float comparison, for every class of
    /// value (zeros, subnormals, normals, infinities, NaN, both signs) against bounds from the
    /// smallest subnormal to the largest finite value.
    #[test]
    fn within_positive_is_the_comparison_of_the_values() {
        extern crate std;
        let mut values = std::vec::Vec::new();
        for bits in (0_u32..=u32::MAX).step_by(65_521) {
            values.push(f32::from_bits(bits));
        }
        values.extend([
            0.0,
            -0.0,
            1e-45,
            -1e-45,
            1e-30,
            1e30,
            f32::MAX,
            f32::MIN_POSITIVE,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            -f32::NAN,
            1.0,
            -1.0,
        ]);
        let bounds = [
            (1e-45, f32::MAX),
            (1e-30, 1e30),
            (f32::MIN_POSITIVE, f32::MAX),
            (1.0, 1.0),
        ];
        for (low, high) in bounds {
            for &x in &values {
                assert_eq!(x.within_positive(low, high), low <= x && x <= high, "{x:e}");
                let (x, low, high) = (f64::from(x), f64::from(low), f64::from(high));
                assert_eq!(x.within_positive(low, high), low <= x && x <= high, "{x:e}");
            }
        }
    }
}

//! The model's numerical choices for each float: where a series takes over from a closed form
//! that cancels, where a small-impulse tail is exact to rounding, what error the math backend
//! adds, and the tables (Gauss-Legendre rules, the flight series) in the float's own precision,
//! narrowed from `f64` at compile time. Not float operations ([`crate::Float`] has those, and
//! requires this trait); sealed like it: only `f32` and `f64` implement it.

use crate::numeric::quadrature::table;
use crate::Nodes;
use sealed::Sealed;

/// The two floats the crate is tuned for, and so the only ones [`Tuning`] and
/// [`Float`](crate::Float) can be.
pub(crate) mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}

/// The per-precision constants and tables the model is tuned with (see the module docs).
pub trait Tuning: Sealed + Sized + 'static {
    /// Below this |y| the model evaluates 1 - sin(y)/y by its Taylor series (docs/physics.md
    /// sec. 3: 0.05 in f64, 0.5 in f32), where the direct form cancels.
    const SINC_SERIES_LIMIT: Self;
    /// A relative size below which an asymptotic small-impulse tail is exact to rounding
    /// (about the cube root of epsilon: 6e-6 in f64, 5e-3 in f32).
    const TAIL_CUTOFF: Self;
    /// Where the map and the averaged tier leave a scene that dissipates between impacts to
    /// the small-impulse asymptote on the way to J = 0, relative to Omega |Delta|: 5e-3 in both
    /// floats. The asymptote leaves out terms of relative size zeta J and J^2 (in units of
    /// Omega |Delta|) of that tail, a few 1e-4 of it at most there, a tenth of the map's
    /// smallest figure (0.3 %) and of the averaged tier's with damping (1 %); on the catalogue's
    /// switches the averaged tier's end moves by 8e-10 to 1e-8 of itself. f64's
    /// [`TAIL_CUTOFF`](Tuning::TAIL_CUTOFF), exact to rounding, walked some 20 more impacts of
    /// the map (the catalogue's maps then took longer than the exact tier) and integrated 7
    /// more units of ln J (14 panels) of the averaged tier (2.4 times its time on the tactile
    /// dome) for nothing either tier's own error would show. A scene that loses nothing
    /// between impacts keeps `TAIL_CUTOFF`: its map is exact, and its averaged tier is the
    /// closed form of the restitution-only lean path.
    #[doc(hidden)]
    const DAMPED_TAIL_CUTOFF: Self;
    /// The departure speed, in units of Omega |Delta|, below which a preloaded flight (damping
    /// ratio <= 1) is its power series in the departure, to rounding: the series' truncation,
    /// (2.2 eps)^13 / eps of the flight (tested in `tiers/exact/tail.rs`), is then below epsilon:
    /// 0.02 in f64, 0.1 in f32. Below it the exact tier solves no root: it walks a Zeno
    /// tail's flights by their series to where the tail's own series is summed.
    const SERIES_EXACT_DEPARTURE: Self;
    /// The smallest positive subnormal number (a bit pattern of 1), as a constant: no
    /// arithmetic that a flush-to-zero target could round to 0.
    #[doc(hidden)]
    const SMALLEST_SUBNORMAL: Self;
    /// The departure speed, in units of Omega |Delta|, above which the exact tier does not try
    /// a Zeno tail's series (its 8-term sum and the size of its last terms, before each
    /// flight): 0.02 in f64, where the truncation (about (2.2 eps)^8 of the tail, 1e-11 at
    /// 0.02) passes only in a bounce some 5e4 times longer than its tail, which the flights solved
    /// instead keep exact (the catalogue's predictions the same to the bit, 4-10 % fewer
    /// instructions on x86-64); 0.25 in f32 (the series' reach: always tried), where a tail near
    /// R = 1 is taken above 0.1 (the dome at R = 0.95 took 1.7 times the Cortex-M4F
    /// instructions without it).
    #[doc(hidden)]
    const TAIL_TRIED_BELOW: Self;
    /// The relative error the math backend can add to a prediction: 0 for libm (its 1-2 ULP
    /// are below the model's own errors), 0.15 for micromath (`f32` only; measured on the
    /// host-tests sweep: its atan2 error of ~3e-3 rad is a large relative error of small
    /// phases).
    const BACKEND_ERROR: f64;
    /// The Taylor coefficients (-1)^k / (2k + 1)!, k = 1, 2, ..., of
    /// [`Float::sin_within_pi`](crate::Float::sin_within_pi), summed as a power series in x^2: 10
    /// in f64 (truncation below 1e-18 at pi/2), 6 in f32 (below 4e-10). One multiplication and
    /// one addition a term, no division.
    const SIN_COEFFICIENTS: &'static [Self];
    /// Whether the exact tier's under-damped flights shorter than 0.5 / Omega take the closed
    /// form (down to 2 zeta / Omega) rather than their Taylor series: in f64, where it takes
    /// fewer instructions; not in f32, where its return speed came out 0.45 epsilon low on
    /// average over a flight (the series' 0.02), which an endless bounce's 10^5 flights
    /// compounded into 1.4e-3 of its time (6e-6 with the series; host-tests `extremes`,
    /// `the_f32_exact_tier_does_not_drift_over_many_flights`).
    #[doc(hidden)]
    const SHORT_FLIGHTS_CLOSED: bool;
    /// The Taylor coefficients 1 / m!, m = 1, 2, ..., of e^x - 1 for |x| <= 1/2 (the exact
    /// tier's flights, and f32's [`Float::exp_m1`](crate::Float::exp_m1)): 15 in f64, 8 in f32
    /// (truncation below a tenth of an epsilon of the sum at |x| = 1/2).
    #[doc(hidden)]
    const EXP_COEFFICIENTS: &'static [Self];
    /// 1 / ((k + 1) k), k = 0, 1, ... (the first unused): the recurrence of the exact tier's
    /// Taylor series of a short flight, in this float (converting an `f64` table term by term
    /// linked a soft-float conversion, 838 bytes on the Uno, and ran it every term).
    #[doc(hidden)]
    const TAYLOR_RECIPROCALS: &'static [Self];
    /// A preloaded flight's duration and return speed as series in the departure speed, in
    /// this float (the exact tier's Zeno tail; packed as `exact::flight_series` says).
    #[doc(hidden)]
    const FLIGHT_SERIES: (&'static [Self], &'static [Self]);
    /// The Gauss-Legendre rule of `n` points (n in 2, 4, 6, 8, 10, 12, 16, 20), positive half.
    fn gauss_legendre_half(n: Nodes) -> &'static [(Self, Self)];
}

/// An `f64` constant rounded to the nearest `f32` (the intent of every narrowing below).
#[allow(clippy::cast_possible_truncation, clippy::as_conversions)]
const fn round_to_f32(x: f64) -> f32 {
    x as f32
}

/// Converts an `f64` table to `f32` at compile time.
const fn narrow<const N: usize>(wide: [(f64, f64); N]) -> [(f32, f32); N] {
    let mut out = [(0.0f32, 0.0f32); N];
    let mut i = 0;
    while i < N {
        // `i < N` bounds the index (const fn: no `get` on arrays in const context).
        #[allow(clippy::indexing_slicing)]
        {
            out[i] = (round_to_f32(wide[i].0), round_to_f32(wide[i].1));
        }
        i += 1;
    }
    out
}

const fn same<const N: usize>(wide: [(f64, f64); N]) -> [(f64, f64); N] {
    wide
}

/// A table of f64 constants rounded to f32 at compile time.
const fn narrow_all<const N: usize>(wide: [f64; N]) -> [f32; N] {
    let mut out = [0.0f32; N];
    let mut i = 0;
    while i < N {
        #[allow(clippy::indexing_slicing)] // i < N
        {
            out[i] = round_to_f32(wide[i]);
        }
        i += 1;
    }
    out
}

macro_rules! select_rule {
    ($n:expr, $ty:ty, $conv:path) => {{
        match $n {
            crate::Nodes::N2 => {
                const R: &[($ty, $ty)] = &$conv(table::GL2);
                R
            }
            crate::Nodes::N4 => {
                const R: &[($ty, $ty)] = &$conv(table::GL4);
                R
            }
            crate::Nodes::N6 => {
                const R: &[($ty, $ty)] = &$conv(table::GL6);
                R
            }
            crate::Nodes::N8 => {
                const R: &[($ty, $ty)] = &$conv(table::GL8);
                R
            }
            crate::Nodes::N10 => {
                const R: &[($ty, $ty)] = &$conv(table::GL10);
                R
            }
            crate::Nodes::N12 => {
                const R: &[($ty, $ty)] = &$conv(table::GL12);
                R
            }
            crate::Nodes::N16 => {
                const R: &[($ty, $ty)] = &$conv(table::GL16);
                R
            }
            crate::Nodes::N20 => {
                const R: &[($ty, $ty)] = &$conv(table::GL20);
                R
            }
        }
    }};
}

/// (-1)^k / (2k + 1)! for k = 1..=N: the sine's Taylor coefficients after the first, each found
/// from the one before by one division in f64 (k roundings at most, far below what the terms
/// add to a sum).
const fn sin_coefficients<const N: usize>() -> [f64; N] {
    let mut out = [0.0; N];
    let mut coefficient = 1.0;
    let mut k = 0;
    while k < N {
        // (2k + 2)(2k + 3) for the k-th entry (k from 0): exact in f64.
        #[allow(clippy::cast_precision_loss, clippy::as_conversions)]
        let denominator = ((2 * k + 2) * (2 * k + 3)) as f64;
        coefficient = -coefficient / denominator;
        #[allow(clippy::indexing_slicing)] // k < N
        {
            out[k] = coefficient;
        }
        k += 1;
    }
    out
}

/// 1 / m! for m = 1..=N, each from the one before by one division in f64.
const fn exp_coefficients<const N: usize>() -> [f64; N] {
    let mut out = [0.0; N];
    let mut coefficient = 1.0;
    let mut m = 0;
    while m < N {
        // m + 1 for the m-th entry (m from 0): exact in f64.
        #[allow(clippy::cast_precision_loss, clippy::as_conversions)]
        let next = (m + 1) as f64;
        coefficient /= next;
        #[allow(clippy::indexing_slicing)] // m < N
        {
            out[m] = coefficient;
        }
        m += 1;
    }
    out
}

impl Tuning for f64 {
    const SINC_SERIES_LIMIT: Self = 0.05;
    const TAIL_CUTOFF: Self = 6e-6;
    const DAMPED_TAIL_CUTOFF: Self = 5e-3;
    const SERIES_EXACT_DEPARTURE: Self = 0.02;
    const SMALLEST_SUBNORMAL: Self = f64::from_bits(1);
    const TAIL_TRIED_BELOW: Self = 0.02;
    const BACKEND_ERROR: f64 = 0.0;
    const SIN_COEFFICIENTS: &'static [Self] = &sin_coefficients::<10>();
    const EXP_COEFFICIENTS: &'static [Self] = &exp_coefficients::<15>();
    const SHORT_FLIGHTS_CLOSED: bool = true;
    const TAYLOR_RECIPROCALS: &'static [Self] = &crate::numeric::tuning::RECIPROCALS;
    const FLIGHT_SERIES: (&'static [Self], &'static [Self]) = (
        &crate::numeric::flight_series::FLIGHT_TIME,
        &crate::numeric::flight_series::RETURN_SPEED,
    );

    #[inline]
    fn gauss_legendre_half(n: Nodes) -> &'static [(Self, Self)] {
        select_rule!(n, f64, same)
    }
}

impl Tuning for f32 {
    const SINC_SERIES_LIMIT: Self = 0.5;
    const TAIL_CUTOFF: Self = 5e-3;
    const DAMPED_TAIL_CUTOFF: Self = 5e-3;
    const SERIES_EXACT_DEPARTURE: Self = 0.1;
    const SMALLEST_SUBNORMAL: Self = f32::from_bits(1);
    const TAIL_TRIED_BELOW: Self = 0.25;
    const BACKEND_ERROR: f64 = if cfg!(feature = "micromath") {
        0.15
    } else {
        0.0
    };
    const SIN_COEFFICIENTS: &'static [Self] = &narrow_all(sin_coefficients::<6>());
    const EXP_COEFFICIENTS: &'static [Self] = &narrow_all(exp_coefficients::<8>());
    const SHORT_FLIGHTS_CLOSED: bool = false;
    const TAYLOR_RECIPROCALS: &'static [Self] = &narrow_all(crate::numeric::tuning::RECIPROCALS);
    const FLIGHT_SERIES: (&'static [Self], &'static [Self]) = (
        &narrow_all(crate::numeric::flight_series::FLIGHT_TIME),
        &narrow_all(crate::numeric::flight_series::RETURN_SPEED),
    );

    #[inline]
    fn gauss_legendre_half(n: Nodes) -> &'static [(Self, Self)] {
        select_rule!(n, f32, narrow)
    }
}

/// Most terms of that series (at lambda t = 0.5 the terms fall below 1e-17 after ~16).
pub(crate) const SERIES_TERMS: usize = 40;
/// 1 / ((k + 1) k), the series' recurrence without a division per term (in each float's
/// precision: [`Tuning::TAYLOR_RECIPROCALS`](crate::numeric::Tuning)).
pub(crate) const RECIPROCALS: [f64; SERIES_TERMS] = {
    let mut table = [0.0; SERIES_TERMS];
    let mut k = 1;
    while k < SERIES_TERMS {
        #[allow(clippy::cast_precision_loss, clippy::as_conversions)] // k < 40: exact
        let kf = k as f64;
        #[allow(clippy::indexing_slicing)] // k < SERIES_TERMS; no `get_mut` in a const block
        {
            table[k] = 1.0 / ((kf + 1.0) * kf);
        }
        k += 1;
    }
    table
};

//! The one error type: every invalid input is named, with the reason.

use core::fmt;

/// A scene parameter, as named in errors.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Parameter {
    /// Natural frequency Omega (rad/s).
    Omega,
    /// Effective mass (kg).
    Mass,
    /// Effective stiffness (N/m).
    Stiffness,
    /// Gap (> 0) or preload (< 0) Delta (m).
    Delta,
    /// Preload force (N).
    PreloadForce,
    /// Coefficient of restitution R.
    Restitution,
    /// r = 1 - R.
    OneMinusRestitution,
    /// Viscous damping ratio zeta.
    DampingRatio,
    /// Relaxation kernel amplitude kappa (1/s^3).
    KernelAmplitude,
    /// Relaxation kernel time constant tau (s).
    KernelTimeConstant,
    /// Relative tolerance of the hereditary harmonic sum.
    HarmonicTolerance,
    /// Closing speed v0 (m/s).
    ClosingSpeed,
    /// Threshold as a fraction of the first impulse.
    ThresholdFraction,
    /// Threshold as an absolute impulse per unit reduced mass (m/s).
    ThresholdImpulse,
    /// Mass of body 1 (kg).
    Mass1,
    /// Stiffness of body 1 (N/m).
    Stiffness1,
    /// Damping coefficient of body 1 (N s/m).
    Damping1,
    /// Mass of body 2 (kg).
    Mass2,
    /// Stiffness of body 2 (N/m).
    Stiffness2,
    /// Damping coefficient of body 2 (N s/m).
    Damping2,
    /// Relative tolerance asked of [`Method::Auto`](crate::Method::Auto).
    Tolerance,
    /// Safety margin factor of a debounce window.
    MarginFactor,
    /// Extra time added to a debounce window (s).
    MarginExtra,
    /// Sampling (tick) period (s).
    SamplePeriod,
    /// A time argument (s).
    Time,
    /// The threshold below which an impact no longer counts.
    Threshold,
}

impl Parameter {
    /// The parameter's name as written in errors (and in the JSON scene keys where one exists).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Omega => "omega",
            Self::Mass => "mass",
            Self::Stiffness => "stiffness",
            Self::Delta => "gap",
            Self::PreloadForce => "preload_force",
            Self::Restitution => "restitution",
            Self::OneMinusRestitution => "one_minus_restitution",
            Self::DampingRatio => "damping_ratio",
            Self::KernelAmplitude => "kernel.kappa",
            Self::KernelTimeConstant => "kernel.tau",
            Self::HarmonicTolerance => "kernel.tolerance",
            Self::ClosingSpeed => "closing_speed",
            Self::ThresholdFraction => "threshold_fraction",
            Self::ThresholdImpulse => "threshold_impulse",
            Self::Mass1 => "two_body.m1",
            Self::Stiffness1 => "two_body.c1",
            Self::Damping1 => "two_body.d1",
            Self::Mass2 => "two_body.m2",
            Self::Stiffness2 => "two_body.c2",
            Self::Damping2 => "two_body.d2",
            Self::Tolerance => "tolerance",
            Self::MarginFactor => "margin_factor",
            Self::MarginExtra => "margin_extra",
            Self::SamplePeriod => "sample_period",
            Self::Time => "time",
            Self::Threshold => "threshold",
        }
    }
}

impl Parameter {
    /// What the model takes for this parameter, in words (the reason's meaning when an
    /// [`Error`] says [`Reason::OutOfRange`]); `None` where only the other reasons apply.
    ///
    /// The figures are those of [`PHYSICAL_RANGE`] and the limits in
    /// [`scene`](crate::scene) (`SMALLEST_RATE`, `SMALLEST_RESTITUTION`, `LARGEST_DAMPING`).
    ///
    /// ```
    /// use contact_bounce::Parameter;
    /// assert_eq!(Parameter::ThresholdFraction.accepted(), Some("values in (0, 1)"));
    /// ```
    #[must_use]
    pub const fn accepted(self) -> Option<&'static str> {
        Some(match self {
            Self::Omega
            | Self::Mass
            | Self::Stiffness
            | Self::ClosingSpeed
            | Self::ThresholdImpulse
            | Self::KernelTimeConstant
            | Self::Mass1
            | Self::Stiffness1
            | Self::Mass2
            | Self::Stiffness2 => "values in [1e-30, 1e30]",
            Self::PreloadForce => "values in [1e-30, 1e30], on a scene type that takes a preload",
            Self::Damping1 | Self::Damping2 => "0 or values in [1e-30, 1e30]",
            Self::Delta => {
                "0 (grazing) or |gap| in [1e-30, 1e30], on the side the scene type takes \
                 (Preload: < 0, Gap: > 0)"
            }
            Self::Restitution => {
                "R in [1e-6, 1], with 1 - R either 0 or at least 1e-12 (R < 1 for the \
                 preload shortcuts, whose bounce must end)"
            }
            Self::OneMinusRestitution => "0 or values in [1e-12, 1 - 1e-6]",
            Self::DampingRatio => "0 or values in [1e-12, 1e3]",
            Self::ThresholdFraction => "values in (0, 1)",
            Self::KernelAmplitude => {
                "kappa tau below Omega^2 (the kernel's static stiffness must leave the spring \
                 a restoring force)"
            }
            Self::HarmonicTolerance => "values in [16 epsilon of the float, 0.1]",
            Self::MarginFactor => "values >= 1",
            Self::Time => {
                "at most 32,767 samples, the debouncer's counter (from saved bytes: what a \
                 learner saves)"
            }
            Self::Tolerance | Self::MarginExtra | Self::SamplePeriod | Self::Threshold => {
                return None
            }
        })
    }
}

impl fmt::Display for Parameter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why a parameter was rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Reason {
    /// NaN.
    NotANumber,
    /// Positive or negative infinity.
    Infinite,
    /// Must be > 0.
    NotPositive,
    /// Must be >= 0.
    Negative,
    /// Outside its allowed interval (the variant's docs give it).
    OutOfRange,
    /// The regime has no end of its own, so it needs a threshold, and none was given.
    Required,
    /// Valid alone, but its combination with the other parameters overflows or loses all
    /// precision (e.g. Omega^2 |Delta| overflowing).
    Overflow,
    /// The threshold is at or above the first impulse (1 + R) v0: no impact would count.
    AboveFirstImpulse,
    /// A preload force needs the stiffness (give mass and stiffness, not Omega alone).
    NeedsStiffness,
    /// The prediction has no end (an endless regime), so no finite window exists.
    Endless,
}

impl fmt::Display for Reason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::NotANumber => "is NaN",
            Self::Infinite => "is infinite",
            Self::NotPositive => "must be > 0",
            Self::Negative => "must be >= 0",
            Self::OutOfRange => "is out of range",
            Self::Required => "is required: this regime never ends by itself",
            Self::Overflow => "overflows in combination with the other parameters",
            Self::AboveFirstImpulse => "must be below the first impulse (1 + R) v0",
            Self::NeedsStiffness => "needs the stiffness: give mass and stiffness, not omega alone",
            Self::Endless => "is endless: the bounce never ends, so no finite window exists",
        })
    }
}

/// An invalid input: which parameter, and why.
///
/// ```
/// use contact_bounce::{Error, Parameter, Reason};
/// let e = Error::new(Parameter::Restitution, Reason::OutOfRange);
/// assert_eq!(e.parameter(), Parameter::Restitution);
/// assert_eq!(
///     format!("{e}"),
///     "restitution is out of range: the model takes R in [1e-6, 1], with 1 - R either 0 or at \
///      least 1e-12 (R < 1 for the preload shortcuts, whose bounce must end)"
/// );
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Error {
    parameter: Parameter,
    reason: Reason,
}

impl Error {
    /// Builds an error.
    #[must_use]
    pub const fn new(parameter: Parameter, reason: Reason) -> Self {
        Self { parameter, reason }
    }
    /// The offending parameter.
    #[must_use]
    pub const fn parameter(&self) -> Parameter {
        self.parameter
    }
    /// Why it was rejected.
    #[must_use]
    pub const fn reason(&self) -> Reason {
        self.reason
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.parameter, self.reason)?;
        match (self.reason, self.parameter.accepted()) {
            (Reason::OutOfRange, Some(range)) => write!(f, ": the model takes {range}"),
            _ => Ok(()),
        }
    }
}

impl core::error::Error for Error {}

/// Checks that a value is finite (not NaN, not infinite).
pub(crate) fn finite<F: crate::Float>(value: F, parameter: Parameter) -> Result<F, Error> {
    if value.is_finite() {
        Ok(value)
    } else if value.is_nan() {
        Err(Error::new(parameter, Reason::NotANumber))
    } else {
        Err(Error::new(parameter, Reason::Infinite))
    }
}

/// Checks that a value is finite and > 0.
pub(crate) fn positive<F: crate::Float>(value: F, parameter: Parameter) -> Result<F, Error> {
    let value = finite(value, parameter)?;
    if value > F::ZERO {
        Ok(value)
    } else {
        Err(Error::new(parameter, Reason::NotPositive))
    }
}

/// The physical domain of dimensional inputs (SI): from 1e-30 to 1e30. MEMS to contactors
/// span about 12 orders of magnitude inside it; outside, products the model forms (up to
/// Omega^3 Delta^2) would leave the float's range.
pub const PHYSICAL_RANGE: (f64, f64) = (1e-30, 1e30);

/// Checks that a dimensional value is finite, positive and within [`PHYSICAL_RANGE`].
///
/// Outlined on Cortex-M: a scene or a lean path checks four to six inputs, and one copy called
/// four times is 120-170 bytes smaller than four inlined on a Cortex-M4F
/// (`scripts/cost-report.sh`). On AVR the inliner then inlined more of `examples/uno_auto.rs`
/// elsewhere (2 KB more, past the Uno's 32 KB), so there the choice stays the compiler's.
#[cfg_attr(not(target_arch = "avr"), inline(never))]
pub(crate) fn physical<F: crate::Float>(value: F, parameter: Parameter) -> Result<F, Error> {
    if value.within_positive(F::from_f64(PHYSICAL_RANGE.0), F::from_f64(PHYSICAL_RANGE.1)) {
        return Ok(value);
    }
    // Outside: say why (NaN, infinite, not positive), else out of range.
    positive(value, parameter)?;
    Err(Error::new(parameter, Reason::OutOfRange))
}

/// Checks that a value is finite and >= 0.
pub(crate) fn non_negative<F: crate::Float>(value: F, parameter: Parameter) -> Result<F, Error> {
    let value = finite(value, parameter)?;
    if value >= F::ZERO {
        Ok(value)
    } else {
        Err(Error::new(parameter, Reason::Negative))
    }
}

/// Checks that a result is a normal number of the float (else it overflowed, or underflowed
/// to a value with fewer significant bits than the float), blaming `parameter`. (A float
/// comparison, not [`Float::within_positive`](crate::Float::within_positive): a caller's
/// later `value > 0` then folds away.)
pub(crate) fn normal<F: crate::Float>(value: F, parameter: Parameter) -> Result<(), Error> {
    if value >= F::MIN_POSITIVE && value.is_finite() {
        Ok(())
    } else {
        Err(Error::new(parameter, Reason::Overflow))
    }
}

/// Checks that a derived quantity is finite and > 0 (else the combination overflowed or
/// underflowed), blaming `parameter`.
pub(crate) fn derived<F: crate::Float>(value: F, parameter: Parameter) -> Result<F, Error> {
    // Finite and > 0: one range of bit patterns, from the smallest subnormal to the largest
    // finite number (NaN, the infinities, zeros and negatives all fall outside): on a
    // Cortex-M4F 9 % fewer instructions to validate a scene and 70-220 bytes less firmware
    // (`scripts/cost-report.sh`). On AVR the two float comparisons stay: there the 32-bit range
    // test validated 2 % slower and made `examples/uno.rs` 536 bytes bigger.
    #[cfg(not(target_arch = "avr"))]
    let ok = value.within_positive(F::SMALLEST_SUBNORMAL, F::MAX);
    #[cfg(target_arch = "avr")]
    let ok = value.is_finite() && value > F::ZERO;
    if ok {
        Ok(value)
    } else {
        Err(Error::new(parameter, Reason::Overflow))
    }
}

//! From a prediction to a debounce window in integer ticks: checked, rounded up.
//!
//! A window must cover the bounce: it is rounded **up** to whole sampling periods, and every
//! conversion is checked (fugit's issue #53: a silent `as u32` turned a minute into four
//! seconds). Also as `const fn`, so firmware can fix its window at compile time.

use crate::physics::error::{finite, non_negative, positive, Error, Parameter, Reason};
use crate::physics::mechanisms::Dissipation;
use crate::scene::OffsetSign;
use crate::tiers::prediction::Prediction;
use crate::{Float, Method, Preloaded, Scene};

/// How much to add to a predicted bounce time: window = factor * t + extra.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Margin<F> {
    factor: F,
    extra: F,
}

impl<F: Float> Margin<F> {
    /// `factor` >= 1 (e.g. 1.5 for +50 %), `extra` >= 0 seconds.
    ///
    /// # Errors
    /// [`Parameter::MarginFactor`] when NaN, infinite or below 1; [`Parameter::MarginExtra`]
    /// when NaN, infinite or negative.
    pub fn new(factor: F, extra: F) -> Result<Self, Error> {
        let factor = finite(factor, Parameter::MarginFactor)?;
        if factor < F::ONE {
            return Err(Error::new(Parameter::MarginFactor, Reason::OutOfRange));
        }
        Ok(Self {
            factor,
            extra: non_negative(extra, Parameter::MarginExtra)?,
        })
    }
    /// No margin: the window is the predicted time.
    #[must_use]
    pub fn none() -> Self {
        Self {
            factor: F::ONE,
            extra: F::ZERO,
        }
    }
    /// Widens the prediction's expected error into the factor: factor * (1 + expected error).
    /// A prediction with no expected error gets no widening: check
    /// [`Prediction::expected_error`] yourself in that case.
    #[must_use]
    pub fn with_expected_error(self, prediction: &Prediction<F>) -> Self {
        Self {
            factor: self.factor * (F::ONE + prediction.expected_error.unwrap_or(F::ZERO)),
            extra: self.extra,
        }
    }
}

/// A debounce window: a whole number of sampling periods.
///
/// ```
/// use contact_bounce::{Margin, Window};
/// // 1.2 ms of bounce, +50 %, sampled every 0.5 ms: ceil(1.8 / 0.5) = 4 ticks.
/// let w = Window::from_seconds(1.2e-3_f64, &Margin::new(1.5, 0.0)?, 0.5e-3)?;
/// assert_eq!(w.ticks(), 4);
/// // A window that cannot fit a u32 is an error, not a truncation.
/// assert!(Window::from_seconds(1e6_f64, &Margin::none(), 1e-9).is_err());
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Window {
    ticks: u32,
}

impl Window {
    /// A window of `ticks` sampling periods.
    #[must_use]
    pub const fn from_ticks(ticks: u32) -> Self {
        Self { ticks }
    }

    /// ceil((factor * seconds + extra) / sample_period) ticks.
    ///
    /// # Errors
    /// [`Parameter::Time`] when `seconds` is NaN, infinite or negative;
    /// [`Parameter::SamplePeriod`] when not finite and positive; [`Reason::Overflow`] when the
    /// window exceeds `u32::MAX` ticks.
    pub fn from_seconds<F: Float>(
        seconds: F,
        margin: &Margin<F>,
        sample_period: F,
    ) -> Result<Self, Error> {
        let seconds = non_negative(seconds, Parameter::Time)?;
        let period = positive(sample_period, Parameter::SamplePeriod)?;
        let covered = margin.factor * seconds + margin.extra;
        (covered / period)
            .ceil_u32()
            // A positive time whose ratio to the period underflows still needs one tick.
            .map(|t| if t == 0 && covered > F::ZERO { 1 } else { t })
            .map(Self::from_ticks)
            .ok_or(Error::new(Parameter::SamplePeriod, Reason::Overflow))
    }

    /// The window covering a prediction's bounce time ([`Prediction::bounce_time`]).
    ///
    /// # Errors
    /// [`Parameter::Time`] with [`Reason::Endless`] when the prediction has no end and no
    /// threshold time; otherwise as [`Window::from_seconds`].
    pub fn from_prediction<F: Float>(
        prediction: &Prediction<F>,
        margin: &Margin<F>,
        sample_period: F,
    ) -> Result<Self, Error> {
        let seconds = prediction
            .bounce_time()
            .ok_or(Error::new(Parameter::Time, Reason::Endless))?;
        Self::from_seconds(seconds, margin, sample_period)
    }

    /// The window covering a scene's bounce time by a method ([`Scene::bounce_time`]): the
    /// window [`Window::from_prediction`] gives for `scene.predict(method)`, without the
    /// counts and expected error the prediction would compute and link (the path for firmware
    /// that wants a window and nothing else).
    ///
    /// ```
    /// use contact_bounce::{scene::catalogue, Margin, Method, Window};
    /// let dome = catalogue::TACTILE_DOME.scene::<f32>()?;
    /// let window = Window::from_scene(&dome, Method::Closed, &Margin::new(1.5, 0.0)?, 10e-6)?;
    /// assert_eq!(window.ticks(), 18); // the closed tier's 115.3 us, +50 %, in 10 us samples
    /// # Ok::<(), contact_bounce::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Window::from_prediction`].
    #[inline]
    pub fn from_scene<F: Float, D: Dissipation<F>, S: OffsetSign>(
        scene: &Scene<F, D, S>,
        method: Method<F>,
        margin: &Margin<F>,
        sample_period: F,
    ) -> Result<Self, Error> {
        let seconds = scene
            .bounce_time(method)
            .ok_or(Error::new(Parameter::Time, Reason::Endless))?;
        Self::from_seconds(seconds, margin, sample_period)
    }

    /// The window in sampling periods.
    #[must_use]
    pub const fn ticks(&self) -> u32 {
        self.ticks
    }
}

impl<F: Float> Preloaded<F> {
    /// The debounce window: the bounce `method` predicts, widened by the prediction's expected
    /// error where the tier states one ([`Margin::with_expected_error`]) and then by `margin`
    /// (at least 1; 1.5 for +50 %), in whole periods of `sample_period` seconds, rounded up.
    /// To see the prediction and its expected error, use [`Preloaded::scene`] and
    /// [`Scene::predict`].
    ///
    /// # Errors
    /// As [`Preloaded::scene`], [`Margin::new`] and [`Window::from_prediction`].
    pub fn window(&self, method: Method<F>, margin: F, sample_period: F) -> Result<Window, Error> {
        let prediction = self.scene()?.predict(method);
        let margin = Margin::new(margin, F::ZERO)?.with_expected_error(&prediction);
        Window::from_prediction(&prediction, &margin, sample_period)
    }
}

/// [`check`], and within [`crate::scene::PHYSICAL_RANGE`] (as `Scene::new` asks of dimensional inputs).
const fn physical(value: f64, parameter: Parameter) -> Result<f64, Error> {
    match check(value, parameter) {
        Ok(v) if v < crate::scene::PHYSICAL_RANGE.0 || v > crate::scene::PHYSICAL_RANGE.1 => {
            Err(Error::new(parameter, Reason::OutOfRange))
        }
        other => other,
    }
}

const fn check(value: f64, parameter: Parameter) -> Result<f64, Error> {
    if value.is_nan() {
        Err(Error::new(parameter, Reason::NotANumber))
    } else if value.is_infinite() {
        Err(Error::new(parameter, Reason::Infinite))
    } else if value <= 0.0 {
        Err(Error::new(parameter, Reason::NotPositive))
    } else {
        Ok(value)
    }
}

/// The leading-order preload bounce time, computable at compile time.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LeadingOrder {
    /// t_b1 = J_B / (r Omega^2 |Delta|) = 2 R v0 m / ((1 - R) F) (s).
    pub seconds: f64,
    /// j0^2 = (J_B / (Omega |Delta|))^2 = 4 R^2 v0^2 m c / F^2: t_b1 is within 1 % while
    /// j0 <= 0.61 (R -> 1; see [`crate::Scene::t_b1`] for its worst case), i.e. j0^2 <= 0.37.
    pub j0_squared: f64,
}

/// t_b1 from mass (kg), stiffness (N/m), preload force (N), closing speed (m/s) and R in
/// (0, 1): `const`, so a window can be fixed at compile time (a `const` that is an `Err` is a
/// compile error when unwrapped with `match`/`panic!`).
///
/// ```
/// use contact_bounce::debounce::window::preload_bounce_time;
/// // The tactile dome of docs/physics.md sec. 7: 2 * 0.7 * 0.5 * 5e-5 / (0.3 * 1.0) s.
/// const DOME: f64 = match preload_bounce_time(5e-5, 5000.0, 1.0, 0.5, 0.7) {
///     Ok(t) => t.seconds,
///     Err(_) => panic!("bad switch parameters"),
/// };
/// assert!((DOME - 1.1666666666666667e-4).abs() < 1e-18);
/// ```
///
/// # Errors
/// The offending parameter when NaN, infinite or not positive, outside
/// [`crate::scene::PHYSICAL_RANGE`], or R outside [`crate::scene::SMALLEST_RESTITUTION`] to 1 -
/// [`crate::scene::SMALLEST_RATE`]: the inputs `Scene::new` refuses.
pub const fn preload_bounce_time(
    mass: f64,
    stiffness: f64,
    preload_force: f64,
    closing_speed: f64,
    restitution: f64,
) -> Result<LeadingOrder, Error> {
    // The same domain `Scene::new` takes: dimensional inputs within PHYSICAL_RANGE, R from
    // SMALLEST_RESTITUTION to 1 - SMALLEST_RATE.
    let mass = match physical(mass, Parameter::Mass) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    let stiffness = match physical(stiffness, Parameter::Stiffness) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    let force = match physical(preload_force, Parameter::PreloadForce) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    let speed = match physical(closing_speed, Parameter::ClosingSpeed) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    let restitution = match check(restitution, Parameter::Restitution) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    if restitution >= 1.0
        || restitution < crate::scene::SMALLEST_RESTITUTION
        || 1.0 - restitution < crate::scene::SMALLEST_RATE
    {
        return Err(Error::new(Parameter::Restitution, Reason::OutOfRange));
    }
    let start = 2.0 * restitution * speed;
    let seconds = start * mass / ((1.0 - restitution) * force);
    let j0_squared = start * start * mass * stiffness / (force * force);
    // Overflow, or underflow to 0 s (subnormal inputs): no silent wrong number.
    if !seconds.is_finite() || seconds <= 0.0 || !j0_squared.is_finite() {
        return Err(Error::new(Parameter::PreloadForce, Reason::Overflow));
    }
    Ok(LeadingOrder {
        seconds,
        j0_squared,
    })
}

/// ceil(factor * seconds / sample_period) as `u32` ticks, `const` and checked.
///
/// ```
/// use contact_bounce::debounce::window::window_ticks;
/// const TICKS: u32 = match window_ticks(1.2e-3, 1.5, 0.5e-3) {
///     Ok(t) => t,
///     Err(_) => panic!("window does not fit"),
/// };
/// assert_eq!(TICKS, 4);
/// ```
///
/// # Errors
/// [`Parameter::Time`] when `seconds` is NaN, infinite or not positive;
/// [`Parameter::MarginFactor`] below 1; [`Parameter::SamplePeriod`] not positive, or with
/// [`Reason::Overflow`] when the window exceeds `u32::MAX` ticks.
pub const fn window_ticks(seconds: f64, factor: f64, sample_period: f64) -> Result<u32, Error> {
    let seconds = match check(seconds, Parameter::Time) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    let factor = match check(factor, Parameter::MarginFactor) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    if factor < 1.0 {
        return Err(Error::new(Parameter::MarginFactor, Reason::OutOfRange));
    }
    let period = match check(sample_period, Parameter::SamplePeriod) {
        Ok(v) => v,
        Err(e) => return Err(e),
    };
    let ticks = factor * seconds / period;
    // u32::MAX as an f64 (exact); `From` is not const.
    if ticks.is_nan() || ticks > 4_294_967_295.0 {
        return Err(Error::new(Parameter::SamplePeriod, Reason::Overflow));
    }
    // A positive time (checked above) whose ratio to the period underflows: one tick, never 0.
    if ticks == 0.0 {
        return Ok(1);
    }
    // In range (checked above), so the conversions are exact or truncate toward zero.
    #[allow(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        clippy::as_conversions
    )]
    let (whole, back) = {
        let whole = ticks as u32;
        (whole, whole as f64)
    };
    if back < ticks {
        // Cannot overflow: ticks <= u32::MAX and whole < ticks.
        Ok(whole + 1)
    } else {
        Ok(whole)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_positive_time_is_never_zero_ticks() {
        // The fuzzing harness's silent wrong number: 1e-300 s at 1e100 s a tick underflowed to
        // Ok(0), a window that covers nothing.
        assert_eq!(window_ticks(1e-300, 1.0, 1e100), Ok(1));
        let w = Window::from_seconds(1e-300_f64, &Margin::none(), 1e100);
        assert_eq!(w.map(|w| w.ticks()), Ok(1));
        // Zero time stays zero ticks where it is allowed.
        let w = Window::from_seconds(0.0_f64, &Margin::none(), 1e-3);
        assert_eq!(w.map(|w| w.ticks()), Ok(0));
        assert_eq!(window_ticks(1.2e-3, 1.5, 0.5e-3), Ok(4));
    }

    #[test]
    fn the_compile_time_bounce_refuses_what_scene_new_refuses() {
        let out = |p| Err(Error::new(p, Reason::OutOfRange));
        assert_eq!(
            preload_bounce_time(1e-40, 5000.0, 1.0, 0.5, 0.7),
            out(Parameter::Mass)
        );
        assert_eq!(
            preload_bounce_time(5e-5, 5000.0, 1.0, 1e31, 0.7),
            out(Parameter::ClosingSpeed)
        );
        assert_eq!(
            preload_bounce_time(5e-5, 5000.0, 1.0, 0.5, 1e-7),
            out(Parameter::Restitution)
        );
        assert_eq!(
            preload_bounce_time(5e-5, 5000.0, 1.0, 0.5, 1.0 - 1e-13),
            out(Parameter::Restitution)
        );
        assert!(preload_bounce_time(5e-5, 5000.0, 1.0, 0.5, 0.7).is_ok());
    }
}

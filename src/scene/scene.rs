//! The scene: a [`Contact`] and its mechanisms, validated once into a [`Scene`].

use crate::physics::error::{
    derived, finite, non_negative, normal, physical, Error, Parameter, Reason,
};
use crate::physics::mechanisms::{restitution::restitution_asymptote, restitution_rate, Asymptote};
use crate::physics::mechanisms::{AnyDissipation, Dissipation, Hereditary, Undamped, Viscous};
use crate::physics::orbit::{Orbit, OrbitPoint};
use crate::physics::regime::Regime;
use crate::physics::sign::{offset_class, AnySign, Gap, OffsetClass, OffsetSign, Preload};
use crate::Float;

/// Where the contact's natural frequency comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Frequency<F> {
    /// Omega (rad/s).
    Omega(F),
    /// Effective (reduced) mass (kg) and stiffness (N/m): Omega = sqrt(stiffness / mass).
    MassStiffness {
        /// Effective mass (kg).
        mass: F,
        /// Effective stiffness (N/m).
        stiffness: F,
    },
}

/// Where the stop is relative to the free rest position.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Offset<F> {
    /// Delta (m): gap > 0, preload < 0, grazing 0.
    Delta(F),
    /// A preload force (N, > 0): Delta = -force / stiffness (needs the stiffness).
    PreloadForce(F),
}

/// The impact law x'(+) = -R x'(-).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Restitution<F> {
    /// R in (0, 1].
    Coefficient(F),
    /// r = 1 - R in [0, 1): keeps the digits of R near 1 (1 - 0.999 in f32 has 4 digits).
    Loss(F),
}

/// The impulse below which an impact no longer counts.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Threshold<F> {
    /// No threshold: only regimes that end by themselves can be predicted.
    None,
    /// A fraction in (0, 1) of the first impulse (1 + R) v0.
    FractionOfFirst(F),
    /// An impulse per unit reduced mass P_end (m/s), below the first impulse (1 + R) v0.
    Impulse(F),
}

/// One contact event, as given: the input to [`Scene::new`].
///
/// ```
/// use contact_bounce::{Contact, Frequency, Offset, Restitution, Scene, Threshold, Undamped};
/// // The tactile dome of docs/physics.md sec. 7 without its damping: m = 5e-5 kg, c = 5000 N/m,
/// // pressed by 1 N, closing at 0.5 m/s, R = 0.7.
/// let contact = Contact {
///     frequency: Frequency::MassStiffness { mass: 5e-5_f32, stiffness: 5000.0 },
///     offset: Offset::PreloadForce(1.0),
///     restitution: Restitution::Coefficient(0.7),
///     closing_speed: 0.5,
///     threshold: Threshold::None,
/// };
/// let scene = Scene::new(contact, Undamped)?;
/// assert_eq!(scene.regime(), contact_bounce::scene::Regime::ZenoAccumulation);
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Contact<F> {
    /// Natural frequency, or mass and stiffness.
    pub frequency: Frequency<F>,
    /// Gap, preload or preload force.
    pub offset: Offset<F>,
    /// R or 1 - R.
    pub restitution: Restitution<F>,
    /// Closing speed v0 at the first impact (m/s, > 0).
    pub closing_speed: F,
    /// Threshold of the impacts that count.
    pub threshold: Threshold<F>,
}

/// Two bodies on springs and dampers (the paper's Eq. 1 and Fig. 2a), colliding at
/// x1 - x2 = Delta.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct TwoBody<F> {
    /// Mass of body 1 (kg, > 0).
    pub m1: F,
    /// Stiffness of body 1 (N/m, > 0).
    pub c1: F,
    /// Damping coefficient of body 1 (N s/m, >= 0).
    pub d1: F,
    /// Mass of body 2 (kg, > 0).
    pub m2: F,
    /// Stiffness of body 2 (N/m, > 0).
    pub c2: F,
    /// Damping coefficient of body 2 (N s/m, >= 0).
    pub d2: F,
}

/// The one-body model of a [`TwoBody`] (docs/physics.md sec. 1).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Reduction<F> {
    /// Omega of the relative motion (rad/s): exact, or the Rayleigh frequency.
    pub omega: F,
    /// Viscous damping ratio of the relative motion.
    pub zeta: F,
    /// Reduced mass m1 m2 / (m1 + m2) (kg).
    pub reduced_mass: F,
    /// m1 / (m1 + m2).
    pub mass_fraction_1: F,
    /// True when c1/m1 = c2/m2 and d1/m1 = d2/m2 (to 8 epsilon): the reduction is exact.
    pub exact: bool,
    /// The larger partial frequency over the smaller (1 when equal).
    pub frequency_mismatch: F,
}

/// The smallest non-zero r = 1 - R and zeta the model takes.
pub const SMALLEST_RATE: f64 = 1e-12;
/// The smallest coefficient of restitution the model takes (an impact that keeps less than a
/// millionth of its speed is a plastic one).
pub const SMALLEST_RESTITUTION: f64 = 1e-6;
/// The largest damping ratio the model takes.
pub const LARGEST_DAMPING: f64 = 1e3;

/// The model's domain: time scales go like 1/r and 1/zeta, so a non-zero loss or damping
/// ratio is at least [`SMALLEST_RATE`] (below, it is zero over any physical horizon: give 0),
/// R at least [`SMALLEST_RESTITUTION`], and zeta at most [`LARGEST_DAMPING`].
fn check_domain<F: Float>(
    given: Restitution<F>,
    restitution: F,
    loss: F,
    zeta: F,
) -> Result<(), Error> {
    let smallest = F::from_f64(SMALLEST_RATE);
    // The error names the parameter the caller gave: R, or 1 - R.
    let given = match given {
        Restitution::Coefficient(_) => Parameter::Restitution,
        Restitution::Loss(_) => Parameter::OneMinusRestitution,
    };
    if restitution < F::from_f64(SMALLEST_RESTITUTION) || (loss > F::ZERO && loss < smallest) {
        return Err(Error::new(given, Reason::OutOfRange));
    }
    if (zeta > F::ZERO && zeta < smallest) || zeta > F::from_f64(LARGEST_DAMPING) {
        return Err(Error::new(Parameter::DampingRatio, Reason::OutOfRange));
    }
    Ok(())
}

/// Delta (validated, so a number) on the side the scene type `S` admits. Tested as the
/// comparisons the mechanisms make (`delta < 0`, `delta > 0`), so that where the scene is
/// built those are known and the other side's asymptote is left out.
#[allow(clippy::neg_cmp_op_on_partial_ord)] // delta is a number here; see above
fn check_sign<F: Float, S: OffsetSign>(delta: F, offset: Offset<F>) -> Result<(), Error> {
    match S::PRELOAD {
        Some(true) if !(delta < F::ZERO) => Err(Error::new(Parameter::Delta, Reason::OutOfRange)),
        Some(false) if !(delta > F::ZERO) => Err(match offset {
            Offset::PreloadForce(_) => Error::new(Parameter::PreloadForce, Reason::OutOfRange),
            Offset::Delta(_) => Error::new(Parameter::Delta, Reason::NotPositive),
        }),
        _ => Ok(()),
    }
}

/// The coefficient that ends (or decays) the regime must be a normal number, or the
/// prediction would silently lose it (e.g. r Omega^2 |Delta| underflowing).
fn check_regime_scale<F: Float>(
    regime: Regime,
    asymptote: &Asymptote<F>,
    kernel: bool,
    (loss, restitution_given): (F, Parameter),
    delta: F,
) -> Result<(), Error> {
    let scale = match regime {
        Regime::ZenoAccumulation => (asymptote.constant, restitution_given),
        Regime::LastImpact if kernel => (asymptote.inverse, Parameter::KernelAmplitude),
        Regime::LastImpact => (asymptote.inverse, Parameter::DampingRatio),
        // An endless decay without a kernel is exponential at small J: its rate must be
        // normal too (a subnormal zeta would make J / |E1| infinite).
        Regime::Endless if !kernel => {
            let culprit = if loss > F::ZERO && delta >= F::ZERO {
                restitution_given
            } else {
                Parameter::DampingRatio
            };
            (asymptote.linear, culprit)
        }
        _ => return Ok(()),
    };
    normal(scale.0, scale.1)
}

/// See [`Scene::impulse_floor`].
fn impulse_floor<F: Float>(orbit: &Orbit<F>) -> F {
    F::MIN_POSITIVE * F::from_f64(1e3) * orbit.offset_impulse().abs().max(F::ONE)
}

fn close<F: Float>(a: F, b: F) -> bool {
    (a - b).abs() <= F::from_f64(8.0) * F::EPSILON * a.abs().max(b.abs())
}

impl<F: Float> TwoBody<F> {
    /// Reduces to the relative coordinate: exactly when the partial frequencies and damping
    /// rates match, otherwise at the Rayleigh frequency
    /// Omega_rel^2 = (c1 m2/m1 + c2 m1/m2) / (m1 + m2) (and the same weighting of d/m),
    /// flagged as approximate (docs/physics.md sec. 1: ~1 % at a 10 % frequency mismatch for a
    /// preload, much worse for a gap).
    ///
    /// # Errors
    /// The offending mass, stiffness or damping when NaN, infinite, or not positive (masses,
    /// stiffnesses) or negative (damping).
    pub fn reduce(&self) -> Result<Reduction<F>, Error> {
        let m1 = physical(self.m1, Parameter::Mass1)?;
        let c1 = physical(self.c1, Parameter::Stiffness1)?;
        let d1 = non_negative(self.d1, Parameter::Damping1)?;
        if d1 > F::ZERO {
            physical(d1, Parameter::Damping1)?;
        }
        let m2 = physical(self.m2, Parameter::Mass2)?;
        let c2 = physical(self.c2, Parameter::Stiffness2)?;
        let d2 = non_negative(self.d2, Parameter::Damping2)?;
        if d2 > F::ZERO {
            physical(d2, Parameter::Damping2)?;
        }
        let total = derived(m1 + m2, Parameter::Mass1)?;
        let w1 = derived(c1 / m1, Parameter::Stiffness1)?;
        let w2 = derived(c2 / m2, Parameter::Stiffness2)?;
        let b1 = finite(d1 / m1, Parameter::Damping1)?;
        let b2 = finite(d2 / m2, Parameter::Damping2)?;
        let exact = close(w1, w2) && close(b1, b2);
        let (omega2, two_zeta_omega) = if exact {
            ((w1 + w2) * F::HALF, (b1 + b2) * F::HALF)
        } else {
            let f1 = m2 / total;
            let f2 = m1 / total;
            (w1 * f1 + w2 * f2, b1 * f1 + b2 * f2)
        };
        let omega = derived(omega2.sqrt(), Parameter::Stiffness1)?;
        let zeta = finite(two_zeta_omega / (F::TWO * omega), Parameter::Damping1)?;
        let mismatch = (w1.max(w2) / w1.min(w2)).sqrt();
        Ok(Reduction {
            omega,
            zeta,
            reduced_mass: derived(m1 * (m2 / total), Parameter::Mass1)?,
            mass_fraction_1: m1 / total,
            exact,
            frequency_mismatch: mismatch,
        })
    }
}

impl<F: Float> Frequency<F> {
    /// Omega, and the stiffness when given.
    fn validate(self) -> Result<(F, Option<F>), Error> {
        match self {
            Self::Omega(omega) => Ok((physical(omega, Parameter::Omega)?, None)),
            Self::MassStiffness { mass, stiffness } => {
                let mass = physical(mass, Parameter::Mass)?;
                let stiffness = physical(stiffness, Parameter::Stiffness)?;
                let omega = derived((stiffness / mass).sqrt(), Parameter::Stiffness)?;
                Ok((omega, Some(stiffness)))
            }
        }
    }
}

impl<F: Float> Offset<F> {
    /// Delta (m), from the preload force and the stiffness where needed.
    fn validate(self, stiffness: Option<F>) -> Result<F, Error> {
        match self {
            Self::Delta(delta) => {
                let delta = finite(delta, Parameter::Delta)?;
                if delta != F::ZERO {
                    physical(delta.abs(), Parameter::Delta)?;
                }
                Ok(delta)
            }
            Self::PreloadForce(force) => {
                let force = physical(force, Parameter::PreloadForce)?;
                let stiffness =
                    stiffness.ok_or(Error::new(Parameter::PreloadForce, Reason::NeedsStiffness))?;
                Ok(-derived(force / stiffness, Parameter::PreloadForce)?)
            }
        }
    }
}

impl<F: Float> Restitution<F> {
    /// (R, r): R in (0, 1], r = 1 - R in [0, 1).
    fn validate(self) -> Result<(F, F), Error> {
        match self {
            Self::Coefficient(r) => {
                let r = finite(r, Parameter::Restitution)?;
                if r > F::ZERO && r <= F::ONE {
                    Ok((r, F::ONE - r))
                } else {
                    Err(Error::new(Parameter::Restitution, Reason::OutOfRange))
                }
            }
            Self::Loss(loss) => {
                let loss = finite(loss, Parameter::OneMinusRestitution)?;
                if loss >= F::ZERO && loss < F::ONE {
                    Ok((F::ONE - loss, loss))
                } else {
                    Err(Error::new(
                        Parameter::OneMinusRestitution,
                        Reason::OutOfRange,
                    ))
                }
            }
        }
    }
}

impl<F: Float> Threshold<F> {
    /// The threshold impulse P_end, if any, below the first impulse.
    fn validate(self, first_impulse: F, restitution: F) -> Result<Option<F>, Error> {
        match self {
            Self::None => Ok(None),
            Self::FractionOfFirst(fraction) => {
                let fraction = finite(fraction, Parameter::ThresholdFraction)?;
                if !(fraction > F::ZERO && fraction < F::ONE) {
                    return Err(Error::new(Parameter::ThresholdFraction, Reason::OutOfRange));
                }
                Ok(Some(derived(
                    fraction * first_impulse,
                    Parameter::ThresholdFraction,
                )?))
            }
            Self::Impulse(impulse) => {
                let impulse = physical(impulse, Parameter::ThresholdImpulse)?;
                if impulse >= first_impulse {
                    return Err(Error::new(
                        Parameter::ThresholdImpulse,
                        Reason::AboveFirstImpulse,
                    ));
                }
                // The generating-impulse threshold must stay representable.
                derived(
                    impulse * F::TWO * restitution / (F::ONE + restitution),
                    Parameter::ThresholdImpulse,
                )?;
                Ok(Some(impulse))
            }
        }
    }
}

/// A validated contact event: after construction nothing can fail.
///
/// `D` names the mechanisms acting between impacts ([`Undamped`], [`Viscous`],
/// [`Hereditary`], tuples of them, or [`AnyDissipation`]); restitution is always there. `S`
/// is the sign of Delta where the type fixes it ([`Preload`], [`Gap`]: built with
/// [`Scene::new_preload`] or [`Scene::new_gap`], and the tiers link only that side's code), or
/// [`AnySign`] (the default, from [`Scene::new`]: decided at run time).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Scene<F, D = Undamped, S = AnySign> {
    orbit: Orbit<F>,
    restitution: F,
    loss: F,
    closing_speed: F,
    threshold: Option<F>,
    dissipation: D,
    regime: Regime,
    asymptote: Asymptote<F>,
    reduction: Option<Reduction<F>>,
    sign: S,
}

impl<F: Float, D: Dissipation<F>> Scene<F, D> {
    /// Validates a contact with the given mechanisms.
    ///
    /// # Errors
    /// An [`Error`] naming the parameter for: NaN or infinite values; Omega, mass, stiffness,
    /// closing speed or preload force not positive; R outside (0, 1] or r outside [0, 1); a
    /// non-zero r or zeta below [`SMALLEST_RATE`] (1e-12), R below [`SMALLEST_RESTITUTION`]
    /// (1e-6) or zeta above [`LARGEST_DAMPING`] (1e3), the model's domain
    /// ([`Reason::OutOfRange`]); a
    /// threshold fraction outside (0, 1) or an impulse not positive or at or above the first
    /// impulse; a preload force without a stiffness; an [`Regime::Endless`] regime with no
    /// threshold ([`Reason::Required`]); combinations that overflow ([`Reason::Overflow`]),
    /// among them Omega (1 + R) v0 above the float's largest value over 2^17 (the acceleration
    /// scale no tier can follow), a first impulse 2 R v0 below [`Scene::impulse_floor`] and a
    /// preload whose first flight 2 R v0 / (Omega^2 |Delta|) is below the float's smallest
    /// normal number (all named the closing speed).
    pub fn new(contact: Contact<F>, dissipation: D) -> Result<Self, Error> {
        Self::build(contact, dissipation, None)
    }

    /// A preloaded scene (Delta < 0: an [`Offset::PreloadForce`], or a negative
    /// [`Offset::Delta`]) whose type says so: the same scene and the same predictions as
    /// [`Scene::new`], and a firmware that uses it links none of a gap's code (its
    /// single-impact test, its closed forms, its last-return search).
    ///
    /// # Errors
    /// As [`Scene::new`]; a Delta of 0 or above is [`Parameter::Delta`] with
    /// [`Reason::OutOfRange`] (checked right after Delta itself).
    pub fn new_preload(contact: Contact<F>, dissipation: D) -> Result<Scene<F, D, Preload>, Error> {
        Scene::build(contact, dissipation, None)
    }

    /// A scene with a gap (Delta > 0) whose type says so: as [`Scene::new_preload`], for the
    /// other side (a firmware that uses it links none of a preload's code, such as the Zeno
    /// tail).
    ///
    /// # Errors
    /// As [`Scene::new`]; a Delta of 0 or below is [`Parameter::Delta`] with
    /// [`Reason::NotPositive`], and a preload force [`Parameter::PreloadForce`] with
    /// [`Reason::OutOfRange`].
    pub fn new_gap(contact: Contact<F>, dissipation: D) -> Result<Scene<F, D, Gap>, Error> {
        Scene::build(contact, dissipation, None)
    }
}

impl<F: Float, D: Dissipation<F>, S: OffsetSign> Scene<F, D, S> {
    fn build(
        contact: Contact<F>,
        dissipation: D,
        reduction: Option<Reduction<F>>,
    ) -> Result<Self, Error> {
        let (omega, stiffness) = contact.frequency.validate()?;
        let stiffness = stiffness.or(reduction.map(|r| r.reduced_mass * r.omega * r.omega));
        let delta = contact.offset.validate(stiffness)?;
        check_sign::<F, S>(delta, contact.offset)?;
        let (restitution, loss) = contact.restitution.validate()?;
        let closing_speed = physical(contact.closing_speed, Parameter::ClosingSpeed)?;
        let first_impulse = derived(
            (F::ONE + restitution) * closing_speed,
            Parameter::ClosingSpeed,
        )?;
        derived(
            F::TWO * restitution * closing_speed,
            Parameter::ClosingSpeed,
        )?;
        // The impulse's acceleration scale Omega J, times the largest factor a tier puts on it
        // (the map's viscous loss over a flight, zeta (2 theta)^2 Omega J times a period: with
        // zeta <= 1e3, below 2^17): beyond it no flight is one the float can follow (f32, a
        // mass of 1e-30 kg closing at 1e30 m/s: the map's loss overflowed and its time was NaN).
        if !(omega * first_impulse * F::from_f64(131_072.0)).is_finite() {
            return Err(Error::new(Parameter::ClosingSpeed, Reason::Overflow));
        }
        let threshold = contact.threshold.validate(first_impulse, restitution)?;
        if delta != F::ZERO {
            // Every scale the model forms from Omega and Delta must be finite and non-zero.
            let q = F::TWO * omega * delta.abs();
            derived(q, Parameter::Delta)?;
            derived(q * q, Parameter::Delta)?;
            derived(omega * omega * delta.abs(), Parameter::Delta)?;
            derived(omega * q * q, Parameter::Delta)?;
            // The dimensionless closing speed j0 = v0 / (Omega |Delta|), which every tier forms
            // (the undamped sums start from it): a scene whose j0 overflows the float in use
            // has no flight the float can describe (and its sums would never shrink from inf).
            derived(
                F::TWO * restitution * closing_speed / (omega * delta.abs()),
                Parameter::ClosingSpeed,
            )?;
        }
        let zeta = dissipation.damping_ratio();
        check_domain(contact.restitution, restitution, loss, zeta)?;
        // A kernel's force kappa y holds a static stiffness kappa tau against the spring's
        // Omega^2: at or above it the contact has no restoring force left.
        if dissipation.static_stiffness() >= omega * omega {
            return Err(Error::new(Parameter::KernelAmplitude, Reason::OutOfRange));
        }
        let sign: i8 = if delta < F::ZERO {
            -1
        } else {
            i8::from(delta > F::ZERO)
        };
        let regime = Regime::classify(
            sign,
            loss == F::ZERO,
            zeta >= F::ONE,
            dissipation.dissipates(),
        );
        if regime == Regime::Endless && threshold.is_none() {
            return Err(Error::new(Parameter::Threshold, Reason::Required));
        }
        let orbit = Orbit::new(omega, delta);
        let asymptote = restitution_asymptote::<F, S>(loss, &orbit).plus(
            dissipation.asymptote_for::<S>(&orbit, crate::physics::mechanisms::sealed::Private(())),
        );
        let restitution_given = match contact.restitution {
            Restitution::Coefficient(_) => Parameter::Restitution,
            Restitution::Loss(_) => Parameter::OneMinusRestitution,
        };
        check_regime_scale(
            regime,
            &asymptote,
            dissipation.has_kernel(),
            (loss, restitution_given),
            delta,
        )?;
        // A first generating impulse below the floor: its phase J / (2 Omega |Delta|) is not a
        // normal number, and no tier could resolve the flights (f32: a closing speed of 1e-30
        // m/s against 2 Omega |Delta| = 6e13 m/s gave NaN).
        if F::TWO * restitution * closing_speed < impulse_floor(&orbit) {
            return Err(Error::new(Parameter::ClosingSpeed, Reason::Overflow));
        }
        // A preload's first flight, about J_B / (Omega^2 |Delta|) for a small impulse, is the
        // shortest time the model forms and bounds every time of the bounce from below: where
        // it is not a normal number, the times keep fewer significant bits than the float
        // (f32: a bounce of 6.6e-42 s held to 2e-4). Multiplied out, not divided (Omega^2
        // |Delta| is a normal number, checked above; where it is below 1, J_B above the
        // impulse floor already keeps the flight normal).
        if delta < F::ZERO
            && F::TWO * restitution * closing_speed
                < F::MIN_POSITIVE * (omega * omega * delta.abs())
        {
            return Err(Error::new(Parameter::ClosingSpeed, Reason::Overflow));
        }
        if let Some(p_end) = threshold {
            let generating = p_end * F::TWO * restitution / (F::ONE + restitution);
            if generating < impulse_floor(&orbit) {
                let parameter = match contact.threshold {
                    Threshold::FractionOfFirst(_) => Parameter::ThresholdFraction,
                    _ => Parameter::ThresholdImpulse,
                };
                return Err(Error::new(parameter, Reason::Overflow));
            }
        }
        Ok(Self {
            orbit,
            restitution,
            loss,
            closing_speed,
            threshold,
            dissipation,
            regime,
            asymptote,
            reduction,
            sign: S::default(),
        })
    }

    /// The generating orbit (Omega, Delta).
    #[must_use]
    pub const fn orbit(&self) -> &Orbit<F> {
        &self.orbit
    }
    /// Omega (rad/s).
    #[must_use]
    pub fn omega(&self) -> F {
        self.orbit.omega()
    }
    /// Delta (m): gap > 0, preload < 0.
    #[must_use]
    pub fn delta(&self) -> F {
        self.orbit.delta()
    }
    /// R.
    #[must_use]
    pub const fn restitution(&self) -> F {
        self.restitution
    }
    /// r = 1 - R, as given or computed.
    #[must_use]
    pub const fn loss(&self) -> F {
        self.loss
    }
    /// v0 (m/s).
    #[must_use]
    pub const fn closing_speed(&self) -> F {
        self.closing_speed
    }
    /// The mechanisms between impacts.
    #[must_use]
    pub const fn dissipation(&self) -> &D {
        &self.dissipation
    }
    /// The regime (docs/physics.md sec. 4).
    #[must_use]
    #[inline]
    pub fn regime(&self) -> Regime {
        crate::physics::sign::narrow::<S>(self.regime)
    }
    /// Preload, gap or grazing: from the type where it fixes the sign, else from Delta.
    #[inline]
    pub(crate) fn offset_class(&self) -> OffsetClass {
        crate::physics::sign::class_of::<S>(offset_class(&self.orbit))
    }
    /// Delta < 0 (one comparison where the type leaves the sign open, as
    /// [`Scene::offset_class`] would take two).
    #[inline]
    pub(crate) fn is_preload(&self) -> bool {
        crate::physics::sign::preload::<F, S>(self.delta())
    }
    /// Delta > 0.
    #[inline]
    pub(crate) fn is_gap(&self) -> bool {
        S::PRELOAD.map_or_else(|| self.delta() > F::ZERO, |preload| !preload)
    }
    /// Delta = 0 (never for a type that fixes the sign).
    #[inline]
    pub(crate) fn is_grazing(&self) -> bool {
        S::PRELOAD.is_none() && self.delta() == F::ZERO
    }
    /// The two-body reduction, if the scene came from [`Scene::two_body`].
    #[must_use]
    pub const fn reduction(&self) -> Option<&Reduction<F>> {
        self.reduction.as_ref()
    }
    /// The impulse of impact 0 per unit reduced mass, P_0 = (1 + R) v0 (m/s).
    #[must_use]
    pub fn first_impulse(&self) -> F {
        (F::ONE + self.restitution) * self.closing_speed
    }
    /// The threshold impulse P_end (m/s), if any.
    #[must_use]
    pub const fn threshold_impulse(&self) -> Option<F> {
        self.threshold
    }
    /// The averaged model's start, the first flight's generating impulse J_B = 2 R v0 (m/s)
    /// (docs/physics.md sec. 3: not the physical (1 + R) v0).
    #[must_use]
    pub fn start_impulse(&self) -> F {
        F::TWO * self.restitution * self.closing_speed
    }
    /// The threshold on the generating impulse, J_end = P_end 2R / (1 + R) (docs/physics.md sec. 3).
    #[must_use]
    pub fn threshold_generating(&self) -> Option<F> {
        self.threshold
            .map(|p| p * F::TWO * self.restitution / (F::ONE + self.restitution))
    }
    /// j0 = J_B / (Omega |Delta|), the dimensionless first impulse; `None` at Delta = 0.
    #[must_use]
    pub fn dimensionless_impulse(&self) -> Option<F> {
        let scale = self.omega() * self.delta().abs();
        (scale > F::ZERO).then(|| self.start_impulse() / scale)
    }
    /// The averaged rate E1(J) (m/s^2, < 0 where the scene dissipates): restitution plus the
    /// scene's mechanisms (docs/physics.md sec. 3).
    #[must_use]
    pub fn rate(&self, impulse: F) -> F {
        self.rate_at(&self.orbit.at(impulse))
    }
    pub(crate) fn rate_at(&self, point: &OrbitPoint<F>) -> F {
        restitution_rate(self.loss, point) + self.dissipation.rate(point)
    }
    /// The smallest generating impulse the model resolves (m/s): 1e3 times the smallest
    /// normal float, times max(1, 2 Omega |Delta|) so that the phase J / (2 Omega |Delta|) stays
    /// normal too. Below it the averaged envelope follows its asymptote, and thresholds are
    /// refused ([`Reason::Overflow`]).
    #[must_use]
    pub fn impulse_floor(&self) -> F {
        impulse_floor(&self.orbit)
    }
    /// The small-impulse asymptote of -E1 (docs/physics.md sec. 4).
    #[must_use]
    pub const fn asymptote(&self) -> &Asymptote<F> {
        &self.asymptote
    }
}

/// A preload-typed scene as one whose sign is decided at run time (to keep it beside scenes of
/// either sign): the same scene, its tiers then carry both sides' code.
impl<F, D> From<Scene<F, D, Preload>> for Scene<F, D, AnySign> {
    fn from(scene: Scene<F, D, Preload>) -> Self {
        scene.with_sign()
    }
}

/// A gap-typed scene as one whose sign is decided at run time.
impl<F, D> From<Scene<F, D, Gap>> for Scene<F, D, AnySign> {
    fn from(scene: Scene<F, D, Gap>) -> Self {
        scene.with_sign()
    }
}

impl<F, D, S> Scene<F, D, S> {
    /// The same scene with the sign type `T` (only where `T` admits its Delta: the `From`
    /// conversions to [`AnySign`]).
    fn with_sign<T: Default>(self) -> Scene<F, D, T> {
        Scene {
            orbit: self.orbit,
            restitution: self.restitution,
            loss: self.loss,
            closing_speed: self.closing_speed,
            threshold: self.threshold,
            dissipation: self.dissipation,
            regime: self.regime,
            asymptote: self.asymptote,
            reduction: self.reduction,
            sign: T::default(),
        }
    }
}

impl<F: Float> Scene<F, AnyDissipation<F>> {
    /// A scene from two bodies (the paper's Eq. 1): reduced exactly when c1/m1 = c2/m2 and
    /// d1/m1 = d2/m2, else at the Rayleigh frequency and flagged approximate in every
    /// prediction. A preload force uses the relative stiffness mu Omega^2.
    ///
    /// # Errors
    /// As [`TwoBody::reduce`] and [`Scene::new`].
    pub fn two_body(
        bodies: TwoBody<F>,
        offset: Offset<F>,
        restitution: Restitution<F>,
        closing_speed: F,
        threshold: Threshold<F>,
        kernel: Option<Hereditary<F>>,
    ) -> Result<Self, Error> {
        let reduction = bodies.reduce()?;
        let viscous = Viscous::optional(reduction.zeta)?;
        let contact = Contact {
            frequency: Frequency::Omega(reduction.omega),
            offset,
            restitution,
            closing_speed,
            threshold,
        };
        Self::build(contact, (viscous, kernel), Some(reduction))
    }
}

//! Your own preloaded switch in a few lines: six numbers in, a validated scene or a window out.

use crate::physics::error::{finite, non_negative, physical, Error, Parameter, Reason};
use crate::scene::scene::{LARGEST_DAMPING, SMALLEST_RATE, SMALLEST_RESTITUTION};
use crate::scene::{Contact, Frequency, Offset, Preload, Restitution, Threshold};
use crate::{Float, Scene, Viscous};

/// A preloaded switch (the spring presses the contacts together at rest: a dome, a leaf or a
/// relay's contact spring) with restitution and viscous damping, given by the six numbers of
/// `docs/physics.md` sec. 7, in SI units. `docs/parameters.md` says where to get each one.
///
/// The shortest path from your own part to a window: one validation, one prediction, one
/// window.
///
/// ```
/// use contact_bounce::{Method, Preloaded};
/// let window = Preloaded {
///     mass: 5e-5_f32, stiffness: 5000.0, preload_force: 1.0,
///     closing_speed: 0.5, restitution: 0.7, damping_ratio: 0.03,
/// }
/// .window(Method::Closed, 1.5, 10e-6)?; // +50 % over the bounce, 10 us samples
/// assert_eq!(window.ticks(), 18); // 115.3 us, +3.5 % expected error, +50 %: 179 us
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Preloaded<F> {
    /// Effective moving mass (kg).
    pub mass: F,
    /// Effective stiffness (N/m).
    pub stiffness: F,
    /// Contact (preload) force at rest (N, > 0).
    pub preload_force: F,
    /// Closing speed at the first contact (m/s).
    pub closing_speed: F,
    /// Coefficient of restitution R.
    pub restitution: F,
    /// Viscous damping ratio zeta: > 0 for [`Preloaded::scene`] and [`Preloaded::window`] (a
    /// preload without viscous damping is `Scene::new(switch.contact(), Undamped)`, which links
    /// none of the damped code). The lean paths of [`tiers`](crate::tiers) also take 0
    /// (`preload_viscous_bounce_time`), or only 0 (`preload_restitution_bounce_seconds`).
    pub damping_ratio: F,
}

impl<F: Float> Preloaded<F> {
    /// The contact as a scene input (no threshold: a damped preload ends by itself).
    #[must_use]
    #[inline]
    pub fn contact(&self) -> Contact<F> {
        Contact {
            frequency: Frequency::MassStiffness {
                mass: self.mass,
                stiffness: self.stiffness,
            },
            offset: Offset::PreloadForce(self.preload_force),
            restitution: Restitution::Coefficient(self.restitution),
            closing_speed: self.closing_speed,
            threshold: Threshold::None,
        }
    }

    /// The validated scene, with its viscous damping, typed as a preload
    /// ([`Scene::new_preload`]): a firmware that uses it links none of a gap's code.
    ///
    /// # Errors
    /// As [`Scene::new`] and [`Viscous::new`]: the first invalid parameter, named (a damping
    /// ratio of 0 is [`Reason::NotPositive`]).
    #[inline]
    pub fn scene(&self) -> Result<Scene<F, Viscous<F>, Preload>, Error> {
        Scene::new_preload(self.contact(), Viscous::new(self.damping_ratio)?)
    }
}

/// A preloaded contact's inputs, checked as [`Scene::new`] checks them, and what the lean paths
/// (no `Scene`: [`preload_viscous_bounce_seconds`](crate::tiers::preload_viscous_bounce_seconds),
/// [`preload_restitution_bounce_seconds`](crate::tiers::preload_restitution_bounce_seconds))
/// compute from them.
pub(crate) struct LeanPreload<F> {
    /// 1 / Omega = sqrt(m / k) (s).
    pub inverse_omega: F,
    /// j0 = J_B / (Omega |Delta|), J_B = 2 R v0.
    pub j0: F,
    pub restitution: F,
    /// r = 1 - R.
    pub loss: F,
    pub zeta: F,
}

/// The lean paths' checks, in [`Scene::new`]'s order and with its errors, and their common
/// arithmetic.
#[inline]
pub(crate) fn lean_preload<F: Float>(switch: &Preloaded<F>) -> Result<LeanPreload<F>, Error> {
    let mass = physical(switch.mass, Parameter::Mass)?;
    let stiffness = physical(switch.stiffness, Parameter::Stiffness)?;
    let force = physical(switch.preload_force, Parameter::PreloadForce)?;
    let speed = physical(switch.closing_speed, Parameter::ClosingSpeed)?;
    let restitution = finite(switch.restitution, Parameter::Restitution)?;
    let loss = F::ONE - restitution;
    // (R above 1 leaves a negative loss.)
    if !restitution.within_positive(F::from_f64(SMALLEST_RESTITUTION), F::ONE)
        || loss < F::from_f64(SMALLEST_RATE)
    {
        return Err(Error::new(Parameter::Restitution, Reason::OutOfRange));
    }
    // Damped within the domain (one integer comparison of the bits), or undamped.
    let zeta = switch.damping_ratio;
    let damped = zeta.within_positive(F::from_f64(SMALLEST_RATE), F::from_f64(LARGEST_DAMPING));
    if !damped && zeta != F::ZERO {
        non_negative(zeta, Parameter::DampingRatio)?;
        return Err(Error::new(Parameter::DampingRatio, Reason::OutOfRange));
    }
    // 1 / Omega = sqrt(m / k) and Omega |Delta| = F / sqrt(k m), sqrt(k m) = k sqrt(m / k): one
    // square root where m / k is a normal number of the float, else (m and k at opposite ends of
    // PHYSICAL_RANGE, where m / k or k m leaves f32's range) one for each.
    let ratio = mass / stiffness;
    let (inverse_omega, root_km) = if ratio.within_positive(F::MIN_POSITIVE, F::MAX) {
        let root = ratio.sqrt();
        (root, stiffness * root)
    } else {
        let (root_m, root_k) = (mass.sqrt(), stiffness.sqrt());
        (root_m / root_k, root_k * root_m)
    };
    // 1 / (Omega |Delta|) = sqrt(k m) / F, a normal number (where Omega |Delta| overflows or
    // underflows, Scene::new refuses the scene: its (2 Omega Delta)^2 leaves the float's range
    // far sooner). Multiplied, not divided, below: a division is ~450 cycles on an AVR.
    let inverse_scale = root_km / force;
    if !inverse_scale.within_positive(F::MIN_POSITIVE, F::MAX) {
        return Err(Error::new(Parameter::PreloadForce, Reason::Overflow));
    }
    // As Scene::new: an acceleration scale Omega (1 + R) v0 beyond the float's largest value
    // over 2^17 is refused.
    if (F::ONE + restitution) * speed > F::MAX / F::from_f64(131_072.0) * inverse_omega {
        return Err(Error::new(Parameter::ClosingSpeed, Reason::Overflow));
    }
    let start = F::TWO * restitution * speed;
    let j0 = start * inverse_scale;
    // As Scene::new: a first impulse below the floor (MIN_POSITIVE 1e3 max(2 Omega |Delta|, 1))
    // has no phase the float can hold. Divided through by Omega |Delta| where 2 Omega |Delta|
    // >= 1: j0 below 2 MIN_POSITIVE 1e3.
    let floor = F::MIN_POSITIVE * F::from_f64(1e3);
    if start < floor || j0 < F::TWO * floor {
        return Err(Error::new(Parameter::ClosingSpeed, Reason::Overflow));
    }
    Ok(LeanPreload {
        inverse_omega,
        j0,
        restitution,
        loss,
        zeta,
    })
}

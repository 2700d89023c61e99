//! Your own preloaded switch in a few lines: six numbers in, a validated scene or a window out.

use crate::error::Error;
use crate::method::Method;
use crate::scene::{Contact, Frequency, Offset, Preload, Restitution, Threshold};
use crate::window::{Margin, Window};
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
    /// ratio of 0 is [`Reason::NotPositive`](crate::Reason::NotPositive)).
    #[inline]
    pub fn scene(&self) -> Result<Scene<F, Viscous<F>, Preload>, Error> {
        Scene::new_preload(self.contact(), Viscous::new(self.damping_ratio)?)
    }

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

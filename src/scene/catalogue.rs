//! Typical switches: the orders of magnitude of docs/physics.md sec. 7.
//!
//! **Assumed, typical values, not datasheet values**: use them to see what the model says of
//! a kind of switch, and measure your own (closing speed, preload force, resonance, R) before
//! trusting a window in a product.

use crate::physics::error::Error;
use crate::scene::{Contact, Preload};
use crate::{Float, Preloaded, Scene, Viscous};

/// A typical switch: effective mass and stiffness, contact (preload) force, closing speed,
/// coefficient of restitution and damping ratio.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Typical {
    /// Short name.
    pub name: &'static str,
    /// Effective mass (kg).
    pub mass: f64,
    /// Effective stiffness (N/m).
    pub stiffness: f64,
    /// Contact (preload) force (N).
    pub preload_force: f64,
    /// Closing speed (m/s).
    pub closing_speed: f64,
    /// Coefficient of restitution.
    pub restitution: f64,
    /// Viscous damping ratio.
    pub damping_ratio: f64,
}

impl Typical {
    /// Its six numbers in the float of your choice (rounded to it).
    #[must_use]
    #[inline]
    pub fn preloaded<F: Float>(&self) -> Preloaded<F> {
        Preloaded {
            mass: F::from_f64(self.mass),
            stiffness: F::from_f64(self.stiffness),
            preload_force: F::from_f64(self.preload_force),
            closing_speed: F::from_f64(self.closing_speed),
            restitution: F::from_f64(self.restitution),
            damping_ratio: F::from_f64(self.damping_ratio),
        }
    }

    /// The contact as a scene input (no threshold).
    #[must_use]
    #[inline]
    pub fn contact<F: Float>(&self) -> Contact<F> {
        self.preloaded().contact()
    }

    /// The validated scene with its viscous damping, typed as the preload it is (as
    /// [`Preloaded::scene`]: a firmware that uses it links none of a gap's code).
    ///
    /// ```
    /// use contact_bounce::{scene::catalogue, Method};
    /// let dome = catalogue::TACTILE_DOME.scene::<f32>()?;
    /// assert!(dome.predict(Method::Closed).bounce_time().is_some());
    /// # Ok::<(), contact_bounce::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`Preloaded::scene`] (never for the catalogue's entries, in f32 or f64).
    #[inline]
    pub fn scene<F: Float>(&self) -> Result<Scene<F, Viscous<F>, Preload>, Error> {
        // Not `self.preloaded().scene()`: converting the damping last, as here, keeps a
        // firmware 88-104 bytes smaller (the size report's tier firmwares, thumbv6m and thumbv7em).
        Scene::new_preload(
            self.contact(),
            Viscous::new(F::from_f64(self.damping_ratio))?,
        )
    }
}

/// MEMS micro-switch.
pub const MEMS: Typical = Typical {
    name: "MEMS micro-switch",
    mass: 5e-11,
    stiffness: 50.0,
    preload_force: 5e-5,
    closing_speed: 0.5,
    restitution: 0.5,
    damping_ratio: 0.02,
};
/// Miniature reed switch.
pub const REED: Typical = Typical {
    name: "miniature reed",
    mass: 2e-6,
    stiffness: 2000.0,
    preload_force: 0.01,
    closing_speed: 0.3,
    restitution: 0.5,
    damping_ratio: 0.01,
};
/// Tactile dome (push button).
pub const TACTILE_DOME: Typical = Typical {
    name: "tactile dome",
    mass: 5e-5,
    stiffness: 5000.0,
    preload_force: 1.0,
    closing_speed: 0.5,
    restitution: 0.7,
    damping_ratio: 0.03,
};
/// Keyboard leaf contact.
pub const KEYBOARD_LEAF: Typical = Typical {
    name: "keyboard leaf contact",
    mass: 3e-5,
    stiffness: 100.0,
    preload_force: 0.05,
    closing_speed: 0.5,
    restitution: 0.6,
    damping_ratio: 0.02,
};
/// Signal relay.
pub const SIGNAL_RELAY: Typical = Typical {
    name: "signal relay",
    mass: 1.5e-4,
    stiffness: 800.0,
    preload_force: 0.1,
    closing_speed: 0.3,
    restitution: 0.5,
    damping_ratio: 0.02,
};
/// Power relay, 30 A.
pub const POWER_RELAY: Typical = Typical {
    name: "power relay 30 A",
    mass: 1.5e-3,
    stiffness: 3000.0,
    preload_force: 1.0,
    closing_speed: 1.0,
    restitution: 0.6,
    damping_ratio: 0.03,
};
/// Contactor, 100 A.
pub const CONTACTOR: Typical = Typical {
    name: "contactor 100 A",
    mass: 0.3,
    stiffness: 2e4,
    preload_force: 40.0,
    closing_speed: 1.5,
    restitution: 0.5,
    damping_ratio: 0.05,
};
/// Large contactor.
pub const LARGE_CONTACTOR: Typical = Typical {
    name: "large contactor",
    mass: 2.0,
    stiffness: 2e4,
    preload_force: 50.0,
    closing_speed: 2.0,
    restitution: 0.6,
    damping_ratio: 0.05,
};

/// The eight switches of docs/physics.md sec. 7, fastest first.
pub const ALL: [Typical; 8] = [
    MEMS,
    REED,
    TACTILE_DOME,
    KEYBOARD_LEAF,
    SIGNAL_RELAY,
    POWER_RELAY,
    CONTACTOR,
    LARGE_CONTACTOR,
];

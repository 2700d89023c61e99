//! What a switch is: one contact event, validated once (`docs/physics.md` sec. 1).
//!
//! A [`Scene`] is built from a [`Contact`] (frequency, offset, restitution, closing speed,
//! threshold) and the mechanisms that dissipate between impacts: [`Undamped`], [`Viscous`],
//! [`Hereditary`] or a tuple of them ([`AnyDissipation`] when chosen at run time). The
//! mechanisms are part of the type, so a switch without viscous damping does not link it; so
//! can be the sign of Delta ([`Scene::new_preload`], [`Scene::new_gap`]: the types [`Preload`]
//! and [`Gap`]), so a preloaded switch does not link a gap's code.
//! [`Scene::two_body`] reduces the paper's two bodies; [`Preloaded`] is the short path for a
//! preloaded switch. Validation limits: [`PHYSICAL_RANGE`], [`SMALLEST_RATE`],
//! [`SMALLEST_RESTITUTION`], [`LARGEST_DAMPING`].
//!
//! [`catalogue`] holds typical switches.

pub mod catalogue;
pub(crate) mod preloaded;
#[allow(clippy::module_inception)] // the scene layer's main file: the Scene itself
pub(crate) mod scene;

pub use crate::physics::error::PHYSICAL_RANGE;
pub use crate::physics::mechanisms::{AnyDissipation, Dissipation, Hereditary, Undamped, Viscous};
pub use crate::physics::regime::Regime;
pub use crate::physics::sign::{AnySign, Gap, OffsetSign, Preload};
pub use preloaded::Preloaded;
pub use scene::{
    Contact, Frequency, Offset, Reduction, Restitution, Scene, Threshold, TwoBody, LARGEST_DAMPING,
    SMALLEST_RATE, SMALLEST_RESTITUTION,
};

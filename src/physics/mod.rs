//! Physics: what a contact does, before any tier predicts it. The errors every input can
//! raise, the generating orbit (`docs/physics.md` sec. 2), the dissipation mechanisms and the
//! terms of the averaged equation's right-hand side (sec. 3), the sign of the offset, the
//! damped flight between two impacts and the regimes (sec. 4).
//!
//! These are the parts of the averaged model for those who build on it; a switch is described
//! by a [`Scene`](crate::Scene) (the layer above), and predicted by [`tiers`](crate::tiers).

pub(crate) mod duration;
pub(crate) mod error;
pub(crate) mod flight;
pub(crate) mod mechanisms;
pub(crate) mod orbit;
pub(crate) mod regime;
pub(crate) mod sign;

pub use mechanisms::{restitution_rate, Asymptote, HarmonicSum};
pub use orbit::{Orbit, OrbitPoint};

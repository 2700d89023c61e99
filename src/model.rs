//! The parts of the averaged model, for those who build on it: the generating orbit
//! (`docs/physics.md` sec. 2), the terms of the averaged equation's right-hand side (sec. 3),
//! the float backend in use, and the constants the model is tuned with in each float.

pub use crate::float::F32_BACKEND;
pub use crate::mechanisms::{restitution_rate, Asymptote, HarmonicSum};
pub use crate::orbit::{Orbit, OrbitPoint};
pub use crate::tuning::Tuning;

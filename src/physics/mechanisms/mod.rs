//! Dissipation mechanisms and the averaged rate E1(J): docs/physics.md sec. 3.
//!
//! Mechanisms add: E1 = restitution + viscous + hereditary. Restitution is part of every
//! [`Scene`](crate::Scene); the others are types implementing [`Dissipation`], so a scene
//! carries exactly the mechanisms it has and **a mechanism the scene lacks costs no flash and
//! no cycles**: a `Scene<f32, Undamped>` never instantiates the viscous or hereditary code (and
//! so never links `sin`). Combine mechanisms with a tuple, `(Viscous<F>, Hereditary<F>)`; pick
//! them at run time with [`AnyDissipation`] (= `(Option<Viscous<F>>, Option<Hereditary<F>>)`).

mod dissipation;
mod hereditary;
pub(crate) mod restitution;
mod viscous;

pub(crate) use dissipation::sealed;
pub use dissipation::{Asymptote, Dissipation, Undamped};
pub use hereditary::{HarmonicSum, Hereditary};
pub use restitution::restitution_rate;
pub use viscous::Viscous;

/// Mechanisms chosen at run time (for tools that read scenes from files). Links every
/// mechanism; firmware with a fixed switch should name its mechanisms in the type instead.
pub type AnyDissipation<F> = (Option<Viscous<F>>, Option<Hereditary<F>>);

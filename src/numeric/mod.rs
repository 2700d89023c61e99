//! Numerics: the arithmetic every tier uses. The sealed [`Float`] trait over `f32` and `f64`
//! with its math backends, the constants each float is tuned with ([`Tuning`]), Gauss-Legendre
//! quadrature ([`Nodes`]) and the generated tables (quadrature nodes, the Zeno tail's flight
//! series).

pub(crate) mod flight_series;
pub(crate) mod float;
pub(crate) mod quadrature;
pub(crate) mod tuning;

pub use float::{Float, F32_BACKEND};
pub use quadrature::Nodes;
pub use tuning::Tuning;

/// `x` in the float in use (constants of the figures and the models).
pub(crate) fn c<F: Float>(x: f64) -> F {
    F::from_f64(x)
}

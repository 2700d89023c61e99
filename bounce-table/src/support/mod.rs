//! What every layer may use: strict reading of the tool's input files, worker threads, and
//! quantiles by bisection.

mod quantile;
pub mod strict;
pub mod workers;

pub use quantile::inverse;

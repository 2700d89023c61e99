//! Host-side checks of `contact-bounce`: the exact reference simulation (std, f64) and the
//! tools built on it.

pub mod grid;
pub mod reference;
pub mod stats;
pub mod traces;

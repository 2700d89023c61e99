//! Host-side checks of `contact-bounce`: the tests, benches and report generators built on the
//! exact reference simulation (`contact-bounce-reference`, std, f64).

pub mod grid;
pub mod traces;

/// The exact reference (its own crate, shared with the desk tool).
pub use contact_bounce_reference as reference;
pub use contact_bounce_reference::stats;

//! Debouncing: from a prediction to a [`Window`] in ticks ([`window`]), a [`Debouncer`] on such
//! windows (2 bytes of [`State`] per pin, integer-only), a [`LearningDebouncer`](learn::LearningDebouncer)
//! that learns its own switch ([`learn`]), a keyboard matrix that learns once for all its keys
//! ([`matrix`]) and, with the `async` feature, the same waiting on a pin's edges ([`wait`]).

mod debouncer;
pub mod learn;
pub mod matrix;
#[cfg(feature = "async")]
#[cfg_attr(docsrs, doc(cfg(feature = "async")))]
pub mod wait;
pub mod window;

pub use debouncer::{Debouncer, Edge, Mode, Polarity, State, Windows};
pub use window::{Margin, Window};

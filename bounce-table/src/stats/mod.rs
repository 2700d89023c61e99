//! What a capture or a scene's ranges say, statistically: a capture's events grouped per switch
//! and kind, the bounce model fitted to them and its held-out checks, the windows that cover
//! them, the contact models; and the table mode's Monte Carlo over a scene's ranges.

pub mod analysis;
pub mod contact;
mod fit;
mod groups;
mod heldout;
mod predictive;
mod window;

pub use fit::{bounces, reopening_threshold, reopens, BounceModel, ImpactFit, LogNormal};
pub(crate) use groups::sorted;
pub use groups::{events_csv, group, Groups};
pub(crate) use heldout::ratio;
pub use heldout::{
    random_splits, validations, RatioSpread, Validation, RANDOM_SPLITS, VALIDATION_QUANTILES,
};
pub use predictive::{Part, Predictive, MIN_FIT};
pub use window::{
    chronological_cover, earlier_count, window, Calibration, CaptureWindow, Cover, FAR_BEYOND,
    MIN_EVENTS,
};

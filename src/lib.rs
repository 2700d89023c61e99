#![doc = include_str!("../README.md")]
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![warn(
    clippy::pedantic,
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    clippy::indexing_slicing,
    clippy::as_conversions
)]
#![allow(
    clippy::module_name_repetitions,
    clippy::similar_names,
    clippy::many_single_char_names,
    clippy::doc_markdown,
    clippy::must_use_candidate,
    clippy::float_cmp,
    clippy::suboptimal_flops,
    clippy::missing_errors_doc,
    clippy::return_self_not_must_use
)]

mod accuracy;
mod averaged;
pub mod catalogue;
mod closed;
pub mod debounce;
mod error;
mod exact;
mod float;
pub mod learn;
mod map;
mod mechanisms;
mod method;
mod orbit;
mod prediction;
mod preloaded;
mod quadrature;
mod regime;
mod scene;
mod window;

pub use averaged::{Averaged, Bodies, EnvelopePoint, Motion};
pub use closed::{preload_viscous_bounce_time, Estimate};
pub use debounce::{Debouncer, Edge, Mode, Polarity, State, Windows};
pub use error::{Error, Parameter, Reason, PHYSICAL_RANGE};
pub use exact::{EXACT_MAX_IMPACTS, ROOT_STEPS};
pub use float::{Float, F32_BACKEND};
pub use learn::{
    Learned, LearningDebouncer, LearningState, Tail, LATE_EVIDENCE, LATE_GAP, WARM_UP,
};
pub use map::{Impact, MapEnd, MapImpacts, DEFAULT_MAX_IMPACTS};
pub use mechanisms::{
    restitution_rate, AnyDissipation, Asymptote, Dissipation, HarmonicSum, Hereditary, Undamped,
    Viscous,
};
pub use method::{Method, Tolerance};
pub use orbit::{Orbit, OrbitPoint};
pub use prediction::{Approximations, ClosedForm, Count, Prediction, Tier, Time};
pub use preloaded::Preloaded;
pub use quadrature::Nodes;
pub use regime::Regime;
pub use scene::{
    Contact, Frequency, Offset, Reduction, Restitution, Scene, Threshold, TwoBody, LARGEST_DAMPING,
    SMALLEST_RATE, SMALLEST_RESTITUTION,
};
pub use window::{preload_bounce_time, window_ticks, LeadingOrder, Margin, Window};

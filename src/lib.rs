//! Predict mechanical contact bounce from physics, and turn the prediction into a debounce
//! window: `no_std`, allocation-free, panic-free, generic over `f32` and `f64`.
//!
//! A switch, relay or contactor bounces after its contacts first meet, for microseconds (reed,
//! MEMS) to a hundred milliseconds (contactors). This crate computes how long from the contact's
//! mechanics (its mass and stiffness, its preload or gap, its coefficient of restitution, its
//! damping and its closing speed) with Krupenin's averaging method for vibro-impact systems, at
//! several levels of cost and accuracy, and gives the window a debouncer needs, in whole
//! sampling periods. `docs/physics.md` in the repository states the model, its formulas and the
//! accuracy of each tier; `docs/parameters.md` says where to get each parameter.
//!
//! ```
//! use contact_bounce::{Method, Preloaded};
//!
//! // A tactile dome: 50 mg moving on 5 N/mm, held by 1 N, closing at 0.5 m/s.
//! let dome = Preloaded {
//!     mass: 5e-5_f32, stiffness: 5000.0, preload_force: 1.0,
//!     closing_speed: 0.5, restitution: 0.7, damping_ratio: 0.03,
//! };
//! let window = dome.window(Method::Closed, 1.5, 10e-6)?; // +50 %, 10 us samples
//! assert_eq!(window.ticks(), 18);
//! # Ok::<(), contact_bounce::Error>(())
//! ```
//!
//! # Where things are
//!
//! - [`scene`]: what a switch is. [`Scene`] is validated once from a [`Contact`] and the
//!   mechanisms that dissipate between impacts ([`Undamped`], [`Viscous`], [`Hereditary`]);
//!   after [`Scene::new`] succeeds nothing can fail, panic or return NaN. The mechanisms are
//!   part of the scene's type, and so can be the sign of its offset: a scene from
//!   [`Scene::new_preload`] (or [`Scene::new_gap`]) links none of the other side's code.
//!   [`Preloaded`] is the short path for the common preloaded switch, [`catalogue`] holds
//!   typical switches (both give preload-typed scenes).
//! - [`tiers`]: how to predict. [`Scene::predict`] with a [`Method`]: the closed forms
//!   (nanoseconds), the averaged model, the per-impact map, the exact solution, or
//!   [`Method::Auto`], the cheapest tier that promises a [`Tolerance`] (and
//!   [`Scene::predict_auto_among`], Auto among the tiers a firmware names). Each gives a
//!   [`Prediction`] with its expected error. The leanest firmware takes a preload's inputs
//!   straight to a time, with no `Scene`: [`tiers::preload_viscous_bounce_seconds`] (t_b1v) and
//!   [`tiers::preload_restitution_bounce_seconds`] (the averaged model with restitution alone).
//! - [`window`]: from a prediction to a [`Window`] in ticks, widened by a [`Margin`]; also as
//!   `const fn`, so a window can be fixed at compile time. [`Window::from_scene`] (and
//!   [`Scene::bounce_time`]) take a scene and a method straight to the window: the same one,
//!   without the counts and expected error a prediction carries, whose code is then not linked.
//! - [`debounce`]: a [`Debouncer`] on such windows (2 bytes of [`State`] per pin, integer-only),
//!   and [`learn`]: a [`LearningDebouncer`] that learns its own switch from a prior window.
//! - [`matrix`]: a keyboard matrix ([`matrix::LearningMatrix`]) whose keys learn their switch
//!   once for all of them, in a byte and three bits a key.
//! - [`model`]: the parts of the averaged model (the generating orbit, the averaged equation's
//!   terms) for those who build on them.
//!
//! Every invalid input is an [`Error`] naming the [`Parameter`] and the [`Reason`].
//!
//! A window from the model covers the bounce of the impact model: the first flights of a
//! contact. Real hand-operated switches also dwell, chatter and bounce again later, beyond it;
//! for them, let a [`LearningDebouncer`] learn the switch, or set the window from a capture
//! (`bounce-table calibrate` and `bounce-table replay` in the repository, `docs/replay.md`).
//!
//! # Features
//!
//! None is on by default. `micromath`: `f32` through micromath's small, fast approximations
//! instead of libm (less flash, a few percent of error: see [`Float`]); `f64` always uses libm.
//! `defmt`: `defmt::Format` on the public types, for logging from firmware.
#![no_std]
#![cfg_attr(target_arch = "avr", feature(core_float_math))]
// docs.rs (its metadata below in Cargo.toml) marks what a feature adds.
#![cfg_attr(docsrs, feature(doc_cfg))]
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
pub mod matrix;
mod mechanisms;
mod method;
pub mod model;
mod orbit;
mod prediction;
mod preloaded;
mod quadrature;
mod regime;
pub mod scene;
mod sign;
pub mod tiers;
mod tuning;
#[cfg(feature = "async")]
#[cfg_attr(docsrs, doc(cfg(feature = "async")))]
pub mod wait;
pub mod window;

// The names most programs need, at the root; everything else in its module.
pub use debounce::{Debouncer, Edge, Mode, State, Windows};
pub use error::{Error, Parameter, Reason};
pub use float::Float;
pub use learn::{LearnerPrior, LearningDebouncer, LearningState};
pub use mechanisms::{Hereditary, Undamped, Viscous};
pub use method::{Method, Tolerance};
pub use prediction::Prediction;
pub use preloaded::Preloaded;
pub use quadrature::Nodes;
pub use scene::{Contact, Frequency, Offset, Restitution, Scene, Threshold};
pub use window::{Margin, Window};

/// The README's examples, compiled and run as doctests (the crate's docs are the ones above).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

/// The firmware guide's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../docs/guide-firmware.md")]
struct FirmwareGuideDoctests;

/// The tiers guide's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../docs/guide-tiers.md")]
struct TiersGuideDoctests;

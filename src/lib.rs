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
//! Five layers, lowest first; each module uses only its own layer and those below it.
//!
//! - [`numeric`]: the arithmetic every tier uses: the sealed [`Float`] over `f32` and `f64`,
//!   the constants each float is tuned with, Gauss-Legendre [`Nodes`].
//! - [`physics`]: what a contact does: the generating orbit, the dissipation mechanisms
//!   ([`Undamped`], [`Viscous`], [`Hereditary`]) and the averaged equation's terms, the damped
//!   flight between two impacts, the regimes. For those who build on the model's parts.
//! - [`scene`]: what a switch is. [`Scene`] is validated once from a [`Contact`] and its
//!   mechanisms; after [`Scene::new`] succeeds nothing can fail, panic or return NaN. The
//!   mechanisms are part of the scene's type, and so can be the sign of its offset: a scene
//!   from [`Scene::new_preload`] (or [`Scene::new_gap`]) links none of the other side's code.
//!   [`Preloaded`] is the short path for the common preloaded switch, [`scene::catalogue`]
//!   holds typical switches (both give preload-typed scenes).
//! - [`tiers`]: how to predict. [`Scene::predict`] with a [`Method`]: the closed forms
//!   (nanoseconds), the averaged model, the per-impact map, the exact solution, or
//!   [`Method::Auto`], the cheapest tier that promises a [`Tolerance`] (and
//!   [`Scene::predict_auto_among`], Auto among the tiers a firmware names). Each gives a
//!   [`Prediction`] with its expected error. The leanest firmware takes a preload's inputs
//!   straight to a time, with no `Scene`: [`tiers::preload_viscous_bounce_seconds`] (t_b1v) and
//!   [`tiers::preload_restitution_bounce_seconds`] (the averaged model with restitution alone).
//! - [`debounce`]: from a prediction to a [`Window`] in ticks, widened by a [`Margin`]
//!   ([`debounce::window`], also as `const fn`, so a window can be fixed at compile time;
//!   [`Window::from_scene`] and [`Scene::bounce_time`] take a scene and a method straight to
//!   the window, without the counts and expected error a prediction carries, whose code is then
//!   not linked); a [`Debouncer`] on such windows (2 bytes of [`State`] per pin,
//!   integer-only); a [`LearningDebouncer`] that learns its own switch from a prior window
//!   ([`debounce::learn`]); a keyboard matrix whose keys learn their switch once for all of them
//!   ([`debounce::matrix::LearningMatrix`], a byte and three bits a key).
//!
//! Every invalid input is an [`Error`] naming the [`Parameter`] and the [`Reason`].
//!
//! A window from the model covers the bounce of the impact model: the first flights of a
//! contact. Real hand-operated switches also dwell, chatter and bounce again later, beyond it;
//! for them, let a [`LearningDebouncer`] learn the switch, or set the window from a capture
//! (`bounce-table calibrate` and `bounce-table replay` in the repository, `docs/reports/replay.md`).
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

// The layers, lowest first: each imports only from itself and the layers below it
// (`scripts/layers.py` checks it).
pub mod debounce;
pub mod numeric;
pub mod physics;
pub mod scene;
pub mod tiers;

// The names most programs need, at the root; everything else in its module.
pub use debounce::learn::{LearnerPrior, LearningDebouncer, LearningState};
pub use debounce::{Debouncer, Edge, Margin, Mode, State, Window, Windows};
pub use numeric::{Float, Nodes};
pub use physics::error::{Error, Parameter, Reason};
pub use scene::{
    Contact, Frequency, Hereditary, Offset, Preloaded, Restitution, Scene, Threshold, Undamped,
    Viscous,
};
pub use tiers::{Method, Prediction, Tolerance};

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

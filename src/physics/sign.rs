//! The sign of Delta as part of a scene's type: a switch known to be preloaded (or to have a
//! gap) when its firmware is written links none of the other side's code.
//!
//! A [`Scene`](crate::Scene) built with [`Scene::new`](crate::Scene::new) decides at run time
//! whether it is a preload (Delta < 0), a gap (Delta > 0) or grazing (Delta = 0), so every
//! tier it calls carries the code of all three: a gap's single-impact test, its closed forms
//! and its last-return search sit in a preloaded dome's firmware, unused.
//! [`Scene::new_preload`](crate::Scene::new_preload) and
//! [`Scene::new_gap`](crate::Scene::new_gap) check the sign once and put it in the type
//! ([`Preload`], [`Gap`]); the tiers then ask the type, and the optimiser leaves the other
//! side out. The predictions are the same, bit for bit. A typed scene converts into an
//! [`AnySign`] one with `From`, to sit beside scenes of either sign.

use core::fmt::Debug;

use crate::physics::orbit::Orbit;
use crate::physics::regime::Regime;
use crate::Float;

mod sealed {
    pub trait Sealed {}
}

/// Which signs of Delta a scene type admits (sealed: [`AnySign`], [`Preload`], [`Gap`]).
///
/// A scene from [`Scene::new`](crate::Scene::new) ([`AnySign`]) decides at run time whether it
/// is a preload, a gap or grazing, so every tier it calls carries the code of all three (on an
/// Arduino Uno a preloaded dome's closed tier linked 6.9 KB of a gap's code).
/// [`Scene::new_preload`](crate::Scene::new_preload) and
/// [`Scene::new_gap`](crate::Scene::new_gap) check the sign once and put it in the type; the
/// predictions are the same, bit for bit. `From` turns a typed scene back into an [`AnySign`]
/// one.
///
/// Type all the scenes of one firmware alike: a preload-typed scene and an [`AnySign`] scene of
/// the same mechanism instantiate every tier twice: twice the flash, and (as the catalogue's
/// cost firmware showed on a Cortex-M4F while it mixed them) more instructions per prediction.
///
/// ```
/// use contact_bounce::scene::{AnySign, Preload};
/// use contact_bounce::{scene::catalogue, Method, Scene, Viscous};
/// let d = catalogue::TACTILE_DOME;
/// let dome: Scene<f32, Viscous<f32>, Preload> =
///     Scene::new_preload(d.contact(), Viscous::new(0.03)?)?;
/// let same: Scene<f32, Viscous<f32>, AnySign> = Scene::new(d.contact(), Viscous::new(0.03)?)?;
/// assert_eq!(dome.predict(Method::Closed), same.predict(Method::Closed));
/// assert!(Scene::new_gap(d.contact::<f32>(), Viscous::new(0.03)?).is_err());
/// # Ok::<(), contact_bounce::Error>(())
/// ```
pub trait OffsetSign: sealed::Sealed + Copy + Debug + PartialEq + Default {
    /// `Some(true)`: every scene of the type is preloaded (Delta < 0); `Some(false)`: every one
    /// has a gap (Delta > 0); `None`: decided by each scene's Delta.
    const PRELOAD: Option<bool>;
}

/// Delta of either sign, or 0: decided at run time (the default).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct AnySign;

/// A preload: the spring holds the contacts closed at rest (Delta < 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Preload;

/// A gap: the contacts are apart at rest (Delta > 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gap;

impl sealed::Sealed for AnySign {}
impl sealed::Sealed for Preload {}
impl sealed::Sealed for Gap {}

impl OffsetSign for AnySign {
    const PRELOAD: Option<bool> = None;
}
impl OffsetSign for Preload {
    const PRELOAD: Option<bool> = Some(true);
}
impl OffsetSign for Gap {
    const PRELOAD: Option<bool> = Some(false);
}

/// The offset class of a scene of sign type `S` whose Delta is `runtime` (what the tiers
/// branch on): a constant where the type fixes it.
#[inline]
pub(crate) fn class_of<S: OffsetSign>(runtime: OffsetClass) -> OffsetClass {
    match S::PRELOAD {
        Some(true) => OffsetClass::Preload,
        Some(false) => OffsetClass::Gap,
        None => runtime,
    }
}

/// Delta < 0, for a scene of sign type `S` whose Delta is `delta` (one comparison where the
/// type leaves the sign open).
#[inline]
pub(crate) fn preload<F: crate::Float, S: OffsetSign>(delta: F) -> bool {
    S::PRELOAD.unwrap_or_else(|| delta < F::ZERO)
}

/// `regime` told apart from the regimes the type rules out (a preload never has a last impact
/// or a single impact, a gap never accumulates), so that their code is left out: the scene's
/// validation made the excluded ones impossible, and the mapping never changes a value.
#[inline]
pub(crate) fn narrow<S: OffsetSign>(regime: Regime) -> Regime {
    match (S::PRELOAD, regime) {
        (Some(true), Regime::LastImpact | Regime::SingleImpact)
        | (Some(false), Regime::ZenoAccumulation) => Regime::Endless,
        _ => regime,
    }
}

/// The sign class of Delta, which decides each mechanism's small-J behaviour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum OffsetClass {
    Preload,
    Grazing,
    Gap,
}

pub(crate) fn offset_class<F: Float>(orbit: &Orbit<F>) -> OffsetClass {
    let delta = orbit.delta();
    if delta < F::ZERO {
        OffsetClass::Preload
    } else if delta > F::ZERO {
        OffsetClass::Gap
    } else {
        OffsetClass::Grazing
    }
}

//! Auto's count of the impacts a tier walks, shared by each tier's estimate of its own cost.

use crate::physics::mechanisms::Dissipation;
use crate::physics::regime::Regime;
use crate::scene::OffsetSign;
use crate::tiers::prediction::Prediction;
use crate::{Float, Scene};

/// Auto's count of the impacts a tier walks one by one from the start down to a generating
/// impulse (its floor): ln(J_B / floor) / ln(1 / R) in a Zeno accumulation (at least
/// 1 / ln(1 / R)), else the closed tier's count (of impacts above the threshold where it has
/// one), `F::MAX` where it has none. The logarithms are taken once for every tier's estimate.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Walk<F> {
    /// ln J_B.
    pub(crate) ln_start: F,
    /// ln(1 / R) in a Zeno accumulation.
    decay: Option<F>,
    /// The closed tier's count elsewhere.
    count: F,
}

impl<F: Float> Walk<F> {
    pub(crate) fn new<D: Dissipation<F>, S: OffsetSign>(
        scene: &Scene<F, D, S>,
        closed: &Prediction<F>,
        ln_start: F,
    ) -> Self {
        let zeno = scene.regime() == Regime::ZenoAccumulation;
        Self {
            ln_start,
            decay: zeno.then(|| -(-scene.loss()).ln_1p()),
            count: closed
                .impacts_above
                .value()
                .or(closed.impacts_total.value())
                .unwrap_or(F::MAX),
        }
    }

    /// Impacts walked down to the floor whose logarithm is `ln_floor`.
    pub(crate) fn down_to(&self, ln_floor: F) -> F {
        self.decay.map_or(self.count, |decay| {
            (self.ln_start - ln_floor).max(F::ONE) / decay
        })
    }
}

//! What every tier returns: one prediction type, with its provenance.

use crate::numeric::quadrature::Nodes;
use crate::physics::duration::{Count, Time};
use crate::physics::mechanisms::Dissipation;
use crate::physics::regime::Regime;
use crate::scene::OffsetSign;
use crate::tiers::accuracy;
use crate::tiers::approximations::Approximations;
use crate::{Float, Scene};

/// A closed form of docs/physics.md sec. 5.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum ClosedForm {
    /// t_b1v = (3 / (2 zeta Omega)) ln(1 + 2 zeta J_B / (3 r Omega |Delta|)): preload, viscous.
    Tb1v,
    /// t_b2 = J_B^2 / (8 zeta Omega^3 Delta^2): gap, viscous, R = 1.
    Tb2,
    /// t_b2r = (pi / (r Omega)) ln(1 + r J_B^2 / (8 pi zeta Omega^2 Delta^2)): gap, both.
    Tb2r,
    /// The small-impulse asymptote of E1 integrated (preload with R = 1, kernels).
    Asymptotic,
    /// Delta = 0: exact, flights pi / Omega_d, impulses shrinking by R exp(-zeta Omega pi / Omega_d).
    Grazing,
    /// zeta = 0 with any Delta: the exact sums (v_{n+1} = R v_n, flights (2/Omega) atan2(R v_n, -Omega Delta)).
    Undamped,
}

/// The tier of fidelity that produced a prediction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Tier {
    /// No model was needed: the regime alone answers (single impact, periodic).
    Regime,
    /// A closed form (docs/physics.md sec. 5).
    Closed(ClosedForm),
    /// The averaged model J' = E1(J), Gauss-Legendre with this many nodes per panel.
    Averaged(crate::Nodes),
    /// The semi-discrete map (docs/physics.md sec. 6).
    Map,
    /// The exact event-driven solution (flights in closed form, returns solved to rounding).
    Exact,
}

impl ClosedForm {
    /// Its name as the physics docs write it: `Tb1v`, `Tb2`, `Tb2r`, `Asymptotic`, `Grazing`,
    /// `Undamped`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Tb1v => "Tb1v",
            Self::Tb2 => "Tb2",
            Self::Tb2r => "Tb2r",
            Self::Asymptotic => "Asymptotic",
            Self::Grazing => "Grazing",
            Self::Undamped => "Undamped",
        }
    }
}

impl Tier {
    /// Its name in reports: `regime`, `closed (Tb1v)`, `averaged N8`, `map`, `exact` (also its
    /// `Display`): the closed form's [`ClosedForm::name`] and the averaged tier's node count
    /// (tested against them).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::Regime => "regime",
            Self::Closed(ClosedForm::Tb1v) => "closed (Tb1v)",
            Self::Closed(ClosedForm::Tb2) => "closed (Tb2)",
            Self::Closed(ClosedForm::Tb2r) => "closed (Tb2r)",
            Self::Closed(ClosedForm::Asymptotic) => "closed (Asymptotic)",
            Self::Closed(ClosedForm::Grazing) => "closed (Grazing)",
            Self::Closed(ClosedForm::Undamped) => "closed (Undamped)",
            Self::Averaged(Nodes::N2) => "averaged N2",
            Self::Averaged(Nodes::N4) => "averaged N4",
            Self::Averaged(Nodes::N6) => "averaged N6",
            Self::Averaged(Nodes::N8) => "averaged N8",
            Self::Averaged(Nodes::N10) => "averaged N10",
            Self::Averaged(Nodes::N12) => "averaged N12",
            Self::Averaged(Nodes::N16) => "averaged N16",
            Self::Averaged(Nodes::N20) => "averaged N20",
            Self::Map => "map",
            Self::Exact => "exact",
        }
    }
}

/// [`Tier::name`].
impl core::fmt::Display for Tier {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}

/// A bounce prediction, the same for every tier.
///
/// Definitions (impact 0 at t = 0 with impulse P_0 = (1 + R) v0; P_end the threshold):
/// - `end_time`: the last impact (gap with damping), the accumulation time (preload, R < 1),
///   0 for a single impact, [`Time::Never`] when endless;
/// - `last_above_time`: the last impact with P >= P_end (the end when there is no threshold);
///   for the averaged tier, when J(t) reaches the scaled threshold P_end 2R / (1 + R);
/// - `impacts_above`: impacts with P >= P_end, impact 0 included (a real number for the
///   averaged tier);
/// - `impacts_total`: all impacts, [`Count::Infinite`] for Zeno and endless regimes.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Prediction<F> {
    /// The regime.
    pub regime: Regime,
    /// When the bounce ends.
    pub end_time: Time<F>,
    /// When the last impact above the threshold happens.
    pub last_above_time: Time<F>,
    /// How many impacts are above the threshold.
    pub impacts_above: Count<F>,
    /// How many impacts there are in all.
    pub impacts_total: Count<F>,
    /// The tier that produced this.
    pub tier: Tier,
    /// What was approximated.
    pub approximations: Approximations,
    /// The relative error docs/physics.md sec. 6 leads one to expect of the bounce time (the end
    /// time when finite, else the last-above time) for this tier on this scene; `None` when
    /// the scene is outside every stated validity.
    pub expected_error: Option<F>,
}

/// What a tier finds of a bounce: its two times and two counts (as [`Prediction`] defines
/// them).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Course<F> {
    pub(crate) end_time: Time<F>,
    pub(crate) last_above_time: Time<F>,
    pub(crate) impacts_above: Count<F>,
    pub(crate) impacts_total: Count<F>,
}

impl<F: Float> Course<F> {
    /// One impact, at t = 0, that ends the bounce.
    pub(crate) fn single_impact() -> Self {
        let one = Count::Finite(F::ONE);
        Self {
            end_time: Time::At(F::ZERO),
            last_above_time: Time::At(F::ZERO),
            impacts_above: one,
            impacts_total: one,
        }
    }
}

impl<F: Float> Prediction<F> {
    /// A tier's prediction on `scene`: the scene's regime; the tier's own `approximations`
    /// beside the scene's reduction flags; and [`Approximations::OUTSIDE_VALIDITY`] wherever
    /// the tier states no expected error (every tier assembles its answer here).
    pub(crate) fn of_tier<D: Dissipation<F>, S: OffsetSign>(
        scene: &Scene<F, D, S>,
        course: Course<F>,
        tier: Tier,
        approximations: Approximations,
        expected_error: Option<F>,
    ) -> Self {
        let mut approximations = approximations.with(accuracy::reduction_flags(scene));
        if expected_error.is_none() {
            approximations = approximations.with(Approximations::OUTSIDE_VALIDITY);
        }
        Self {
            regime: scene.regime(),
            end_time: course.end_time,
            last_above_time: course.last_above_time,
            impacts_above: course.impacts_above,
            impacts_total: course.impacts_total,
            tier,
            approximations,
            expected_error,
        }
    }

    /// Maps times and counts beyond the float's range to `Never` / `Infinite`, flagged
    /// [`Approximations::BEYOND_RANGE`] (NaN is left alone: it would be a bug), and keeps
    /// `last_above_time <= end_time` and `impacts_above <= impacts_total`.
    pub(crate) fn within_range(mut self) -> Self {
        let in_range = |x: F| x.is_finite() || x.is_nan();
        for t in [&mut self.end_time, &mut self.last_above_time] {
            if let Time::At(s) = *t {
                if !in_range(s) {
                    *t = Time::Never;
                    self.approximations = self.approximations.with(Approximations::BEYOND_RANGE);
                }
            }
        }
        for n in [&mut self.impacts_above, &mut self.impacts_total] {
            if let Count::Finite(v) = *n {
                if !in_range(v) {
                    *n = Count::Infinite;
                    self.approximations = self.approximations.with(Approximations::BEYOND_RANGE);
                }
            }
        }
        // What holds by definition holds in the numbers too: the last impact above the
        // threshold is not after the end, and the impacts above are not more than all of
        // them. Where a tier hands over between approximations (the map to the averaged
        // tail) the two sides can disagree by their rounding; the result keeps the order.
        if let (Time::At(above), Time::At(end)) = (self.last_above_time, self.end_time) {
            if above > end {
                self.last_above_time = Time::At(end);
            }
        }
        if let (Count::Finite(above), Count::Finite(total)) =
            (self.impacts_above, self.impacts_total)
        {
            if above > total {
                self.impacts_above = Count::Finite(total);
            }
        }
        self
    }

    /// The time a debounce window must cover: the end of the bounce when finite, else the last
    /// impact above the threshold; `None` when both are endless.
    #[must_use]
    pub fn bounce_time(&self) -> Option<F> {
        self.end_time.seconds().or(self.last_above_time.seconds())
    }

    /// `self.within_range().bounce_time()`, from the times alone: `within_range` turns a time
    /// beyond the float's range into `Never` and otherwise changes the last-above time only
    /// where the end is finite, when `bounce_time` reads the end.
    #[inline]
    pub(crate) fn bounce_time_in_range(&self) -> Option<F> {
        let in_range = |t: Time<F>| t.seconds().filter(|s| s.is_finite() || s.is_nan());
        in_range(self.end_time).or_else(|| in_range(self.last_above_time))
    }
}

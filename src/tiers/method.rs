//! Choosing a tier: the [`Method`] enum, and `Auto`.

use crate::numeric::quadrature::{panel_count, Nodes};
use crate::physics::duration::Time;
use crate::physics::error::{positive, Error, Parameter};
use crate::physics::mechanisms::Dissipation;
use crate::scene::OffsetSign;
use crate::tiers::averaged::Averaged;
use crate::tiers::prediction::Prediction;
use crate::tiers::walk::Walk;
use crate::tiers::{accuracy, closed, exact, map};
use crate::{Float, Scene};

/// A relative tolerance asked of [`Method::Auto`] (finite, > 0).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Tolerance<F>(F);

impl<F: Float> Tolerance<F> {
    /// A relative tolerance, e.g. 0.01 for 1 %.
    ///
    /// # Errors
    /// [`Parameter::Tolerance`] when NaN, infinite or not positive.
    pub fn new(relative: F) -> Result<Self, Error> {
        positive(relative, Parameter::Tolerance).map(Self)
    }
    /// The relative tolerance.
    #[must_use]
    pub const fn get(self) -> F {
        self.0
    }
}

/// The tier of fidelity to predict with.
///
/// # What a call costs
///
/// Every tier's work is bounded by its settings, known before the call; none loops on its
/// input. In evaluations (a few dozen float operations each; on a Cortex-M4F in f32, an impact of
/// the map is about 300 instructions, `docs/reports/cost-report.md`):
/// - `Closed`: a fixed handful of logarithms and roots.
/// - `Averaged(n)`: at most 2,000 panels of `n` nodes for each of the (at most three) integrals a
///   prediction takes; with a relaxation kernel each node sums the kernel's harmonics.
/// - `Map { max_impacts }`: at most `max_impacts` impacts, then the averaged model (N8): linear
///   in the cap. `u32::MAX` is four billion impacts, minutes on a desktop: a cap is a promise
///   of work, not a hint.
/// - `Exact { max_impacts }`: at most [`Scene::exact_work`]`(max_impacts)` evaluations of the
///   motion (134 a flight without a kernel, at most
///   [`KERNEL_FLIGHT_STEPS`](crate::tiers::KERNEL_FLIGHT_STEPS) with one), then the averaged
///   model.
/// - `Auto(_)`: the closed tier, then each other tier at most once at its default cap: at
///   worst the three together, the exact tier's at
///   [`EXACT_MAX_IMPACTS`](crate::tiers::EXACT_MAX_IMPACTS) dominating (on a kernel of long
///   memory, up to 100,000 x 4,096 evaluations: the fuzzing harness's slowest calls, its
///   report in `docs/reports/fuzz.md`, are of this kind).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Method<F> {
    /// Closed forms (docs/physics.md sec. 5): exact sums where they exist, else t_b1v / t_b2r.
    Closed,
    /// The averaged model with this many Gauss-Legendre nodes per panel.
    Averaged(Nodes),
    /// The semi-discrete map, iterating at most this many impacts.
    Map {
        /// Cap on iterated impacts (the averaged model finishes beyond it).
        max_impacts: u32,
    },
    /// The exact solution, impact by impact (one body, restitution, viscous damping and one
    /// exponential relaxation kernel), solving at most this many flights (the averaged model
    /// finishes beyond; see [`Scene::exact_work`] for the bound on its work). Its expected
    /// error is the float's rounding. Scenes without viscous damping or with Delta = 0 get the
    /// closed tier's exact sums; with two kernels, or a kernel whose modes are nearly
    /// degenerate (their pair's damping ratio above 0.995), it answers with the averaged model
    /// (20 nodes), whose [`Tier`](crate::tiers::Tier) and expected error say so.
    Exact {
        /// Cap on solved flights ([`EXACT_MAX_IMPACTS`](crate::tiers::EXACT_MAX_IMPACTS) is the
        /// default).
        max_impacts: u32,
    },
    /// The cheapest tier whose expected error (docs/physics.md sec. 6) is within the tolerance:
    /// closed if it is; else the map, the averaged model and the exact tier in the order of
    /// their estimated cost (known before any of them runs: impacts to walk, panels, flights;
    /// weighed as on a Cortex-M4F, `docs/reports/cost-report.md`), the exact tier always among them, as
    /// it promises the float's rounding on every one-body scene with at most one kernel. Where
    /// nothing does (two kernels; f32 over very many impacts; a return decided by rounding;
    /// more flights than the exact tier's cap) the smallest expected error wins (the closed
    /// forms' answer with neither a figure nor a time ranks after every other): check
    /// [`Prediction::promises`]. Its worst-case
    /// work is the
    /// exact
    /// tier's at [`EXACT_MAX_IMPACTS`](crate::tiers::EXACT_MAX_IMPACTS)
    /// ([`Scene::exact_work`]); firmware that cannot afford that names a tier, or
    /// `Method::Exact` with a smaller cap. Every tier is linked into a firmware that names
    /// `Auto`; [`Scene::predict_auto_among`] weighs only the tiers it names.
    Auto(Tolerance<F>),
}

/// The tiers [`Scene::predict_auto_among`] may run after the closed forms (which Auto always
/// tries first), as bit flags to OR together. Named at compile time, the set decides what is
/// linked: `AutoTiers::EXACT` alone links the closed forms and the exact tier, and no map,
/// no averaged quadrature and none of their expected errors (on the Uno, Auto among all tiers
/// does not fit its 32 KB; among the closed forms and the exact tier it does:
/// `docs/reports/cost-report.md`, auto-exact).
///
/// ```
/// use contact_bounce::{scene::catalogue, tiers::AutoTiers, Tolerance};
/// let dome = catalogue::TACTILE_DOME.scene::<f32>()?;
/// let p = dome.predict_auto_among::<{ AutoTiers::EXACT }>(Tolerance::new(0.01)?);
/// assert!(p.promises(Tolerance::new(0.01)?)); // the exact tier always does (one body)
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct AutoTiers;

impl AutoTiers {
    /// The per-impact map (`Method::Map`, at [`DEFAULT_MAX_IMPACTS`](crate::tiers::DEFAULT_MAX_IMPACTS)).
    pub const MAP: u8 = 1;
    /// The averaged model (`Method::Averaged`, 8 nodes).
    pub const AVERAGED: u8 = 2;
    /// The exact tier (`Method::Exact`, at [`EXACT_MAX_IMPACTS`](crate::tiers::EXACT_MAX_IMPACTS)):
    /// without it, Auto may have no tier that promises the tolerance (it then answers with the
    /// smallest expected error, as `Method::Auto` does where nothing promises).
    pub const EXACT: u8 = 4;
    /// Every tier: what [`Method::Auto`] weighs.
    pub const ALL: u8 = Self::MAP | Self::AVERAGED | Self::EXACT;
}

/// One of the tiers Auto weighs after the closed tier: an element of an [`AutoTiers`] set.
#[derive(Debug, Clone, Copy, PartialEq)]
enum AutoTier {
    Map,
    Averaged,
    Exact,
}

impl AutoTier {
    const ALL: [Self; 3] = [Self::Map, Self::Averaged, Self::Exact];

    const fn index(self) -> usize {
        match self {
            Self::Map => 0,
            Self::Averaged => 1,
            Self::Exact => 2,
        }
    }

    /// Whether the set `tiers` ([`AutoTiers`] flags) holds this candidate.
    const fn within(self, tiers: u8) -> bool {
        let bit = match self {
            Self::Map => AutoTiers::MAP,
            Self::Averaged => AutoTiers::AVERAGED,
            Self::Exact => AutoTiers::EXACT,
        };
        tiers & bit != 0
    }
}

impl<F: Float> Prediction<F> {
    /// True when the expected error is known and within `tolerance`.
    #[must_use]
    pub fn promises(&self, tolerance: Tolerance<F>) -> bool {
        self.expected_error.is_some_and(|e| e <= tolerance.get())
    }
}

impl<F: Float, D: Dissipation<F>, S: OffsetSign> Scene<F, D, S> {
    /// Predicts the bounce with the given method. Never fails: the scene was validated.
    ///
    /// ```
    /// use contact_bounce::{Contact, Frequency, Method, Nodes, Offset, Restitution, Scene, Threshold, Viscous};
    /// let dome = Scene::new(Contact {
    ///     frequency: Frequency::MassStiffness { mass: 5e-5_f64, stiffness: 5000.0 },
    ///     offset: Offset::PreloadForce(1.0),
    ///     restitution: Restitution::Coefficient(0.7),
    ///     closing_speed: 0.5,
    ///     threshold: Threshold::None,
    /// }, Viscous::new(0.03)?)?;
    /// let closed = dome.predict(Method::Closed).bounce_time().unwrap();
    /// let averaged = dome.predict(Method::Averaged(Nodes::N8)).bounce_time().unwrap();
    /// let map = dome.predict(Method::Map { max_impacts: 10_000 }).bounce_time().unwrap();
    /// // About 0.2 ms, and the tiers agree to within their stated errors.
    /// assert!(averaged > 1e-4 && averaged < 3e-4);
    /// assert!((map / averaged - 1.0).abs() < 0.05 && (closed / averaged - 1.0).abs() < 0.3);
    /// # Ok::<(), contact_bounce::Error>(())
    /// ```
    ///
    /// Always inlined: where the method is a constant (firmware that names its tier, the C API's
    /// one function per tier) only that tier is linked, whichever other calls the firmware has.
    #[must_use]
    #[allow(clippy::inline_always)] // a dispatch on the method, small beside any tier
    #[inline(always)]
    pub fn predict(&self, method: Method<F>) -> Prediction<F> {
        match method {
            Method::Closed => closed::predict::<F, D, S, true>(self),
            Method::Averaged(nodes) => Averaged::new(self, nodes).predict(),
            Method::Map { max_impacts } => map::predict::<F, D, S, true>(self, max_impacts),
            Method::Exact { max_impacts } => exact::predict::<F, D, S, true>(self, max_impacts),
            Method::Auto(tolerance) => self.auto::<{ AutoTiers::ALL }>(tolerance),
        }
        .within_range()
    }

    /// The time a debounce window must cover, as [`predict`](Scene::predict) then
    /// [`Prediction::bounce_time`] give it (the same number, bit for bit), worked out without
    /// the counts and the expected error a [`Prediction`] carries: firmware that asks only for
    /// a window links none of their code (on the tactile dome in f32, 0.8-2.1 KB less per tier
    /// on a Cortex-M4F and 1.4-4.3 KB on the Uno: "One firmware per tier" in the repository's
    /// `docs/reports/cost-report.md`). `Method::Auto` chooses its tier by the expected errors, so it
    /// computes them all the same. `None` where [`Prediction::bounce_time`] is `None` (no end
    /// and no threshold time: both beyond the float's range).
    /// [`Window::from_scene`](crate::Window::from_scene) turns it into a window.
    ///
    /// ```
    /// use contact_bounce::{scene::catalogue, Method};
    /// let dome = catalogue::TACTILE_DOME.scene::<f32>()?;
    /// let map = Method::Map { max_impacts: 10_000 };
    /// assert_eq!(dome.bounce_time(map), dome.predict(map).bounce_time());
    /// # Ok::<(), contact_bounce::Error>(())
    /// ```
    #[must_use]
    #[allow(clippy::inline_always)] // a dispatch on the method, as `predict`'s
    #[inline(always)]
    pub fn bounce_time(&self, method: Method<F>) -> Option<F> {
        match method {
            Method::Closed => closed::predict::<F, D, S, false>(self),
            Method::Averaged(nodes) => Averaged::new(self, nodes).predict_times(),
            Method::Map { max_impacts } => map::predict::<F, D, S, false>(self, max_impacts),
            Method::Exact { max_impacts } => exact::predict::<F, D, S, false>(self, max_impacts),
            Method::Auto(tolerance) => self.auto::<{ AutoTiers::ALL }>(tolerance),
        }
        .bounce_time_in_range()
    }

    /// The averaged model, for its envelope J(t) and laws of motion.
    #[must_use]
    pub const fn averaged(&self, nodes: Nodes) -> Averaged<'_, F, D, S> {
        Averaged::new(self, nodes)
    }

    /// [`Method::Auto`] weighing, after the closed forms, only the tiers in `TIERS` (an OR of
    /// [`AutoTiers`] flags, named at compile time): a firmware links those tiers alone, and
    /// none of the others' expected errors or cost estimates. With
    /// [`AutoTiers::ALL`] it is `predict(Method::Auto(tolerance))`, bit for bit. Without
    /// [`AutoTiers::EXACT`] nothing may promise the tolerance: check
    /// [`Prediction::promises`].
    #[must_use]
    pub fn predict_auto_among<const TIERS: u8>(&self, tolerance: Tolerance<F>) -> Prediction<F> {
        self.auto::<TIERS>(tolerance).within_range()
    }

    fn auto<const TIERS: u8>(&self, tolerance: Tolerance<F>) -> Prediction<F> {
        let closed = closed::predict::<F, D, S, true>(self);
        if closed.promises(tolerance) {
            return closed;
        }
        // Expected errors and rough costs of the other tiers, known before running them
        // (costs: `auto_costs`).
        let estimate = closed.impacts_total.value();
        // (A tier outside `TIERS` is neither estimated nor run: these tests fold away.)
        let (use_map, use_averaged, use_exact) = (
            AutoTier::Map.within(TIERS),
            AutoTier::Averaged.within(TIERS),
            AutoTier::Exact.within(TIERS),
        );
        let averaged_error = if use_averaged {
            accuracy::with_reduction(self, accuracy::averaged(self, estimate))
        } else {
            None
        };
        let map_error = if use_map {
            accuracy::with_reduction(self, accuracy::map(self, estimate))
        } else {
            None
        };
        // The costs only order the tiers: a set of one has nothing to order, and links none of
        // this.
        let (map_cost, averaged_cost, exact_cost) = if TIERS.count_ones() > 1 {
            self.auto_costs::<TIERS>(&closed)
        } else {
            (F::ZERO, F::ZERO, F::ZERO)
        };
        let fits = |e: Option<F>| e.is_some_and(|e| e <= tolerance.get());
        // The tiers expected to promise, cheapest first (on a tie the map, then the averaged
        // model, then the exact tier, which always is). A tier chosen on estimates states its
        // own error once it has run (the map's, say, from the count it found): it is kept
        // only if it still promises. Where none does (a kernel, a return decided by rounding,
        // f32 over many impacts), the smallest expected error wins; no tier is run twice.
        let mut order = [
            (map_cost, AutoTier::Map, fits(map_error)),
            (averaged_cost, AutoTier::Averaged, fits(averaged_error)),
            (exact_cost, AutoTier::Exact, use_exact),
        ];
        // Three entries, sorted stably by cost.
        for (i, j) in [(0, 1), (1, 2), (0, 1)] {
            if let (Some(first), Some(second)) = (order.get(i), order.get(j)) {
                if second.0 < first.0 {
                    order.swap(i, j);
                }
            }
        }
        // The smaller expected error wins. The closed tier's answer with neither a figure nor
        // a time (its asymptote outside its validity on an endless scene with a threshold, or
        // a time past the float's range, not yet turned into `Never`) ranks after every
        // other: a tier that finds the time is never passed over for it.
        let rank = |p: &Prediction<F>| p.expected_error.unwrap_or(F::MAX);
        let timeless = match closed.last_above_time {
            Time::At(t) => !t.is_finite(),
            Time::Never => true,
        };
        let mut best_rank = if closed.expected_error.is_none() && timeless {
            F::MAX * F::TWO
        } else {
            rank(&closed)
        };
        let mut best = closed;
        let mut ran = [false; 3];
        for (_, candidate, expected) in order {
            if expected {
                let p = self.run::<TIERS>(candidate, &closed);
                if p.promises(tolerance) {
                    return p;
                }
                if let Some(done) = ran.get_mut(candidate.index()) {
                    *done = true;
                }
                if rank(&p) < best_rank {
                    (best, best_rank) = (p, rank(&p));
                }
            }
        }
        for (done, candidate) in ran.into_iter().zip(AutoTier::ALL) {
            if !done {
                let p = self.run::<TIERS>(candidate, &closed);
                if rank(&p) < best_rank {
                    (best, best_rank) = (p, rank(&p));
                }
            }
        }
        best
    }

    /// Auto's estimates of the cost of the map, the averaged model and the exact tier (`F::MAX`
    /// for one outside `TIERS`), in map impacts: on a Cortex-M4F (f32), on the tactile dome, an
    /// impact of the map costs about 300 instructions (3594 over ~12 impacts walked before the
    /// Zeno tail) and an E1 evaluation of the averaged tier about 185 (N8: 13323 over 9 panels x
    /// 8 nodes), so 0.6 of an impact (`docs/reports/cost-report.md`, `scripts/cost-report.sh`). The
    /// exact tier's is `exact::cost`. Inlined into its one caller, as it was written there.
    #[allow(clippy::inline_always)]
    #[inline(always)]
    fn auto_costs<const TIERS: u8>(&self, closed: &Prediction<F>) -> (F, F, F) {
        let (use_map, use_averaged, use_exact) = (
            AutoTier::Map.within(TIERS),
            AutoTier::Averaged.within(TIERS),
            AutoTier::Exact.within(TIERS),
        );
        let start = self.start_impulse();
        let floor_at = |cutoff: F| {
            self.threshold_generating()
                .unwrap_or(start * F::TAIL_CUTOFF)
                .max(cutoff * self.omega() * self.delta().abs())
        };
        let floor = floor_at(F::TAIL_CUTOFF);
        let walk = Walk::new(self, closed, start.ln());
        let ln_floor = floor.ln();
        // A scene that dissipates between impacts leaves its tail to the asymptote from higher
        // up: the map a preload's, the averaged tier any scene's on the way to J = 0
        // (`Asymptote::tail_cutoff`; in f32 the two cutoffs are one, and this folds away).
        let map_damped = use_map && self.is_preload();
        let ln_damped_floor = if (map_damped || use_averaged)
            && F::DAMPED_TAIL_CUTOFF > F::TAIL_CUTOFF
            && self.dissipation().dissipates()
        {
            let damped = floor_at(F::DAMPED_TAIL_CUTOFF);
            if damped > floor {
                damped.ln()
            } else {
                ln_floor
            }
        } else {
            ln_floor
        };
        let ln_map_floor = if map_damped {
            ln_damped_floor
        } else {
            ln_floor
        };
        let averaged_cost = if use_averaged {
            let (panels, _) = panel_count((walk.ln_start - ln_damped_floor).max(F::ZERO));
            let per_evaluation = if self.dissipation().has_kernel() {
                // With a kernel an E1 evaluation costs 5.2 times more (N8 on the dome: about
                // 69,800 instructions with a kernel, 13,350 without, `docs/reports/cost-report.md`).
                3.1
            } else {
                0.6
            };
            F::from_u32(panels.saturating_mul(Nodes::N8.count())) * F::from_f64(per_evaluation)
        } else {
            F::MAX
        };
        let map_cost = if use_map {
            walk.down_to(ln_map_floor)
        } else {
            F::MAX
        };
        let exact_cost = if use_exact {
            exact::cost(self, &walk)
        } else {
            F::MAX
        };
        (map_cost, averaged_cost, exact_cost)
    }

    /// One of Auto's candidates, at Auto's settings (outside `TIERS`, `closed`). Always
    /// inlined: outlined, it is a second caller of each tier in every firmware (the `Auto` arm
    /// of `predict` is compiled before it is found dead), and the inliner then outlines the tier
    /// a firmware names (+616 B for the restitution-only averaged firmware on the M4F).
    #[allow(clippy::inline_always)]
    #[inline(always)]
    fn run<const TIERS: u8>(&self, candidate: AutoTier, closed: &Prediction<F>) -> Prediction<F> {
        match candidate {
            AutoTier::Map if AutoTier::Map.within(TIERS) => {
                map::predict::<F, D, S, true>(self, crate::tiers::map::DEFAULT_MAX_IMPACTS)
            }
            AutoTier::Averaged if AutoTier::Averaged.within(TIERS) => {
                Averaged::new(self, Nodes::N8).predict()
            }
            AutoTier::Exact if AutoTier::Exact.within(TIERS) => {
                exact::predict::<F, D, S, true>(self, exact::EXACT_MAX_IMPACTS)
            }
            // Outside `TIERS` (never expected to promise, so run only where Auto takes the
            // smallest error of all): the closed tier's answer, which Auto already holds.
            _ => *closed,
        }
    }
}

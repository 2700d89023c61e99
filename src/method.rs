//! Choosing a tier: the [`Method`] enum, and `Auto`.

use crate::averaged::Averaged;
use crate::error::{positive, Error, Parameter};
use crate::mechanisms::Dissipation;
use crate::prediction::Prediction;
use crate::quadrature::{panel_count, Nodes};
use crate::regime::Regime;
use crate::{accuracy, closed, exact, map, Float, Scene};

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
    /// closed, then the map or the averaged model by their cost, then the exact tier, which
    /// promises the float's rounding on every one-body scene with at most one kernel. Where
    /// nothing does (two kernels; f32 over very many impacts; a return decided by rounding) the
    /// smallest expected error wins: check [`Prediction::promises`]. Its worst-case work is the
    /// exact
    /// tier's at [`EXACT_MAX_IMPACTS`](crate::tiers::EXACT_MAX_IMPACTS)
    /// ([`Scene::exact_work`]); firmware that cannot afford that names a tier, or
    /// `Method::Exact` with a smaller cap.
    Auto(Tolerance<F>),
}

impl<F: Float> Prediction<F> {
    /// True when the expected error is known and within `tolerance`.
    #[must_use]
    pub fn promises(&self, tolerance: Tolerance<F>) -> bool {
        self.expected_error.is_some_and(|e| e <= tolerance.get())
    }
}

impl<F: Float, D: Dissipation<F>> Scene<F, D> {
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
            Method::Closed => closed::predict(self),
            Method::Averaged(nodes) => Averaged::new(self, nodes).predict(),
            Method::Map { max_impacts } => map::predict(self, max_impacts),
            Method::Exact { max_impacts } => exact::predict(self, max_impacts),
            Method::Auto(tolerance) => self.auto(tolerance),
        }
        .within_range()
    }

    /// The averaged model, for its envelope J(t) and laws of motion.
    #[must_use]
    pub const fn averaged(&self, nodes: Nodes) -> Averaged<'_, F, D> {
        Averaged::new(self, nodes)
    }

    fn auto(&self, tolerance: Tolerance<F>) -> Prediction<F> {
        let closed = closed::predict(self);
        if closed.promises(tolerance) {
            return closed;
        }
        // Expected errors and rough costs of the other tiers, known before running them. Costs
        // are in map impacts: on a Cortex-M4F (f32), on the tactile dome, an impact of the map
        // costs about 300 instructions (3594 over ~12 impacts walked before the Zeno tail) and
        // an E1 evaluation of the averaged tier about 185 (N8: 13323 over 9 panels x 8 nodes),
        // so 0.6 of an impact (`docs/cost-report.md`, `scripts/cost-report.sh`).
        let estimate = closed.impacts_total.value();
        let averaged_error = accuracy::with_reduction(self, accuracy::averaged(self, estimate));
        let map_error = accuracy::with_reduction(self, accuracy::map(self, estimate));
        let start = self.start_impulse();
        let floor = self
            .threshold_generating()
            .unwrap_or(start * F::TAIL_CUTOFF)
            .max(F::TAIL_CUTOFF * self.omega() * self.delta().abs());
        let (panels, _) = panel_count((start.ln() - floor.ln()).max(F::ZERO));
        let averaged_cost =
            F::from_u32(panels.saturating_mul(Nodes::N8.count())) * F::from_f64(0.6);
        let map_cost = match (
            self.regime(),
            closed.impacts_above.value(),
            closed.impacts_total.value(),
        ) {
            (Regime::ZenoAccumulation, _, _) => {
                let decay = -(-self.loss()).ln_1p();
                (start.ln() - floor.ln()).max(F::ONE) / decay
            }
            (_, Some(n), _) | (_, None, Some(n)) => n,
            _ => F::MAX,
        };
        let fits = |e: Option<F>| e.is_some_and(|e| e <= tolerance.get());
        let cap = crate::map::DEFAULT_MAX_IMPACTS;
        let run_map = || map::predict(self, cap);
        let run_averaged = || Averaged::new(self, Nodes::N8).predict();
        let map_first = map_cost <= averaged_cost;
        // (true, _) for the map, (false, _) for the averaged model.
        let cheaper = match (fits(map_error), fits(averaged_error), map_first) {
            (true, true, true) | (true, false, _) => Some((true, run_map())),
            (_, true, _) => Some((false, run_averaged())),
            _ => None,
        };
        // A tier chosen on estimates states its own error once it has run (the map's, say,
        // from the count it found): it is kept only if it still promises.
        if let Some((_, p)) = cheaper {
            if p.promises(tolerance) {
                return p;
            }
        }
        // The exact tier, whose error is the float's rounding (or the averaged rest past its
        // cap). If even it does not promise (a kernel, a return decided by rounding, f32 over
        // many impacts), the smallest expected error wins (a tier already run is not rerun).
        let exact = exact::predict(self, exact::EXACT_MAX_IMPACTS);
        if exact.promises(tolerance) {
            return exact;
        }
        let (map, averaged) = match cheaper {
            Some((true, p)) => (p, run_averaged()),
            Some((false, p)) => (run_map(), p),
            None => (run_map(), run_averaged()),
        };
        let rank = |e: Option<F>| e.unwrap_or(F::MAX);
        let mut best = closed;
        for other in [map, averaged, exact] {
            if rank(other.expected_error) < rank(best.expected_error) {
                best = other;
            }
        }
        best
    }
}

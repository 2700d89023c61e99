//! Closed forms: docs/physics.md sec. 5, with the exact zeta = 0 sums.
//!
//! Every form returns an [`Estimate`]: the time and the relative error docs/physics.md sec. 6 leads
//! one to expect on this scene (`None` outside every stated validity), so a caller knows when
//! to trust it. A form that does not apply to the scene's regime returns `None`.

use crate::numeric::float::{log_growth, log_growth_of_ratio};
use crate::numeric::quadrature::Compensated;
use crate::physics::duration::{Count, Time};
use crate::physics::error::{normal, Error, Parameter};
use crate::physics::mechanisms::Dissipation;
use crate::physics::regime::Regime;
use crate::physics::sign::OffsetClass;
use crate::scene::preloaded::lean_preload;
use crate::scene::OffsetSign;
use crate::tiers::accuracy;
use crate::tiers::approximations::Approximations;
use crate::tiers::prediction::{ClosedForm, Course, Prediction, Tier};
use crate::{Float, Preloaded, Scene};

/// A closed-form time with the error to expect of it. The methods that give one
/// ([`Scene::t_b1`], [`Scene::t_b1v`], [`Scene::t_b2`], [`Scene::t_b2r`], [`Scene::t_grazing`])
/// return `None` where the form does not apply, and also where its time is beyond the float's
/// range (never an infinite time).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Estimate<F> {
    /// The time (s).
    pub time: F,
    /// Expected relative error (docs/physics.md sec. 5-6), `None` when outside the stated validity.
    pub expected_error: Option<F>,
}

impl<F: Float> Estimate<F> {
    /// The estimate, if its time is a number the float holds (a closed form can overflow it,
    /// e.g. t_b2 with a tiny zeta in f32): `None` is "beyond this float's range", never inf.
    fn in_range(self) -> Option<Self> {
        (self.time.is_finite() && self.time >= F::ZERO).then_some(self)
    }
}

/// t_b1v straight from a preloaded contact's datasheet-like inputs, with no [`Scene`]: the lean
/// path for firmware that needs a window and nothing else (it links the checks, two square
/// roots and one `ln_1p`; [`Scene::t_b1v`] gives the same value from a scene), with its
/// expected error. [`preload_viscous_bounce_seconds`] gives the time alone.
///
/// t_b1v = (3 / (2 zeta Omega)) ln(1 + 2 zeta J_B / (3 r Omega |Delta|)), J_B = 2 R v0,
/// Omega = sqrt(k / m), |Delta| = F / k: restitution and viscous damping, the bounce of a
/// preload; zeta = 0 gives t_b1. Expected error as [`Scene::t_b1v`]'s
/// (within 2.5 % plus the atan linearisation for j0 <= 1; `None` beyond).
///
/// ```
/// use contact_bounce::{scene::catalogue, tiers::preload_viscous_bounce_time};
/// let d = catalogue::TACTILE_DOME;
/// let lean = preload_viscous_bounce_time(&d.preloaded::<f64>())?;
/// let scene = d.scene::<f64>()?;
/// let full = scene.t_b1v().map(|e| e.time);
/// assert!(full.is_some_and(|t| (lean.time / t - 1.0).abs() < 1e-12));
/// # Ok::<(), contact_bounce::Error>(())
/// ```
///
/// # Errors
/// As [`Scene::new`] for these inputs: [`Parameter::Mass`], [`Parameter::Stiffness`],
/// [`Parameter::PreloadForce`] or [`Parameter::ClosingSpeed`] outside
/// [`PHYSICAL_RANGE`](crate::scene::PHYSICAL_RANGE); [`Parameter::Restitution`] outside
/// [1e-6, 1 - 1e-12]; [`Parameter::DampingRatio`] negative, below 1e-12 but not 0, or above
/// 1e3; [`Parameter::ClosingSpeed`] with [`Reason::Overflow`](crate::Reason::Overflow) for a first impulse below
/// [`Scene::impulse_floor`] or Omega (1 + R) v0 above the float's largest value over 2^17;
/// [`Parameter::PreloadForce`] with [`Reason::Overflow`](crate::Reason::Overflow) when the time is not a normal
/// number of the float (it overflowed, or underflowed below the smallest normal number).
pub fn preload_viscous_bounce_time<F: Float>(switch: &Preloaded<F>) -> Result<Estimate<F>, Error> {
    let lean = lean_tb1v(switch)?;
    Ok(Estimate {
        time: lean.time,
        expected_error: accuracy::t_b1v(lean.j0, lean.restitution, lean.zeta),
    })
}

/// t_b1v (s) alone, as [`preload_viscous_bounce_time`] computes it (the same value, the same
/// errors), without its expected error: the leanest path from a preloaded contact's inputs to a
/// window, for firmware that sets its margin itself ([`Window::from_seconds`]). The expected
/// error it leaves out is up to 2.5 % plus the atan linearisation (a square root and two
/// divisions: about a fifth of the call on an AVR).
///
/// [`Window::from_seconds`]: crate::Window::from_seconds
///
/// ```
/// use contact_bounce::{tiers::preload_viscous_bounce_seconds, Margin, Preloaded, Window};
/// let t = preload_viscous_bounce_seconds(&Preloaded {
///     mass: 5e-5_f32, stiffness: 5000.0, preload_force: 1.0,
///     closing_speed: 0.5, restitution: 0.7, damping_ratio: 0.03,
/// })?;
/// let window = Window::from_seconds(t, &Margin::new(1.5, 0.0)?, 10e-6)?;
/// assert_eq!(window.ticks(), 18); // 115.3 us, +50 %
/// # Ok::<(), contact_bounce::Error>(())
/// ```
///
/// # Errors
/// As [`preload_viscous_bounce_time`].
pub fn preload_viscous_bounce_seconds<F: Float>(switch: &Preloaded<F>) -> Result<F, Error> {
    lean_tb1v(switch).map(|lean| lean.time)
}

/// t_b1v from the inputs, with what its expected error needs.
struct LeanTb1v<F> {
    time: F,
    j0: F,
    restitution: F,
    zeta: F,
}

/// The checks and the arithmetic of [`preload_viscous_bounce_time`].
#[inline]
fn lean_tb1v<F: Float>(switch: &Preloaded<F>) -> Result<LeanTb1v<F>, Error> {
    let p = lean_preload(switch)?;
    let time = log_growth_of_ratio(p.j0, p.loss, p.zeta * F::from_f64(2.0 / 3.0)) * p.inverse_omega;
    Ok(LeanTb1v {
        time: normal(time, Parameter::PreloadForce).map(|()| time)?,
        j0: p.j0,
        restitution: p.restitution,
        zeta: p.zeta,
    })
}

/// Below this the terms atan(y) of a sum are replaced by their series tail.
const SMALL_TERM: f64 = 1e-3;
/// Above this ln(1/R) the sums are direct (at most ~1500 terms); below, Euler-Maclaurin.
const DIRECT_DECAY: f64 = 0.05;
/// Finite sums of at most this many terms are always direct.
const DIRECT_TERMS: f64 = 256.0;

/// sum_{m >= 0} atan(y R^m) for y <= SMALL_TERM: y/(1-R) - y^3/(3(1-R^3)) + y^5/(5(1-R^5)),
/// relative error below y^6/7 (1.5e-19).
fn small_tail<F: Float>(y: F, restitution: F, loss: F) -> F {
    let r = restitution;
    let r2 = r * r;
    let y2 = y * y;
    let geometric3 = loss * (F::ONE + r + r2);
    let geometric5 = loss * (F::ONE + r + r2 + r2 * r + r2 * r2);
    y / loss - y * y2 / (F::from_f64(3.0) * geometric3)
        + y * y2 * y2 / (F::from_f64(5.0) * geometric5)
}

/// Euler-Maclaurin for sum_{m >= 0} atan(x e^{-lambda m}) (lambda < 0.05): the integral
/// Ti2(x)/lambda plus f(0)/2 - f'(0)/12 + f'''(0)/720; the remainder is O(lambda^5 / 30240),
/// below 1e-12 relative.
fn euler_maclaurin<F: Float>(x: F, decay: F) -> F {
    // x/(1+x^2) and x(1-6x^2+x^4)/(1+x^2)^3 are symmetric under x -> 1/x: use the smaller.
    let v = if x > F::ONE { F::ONE / x } else { x };
    let v2 = v * v;
    let d1 = v / (F::ONE + v2);
    let d3 = v * (F::ONE - F::from_f64(6.0) * v2 + v2 * v2)
        / ((F::ONE + v2) * (F::ONE + v2) * (F::ONE + v2));
    crate::numeric::quadrature::inverse_tangent_integral(x) / decay
        + x.atan() * F::HALF
        + decay * d1 / F::from_f64(12.0)
        - decay * decay * decay * d3 / F::from_f64(720.0)
}

/// sum_{m=0}^{n-1} atan(x R^m) (n = `None`: the infinite sum, R < 1), x > 0.
///
/// Direct (compensated) while terms are large, then the series tail; Euler-Maclaurin when
/// ln(1/R) < 0.05 and more than 256 terms are asked. Relative error: a few ULP times the
/// number of direct terms in f64 (below 1e-12), ~1e-5 in f32 when R -> 1.
pub(crate) fn atan_geometric_sum<F: Float>(x: F, restitution: F, loss: F, n: Option<F>) -> F {
    if loss <= F::ZERO {
        // R = 1: every term equals atan(x).
        return n.map_or(F::MAX, |n| n * x.atan());
    }
    let decay = -(-loss).ln_1p();
    let few = n.is_some_and(|n| n <= F::from_f64(DIRECT_TERMS));
    if decay < F::from_f64(DIRECT_DECAY) && !few {
        let total = euler_maclaurin(x, decay);
        return match n {
            None => total,
            // x e^(-decay n) as one exponential: e^(-decay n) alone can underflow where the
            // product is a normal number (f32: x = 6e24 after 1e5 flights of r = 1e-3).
            Some(n) => total - euler_maclaurin((x.ln() - decay * n).exp(), decay),
        };
    }
    let small = F::from_f64(SMALL_TERM);
    let mut sum = Compensated::new();
    let mut y = x;
    let mut m = F::ZERO;
    loop {
        if n.is_some_and(|n| m >= n) {
            break;
        }
        if y < small {
            sum.add(small_tail(y, restitution, loss));
            if let Some(n) = n {
                let rest = n - m;
                sum.add(-small_tail(y * (-decay * rest).exp(), restitution, loss));
            }
            break;
        }
        sum.add(y.atan());
        y *= restitution;
        m += F::ONE;
    }
    sum.value()
}

/// Impacts with P >= P_end when impulses shrink by `factor` per impact (`decay` = ln(1/factor)):
/// floor(ln(P0 / P_end) / decay) + 1.
fn impacts_above_geometric<F: Float>(first: F, threshold: F, decay: F) -> F {
    ((first.ln() - threshold.ln()) / decay).floor() + F::ONE
}

impl<F: Float, D: Dissipation<F>, S: OffsetSign> Scene<F, D, S> {
    fn preload_scale(&self) -> Option<F> {
        self.is_preload().then(|| self.omega() * self.delta().abs())
    }

    /// t_b1 = J_B / (r Omega^2 |Delta|) (docs/physics.md sec. 5): preload, R < 1, restitution only.
    /// Exact as J_B -> 0; the error of linearising atan is 1 % at j0 = 0.61, 10 % at 2.1, 50 % at
    /// 6.4 (expected error given up to j0 = 6.4). `None` unless preload with R < 1.
    ///
    /// ```
    /// use contact_bounce::{Contact, Frequency, Offset, Restitution, Scene, Threshold, Undamped};
    /// let scene = Scene::new(Contact {
    ///     frequency: Frequency::Omega(1000.0_f64), offset: Offset::Delta(-1e-3),
    ///     restitution: Restitution::Coefficient(0.5), closing_speed: 0.1, threshold: Threshold::None,
    /// }, Undamped)?;
    /// let t = scene.t_b1().unwrap().time; // J_B = 0.1, r Omega^2 |Delta| = 500
    /// assert!((t - 0.1 / 500.0).abs() < 1e-15);
    /// # Ok::<(), contact_bounce::Error>(())
    /// ```
    #[must_use]
    pub fn t_b1(&self) -> Option<Estimate<F>> {
        let scale = self.preload_scale()?;
        (self.loss() > F::ZERO)
            .then(|| {
                let j0 = self.start_impulse() / scale;
                Estimate {
                    time: self.start_impulse() / (self.loss() * self.omega() * scale),
                    expected_error: accuracy::atan_linearisation(j0),
                }
            })
            .and_then(Estimate::in_range)
    }

    /// t_b1v = (3 / (2 zeta Omega)) ln(1 + 2 zeta J_B / (3 r Omega |Delta|)) (docs/physics.md sec. 5):
    /// preload, R < 1, viscous. Within 2.5 % for j0 <= 1, R in [0.05, 0.999], zeta <= 0.5.
    /// Equals t_b1 at zeta = 0. `None` unless preload with R < 1.
    #[must_use]
    pub fn t_b1v(&self) -> Option<Estimate<F>> {
        self.t_b1v_unbounded().and_then(Estimate::in_range)
    }

    /// [`Scene::t_b1v`], even beyond the float's range (the closed tier maps that itself).
    fn t_b1v_unbounded(&self) -> Option<Estimate<F>> {
        let scale = self.preload_scale()?;
        if self.loss() <= F::ZERO {
            return None;
        }
        let zeta = self.dissipation().damping_ratio();
        let omega = self.omega();
        let start = self.start_impulse();
        // (3/(2 zeta Omega)) ln(1 + z) = t_b1 ln(1+z)/z, z = (2 zeta / 3) j0 / r: no division
        // by zeta, and finite where z overflows.
        Some(Estimate {
            time: log_growth_of_ratio(start / scale, self.loss(), F::TWO * zeta / F::from_f64(3.0))
                / omega,
            expected_error: accuracy::t_b1v(start / scale, self.restitution(), zeta),
        })
    }

    /// t_b2 = J_B^2 / (8 zeta Omega^3 Delta^2) (docs/physics.md sec. 5): gap, viscous, R = 1.
    /// Rarely within 10 %: it needs J_B << 0.3 Omega |Delta| and many impacts, which a small
    /// J_B seldom has. It states no expected error: where it was given 10 % (j0 <= 0.03), the
    /// fuzzing harness found it 11-118 % off; in a sweep of gaps (j0 3e-4 to 0.03, R 0.1-1,
    /// zeta 1e-9 to 0.3, against the exact tier) 20 of the 49 that bounced more than once were
    /// within 10 % (those with many impacts), the median 18 % off and the worst 128 %. `None`
    /// unless a gap with zeta > 0.
    #[must_use]
    pub fn t_b2(&self) -> Option<Estimate<F>> {
        self.t_b2_unbounded().and_then(Estimate::in_range)
    }

    /// [`Scene::t_b2`], even beyond the float's range.
    fn t_b2_unbounded(&self) -> Option<Estimate<F>> {
        let zeta = self.dissipation().damping_ratio();
        if !self.is_gap() || zeta <= F::ZERO {
            return None;
        }
        let q = self.orbit().offset_impulse();
        let start = self.start_impulse();
        let omega = self.omega();
        Some(Estimate {
            time: start * start / (F::TWO * zeta * omega * q * q),
            expected_error: None,
        })
    }

    /// t_b2r = (pi / (r Omega)) ln(1 + r J_B^2 / (8 pi zeta Omega^2 Delta^2)) (docs/physics.md
    /// sec. 5): gap, restitution and viscous. Equals t_b2 as r -> 0. `None` unless a gap with
    /// zeta > 0.
    #[must_use]
    pub fn t_b2r(&self) -> Option<Estimate<F>> {
        self.t_b2r_unbounded().and_then(Estimate::in_range)
    }

    /// [`Scene::t_b2r`], even beyond the float's range.
    fn t_b2r_unbounded(&self) -> Option<Estimate<F>> {
        let t_b2 = self.t_b2_unbounded()?;
        // t_b2 ln(1 + z) / z with z = (r / pi) Omega t_b2.
        let omega_t = t_b2.time * self.omega();
        Some(Estimate {
            time: log_growth(omega_t, self.loss() / F::PI) / self.omega(),
            expected_error: t_b2.expected_error,
        })
    }

    /// Delta = 0 (docs/physics.md sec. 5): t = ln(J_B / J_end) / ((r/pi + zeta) Omega), the averaged
    /// exponential to the threshold. Off by about r/2 against the discrete impacts (sec. 6);
    /// the closed tier uses the exact discrete form instead. `None` unless Delta = 0 with a
    /// threshold and some loss.
    #[must_use]
    pub fn t_grazing(&self) -> Option<Estimate<F>> {
        if !self.is_grazing() {
            return None;
        }
        let end = self.threshold_generating()?;
        let zeta = self.dissipation().damping_ratio();
        let rate = (self.loss() / F::PI + zeta) * self.omega();
        (rate > F::ZERO)
            .then(|| Estimate {
                time: (self.start_impulse().ln() - end.ln()) / rate,
                expected_error: accuracy::discreteness(self)
                    .map(|(bias, _)| bias + F::from_f64(0.02) + zeta * zeta),
            })
            .and_then(Estimate::in_range)
    }

    /// The exact accumulation time of an undamped preload (docs/physics.md sec. 5):
    /// sum_{n>=0} (2/Omega) atan(R^{n+1} v0 / (Omega |Delta|)), summed directly or by
    /// Euler-Maclaurin (see [`Scene::undamped_flights_until`]). Its bouncing-ball limit is
    /// t_b1. `None` unless preload with R < 1 (its value ignores any damping).
    #[must_use]
    pub fn undamped_accumulation_time(&self) -> Option<F> {
        let scale = self.preload_scale()?;
        (self.loss() > F::ZERO).then(|| {
            let x = self.restitution() * self.closing_speed() / scale;
            F::TWO / self.omega() * atan_geometric_sum(x, self.restitution(), self.loss(), None)
        })
    }

    /// The exact time of impact `n` (n >= 0, a whole number) without damping between impacts:
    /// the sum of the first n flights (2/Omega) atan2(R^{m+1} v0, -Omega Delta), any Delta.
    /// Relative error below 1e-12 in f64.
    #[must_use]
    pub fn undamped_flights_until(&self, n: F) -> F {
        if n <= F::ZERO {
            return F::ZERO;
        }
        let omega = self.omega();
        let delta = self.delta();
        let r = self.restitution();
        if self.is_grazing() {
            return n * F::PI / omega;
        }
        let x = r * self.closing_speed() / (omega * delta.abs());
        let sum = atan_geometric_sum(x, r, self.loss(), Some(n));
        if self.is_preload() {
            F::TWO / omega * sum
        } else {
            F::TWO / omega * (n * F::PI - sum)
        }
    }
}

/// The closed-form tier: the exact discrete sums where they exist (no damping between impacts,
/// or Delta = 0 without a kernel), else the closed forms of sec. 5 (t_b1v, t_b2r and the
/// small-impulse asymptote they come from).
///
/// Never inlined: it was outlined while the exact tier called it as well, and inlined into a
/// firmware's one caller it is larger (920 B on the Uno, 296 B on the M4F).
///
/// `FULL`: every field (false: the times alone, see [`Scene::bounce_time`]; the counts are
/// then `Infinite` and the expected error `None`, placeholders no caller reads).
#[inline(never)]
pub(crate) fn predict<F: Float, D: Dissipation<F>, S: OffsetSign, const FULL: bool>(
    scene: &Scene<F, D, S>,
) -> Prediction<F> {
    if let Some(p) = crate::tiers::settled::answer(scene) {
        return p;
    }
    let dissipation = scene.dissipation();
    if !dissipation.dissipates() || (scene.is_grazing() && !dissipation.has_kernel()) {
        return exact_discrete(scene);
    }
    let asymptote = scene.asymptote();
    let start = scene.start_impulse();
    // The named forms are the asymptote's integral to J = 0; report them as they are.
    let named = match (scene.offset_class(), dissipation.has_kernel()) {
        // Unbounded: a time beyond the float's range becomes `Never` with its flag, below.
        (OffsetClass::Preload, false) => scene.t_b1v_unbounded().map(|e| (ClosedForm::Tb1v, e)),
        (OffsetClass::Gap, false) if scene.loss() > F::ZERO => {
            scene.t_b2r_unbounded().map(|e| (ClosedForm::Tb2r, e))
        }
        (OffsetClass::Gap, false) => scene.t_b2_unbounded().map(|e| (ClosedForm::Tb2, e)),
        _ => None,
    };
    let (form, expected, end_time) = match named {
        Some((form, estimate)) => (form, estimate.expected_error, Time::At(estimate.time)),
        None => (
            ClosedForm::Asymptotic,
            None,
            asymptote.fall_time(start, F::ZERO),
        ),
    };
    let count_to = |low: F| {
        if FULL {
            asymptote
                .fall_count::<S>(scene.orbit(), start, low)
                .after(F::ONE)
        } else {
            Count::Infinite
        }
    };
    let impacts_total = count_to(F::ZERO);
    let (last_above_time, impacts_above) = match scene.threshold_generating() {
        Some(end) => (
            asymptote.fall_time(start, end).min_with(end_time),
            count_to(end).min_with(impacts_total),
        ),
        None => (end_time, impacts_total),
    };
    Prediction::of_tier(
        scene,
        Course {
            end_time,
            last_above_time,
            impacts_above,
            impacts_total,
        },
        Tier::Closed(form),
        Approximations::NONE,
        if FULL {
            accuracy::with_reduction(scene, expected)
        } else {
            None
        },
    )
}

/// Exact discrete impacts: zeta = 0 (any Delta; impulses x R per impact) or Delta = 0 with
/// viscous damping (flights pi / Omega_d, impulses x R exp(-zeta Omega pi / Omega_d)). The
/// exact tier answers those scenes with it too (without the closed forms of sec. 5, which it
/// then does not link).
pub(crate) fn exact_discrete<F: Float, D: Dissipation<F>, S: OffsetSign>(
    scene: &Scene<F, D, S>,
) -> Prediction<F> {
    let zeta = scene.dissipation().damping_ratio();
    let omega = scene.omega();
    let loss_decay = -(-scene.loss()).ln_1p();
    // Its callers send a scene that dissipates here only with Delta = 0, so a mechanism that
    // always dissipates ([`Viscous`](crate::Viscous)) is grazing at compile time, and its
    // firmware links none of the undamped sums below.
    let grazing = scene.dissipation().dissipates() || scene.is_grazing();
    // Per-impact decay of the impulse, and (Delta = 0 only) the constant flight time.
    let (decay, grazing_flight) = if grazing {
        let damped = omega * (F::ONE - zeta * zeta).sqrt();
        (
            loss_decay + zeta * omega * F::PI / damped,
            Some(F::PI / damped),
        )
    } else {
        (loss_decay, None)
    };
    let time_of = |n: F| match grazing_flight {
        Some(flight) => n * flight,
        None => scene.undamped_flights_until(n),
    };
    // Only a preload accumulates (Delta = 0 decays without end).
    let end_time = match scene.regime() {
        Regime::ZenoAccumulation if !grazing => scene
            .undamped_accumulation_time()
            .map_or(Time::Never, Time::At),
        _ => Time::Never,
    };
    let (last_above_time, impacts_above) = match scene.threshold_impulse() {
        Some(threshold) => {
            let n = impacts_above_geometric(scene.first_impulse(), threshold, decay);
            if n.is_finite() {
                (Time::At(time_of(n - F::ONE)), Count::Finite(n))
            } else {
                // More impacts than the float counts: beyond range (flagged by the caller).
                (Time::At(F::MAX * F::TWO), Count::Finite(n))
            }
        }
        None => (end_time, Count::Infinite),
    };
    Prediction::of_tier(
        scene,
        Course {
            end_time,
            last_above_time,
            impacts_above,
            impacts_total: Count::Infinite,
        },
        Tier::Closed(if grazing {
            ClosedForm::Grazing
        } else {
            ClosedForm::Undamped
        }),
        Approximations::NONE,
        accuracy::with_reduction(scene, Some(accuracy::exact_sum::<F>())),
    )
}

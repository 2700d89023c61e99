//! The averaged model J' = E1(J): docs/physics.md sec. 3.
//!
//! Started from J_B = 2 R v0 (the first flight's generating impulse), the bounce time and the
//! impact count are t = integral dJ / |E1|, n = 1 + integral dJ / (|E1| T), computed in s = ln J
//! (smooth, bounded integrands) by composite Gauss-Legendre, panels at most 0.5 wide, with
//! [`Nodes`] points each. On the way to J = 0, below J = 5e-3 Omega |Delta| where the scene
//! dissipates between impacts, and below [`Tuning::TAIL_CUTOFF`](crate::numeric::Tuning::TAIL_CUTOFF)
//! Omega |Delta| (exact to rounding) with restitution alone, the small-impulse asymptote of E1
//! (docs/physics.md sec. 4) is integrated in closed form: its relative error there is O(cutoff),
//! on a tail that is itself O(cutoff) of the total (with damping, 8e-10 to 1e-8 of the end on the
//! catalogue's switches, far below the tier's own error of 1 % and more).

use crate::numeric::quadrature::{integrate_exp, panel, Nodes, MAX_PANELS, PANEL_WIDTH};
use crate::physics::duration::{Count, Time};
use crate::physics::error::{non_negative, normal, Error, Parameter, Reason};
use crate::physics::mechanisms::{Asymptote, Dissipation};
use crate::physics::regime::Regime;
use crate::scene::preloaded::lean_preload;
use crate::scene::{AnySign, OffsetSign};
use crate::tiers::accuracy;
use crate::tiers::approximations::Approximations;
use crate::tiers::prediction::{Course, Prediction, Tier};
use crate::{Float, Preloaded, Scene};

/// The averaged model's bounce time (s) of a preloaded contact with restitution alone, straight
/// from its datasheet-like inputs, with no [`Scene`] and no expected error: the lean path for
/// firmware that needs a window and nothing else ([`Window::from_seconds`]). With E1 = -r J / T
/// and T = 2 atan(J / |q|) / Omega, q = 2 Omega Delta, the bounce from J_B = 2 R v0 to rest takes
///
/// t = (2 / (r Omega)) Ti2(J_B / |q|), Ti2(x) = integral_0^x atan(y) / y dy,
///
/// in closed form: the value [`Method::Averaged`](crate::Method::Averaged) gives for the same
/// contact as a `Scene<F, Undamped>` (to rounding; the nodes do not matter there), and it links
/// the checks, one square root, twelve arctangents and one logarithm (above j0 = 2). Its error
/// against the exact bounce is the averaged model's on a preload (`docs/physics.md` sec. 6: at
/// j0 = 1 long by 4.7 % at R = 0.05, 1.7 % at R = 0.5, 0.26 % at R = 0.9, and less below); for
/// an expected error, build the scene and predict.
///
/// [`Window::from_seconds`]: crate::Window::from_seconds
///
/// ```
/// use contact_bounce::{tiers::preload_restitution_bounce_seconds, Margin, Preloaded, Window};
/// let t = preload_restitution_bounce_seconds(&Preloaded {
///     mass: 5e-5_f32, stiffness: 5000.0, preload_force: 1.0,
///     closing_speed: 0.5, restitution: 0.7, damping_ratio: 0.0, // restitution alone
/// })?;
/// let window = Window::from_seconds(t, &Margin::new(1.5, 0.0)?, 10e-6)?;
/// assert_eq!(window.ticks(), 18); // 116.3 us, +50 %
/// # Ok::<(), contact_bounce::Error>(())
/// ```
///
/// # Errors
/// As [`preload_viscous_bounce_time`](crate::tiers::preload_viscous_bounce_time) with no
/// damping: [`Parameter::Mass`], [`Parameter::Stiffness`], [`Parameter::PreloadForce`] or
/// [`Parameter::ClosingSpeed`] outside [`PHYSICAL_RANGE`](crate::scene::PHYSICAL_RANGE);
/// [`Parameter::Restitution`] outside [1e-6, 1 - 1e-12]; [`Parameter::ClosingSpeed`] with
/// [`Reason::Overflow`] for a first impulse below [`Scene::impulse_floor`] or Omega (1 + R) v0
/// above the float's largest value over 2^17; [`Parameter::PreloadForce`] with
/// [`Reason::Overflow`] when the time is not a normal number of the float (it overflowed, or
/// underflowed below the smallest normal number); [`Parameter::DampingRatio`] with
/// [`Reason::OutOfRange`] for any damping ratio but 0 (the path has no damping: use
/// [`preload_viscous_bounce_seconds`](crate::tiers::preload_viscous_bounce_seconds)).
pub fn preload_restitution_bounce_seconds<F: Float>(switch: &Preloaded<F>) -> Result<F, Error> {
    let p = lean_preload(switch)?;
    // Restitution alone: a damping ratio would be left out of the time without a word.
    if switch.damping_ratio != F::ZERO {
        return Err(Error::new(Parameter::DampingRatio, Reason::OutOfRange));
    }
    // J_B / |q| = j0 / 2.
    let integral = crate::numeric::quadrature::inverse_tangent_integral(p.j0 * F::HALF);
    let time = F::TWO * integral / p.loss * p.inverse_omega;
    normal(time, Parameter::PreloadForce).map(|()| time)
}

/// The averaged model of a scene, integrated with a given number of nodes per panel.
///
/// ```
/// use contact_bounce::{tiers::Averaged, Contact, Frequency, Nodes, Offset, Restitution, Scene, Threshold, Undamped};
/// let scene = Scene::new(Contact {
///     frequency: Frequency::Omega(1000.0_f64), offset: Offset::Delta(-1e-3),
///     restitution: Restitution::Coefficient(0.9), closing_speed: 0.01, threshold: Threshold::None,
/// }, Undamped)?;
/// let averaged = Averaged::new(&scene, Nodes::N8);
/// let end = averaged.predict().end_time.seconds().unwrap();
/// // j0 = 0.018: the bouncing-ball limit t_b1 holds to ~1e-4.
/// let t_b1 = scene.t_b1().unwrap().time;
/// assert!((end / t_b1 - 1.0).abs() < 1e-3);
/// // The envelope falls from J_B at t = 0 to 0 at the end.
/// assert!((averaged.envelope(0.0)?.impulse - scene.start_impulse()).abs() < 1e-15);
/// assert_eq!(averaged.envelope(end * 1.01)?.impulse, 0.0);
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Averaged<'a, F, D, S = AnySign> {
    scene: &'a Scene<F, D, S>,
    nodes: Nodes,
}

/// The averaged state at a time.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct EnvelopePoint<F> {
    /// The generating impulse J(t) (m/s); 0 once the bounce has ended.
    pub impulse: F,
    /// The averaged number of impacts up to t, impact 0 included (infinite past a Zeno end).
    pub impacts: Count<F>,
}

/// Positions of the two contacts reconstructed from the envelope (the paper's laws of motion,
/// Fig. 3).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Motion<F> {
    /// x = x1 - x2 (m).
    pub relative: F,
    /// x1 (m).
    pub body1: F,
    /// x2 (m).
    pub body2: F,
}

/// How the relative motion is shared between the bodies: x1 = X + (m2/M) x, x2 = X - (m1/M) x,
/// X the centre of mass, a free damped oscillator (exact when the partial frequencies match).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Bodies<F> {
    /// m1 / (m1 + m2), in [0, 1].
    pub mass_fraction_1: F,
    /// X(0) (m).
    pub centre: F,
    /// X'(0) (m/s).
    pub centre_velocity: F,
}

impl<F: Float> Bodies<F> {
    /// Equal masses, centre of mass at rest at 0: the paper's x1 = -J chi / 2, x2 = J chi / 2.
    #[must_use]
    pub fn equal_at_rest() -> Self {
        Self {
            mass_fraction_1: F::HALF,
            centre: F::ZERO,
            centre_velocity: F::ZERO,
        }
    }
    /// Body 2 at `x2` moving at `v2`, body 1 at x2 + Delta closing at v0 relative to body 2,
    /// with mass fraction m1 / (m1 + m2).
    #[must_use]
    pub fn from_initial(mass_fraction_1: F, delta: F, closing_speed: F, x2: F, v2: F) -> Self {
        Self {
            mass_fraction_1,
            centre: x2 + mass_fraction_1 * delta,
            centre_velocity: v2 + mass_fraction_1 * closing_speed,
        }
    }
}

/// x(t) of x'' + 2 zeta Omega x' + Omega^2 x = 0 from x(0), x'(0): under-, critically and
/// over-damped.
pub(crate) fn free_damped<F: Float>(omega: F, zeta: F, x0: F, v0: F, t: F) -> F {
    if x0 == F::ZERO && v0 == F::ZERO {
        // At rest it stays at rest, whatever the phase (which may overflow at large t).
        return F::ZERO;
    }
    if zeta < F::ONE {
        let damped = omega * (F::ONE - zeta * zeta).sqrt();
        let decay = (-zeta * omega * t).exp();
        if decay == F::ZERO {
            // Decayed beyond the float's range: the phase no longer matters.
            return F::ZERO;
        }
        decay * (x0 * (damped * t).cos() + (v0 + zeta * omega * x0) / damped * (damped * t).sin())
    } else if zeta == F::ONE {
        (-omega * t).exp() * (x0 + (v0 + omega * x0) * t)
    } else {
        let root = (zeta * zeta - F::ONE).sqrt();
        let slow = -omega / (zeta + root); // -omega (zeta - root), without cancellation
        let fast = -omega * (zeta + root);
        let a = (v0 - fast * x0) / (slow - fast);
        a * (slow * t).exp() + (x0 - a) * (fast * t).exp()
    }
}

/// (1 - e^-x) / x, accurate for small x.
fn relaxed<F: Float>(x: F) -> F {
    if x.abs() < F::from_f64(1e-8) {
        F::ONE - x * F::HALF
    } else {
        -(-x).exp_m1() / x
    }
}

impl<'a, F: Float, D: Dissipation<F>, S: OffsetSign> Averaged<'a, F, D, S> {
    /// The averaged model of `scene` with `nodes` points per panel.
    #[must_use]
    pub const fn new(scene: &'a Scene<F, D, S>, nodes: Nodes) -> Self {
        Self { scene, nodes }
    }

    /// The impulse below which the asymptote replaces the quadrature (0: none, when Delta = 0
    /// makes E1 exactly linear, or when the asymptote is degenerate).
    fn cutoff(&self) -> F {
        let a = self.scene.asymptote();
        let degenerate = a.constant <= F::ZERO && a.linear <= F::ZERO && a.inverse <= F::ZERO;
        if degenerate {
            F::ZERO
        } else {
            Asymptote::<F>::tail_cutoff(self.scene.dissipation().dissipates())
                * self.scene.omega()
                * self.scene.delta().abs()
        }
    }

    /// The integrands in s = ln J: (J / |E1|, J / (|E1| T)).
    fn integrand(&self, s: F) -> (F, F) {
        self.integrand_at(s.exp())
    }

    /// The integrands in s = ln J at J = e^s.
    ///
    /// Outlined on AVR: a quadrature panel evaluates it at two nodes, and inlined at both it
    /// took 1.5 KB more of the Uno's flash in the averaged and exact tiers (and 34k more
    /// cycles on the dome: the inlined copies spilled); on Cortex-M the inliner decides.
    #[cfg_attr(target_arch = "avr", inline(never))]
    fn integrand_at(&self, impulse: F) -> (F, F) {
        let point = self.scene.orbit().at(impulse);
        let w = impulse / -self.scene.rate_at(&point);
        (w, w / point.period())
    }

    /// [`Averaged::fall`] with restitution alone, in closed form: E1 = -r J / T(J),
    /// T = 2 theta / Omega, so t = (2 / (r Omega)) integral theta dJ / J and n = ln(J1 / J2) / r.
    /// With theta = atan(J / |q|) on a preload (q = 2 Omega Delta) the integral is
    /// Ti2(J1 / |q|) - Ti2(J2 / |q|), Ti2 the inverse tangent integral; with
    /// theta = pi - atan(J / q) in a gap it is pi ln(J1 / J2) minus that; at Delta = 0,
    /// (pi / 2) ln(J1 / J2). Exact for the averaged model (Ti2 to 1e-16): the nodes do not
    /// matter here. Taken for [`Undamped`](crate::Undamped) scenes (a damped type with zeta 0
    /// integrates numerically, to the same value within the quadrature's error).
    fn restitution_only_fall(&self, high: F, low: F) -> (Time<F>, Count<F>, bool) {
        let scene = self.scene;
        let loss = scene.loss();
        if high <= low {
            return (Time::At(F::ZERO), Count::Finite(F::ZERO), false);
        }
        if loss <= F::ZERO {
            // No loss at all: J never falls.
            return (Time::Never, Count::Infinite, false);
        }
        let q = scene.orbit().offset_impulse();
        let ti2 = crate::numeric::quadrature::inverse_tangent_integral;
        let ratio_ln = if low > F::ZERO {
            Some(high.ln() - low.ln())
        } else {
            None
        };
        let integral = if q < F::ZERO {
            let scale = -q;
            let lower = if low > F::ZERO {
                ti2(low / scale)
            } else {
                F::ZERO
            };
            Some(ti2(high / scale) - lower)
        } else if q > F::ZERO {
            ratio_ln.map(|l| F::PI * l - (ti2(high / q) - ti2(low / q)))
        } else {
            ratio_ln.map(|l| F::HALF * F::PI * l)
        };
        let time = integral.map_or(Time::Never, |i| {
            let t = F::TWO * i / (loss * scene.omega());
            if t.is_finite() {
                Time::At(t)
            } else {
                Time::Never
            }
        });
        let count = ratio_ln.map_or(Count::Infinite, |l| Count::Finite(l / loss));
        (time, count, false)
    }

    /// Time and impacts while J falls from `high` to `low` (0 <= low < high), and whether the
    /// panel cap was hit: quadrature down to the cutoff, the asymptote below it.
    pub(crate) fn fall(&self, high: F, low: F) -> (Time<F>, Count<F>, bool) {
        if D::NEVER_DISSIPATES {
            // (A scene type without damping links none of the quadrature below, and a damped
            // one none of this.)
            return self.restitution_only_fall(high, low);
        }
        // The asymptote only replaces the quadrature on the way to J = 0 (where its tail is
        // O(cutoff) of the total); down to a threshold the quadrature goes all the way.
        let cut = if low > F::ZERO {
            F::ZERO
        } else {
            self.cutoff()
        };
        let quad_low = low.max(cut);
        let (mut time, mut impacts, mut capped) = (F::ZERO, F::ZERO, false);
        if quad_low > F::ZERO && high > quad_low {
            let ((t, n), cap) = integrate_exp(quad_low.ln(), high.ln(), self.nodes, |j| {
                self.integrand_at(j)
            });
            // (NaN, negative and infinite in two comparisons: on the Uno 52-104 B smaller in
            // each tier that integrates than testing NaN, sign and finiteness apart.)
            if !(t >= F::ZERO && t <= F::MAX) {
                // The decay rate vanished in this float on the way down (it underflows, or
                // rounds to the wrong sign, at small J): J does not reach `low` in any time
                // the float can tell.
                return (Time::Never, Count::Infinite, cap);
            }
            (time, impacts, capped) = (t, n, cap);
            if !impacts.is_finite() {
                return (Time::At(time), Count::Infinite, capped);
            }
        }
        let asymptote_top = if quad_low > F::ZERO {
            high.min(quad_low)
        } else {
            high
        };
        if low < asymptote_top {
            let a = self.scene.asymptote();
            let Time::At(t) = a.fall_time(asymptote_top, low) else {
                return (Time::Never, Count::Infinite, capped);
            };
            time += t;
            return match a.fall_count::<S>(self.scene.orbit(), asymptote_top, low) {
                Count::Finite(n) => (Time::At(time), Count::Finite(impacts + n), capped),
                Count::Infinite => (Time::At(time), Count::Infinite, capped),
            };
        }
        (Time::At(time), Count::Finite(impacts), capped)
    }

    /// The averaged prediction (docs/physics.md sec. 3). Expected error: docs/physics.md sec. 6 (preload
    /// at j0 <= 1 long by at most 4.7 % (R = 0.05), 1.7 % from R = 0.5; gap end -4 % to +99 % with
    /// few impacts; thresholds ~ r/2).
    ///
    /// Outlined on AVR: inlined into a firmware's caller it spills more than the call costs
    /// (800 B of the Uno's flash for the averaged tiers); on Cortex-M the inliner decides.
    #[must_use]
    #[cfg_attr(target_arch = "avr", inline(never))]
    pub fn predict(&self) -> Prediction<F> {
        self.predict_as::<true>().within_range()
    }

    /// The times of [`Averaged::predict`] alone (see [`Scene::bounce_time`]): its counts are
    /// worked out, its expected error is not (`None`, a placeholder no caller reads), and
    /// nothing is brought within range. Outlined on AVR, as [`Averaged::predict`].
    #[cfg_attr(target_arch = "avr", inline(never))]
    pub(crate) fn predict_times(&self) -> Prediction<F> {
        self.predict_as::<false>()
    }

    /// The prediction, with every field (`FULL`) or without the expected error.
    fn predict_as<const FULL: bool>(&self) -> Prediction<F> {
        if let Some(p) = crate::tiers::settled::answer(self.scene) {
            return p;
        }
        let start = self.scene.start_impulse();
        let ends = matches!(
            self.scene.regime(),
            Regime::ZenoAccumulation | Regime::LastImpact
        );
        let (threshold_part, rest_from) = match self.scene.threshold_generating() {
            Some(end) => (Some(self.fall(start, end)), end),
            None => (None, start),
        };
        let (end_time, impacts_total, cap_end) = if ends {
            let (t_rest, n_rest, cap) = self.fall(rest_from, F::ZERO);
            match threshold_part {
                // The rest follows the fall to the threshold: the end is their sum, beyond
                // what the float tells where either part is (a threshold part that was not a
                // finite time and count used to be dropped, and the end taken from the
                // threshold on; no input is known to reach that, but nothing rules it out).
                Some((Time::At(t), n, _)) => (
                    t_rest.after(t),
                    // (A count beyond the float's range is infinite: flagged by the caller.)
                    n_rest.value().map_or(Count::Infinite, |nr| {
                        Count::Finite(n.value().unwrap_or(F::MAX * F::TWO) + nr + F::ONE)
                    }),
                    cap,
                ),
                Some(_) => (Time::Never, Count::Infinite, cap),
                None => (t_rest, n_rest.after(F::ONE), cap),
            }
        } else {
            (Time::Never, Count::Infinite, false)
        };
        let (last_above_time, impacts_above, cap_above) = match threshold_part {
            Some((t, n, cap)) => (t, n.after(F::ONE), cap),
            None => (end_time, impacts_total, false),
        };
        let approximations = if cap_end || cap_above {
            Approximations::PANELS_CAPPED
        } else {
            Approximations::NONE
        };
        let expected = if FULL {
            accuracy::with_reduction(
                self.scene,
                accuracy::averaged(self.scene, impacts_total.value())
                    .map(|e| e + accuracy::quadrature::<F>(self.nodes)),
            )
        } else {
            None
        };
        Prediction::of_tier(
            self.scene,
            Course {
                end_time,
                last_above_time,
                impacts_above,
                impacts_total,
            },
            Tier::Averaged(self.nodes),
            approximations,
            expected,
        )
    }

    /// The envelope J(t) and the averaged impact count at time `t` >= 0 (s): the inverse of
    /// t(J), found panel by panel and then by safeguarded Newton inside the panel, to a few ULP
    /// of ln J.
    ///
    /// # Errors
    /// [`Parameter::Time`] when `t` is NaN, infinite or negative.
    pub fn envelope(&self, t: F) -> Result<EnvelopePoint<F>, Error> {
        let t = non_negative(t, Parameter::Time)?;
        let scene = self.scene;
        let start = scene.start_impulse();
        match scene.regime() {
            Regime::SingleImpact => {
                return Ok(EnvelopePoint {
                    impulse: if t > F::ZERO { F::ZERO } else { start },
                    impacts: Count::Finite(F::ONE),
                })
            }
            Regime::Periodic => {
                let period = scene.orbit().at(start).period();
                return Ok(EnvelopePoint {
                    impulse: start,
                    impacts: counted(F::ONE + (t / period).floor()),
                });
            }
            _ => {}
        }
        // Regimes that end hand over to the asymptote at the cutoff, or at the threshold where
        // that is lower (the prediction integrates all the way down to a threshold, and the
        // envelope meets it at the prediction's last time above it); endless ones march on.
        let ends = matches!(
            scene.regime(),
            Regime::ZenoAccumulation | Regime::LastImpact
        );
        let cut = if ends {
            let cutoff = self.cutoff();
            scene
                .threshold_generating()
                .map_or(cutoff, |end| cutoff.min(end))
        } else {
            F::ZERO
        };
        // Never march below the impulse floor (the phase would turn subnormal, E1 vanish).
        let floor = scene.impulse_floor().ln();
        let s_cut = Some(if cut > F::ZERO {
            cut.ln().max(floor)
        } else {
            floor
        });
        let mut s_hi = start.ln();
        let mut elapsed = F::ZERO;
        let mut impacts = F::ONE;
        let width = F::from_f64(PANEL_WIDTH);
        let mut f = |s: F| self.integrand(s);
        for _ in 0..MAX_PANELS {
            let mut s_lo = s_hi - width;
            if let Some(c) = s_cut {
                s_lo = s_lo.max(c);
            }
            if s_lo >= s_hi {
                break;
            }
            let (dt, dn) = panel(s_lo, s_hi, self.nodes, &mut f);
            if dt.is_nan() || dt <= F::ZERO || !dt.is_finite() {
                // Below s_hi the decay rate vanishes in this float: J stays where it is, and
                // the impacts go on at its period.
                let impulse = s_hi.exp();
                let period = scene.orbit().at(impulse).period();
                return Ok(EnvelopePoint {
                    impulse,
                    impacts: counted(impacts + (t - elapsed) / period),
                });
            }
            if elapsed + dt >= t {
                let s = self.solve_in_panel(s_lo, s_hi, t - elapsed, dt);
                let (_, dn_part) = panel(s, s_hi, self.nodes, &mut f);
                return Ok(EnvelopePoint {
                    impulse: s.exp(),
                    impacts: counted(impacts + dn_part),
                });
            }
            elapsed += dt;
            impacts += dn;
            s_hi = s_lo;
        }
        // Below the cutoff: invert the asymptote in closed form.
        let from = s_hi.exp();
        let tau = t - elapsed;
        let a = scene.asymptote();
        let impulse = if a.inverse > F::ZERO {
            let squared = from * from * (-F::TWO * a.linear * tau).exp()
                - F::TWO * a.inverse * tau * relaxed(F::TWO * a.linear * tau);
            if squared > F::ZERO {
                squared.sqrt()
            } else {
                F::ZERO
            }
        } else if a.constant > F::ZERO {
            let j = from * (-a.linear * tau).exp() - a.constant * tau * relaxed(a.linear * tau);
            j.max(F::ZERO)
        } else {
            from * (-a.linear * tau).exp()
        };
        let more = if impulse > F::ZERO {
            a.fall_count::<S>(scene.orbit(), from, impulse)
        } else {
            a.fall_count::<S>(scene.orbit(), from, F::ZERO)
        };
        Ok(EnvelopePoint {
            impulse,
            impacts: match more {
                Count::Finite(n) => counted(impacts + n),
                Count::Infinite => Count::Infinite,
            },
        })
    }

    /// s in [s_lo, s_hi] with integral_s^{s_hi} J/|E1| ds = goal (0 <= goal <= whole).
    fn solve_in_panel(&self, s_lo: F, s_hi: F, goal: F, whole: F) -> F {
        let mut f = |s: F| self.integrand(s);
        let (mut lo, mut hi) = (s_lo, s_hi);
        let mut s = if whole > F::ZERO {
            s_hi - (s_hi - s_lo) * (goal / whole)
        } else {
            s_hi
        };
        for _ in 0..60 {
            let (done, _) = panel(s, s_hi, self.nodes, &mut f);
            let excess = done - goal;
            if excess > F::ZERO {
                lo = s;
            } else {
                hi = s;
            }
            let slope = f(s).0;
            let mut next = s + excess / slope;
            if !(next > lo && next < hi) {
                next = (lo + hi) * F::HALF;
            }
            let step = (next - s).abs();
            s = next;
            if step <= F::from_f64(4.0) * F::EPSILON * s.abs().max(F::ONE)
                || hi - lo <= F::EPSILON * s.abs().max(F::ONE)
            {
                break;
            }
        }
        s
    }

    /// The positions of the contacts at time `t` (s) reconstructed from the envelope: the
    /// relative x(t) = -J(t) chi(tau), tau the time since the last averaged impact
    /// (frac(N(t) - 1) T(J)), shared between the bodies about the centre of mass. After the
    /// bounce ends the relative position is the rest: Delta for a preload (closed), 0 for a gap.
    ///
    /// # Errors
    /// [`Parameter::Time`] when `t` is NaN, infinite or negative, or with [`Reason::Overflow`]
    /// when an undamped, moving centre of mass has a phase `Omega t` beyond the float's range;
    /// [`Parameter::ClosingSpeed`] with [`Reason::Overflow`] when a position leaves the float's
    /// range (an orbit amplitude h / (2 Omega) beyond it).
    pub fn motion(&self, t: F, bodies: &Bodies<F>) -> Result<Motion<F>, Error> {
        let point = self.envelope(t)?;
        let scene = self.scene;
        let orbit = scene.orbit();
        let relative = match point.impacts {
            Count::Finite(n) if point.impulse > F::ZERO => {
                let p = orbit.at(point.impulse);
                let cycles = n - F::ONE;
                let fraction = cycles - cycles.floor();
                let local = if fraction > F::ZERO {
                    fraction * p.period()
                } else {
                    p.period()
                };
                let local = if t <= F::ZERO { F::ZERO } else { local };
                -(p.hypot() / (F::TWO * orbit.omega()))
                    * (orbit.omega() * local - p.phase()).cos_within_pi()
            }
            _ => scene.delta().min(F::ZERO),
        };
        let centre = free_damped(
            orbit.omega(),
            scene.dissipation().damping_ratio(),
            bodies.centre,
            bodies.centre_velocity,
            t,
        );
        if !centre.is_finite() {
            // An undamped centre of mass whose phase Omega t is beyond the float's range.
            return Err(Error::new(Parameter::Time, Reason::Overflow));
        }
        let motion = Motion {
            relative,
            body1: centre + (F::ONE - bodies.mass_fraction_1) * relative,
            body2: centre - bodies.mass_fraction_1 * relative,
        };
        if !(motion.relative.is_finite() && motion.body1.is_finite() && motion.body2.is_finite()) {
            // The orbit's amplitude h / (2 Omega) beyond the float's range (a huge closing
            // speed over a tiny Omega): no position this float can tell.
            return Err(Error::new(Parameter::ClosingSpeed, Reason::Overflow));
        }
        Ok(motion)
    }
}

/// A count as the envelope reports it: beyond the float's range it is `Infinite`, as a
/// prediction's count is (never `Finite(inf)`).
fn counted<F: Float>(n: F) -> Count<F> {
    if n.is_finite() {
        Count::Finite(n)
    } else {
        Count::Infinite
    }
}

//! The damped flight between two impacts (docs/physics.md sec. 1): the motion in closed form
//! and as a series, and its return to the stop.
//!
//! Between impacts x'' + 2 zeta Omega x' + Omega^2 x = 0 is solved in closed form (under-,
//! critically and over-damped). The next impact is the root of y = x - Delta in the bracket
//! where y rises monotonically, from the first minimum of x to its next maximum; if y is still
//! negative at that maximum, impacts have ended. The root is found by Newton steps started from
//! the undamped flight (2 / Omega) atan2(a, -Omega Delta) and kept inside the bracket by
//! bisection, at most [`ROOT_STEPS`] evaluations. A preload's flights start instead from a
//! guess within a few percent and take Halley steps (y'' is given by the equation of motion):
//! below a departure of Omega |Delta| / 4, the flight's own power series in the departure
//! (`flight_series.rs`, within about (2.2 a / (Omega |Delta|))^12 of it, so one evaluation
//! settles it); above, the previous flight scaled as the undamped flights scale (two
//! evaluations).
//!
//! Under-damped, the closed form is written without cancellation in the displacement's own
//! part (e^(-alpha t) cos wt - 1 as expm1(-alpha t) cos wt - 2 sin^2(wt / 2)); what it still
//! loses near a root is the decay's linear term, zeta / (Omega t) of y's scale. Flights shorter
//! than 2 zeta / Omega in f64 (0.5 / Omega in f32, where the closed form's return speed is
//! biased by half an epsilon; and, at any damping, lambda t <= 0.5, lambda the fastest rate of
//! the free motion) are evaluated from the Taylor series of y(t) / t about the departure instead:
//! the trivial root at t = 0 is divided out, so the tiny flights of a Zeno accumulation keep
//! their digits.

use crate::numeric::c;
use crate::numeric::float::exp_and_m1;
use crate::physics::sign::{AnySign, OffsetSign};
use crate::Float;

/// Most evaluations of the motion spent on one flight's return (Newton steps, bisections and
/// the bracket's own evaluations): with [`EXACT_MAX_IMPACTS`](crate::tiers::EXACT_MAX_IMPACTS) it
/// bounds the work of one prediction, see [`Scene::exact_work`](crate::Scene::exact_work).
pub const ROOT_STEPS: u32 = 128;

/// Most Halley steps tried from a guess before the bracketed search takes over.
pub(crate) const HALLEY_STEPS: u32 = 6;

/// lambda t below which y(t) / t is summed as a series. Above it the closed form loses at most
/// |Delta| / |y| ~ a few epsilon at the root (y rises at the return speed over a flight long
/// enough for lambda t > 0.5).
pub(crate) const SERIES_LIMIT: f64 = 0.5;
/// Under-damped, the closed form keeps the displacement's own part free of cancellation
/// (`expm1` and the half angle), and what it loses near a root is the decay's linear term, of
/// relative size zeta / (Omega t) against y's: the series serves only below this times
/// zeta / Omega (and below [`SERIES_LIMIT`]), in f64 only
/// ([`Tuning::SHORT_FLIGHTS_CLOSED`](crate::numeric::Tuning)). Measured by the test
/// `the_closed_form_meets_the_series_at_the_root` (zeta 0.001-0.9, departures 1e-4 to 1
/// Omega |Delta|): the two roots agree within 7.3 epsilon of the flight (12.2 with a quarter
/// of this limit).
pub(crate) const UNDER_SERIES_LIMIT: f64 = 2.0;
/// A clearance (the top of a flight relative to the stop) within this many epsilons of |Delta|
/// decides a return by rounding: the count may be off by one.
pub(crate) const GRAZING_EPSILONS: f64 = 64.0;
/// (sin x, cos x) for the phases of one flight (0 <= x <= ~3 pi, the bracket's end): reduced by
/// whole turns into [-pi, pi) and summed by [`Float::sin_within_pi`], so the tier links no libm
/// `sin`/`cos` (their range reduction alone is several KB of flash). Absolute error a few ULP
/// of the phase; below pi x is not touched, so sin x keeps its relative accuracy at small x
/// (the half angle of a short flight).
pub(crate) fn sin_cos_small<F: Float>(x: F) -> (F, F) {
    let turn = F::TWO * F::PI;
    let turns = if x < F::PI {
        F::ZERO
    } else {
        ((x + F::PI) / turn).floor()
    };
    // y = x - whole turns, in [-pi, pi) (x itself below pi).
    let y = x - turns * turn;
    (y.sin_within_pi(), y.cos_within_pi())
}

/// The running sums of a flight's Taylor series, y(t) / t = sum c_k t^(k - 1) and
/// y'(t) = sum k c_k t^(k - 1), fed one coefficient at a time (k >= 2; c_1 starts them).
#[derive(Debug, Clone, Copy)]
pub(crate) struct TaylorSum<F> {
    pub(crate) over_t: F,
    pub(crate) slope: F,
    pub(crate) power: F,
    pub(crate) quiet: u32,
}

impl<F: Float> TaylorSum<F> {
    pub(crate) fn new(first: F) -> Self {
        Self {
            over_t: first,
            slope: first,
            power: F::ONE,
            quiet: 0,
        }
    }

    /// Adds c_k at `t`: true once `settle` terms in a row were below 1 % of an epsilon of the
    /// sums (the series is summed).
    #[inline]
    pub(crate) fn add(&mut self, k: F, coefficient: F, t: F, settle: u32) -> bool {
        self.power *= t;
        let term = coefficient * self.power;
        self.over_t += term;
        self.slope += k * term;
        let scale = (k * self.over_t.abs()).max(self.slope.abs());
        if k * term.abs() <= F::EPSILON * c::<F>(0.01) * scale {
            self.quiet += 1;
            self.quiet >= settle
        } else {
            self.quiet = 0;
            false
        }
    }
}

/// The free motion's constants.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Damping<F> {
    /// zeta < 1: decay alpha = zeta Omega, frequency w = Omega sqrt(1 - zeta^2).
    Under { alpha: F, w: F },
    /// zeta = 1.
    Critical,
    /// zeta > 1: the two real rates (negative), slow and fast.
    Over { slow: F, fast: F },
}

/// x'' + 2 zeta Omega x' + Omega^2 x = 0 between impacts at x = Delta; `S`, the sign of Delta
/// where its scene's type fixes it (a preload's flights then link no gap's branch).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Oscillator<F, S = AnySign> {
    pub(crate) omega: F,
    pub(crate) zeta: F,
    pub(crate) delta: F,
    pub(crate) damping: Damping<F>,
    /// The fastest rate of the free motion (1/s).
    pub(crate) lambda: F,
    pub(crate) sign: core::marker::PhantomData<S>,
}

/// How a flight that leaves the stop ends.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Landing<F> {
    /// It returns after this time (s) at this speed (m/s); `grazing` when the return was
    /// decided by rounding (its top within [`GRAZING_EPSILONS`] of the stop).
    Returns { time: F, speed: F, grazing: bool },
    /// It does not return (`grazing` as above). Where rounding decided that, `touch` is the
    /// latest time (s) its swing may still reach the stop (0 where not so decided, or not
    /// known): the bounce may last that long.
    Stays { grazing: bool, touch: F },
}

#[cfg(test)]
impl<F: Float> Oscillator<F> {
    pub(crate) fn new(omega: F, zeta: F, delta: F) -> Self {
        Self::signed(omega, zeta, delta)
    }
}

impl<F: Float, S: OffsetSign> Oscillator<F, S> {
    /// The oscillator of a scene of sign type `S` (its `delta` on the side `S` admits).
    pub(crate) fn signed(omega: F, zeta: F, delta: F) -> Self {
        let (damping, lambda) = if zeta < F::ONE {
            let w = omega * ((F::ONE - zeta) * (F::ONE + zeta)).sqrt();
            (
                Damping::Under {
                    alpha: zeta * omega,
                    w,
                },
                omega,
            )
        } else if zeta == F::ONE {
            (Damping::Critical, omega)
        } else {
            let root = ((zeta - F::ONE) * (zeta + F::ONE)).sqrt();
            let fast = omega * (zeta + root);
            (
                Damping::Over {
                    slow: -omega / (zeta + root),
                    fast: -fast,
                },
                fast,
            )
        };
        Self {
            omega,
            zeta,
            delta,
            damping,
            lambda,
            sign: core::marker::PhantomData,
        }
    }

    /// (y(t), y'(t)) in closed form for a flight leaving at speed `a`.
    pub(crate) fn closed(&self, a: F, t: F) -> (F, F) {
        let (omega, delta) = (self.omega, self.delta);
        let v0 = -a;
        let (y, v) = match self.damping {
            Damping::Under { alpha, w } => {
                // y = Delta (e^(-alpha t) cos wt - 1) + e^(-alpha t) B sin wt, with
                // e^(-alpha t) cos wt - 1 = expm1(-alpha t) cos wt - 2 sin^2(wt / 2): no
                // difference of nearly equal numbers in the displacement's own part.
                let (s, co) = sin_cos_small(w * t * F::HALF);
                let (e, em) = exp_and_m1(-alpha * t);
                let (sine, versine) = (F::TWO * s * co, F::TWO * s * s);
                let cosine = F::ONE - versine;
                let y = delta * (em * cosine - versine) + e * (v0 + alpha * delta) / w * sine;
                return (
                    y,
                    e * (v0 * cosine - (alpha * v0 + omega * omega * delta) / w * sine),
                );
            }
            // Summed from the modes' departures, x - Delta = sum A expm1(s t), where that
            // rounds less (its terms are smaller), else from the modes themselves, sum A e^(s t)
            // - Delta: the first keeps a short flight's digits (from x near Delta it lost
            // log10(|Delta| / |y|) of them: an overdamped return in f32 off by up to 12 times
            // its figure), the second a long one's (a mode decayed to near Delta: A (e^(s t) -
            // 1) + A keeps nothing of A e^(s t); f32, a preload of 7e-15 m, 1.3 % off). The
            // critically damped flight by the time its mode has taken: an e-fold.
            Damping::Critical => {
                let (e, em) = exp_and_m1(-omega * t);
                let b = v0 + omega * delta;
                let from_departure = omega * t <= F::ONE;
                let y = if from_departure {
                    delta * em
                } else {
                    e * delta - delta
                } + e * b * t;
                (y, e * (v0 - omega * b * t))
            }
            Damping::Over { slow, fast } => {
                // A_s + A_f = Delta, each amplitude from its own numerator: A_f as Delta - A_s
                // lost the many epsilons by which it is smaller (1/142 of Delta at zeta 7).
                // Near critical damping both grow as 1 / (s - f) and cancel: the figure counts
                // that (`solve`), where a cosh/sinh form would cost the Uno's exact tier the
                // flash it does not have.
                let amp_slow = (v0 - fast * delta) / (slow - fast);
                let amp_fast = (slow * delta - v0) / (slow - fast);
                let (es, ems) = exp_and_m1(slow * t);
                let (ef, emf) = exp_and_m1(fast * t);
                let (ms, mf) = (amp_slow * es, amp_fast * ef);
                let (ds, df) = (amp_slow * ems, amp_fast * emf);
                let y = if ds.abs() + df.abs() <= ms.abs() + mf.abs() + delta.abs() {
                    ds + df
                } else {
                    ms + mf - delta
                };
                (y, slow * ms + fast * mf)
            }
        };
        (y, v)
    }

    /// (y(t) / t, y'(t)) from the Taylor series of y about the departure, in the time
    /// u = Omega t: y = sum d_k u^k with d1 = -a / Omega, d2 = (2 zeta a / Omega - Delta) / 2,
    /// d_{k+2} = -(2 zeta (k + 1) d_{k+1} + d_k) / ((k + 2)(k + 1)). (In seconds the
    /// coefficients grow as Omega^k: beyond f32's range at k = 7 for Omega = 1e6 rad/s.)
    pub(crate) fn series(&self, a: F, t: F) -> (F, F) {
        let zeta2 = F::TWO * self.zeta;
        let u = self.omega * t;
        let first = -a / self.omega;
        let (mut previous, mut current) = (first, (-zeta2 * first - self.delta) * F::HALF);
        let mut sum = TaylorSum::new(previous);
        let mut kf = F::ONE;
        for reciprocal in F::TAYLOR_RECIPROCALS.iter().skip(2) {
            kf += F::ONE;
            if sum.add(kf, current, u, 2) {
                break;
            }
            let next = -(zeta2 * kf * current + previous) * *reciprocal;
            previous = current;
            current = next;
        }
        (sum.over_t * self.omega, sum.slope * self.omega)
    }

    /// (y(t), y'(t)): the series for short times, the closed form beyond.
    pub(crate) fn eval(&self, a: F, t: F) -> (F, F) {
        // (Under-damped lambda = Omega; at zeta >= 1 the second test always holds.)
        let u = self.lambda * t;
        if u <= c(SERIES_LIMIT)
            && (!F::SHORT_FLIGHTS_CLOSED || u <= c::<F>(UNDER_SERIES_LIMIT) * self.zeta)
        {
            let (over_t, slope) = self.series(a, t);
            (over_t * t, slope)
        } else {
            self.closed(a, t)
        }
    }

    /// The first minimum of x after leaving the stop at `a` (x turns before any return).
    pub(crate) fn first_minimum(&self, a: F) -> Option<F> {
        let (omega, delta) = (self.omega, self.delta);
        match self.damping {
            Damping::Under { alpha, w } => {
                let k = (omega * omega * delta - alpha * a) / w;
                Some(a.atan2(-k) / w)
            }
            Damping::Critical => {
                let den = omega * (a - omega * delta);
                (den > F::ZERO).then(|| a / den)
            }
            Damping::Over { slow, fast } => {
                // x' = 0 where e^((s - f) t) = -f A_f / (s A_s) = 1 + a / (s A_s) (the numerator
                // -f A_f - s A_s is a exactly), taken as ln(1 + x): formed as a ratio of the
                // amplitudes it rounded to 1 for departures below an epsilon of Omega |Delta|,
                // and the preload's flight was taken for one that stays.
                // (ln(1 + x) by Goldberg's form, ln(u) x / (u - 1) with u = 1 + x, within a few
                // ulps: no `ln_1p` linked for it.)
                let amp_slow = (-a - fast * delta) / (slow - fast);
                let x = a / (slow * amp_slow);
                let u = F::ONE + x;
                let ln = if u == F::ONE {
                    x
                } else {
                    u.ln() * x / (u - F::ONE)
                };
                (x > F::ZERO).then(|| ln / (slow - fast))
            }
        }
    }

    /// True when `y` is within rounding of the stop.
    pub(crate) fn grazes(&self, y: F) -> bool {
        y.abs() <= c::<F>(GRAZING_EPSILONS) * F::EPSILON * self.delta.abs()
    }

    /// A preload's return by Halley steps alone (y'' comes free from the equation of motion,
    /// and the convergence is cubic), from a guess within a few percent (the previous flight
    /// scaled as the undamped flights scale). Once a step is below a tenth of
    /// [`Tuning::TAIL_CUTOFF`](crate::numeric::Tuning::TAIL_CUTOFF) (about the cube root of epsilon)
    /// of t, the next iterate is exact
    /// to rounding, and so is the return speed carried to it by its Taylor series to second
    /// order: no further evaluation. `None` when a step leaves 10 % of the guess, the speed is
    /// not rising or [`HALLEY_STEPS`] steps do not settle; the bracketed search then decides.
    /// (A preload always returns: x swings through rest, beyond the stop.)
    pub(crate) fn halley(&self, a: F, guess: F) -> Option<Landing<F>> {
        let (low, high) = (guess * c::<F>(0.9), guess * c::<F>(1.1));
        let damping = F::TWO * self.zeta * self.omega;
        let w2 = self.omega * self.omega;
        let settled = F::TAIL_CUTOFF * c::<F>(0.1);
        // The step in units of the departure speed: see below.
        let per_speed = F::ONE / a;
        let mut t = guess;
        for _ in 0..HALLEY_STEPS {
            let (y, v) = self.eval(a, t);
            if v <= F::ZERO || v.is_nan() {
                return None;
            }
            let acceleration = -damping * v - w2 * (y + self.delta);
            // Halley's step y / v / (1 - y a / (2 v^2)) = 2 y v / (2 v^2 - y a), one division;
            // Newton's y / v where the correction would more than double it (y a >= v^2).
            // Formed from y, v and a over the departure speed, a time, a number near 1 and a
            // rate, never from the plain products y v and v^2: at small lengths those fell below
            // the float's normal range and lost their digits (f32, a preload of Delta = -9e-19 m
            // at R = 1: steps settled on rounding, and the bounce ended 23 % early, stating 5 %).
            let (ys, vs) = (y * per_speed, v * per_speed);
            let (square, curvature) = (vs * vs, ys * (acceleration * per_speed));
            let step = if square > curvature {
                F::TWO * ys * vs / (F::TWO * square - curvature)
            } else {
                ys / vs
            };
            let next = t - step;
            if !(next > low && next < high) {
                return None;
            }
            if step.abs() <= settled * t {
                let h = next - t;
                let jerk = -damping * acceleration - w2 * v;
                return Some(Landing::Returns {
                    time: next,
                    speed: v + acceleration * h + jerk * h * h * F::HALF,
                    grazing: false,
                });
            }
            t = next;
        }
        None
    }

    /// The flight leaving the stop at speed `a` > 0.
    pub(crate) fn land(&self, a: F) -> Landing<F> {
        let Some(low) = self.first_minimum(a) else {
            return Landing::Stays {
                grazing: false,
                touch: F::ZERO,
            };
        };
        let mut steps = 1;
        let high = if let Damping::Under { w, .. } = self.damping {
            low + F::PI / w
        } else {
            if !crate::physics::sign::preload::<F, S>(self.delta) {
                // Over- or critically damped above the rest position: no return.
                return Landing::Stays {
                    grazing: false,
                    touch: F::ZERO,
                };
            }
            // x creeps back to rest through the stop: double until y >= 0.
            let mut high = (low + low).max(F::MIN_POSITIVE);
            loop {
                if steps >= ROOT_STEPS {
                    return Landing::Stays {
                        grazing: true,
                        touch: F::ZERO,
                    };
                }
                steps += 1;
                if self.eval(a, high).0 >= F::ZERO {
                    break high;
                }
                high = high + high;
            }
        };
        let top = self.eval(a, high).0;
        // Under-damped, `top` is where the swing turns: within rounding of the stop, rounding
        // decides the return. Over- or critically damped (a preload), x creeps on towards rest,
        // beyond the stop: `high` is past the return, however close to the stop it lies.
        let grazing = matches!(self.damping, Damping::Under { .. }) && self.grazes(top);
        if top < F::ZERO {
            let touch = if grazing { high } else { F::ZERO };
            return Landing::Stays { grazing, touch };
        }
        // From the undamped flight.
        let guess = F::TWO / self.omega * a.atan2(-self.omega * self.delta);
        let (_, speed, t) = bracketed_root(
            |t| self.eval(a, t),
            (low, high),
            guess,
            ROOT_STEPS.saturating_sub(steps),
        );
        if speed > F::ZERO {
            Landing::Returns {
                time: t,
                speed,
                grazing,
            }
        } else {
            Landing::Stays {
                grazing: true,
                touch: t,
            }
        }
    }
}

/// The return in `bracket` = (low, high), where y(low) < 0 <= y(high) and y rises: Newton
/// steps from `guess` (the middle if the guess is outside), kept inside the shrinking bracket
/// by bisection, until a step or the bracket is within 2 epsilon of t, or `steps` evaluations
/// of `eval` (t -> (y, y')) are spent. Returns (evaluations, y' at the root, the root); y' is
/// 0 where `eval` gives a number that is not finite.
pub(crate) fn bracketed_root<F: Float>(
    eval: impl Fn(F) -> (F, F),
    bracket: (F, F),
    guess: F,
    steps: u32,
) -> (u32, F, F) {
    let (mut low, mut high) = bracket;
    let mut t = if guess > low && guess < high {
        guess
    } else {
        low + (high - low) * F::HALF
    };
    let mut speed = F::ZERO;
    let mut spent = 0;
    while spent < steps {
        spent += 1;
        let (y, v) = eval(t);
        speed = v;
        if !(y.is_finite() && v.is_finite()) {
            // The motion lost to the float (an overflow, a NaN): no root here. A speed of 0
            // makes every caller take the flight as undecided (no figure), where reading the
            // NaN as positive would bisect to a wrong return.
            return (spent, F::ZERO, t);
        }
        if y == F::ZERO {
            break;
        }
        if y < F::ZERO {
            low = t;
        } else {
            high = t;
        }
        let newton = t - y / v;
        if v > F::ZERO && newton == t {
            // A step below the rounding of t: t is the root (and t is a bound of the
            // bracket, so the test below would bisect away from it).
            break;
        }
        let next = if v > F::ZERO && newton > low && newton < high {
            newton
        } else {
            low + (high - low) * F::HALF
        };
        let settled =
            (next - t).abs() <= F::TWO * F::EPSILON * t || high - low <= F::TWO * F::EPSILON * high;
        t = next;
        if settled {
            speed = eval(t).1;
            break;
        }
    }
    (spent, speed, t)
}

/// A sufficient condition, with no transcendental function, for a gap's flight leaving at
/// `departure` to come back to the stop. Leaving x = Delta > 0 at -a, the motion is
/// M e^(-alpha t) cos(w t - phi) with M = hypot(Delta, (alpha Delta - a) / w); its extrema are
/// +-M (w / Omega) e^(-alpha t), the first maximum after the first minimum at t <= 2 pi / w. So
/// it returns if M (w / Omega) (1 - 2 pi alpha / w) > Delta (e^-y >= 1 - y), here with a
/// margin of 64 epsilon for the rounding of this test. False means "decide exactly".
pub(crate) fn surely_returns<F: Float>(omega: F, zeta: F, delta: F, departure: F) -> bool {
    if zeta >= F::ONE {
        return false;
    }
    let w = omega * ((F::ONE - zeta) * (F::ONE + zeta)).sqrt();
    let alpha = zeta * omega;
    let decay = F::ONE - F::TWO * F::PI * alpha / w;
    if decay <= F::ZERO {
        return false;
    }
    let k = (alpha * delta - departure) / w;
    let amplitude = (delta * delta + k * k).sqrt();
    let margin = F::ONE + c::<F>(64.0) * F::EPSILON;
    amplitude.is_finite() && amplitude * (w / omega) * decay > delta * margin
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The worst distance, in epsilons of the flight, between the closed form's value at the
    /// series' root and that root (y / y'), over preloads with zeta 0.001-0.9 and departures
    /// 1e-4 to 1 Omega |Delta|, wherever `eval` takes the closed form with the series limit
    /// `limit` times zeta / Omega.
    fn worst_closed_root(limit: f64) -> f64 {
        let (omega, delta) = (1000.0_f64, -1e-3_f64);
        let mut worst = 0.0_f64;
        for z in 0..60 {
            let zeta = 10f64.powf(-3.0 + f64::from(z) / 20.0);
            let osc = Oscillator::new(omega, zeta, delta);
            for e in -400..=0 {
                let a = 10f64.powf(f64::from(e) / 100.0) * omega * delta.abs();
                // The root by Newton steps on the series alone (a rising y: it settles).
                let mut t = 2.0 * a / (omega * omega * delta.abs());
                for _ in 0..60 {
                    let (over_t, v) = osc.series(a, t);
                    t -= over_t * t / v;
                }
                if t <= SERIES_LIMIT.min(limit * zeta) / omega {
                    continue;
                }
                let (_, v) = osc.series(a, t);
                let (y, _) = osc.closed(a, t);
                worst = worst.max((y / v).abs() / t / f64::EPSILON);
            }
        }
        worst
    }

    #[test]
    fn the_closed_form_meets_the_series_at_the_root() {
        // Within the 8 epsilons a solved flight is allowed (ROUNDING_PER_FLIGHT) at the limit
        // in use (7.3 measured); at a quarter of it the decay's cancellation shows (12.2).
        let used = worst_closed_root(UNDER_SERIES_LIMIT);
        assert!(used <= crate::tiers::exact::ROUNDING_PER_FLIGHT, "{used}");
        let lower = worst_closed_root(UNDER_SERIES_LIMIT / 4.0);
        assert!(lower > crate::tiers::exact::ROUNDING_PER_FLIGHT, "{lower}");
    }

    #[test]
    fn a_flight_said_surely_to_return_does_return() {
        // Against the exact top of the first swing, over zeta in (0, 0.2], departures from
        // 1e-3 to 1e3 Omega Delta, in f64 and f32; and the test must spare the exact check
        // often (most light-damped gaps).
        let (omega, delta) = (1000.0_f64, 1e-3_f64);
        let (mut spared, mut total) = (0, 0);
        for z in 1..=40 {
            let zeta = f64::from(z) * 0.005;
            for e in -30..=30 {
                let departure = omega * delta * 10f64.powf(f64::from(e) / 10.0);
                total += 1;
                let osc = Oscillator::new(omega, zeta, delta);
                let (Damping::Under { w, .. }, Some(low)) =
                    (osc.damping, osc.first_minimum(departure))
                else {
                    assert!(zeta >= 1.0, "{zeta}: under-damped, so it turns");
                    continue;
                };
                let top = osc.eval(departure, low + core::f64::consts::PI / w).0;
                if surely_returns(omega, zeta, delta, departure) {
                    spared += 1;
                    assert!(top > 0.0, "{zeta} {departure}: top {top}");
                }
                let narrow = surely_returns(
                    <f32 as Float>::from_f64(omega),
                    <f32 as Float>::from_f64(zeta),
                    <f32 as Float>::from_f64(delta),
                    <f32 as Float>::from_f64(departure),
                );
                assert!(!narrow || top > 0.0, "f32 {zeta} {departure}: top {top}");
            }
        }
        assert!(spared * 3 > total, "{spared} of {total}");
    }
}

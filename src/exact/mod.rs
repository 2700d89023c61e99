//! The exact tier: one body against a stop with restitution, viscous damping and an exponential
//! relaxation kernel, solved impact by impact (docs/physics.md sec. 1), with nothing approximated but the rounding of the float.
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
//!
//! A preload's Zeno tail (zeta <= 1) is summed as a power series in the departure speed
//! (`tail.rs`: the rest of the bounce S solves S(a) = t(a) + S(R v(a)), t and v the flight
//! and its return speed as series), once its last two terms say that the truncation is below
//! an epsilon of the bounce (f64: near 0.005 Omega |Delta|, 0.004-0.007 on the catalogue,
//! where the first-order sum below waits for 6e-6 Omega |Delta|: ln(800) / ln(1 / R) flights
//! later). Below
//! [`Tuning::SERIES_EXACT_DEPARTURE`](crate::model::Tuning) Omega |Delta| (f64: 0.02) a flight
//! is its series to rounding: the flights from there to where S is summed are walked by their
//! series, no root solved. Over-damped
//! (zeta > 1), it is summed to first order once the departure speed a is below
//! [`Tuning::TAIL_CUTOFF`](crate::model::Tuning::TAIL_CUTOFF) Omega |Delta| and the damping's
//! drift of
//! the ratio of successive flights, d = 4 zeta a / (3 r Omega |Delta|), is below it too: the
//! series of one flight gives t = (2a / (Omega^2 |Delta|)) (1 - 2 zeta a / (3 Omega |Delta|))
//! and a return speed a (1 - 4 zeta a / (3 Omega |Delta|)), so the rest lasts
//! T = 2 a / (r Omega^2 |Delta|) (1 - d / 2); what is left out is of order d^2 and
//! (a / (Omega |Delta|))^2 of the tail.
//!
//! Scenes without viscous damping, or with Delta = 0, have exact sums in closed form: the
//! closed tier's, which this tier returns. A relaxation kernel adds a third state, its force,
//! carried from flight to flight: its flights are solved mode by mode (`kernel.rs`), and where
//! the modes are nearly degenerate, or two kernels act, this tier answers with the averaged model
//! (its [`Tier`] says so).
//!
//! A gap's end hangs on its last return, which may nearly graze the stop: the last two flights
//! are solved again from departures off by the accumulated rounding, and the time they move is
//! part of the expected error (a count that changes withdraws it). A last flight whose swing
//! the float cannot tell from touching the stop ends the bounce at the latest time it may touch
//! it, with no figure: never earlier, as a bounce of 0 s where the swing returns.

pub(crate) mod flight_series;
mod kernel;
mod tail;

pub use kernel::KERNEL_FLIGHT_STEPS;

use crate::accuracy::{self, c};
use crate::averaged::Averaged;
use crate::closed;
use crate::float::exp_and_m1;
use crate::mechanisms::restitution::rebound;
use crate::mechanisms::Dissipation;
use crate::method::Walk;
use crate::prediction::{Approximations, Count, Course, Prediction, Tier, Time};
use crate::quadrature::{Compensated, Nodes};
use crate::regime::Regime;
use crate::scene::{AnySign, OffsetSign};
use crate::{Float, Scene};

/// The exact tier's default cap on solved flights: past it the averaged model finishes the
/// sum (flagged [`Approximations::MAP_CONTINUED_AVERAGED`]).
pub const EXACT_MAX_IMPACTS: u32 = 100_000;

/// Most evaluations of the motion spent on one flight's return (Newton steps, bisections and
/// the bracket's own evaluations): with [`EXACT_MAX_IMPACTS`] it bounds the work of one
/// prediction, see [`Scene::exact_work`].
pub const ROOT_STEPS: u32 = 128;

/// Auto's estimate of the exact tier's work with a relaxation kernel before its first flight,
/// in map impacts (see [`cost`]).
const KERNEL_BASE: f64 = 15.0;
/// ... and a flight.
const KERNEL_FLIGHT: f64 = 10.0;

/// Most Halley steps tried from a guess before the bracketed search takes over.
const HALLEY_STEPS: u32 = 6;

/// lambda t below which y(t) / t is summed as a series. Above it the closed form loses at most
/// |Delta| / |y| ~ a few epsilon at the root (y rises at the return speed over a flight long
/// enough for lambda t > 0.5).
const SERIES_LIMIT: f64 = 0.5;
/// Under-damped, the closed form keeps the displacement's own part free of cancellation
/// (`expm1` and the half angle), and what it loses near a root is the decay's linear term, of
/// relative size zeta / (Omega t) against y's: the series serves only below this times
/// zeta / Omega (and below [`SERIES_LIMIT`]), in f64 only
/// ([`Tuning::SHORT_FLIGHTS_CLOSED`](crate::model::Tuning)). Measured by the test
/// `the_closed_form_meets_the_series_at_the_root` (zeta 0.001-0.9, departures 1e-4 to 1
/// Omega |Delta|): the two roots agree within 7.3 epsilon of the flight (12.2 with a quarter
/// of this limit).
const UNDER_SERIES_LIMIT: f64 = 2.0;
/// Most terms of that series (at lambda t = 0.5 the terms fall below 1e-17 after ~16).
const SERIES_TERMS: usize = 40;
/// 1 / ((k + 1) k), the series' recurrence without a division per term (in each float's
/// precision: [`Tuning::TAYLOR_RECIPROCALS`](crate::model::Tuning)).
pub(crate) const RECIPROCALS: [f64; SERIES_TERMS] = {
    let mut table = [0.0; SERIES_TERMS];
    let mut k = 1;
    while k < SERIES_TERMS {
        #[allow(clippy::cast_precision_loss, clippy::as_conversions)] // k < 40: exact
        let kf = k as f64;
        #[allow(clippy::indexing_slicing)] // k < SERIES_TERMS; no `get_mut` in a const block
        {
            table[k] = 1.0 / ((kf + 1.0) * kf);
        }
        k += 1;
    }
    table
};
/// Relative rounding the exact tier promises per solved flight, in units of epsilon: its
/// expected error is this times epsilon times the flights solved (errors of successive
/// departures compound at worst linearly). Measured against the host reference: see
/// host-tests `against_reference`.
pub(crate) const ROUNDING_PER_FLIGHT: f64 = 8.0;
/// A clearance (the top of a flight relative to the stop) within this many epsilons of |Delta|
/// decides a return by rounding: the count may be off by one.
const GRAZING_EPSILONS: f64 = 64.0;
/// Rounding of a tail summed as a series, in epsilons of the tail: its coefficients are found
/// in about 12 steps that each round, and summed as a polynomial.
const TAIL_ROUNDING: f64 = 16.0;

/// (sin x, cos x) for the phases of one flight (0 <= x <= ~3 pi, the bracket's end): reduced by
/// whole turns into [-pi, pi) and summed by [`Float::sin_within_pi`], so the tier links no libm
/// `sin`/`cos` (their range reduction alone is several KB of flash). Absolute error a few ULP
/// of the phase; below pi x is not touched, so sin x keeps its relative accuracy at small x
/// (the half angle of a short flight).
fn sin_cos_small<F: Float>(x: F) -> (F, F) {
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
struct TaylorSum<F> {
    over_t: F,
    slope: F,
    power: F,
    quiet: u32,
}

impl<F: Float> TaylorSum<F> {
    fn new(first: F) -> Self {
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
    fn add(&mut self, k: F, coefficient: F, t: F, settle: u32) -> bool {
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
enum Damping<F> {
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
    omega: F,
    zeta: F,
    delta: F,
    damping: Damping<F>,
    /// The fastest rate of the free motion (1/s).
    lambda: F,
    sign: core::marker::PhantomData<S>,
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
    fn closed(&self, a: F, t: F) -> (F, F) {
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
    fn series(&self, a: F, t: F) -> (F, F) {
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
    fn eval(&self, a: F, t: F) -> (F, F) {
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
    fn first_minimum(&self, a: F) -> Option<F> {
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
    fn grazes(&self, y: F) -> bool {
        y.abs() <= c::<F>(GRAZING_EPSILONS) * F::EPSILON * self.delta.abs()
    }

    /// A preload's return by Halley steps alone (y'' comes free from the equation of motion,
    /// and the convergence is cubic), from a guess within a few percent (the previous flight
    /// scaled as the undamped flights scale). Once a step is below a tenth of
    /// [`Tuning::TAIL_CUTOFF`](crate::model::Tuning::TAIL_CUTOFF) (about the cube root of epsilon)
    /// of t, the next iterate is exact
    /// to rounding, and so is the return speed carried to it by its Taylor series to second
    /// order: no further evaluation. `None` when a step leaves 10 % of the guess, the speed is
    /// not rising or [`HALLEY_STEPS`] steps do not settle; the bracketed search then decides.
    /// (A preload always returns: x swings through rest, beyond the stop.)
    fn halley(&self, a: F, guess: F) -> Option<Landing<F>> {
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
            if !crate::sign::preload::<F, S>(self.delta) {
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
fn bracketed_root<F: Float>(
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

/// A gap's bounce that ends at the first contact: the first flight (leaving at R v0) does not
/// come back to the stop, decided exactly by the top of its first swing (one `atan2`, one `exp`
/// and a sine: no root is solved). Then every tier answers exactly: one impact, at t = 0.
/// `None` otherwise, and where it does not apply (no viscous damping, a kernel, Delta <= 0).
pub(crate) fn ends_at_first_contact<F: Float, D: Dissipation<F>, S: OffsetSign>(
    scene: &Scene<F, D, S>,
) -> Option<Prediction<F>> {
    let dissipation = scene.dissipation();
    // (`dissipates` first: a scene type without damping links none of this.)
    if !dissipation.dissipates() || scene.regime() != Regime::LastImpact || dissipation.has_kernel()
    {
        return None;
    }
    let zeta = dissipation.damping_ratio();
    let departure = rebound(scene.closing_speed(), scene.restitution(), scene.loss());
    if surely_returns(scene.omega(), zeta, scene.delta(), departure) {
        return None;
    }
    let oscillator = Oscillator::<F, S>::signed(scene.omega(), zeta, scene.delta());
    let Damping::Under { w, .. } = oscillator.damping else {
        return None; // over-damped gaps are the single-impact regime
    };
    let low = oscillator.first_minimum(departure)?;
    let top = oscillator.eval(departure, low + F::PI / w).0;
    if top >= F::ZERO || oscillator.grazes(top) {
        return None;
    }
    Some(Prediction::of_tier(
        scene,
        Course::single_impact(),
        Tier::Regime,
        Approximations::NONE,
        accuracy::with_reduction(scene, Some(F::ZERO)),
    ))
}

/// A sufficient condition, with no transcendental function, for a gap's flight leaving at
/// `departure` to come back to the stop. Leaving x = Delta > 0 at -a, the motion is
/// M e^(-alpha t) cos(w t - phi) with M = hypot(Delta, (alpha Delta - a) / w); its extrema are
/// +-M (w / Omega) e^(-alpha t), the first maximum after the first minimum at t <= 2 pi / w. So
/// it returns if M (w / Omega) (1 - 2 pi alpha / w) > Delta (e^-y >= 1 - y), here with a
/// margin of 64 epsilon for the rounding of this test. False means "decide exactly".
fn surely_returns<F: Float>(omega: F, zeta: F, delta: F, departure: F) -> bool {
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

/// [`Method::Auto`](crate::Method::Auto)'s estimate of this tier's work on `scene`, before it
/// runs, in Auto's unit: an impact of the map, about 300 instructions on a Cortex-M4F in f32.
/// Measured there (f32, the catalogue's switches and the tactile dome with a relaxation kernel,
/// `docs/cost-report.md`): with viscous damping about 3,500 instructions before the first
/// flight (the regime's closed forms, the tail's series) and 850-900 a flight (2 to 6 flights
/// solved on the catalogue's switches), so 12 + 3 a flight;
/// with a kernel, whose flights are solved mode by mode, about 4,500 and 2,900 a flight (5 to 37
/// flights; a flight that does not return scans its whole bracket, up to 40,000), so 15 + 10.
/// Flights are counted from the first impulse down to the threshold or to where the tail is
/// walked by their series (the series' departure, [`Tuning::SERIES_EXACT_DEPARTURE`](crate::model::Tuning),
/// in a preload's Zeno accumulation with zeta <= 1; the first-order tail's elsewhere), or are the
/// closed tier's count. Scenes this tier hands to the closed tier cost what it does.
pub(crate) fn cost<F: Float, D: Dissipation<F>, S: OffsetSign>(
    scene: &Scene<F, D, S>,
    walk: &Walk<F>,
) -> F {
    let dissipation = scene.dissipation();
    if !dissipation.has_kernel() && (!dissipation.dissipates() || scene.is_grazing()) {
        return F::ONE;
    }
    let scale = scene.omega() * scene.delta().abs();
    let series =
        scene.is_preload() && !dissipation.has_kernel() && dissipation.damping_ratio() <= F::ONE;
    let tail = F::TWO
        * scale
        * if series {
            F::SERIES_EXACT_DEPARTURE
        } else {
            F::TAIL_CUTOFF
        };
    let floor = scene.threshold_generating().map_or(tail, |t| t.min(tail));
    let flights = walk.down_to(floor.ln());
    let (base, per_flight) = if dissipation.has_kernel() {
        (KERNEL_BASE, KERNEL_FLIGHT)
    } else {
        (12.0, 3.0)
    };
    c::<F>(base) + c::<F>(per_flight) * flights
}

/// Where the iteration stopped.
enum Stop<F> {
    /// The last flight did not return.
    Ended,
    /// A Zeno tail of this duration (s) remains.
    Tail { time: F, error: F },
    /// Below the threshold in an endless regime.
    BelowThreshold,
    /// The cap: the averaged model finishes from this generating impulse (m/s).
    Capped(F),
}

impl<F: Float, D: Dissipation<F>, S: OffsetSign> Scene<F, D, S> {
    /// The most evaluations of the motion [`Method::Exact`](crate::Method::Exact) spends on
    /// this scene with `max_impacts` (each an `exp` and the sine series, or a Taylor series of
    /// at most 40 terms; per flight at most 6 Halley steps, then at most [`ROOT_STEPS`] in the
    /// bracketed search), before the averaged model finishes what is left: known before
    /// calling. (A Zeno tail may also walk up to 64 flights by their series, two polynomials
    /// each, once a prediction: see `exact/tail.rs`.)
    /// `None` where the tier evaluates no flight (the closed tier's exact sums answer, or the
    /// averaged model where the kernel's modes are nearly real or two kernels act). With a
    /// relaxation kernel a flight takes at most [`KERNEL_FLIGHT_STEPS`]
    /// evaluations (its scan for the return included).
    #[must_use]
    pub fn exact_work(&self, max_impacts: u32) -> Option<u64> {
        let d = self.dissipation();
        let flights = u64::from(max_impacts) + 1;
        if d.has_kernel() {
            return kernel::Kernel::new(self).map(|_| flights * u64::from(KERNEL_FLIGHT_STEPS));
        }
        let solved = d.dissipates() && !self.is_grazing();
        solved.then(|| flights * u64::from(ROOT_STEPS + HALLEY_STEPS))
    }
}

/// Flights solved one after another from the stop: the free motion of one model (viscous
/// damping; or a relaxation kernel, whose state is carried from flight to flight).
pub(crate) trait Flights<F: Float> {
    /// The flight that leaves the stop at `departure` (m/s, > 0). On a return the model's
    /// state moves to that impact.
    fn land(&mut self, departure: F) -> Landing<F>;
    /// The rest of a Zeno accumulation whose next flight leaves at `departure`, `elapsed`
    /// (s) after the first impact, summed in closed form, with a bound on its error (s):
    /// `None` until that form is exact to the rounding of the whole bounce.
    fn tail(&mut self, departure: F, elapsed: F) -> Option<(F, F)>;
    /// The last return's rounding where its conditioning makes it more than a few epsilons of
    /// the flight: (an error of its time (s), a relative error of its speed, which every later
    /// flight inherits), each an epsilon times the sizes of the terms the return is the
    /// difference of, over the return speed. (0, 0) where the flight's own form keeps its
    /// digits (viscous flights: their terms decay with the motion). Before the first flight,
    /// (0, the relative error of the first flight's fall from the model's starting state).
    fn rounding(&self) -> (F, F) {
        (F::ZERO, F::ZERO)
    }
    /// Whether [`Flights::rounding`] can be other than (0, 0) (a constant: where it is not,
    /// the exact tier links none of its bookkeeping).
    const ROUNDED: bool = false;
}

/// Viscous damping's flights, with the next guess from the last flight.
#[derive(Debug, Clone, Copy)]
struct Damped<'a, F, S> {
    oscillator: Oscillator<F, S>,
    /// Omega |Delta| (m/s).
    scale: F,
    /// 1 / (Omega |Delta|) and 1 / Omega, on hosts: see [`Damped::series_guess`].
    #[cfg(not(target_os = "none"))]
    reciprocals: (F, F),
    /// R.
    restitution: F,
    /// 1 - R.
    loss: F,
    /// The last flight and the undamped flight of its departure.
    previous: Option<(F, F)>,
    /// A Zeno accumulation's tail as a series (zeta <= 1), else `None`: the first-order sum.
    /// Borrowed: the flights are copied at each impact, the series need not be.
    series: Option<&'a tail::ZenoTail<F>>,
    /// Whether the tail may still walk flights by their series to where it is summed (until a
    /// walk of [`WALKED_FLIGHTS`] fell short: R near 1).
    walk: bool,
}

/// Most flights the tail walks by their series in one call (see [`Damped::tail`]).
const WALKED_FLIGHTS: u32 = 64;

impl<F: Float, S: OffsetSign> Damped<'_, F, S> {
    /// The flight from `departure` (s) by the tail's series, where it reaches. On hosts the
    /// departure is brought to the series' units and the flight back to seconds by
    /// multiplying with reciprocals kept from the start: two divisions that waited on each
    /// other on every flight's way to its root (x86-64, f64: 3-5 % of the catalogue's time,
    /// paired runs). On bare metal they stay divisions: the two reciprocals cost the Uno's
    /// exact tier about 100 bytes it does not have, for under 1 % of its cycles.
    #[inline]
    fn series_guess(&self, departure: F) -> Option<F> {
        let series = self.series?;
        #[cfg(not(target_os = "none"))]
        let guess = {
            let (inverse_scale, inverse_omega) = self.reciprocals;
            series
                .flight(departure * inverse_scale)
                .map(|flight| flight * inverse_omega)
        };
        #[cfg(target_os = "none")]
        let guess = series
            .flight(departure / self.scale)
            .map(|flight| flight / self.oscillator.omega);
        guess
    }
}

impl<F: Float, S: OffsetSign> Flights<F> for Damped<'_, F, S> {
    fn land(&mut self, departure: F) -> Landing<F> {
        let (omega, delta) = (self.oscillator.omega, self.oscillator.delta);
        let preload = crate::sign::preload::<F, S>(delta);
        // The first guess: the flight's series where it reaches, else the last flight scaled
        // as the undamped flights scale, else (a preload's first flight) the undamped flight.
        // Where the guess is off by more than Halley's window, the bracketed search decides.
        if let Some(guess) = self.series_guess(departure) {
            // Departures only fall from here, so the series reaches every later flight and the
            // scaled guess (an `atan2` a flight) is not needed again.
            self.previous = None;
            return self
                .oscillator
                .halley(departure, guess)
                .unwrap_or_else(|| self.oscillator.land(departure));
        }
        let undamped = F::TWO / omega * departure.atan2(-omega * delta);
        let scaled = match self.previous {
            Some((flight, undamped_before)) if preload && undamped_before > F::ZERO => {
                Some(flight * (undamped / undamped_before))
            }
            None if preload && undamped > F::ZERO => Some(undamped),
            _ => None,
        };
        let guessed = scaled.and_then(|guess| self.oscillator.halley(departure, guess));
        let landing = guessed.unwrap_or_else(|| self.oscillator.land(departure));
        if let Landing::Returns { time, .. } = landing {
            self.previous = Some((time, undamped));
        }
        landing
    }

    // Outlined on AVR, as `solve` is: inlined there, its loop's floats spill.
    #[cfg_attr(target_arch = "avr", inline(never))]
    fn tail(&mut self, departure: F, elapsed: F) -> Option<(F, F)> {
        let small = departure / self.scale;
        if let Some(series) = self.series {
            // Taken where the truncation (twice the last two terms) is below an epsilon of
            // the bounce so far; the sum's own rounding is a few epsilon of the tail. Until
            // then, where the flights' own series are exact to rounding, they are walked here
            // (two polynomials a flight, no root solved); each walked departure rounds, and
            // that compounds as a solved flight's does.
            // Not tried where its truncation is surely far above an epsilon.
            if small > F::TAIL_TRIED_BELOW {
                return None;
            }
            let omega = self.oscillator.omega;
            let (mut eps, mut walked, mut steps) = (small, F::ZERO, 0_u32);
            loop {
                let (sum, last) = series.sum(eps)?;
                let (tail, truncation) = ((walked + sum) / omega, F::TWO * last / omega);
                if tail.is_finite() && truncation <= F::EPSILON * (elapsed + tail) {
                    let rounding =
                        c::<F>(TAIL_ROUNDING) + c::<F>(ROUNDING_PER_FLIGHT) * F::from_u32(steps);
                    return Some((tail, truncation + rounding * F::EPSILON * tail));
                }
                if !self.walk {
                    return None;
                }
                if steps >= WALKED_FLIGHTS {
                    self.walk = false;
                    return None;
                }
                let (flight, speed) = series.exact_flight(eps)?;
                steps += 1;
                walked += flight;
                eps = rebound(speed, self.restitution, self.loss);
            }
        }
        if departure > F::TAIL_CUTOFF * self.scale {
            return None;
        }
        let drift = c::<F>(4.0 / 3.0) * self.oscillator.zeta * small / self.loss;
        (drift <= F::TAIL_CUTOFF).then(|| {
            let g = self.oscillator.omega * self.scale;
            let tail = F::TWO * departure / (self.loss * g) * (F::ONE - drift * F::HALF);
            (tail, tail * c::<F>(4.0) * (drift * drift + small * small))
        })
    }
}

/// The exact tier's prediction, solving at most `max_impacts` flights. `FULL`: every field
/// (false: the times alone, see [`Scene::bounce_time`]; the expected error is then `None`, a
/// placeholder no caller reads, and a gap's last flights are not solved again for it).
/// (Outlined on AVR, as `solve` is, and for the same reason.)
#[cfg_attr(target_arch = "avr", inline(never))]
pub(crate) fn predict<F: Float, D: Dissipation<F>, S: OffsetSign, const FULL: bool>(
    scene: &Scene<F, D, S>,
    max_impacts: u32,
) -> Prediction<F> {
    if let Some(p) = crate::regime::answer(scene) {
        return p;
    }
    let dissipation = scene.dissipation();
    if dissipation.has_kernel() {
        return match kernel::Kernel::new(scene) {
            Some(flights) => solve::<F, D, _, S, FULL>(scene, max_impacts, flights),
            None if FULL => Averaged::new(scene, Nodes::N20).predict(),
            None => Averaged::new(scene, Nodes::N20).predict_times(),
        };
    }
    if !dissipation.dissipates() || scene.is_grazing() {
        return closed::exact_discrete(scene);
    }
    let zeta = dissipation.damping_ratio();
    let mut tail = tail::ZenoTail::EMPTY;
    let series = (scene.regime() == Regime::ZenoAccumulation
        && tail.prepare(zeta, scene.restitution(), scene.loss()))
    .then_some(&tail);
    let scale = scene.omega() * scene.delta().abs();
    let flights = Damped {
        oscillator: Oscillator::<F, S>::signed(scene.omega(), zeta, scene.delta()),
        scale,
        #[cfg(not(target_os = "none"))]
        reciprocals: (F::ONE / scale, F::ONE / scene.omega()),
        restitution: scene.restitution(),
        loss: scene.loss(),
        previous: None,
        series,
        walk: true,
    };
    solve::<F, D, _, S, FULL>(scene, max_impacts, flights)
}

/// Solves at most `max_impacts` flights of `flights`, then the tail, the end or the averaged
/// rest; counts and the threshold's crossing as they pass.
///
/// Outlined on AVR, as `predict` is: on the Uno (every float operation a call, 32 registers of 8
/// bits) the two inlined into the firmware's one caller spill more than the calls cost, and
/// outlined the exact tier's firmware is 3.7 KB smaller (`scripts/cost-report.sh`). On Cortex-M
/// the inliner's choice is the smaller one.
#[allow(clippy::too_many_lines)] // one loop and its hand-over; splitting it would hide the state
#[cfg_attr(target_arch = "avr", inline(never))]
fn solve<F: Float, D: Dissipation<F>, M: Flights<F> + Copy, S: OffsetSign, const FULL: bool>(
    scene: &Scene<F, D, S>,
    max_impacts: u32,
    mut flights: M,
) -> Prediction<F> {
    let loss = scene.loss();
    let restitution = scene.restitution();
    let zeno = scene.regime() == Regime::ZenoAccumulation;
    let endless = scene.regime() == Regime::Endless;
    let threshold = scene.threshold_impulse();
    let impulse = |v: F| (F::ONE + restitution) * v;

    let mut time = Compensated::new();
    let mut speed = scene.closing_speed();
    let mut solved: u32 = 0;
    let mut last_above = F::ZERO;
    let mut above: u32 = 1;
    let mut still_above = true;
    let mut grazing = false;
    // The last flight solved, and the share of the generating impulse lost over it.
    let mut last_flight = F::ZERO;
    // Ill-conditioned returns' rounding (`Flights::rounding`): the time it moved (s), and the
    // relative error of the speed the later flights inherit.
    // The first flight inherits the starting state's rounding (a bound already).
    let (mut conditioned, mut inherited) = (F::ZERO, flights.rounding().1);
    let mut last_decay = F::ONE;
    // The model before the last flight that returned, its departure and its time: the
    // conditioning of a gap's last return is probed from there.
    // (Kept for a gap alone, where it is used: a copy of the model a flight otherwise.)
    let gap = crate::sign::narrow::<S>(scene.regime()) == Regime::LastImpact;
    let mut last_return: Option<(M, F, F)> = None;
    let mut final_departure = F::ZERO;
    let stop = loop {
        let departure = rebound(speed, restitution, loss);
        if zeno && !(still_above && threshold.is_some()) {
            if let Some((tail, error)) = flights.tail(departure, time.value()) {
                break Stop::Tail { time: tail, error };
            }
        }
        if departure < F::MIN_POSITIVE {
            break Stop::Ended;
        }
        if solved >= max_impacts {
            break Stop::Capped(F::TWO * departure);
        }
        let before = gap.then_some(flights);
        match flights.land(departure) {
            Landing::Stays { grazing: g, touch } => {
                grazing |= g;
                final_departure = departure;
                if zeno {
                    // In a Zeno accumulation every flight returns: one that does not was lost
                    // to the float (a return it cannot resolve). The bounce goes on: the
                    // averaged model finishes it from this impulse, with no figure, where
                    // ending here gave a bounce time short by the rest (0 s at the first
                    // flight).
                    grazing = true;
                    break Stop::Capped(F::TWO * departure);
                }
                // A stay that rounding decided may be a return just touching the stop, and the
                // bounce may last until it (f32, a kernel gap whose first swing tops out 7.6e-14
                // m past a stop of 1.7e-6 m: 0 s where f64 solves 9.6e-6 s). No figure.
                time.add(touch);
                break Stop::Ended;
            }
            Landing::Returns {
                time: t,
                speed: v,
                grazing: g,
            } => {
                grazing |= g;
                time.add(t);
                // Taken 4 times, as the bound of a difference of terms each rounded a few
                // times.
                if M::ROUNDED {
                    let (moved, speed_error) = flights.rounding();
                    conditioned += c::<F>(4.0) * moved + inherited * t;
                    inherited += c::<F>(4.0) * speed_error;
                }
                if let Some(before) = before {
                    last_return = Some((before, departure, t));
                }
                last_flight = t;
                last_decay = (departure - restitution * v) / departure;
                speed = v;
                solved += 1;
                if still_above {
                    if threshold.is_some_and(|end| impulse(v) < end) {
                        still_above = false;
                        if endless {
                            break Stop::BelowThreshold;
                        }
                    } else {
                        last_above = time.value();
                        above = solved + 1;
                    }
                }
            }
        }
    };
    let count = F::from_u32(solved) + F::ONE;
    let elapsed = time.value();
    let mut approximations = Approximations::NONE;
    let mut last_above_time = Time::At(last_above);
    let mut impacts_above = Count::Finite(F::from_u32(above));
    let mut rest_error = F::ZERO;
    let (end_time, impacts_total) = match stop {
        // An endless regime never ends: where the float loses the next return (an impulse
        // below its range, a root lost in rounding), that impact is below any threshold.
        Stop::Ended if endless => (Time::Never, Count::Infinite),
        Stop::Ended => (Time::At(elapsed), Count::Finite(count)),
        Stop::BelowThreshold => (Time::Never, Count::Infinite),
        Stop::Tail { time: tail, error } => {
            rest_error = error + inherited * tail;
            (Time::At(elapsed + tail), Count::Infinite)
        }
        Stop::Capped(j) => {
            // Past the cap the impulse falls by a share `last_decay` per flight at most:
            // averaging over flights that change this little is accurate to about that share
            // (taken 4 times), and the averaged count of a threshold's crossing can be off by
            // one flight. A share e of the exact rest is, of the averaged rest dt, up to
            // e / (1 - e).
            // With a kernel the rest has no figure: the force the kernel remembers at the cap
            // is not the averaged model's. Capped at 100 impacts, 63 kernel predictions of
            // 2,000 random scenes per float ended beyond the figure the static stiffness gave
            // (up to 25 times the time; `host-tests/tests/fuzz.rs`, the promises).
            // In a gap the rest's end is the averaged model's, which may also overshoot the last
            // return by a few free periods (`accuracy::gap_end_overshoot`).
            approximations = approximations.with(Approximations::MAP_CONTINUED_AVERAGED);
            let averaged = Averaged::new(scene, Nodes::N8);
            let share = if scene.dissipation().has_kernel() {
                F::ONE
            } else {
                c::<F>(4.0) * last_decay
            };
            let overshoot = if gap {
                accuracy::gap_end_overshoot(scene)
            } else {
                Some(F::ZERO)
            };
            let figure = |dt: F| {
                if share < F::ONE {
                    dt * share / (F::ONE - share) + last_flight
                } else {
                    F::MAX
                }
            };
            if still_above {
                if let Some(j_end) = scene.threshold_generating() {
                    // Every outcome of the rest is taken: one left out kept the last impact
                    // solved as the last above, with no error for the rest (f32, a kernel's
                    // slow decay: 160 s with a 1 % figure, where the rest takes 6e27 s).
                    let (dt, dn, _) = averaged.fall(j, j_end);
                    last_above_time = dt.reached_after(elapsed);
                    impacts_above = dn.reached_after(count);
                    rest_error = dt.seconds().map_or(F::MAX, figure);
                }
            }
            if endless {
                (Time::Never, Count::Infinite)
            } else {
                let (dt, dn, _) = averaged.fall(j, F::ZERO);
                rest_error = match (dt.seconds(), overshoot) {
                    (Some(t), Some(o)) if figure(t) < F::MAX => figure(t) + o,
                    _ => F::MAX,
                };
                (dt.after(elapsed), dn.after(count))
            }
        }
    };
    if threshold.is_none() {
        last_above_time = end_time;
        impacts_above = impacts_total;
    }
    // Rounding compounds at worst linearly over the flights solved; a tail or the averaged
    // rest adds its own error in proportion to its share of the bounce time.
    // Overdamped, a flight's closed form is a difference of its two modes, each up to
    // 1 / (2 sqrt(zeta^2 - 1)) times the motion's size: near critical damping that many more
    // epsilons (f32 at zeta 1.003-1.006: the flights' rounding 2-4 times the plain figure).
    let zeta = scene.dissipation().damping_ratio();
    let overdamped = if zeta > F::ONE {
        F::ONE + F::HALF / ((zeta - F::ONE) * (zeta + F::ONE)).sqrt()
    } else {
        F::ONE
    };
    let rounding = c::<F>(ROUNDING_PER_FLIGHT) * F::EPSILON * count * overdamped;
    let total = end_time
        .seconds()
        .or(last_above_time.seconds())
        .unwrap_or(F::ZERO);
    // A gap's end hangs on its last two flights: the last return (near grazing, its time
    // moves by the error of its departure over its small return speed) and the flight that
    // does not return. Both are solved again from departures off by the rounding: a count that
    // changes has no figure, a time that moves adds its shift.
    if FULL && matches!(stop, Stop::Ended) && scene.regime() == Regime::LastImpact {
        let (up, down) = (F::ONE + rounding, F::ONE - rounding);
        let mut after = flights;
        if final_departure > F::ZERO
            && matches!(after.land(final_departure * up), Landing::Returns { .. })
        {
            grazing = true;
        }
        if let Some((model, departure, t)) = last_return {
            for factor in [up, down] {
                let mut probe = model;
                match probe.land(departure * factor) {
                    Landing::Returns { time: moved, .. } => {
                        rest_error = rest_error.max((moved - t).abs());
                    }
                    Landing::Stays { .. } => grazing = true,
                }
            }
        }
    }
    let rest_error = rest_error + conditioned;
    let share = if total > F::ZERO {
        (rest_error / total).min(F::MAX)
    } else {
        F::ZERO
    };
    // A walk whose impulse falls by less per flight than a flight's rounding (f32, R = 1 and
    // zeta = 3e-11: the decay 1e-10 a flight under epsilon 1.2e-7) does not resolve when the
    // bounce ends: the end was 8 % off where 0.9 % was stated, and the figure could turn
    // negative (the promise harness). No figure there.
    let unresolved = solved > 0 && last_decay <= c::<F>(ROUNDING_PER_FLIGHT) * F::EPSILON;
    let expected = if !FULL || grazing || unresolved || rest_error >= F::MAX {
        None
    } else {
        accuracy::reduced(scene, Some(rounding + share))
    };
    Prediction::of_tier(
        scene,
        Course {
            end_time,
            last_above_time,
            impacts_above,
            impacts_total,
        },
        Tier::Exact,
        approximations,
        expected,
    )
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
        assert!(used <= ROUNDING_PER_FLIGHT, "{used}");
        let lower = worst_closed_root(UNDER_SERIES_LIMIT / 4.0);
        assert!(lower > ROUNDING_PER_FLIGHT, "{lower}");
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

//! The exact tier: one body against a stop with restitution, viscous damping and an exponential
//! relaxation kernel, solved impact by impact (docs/physics.md sec. 1), with nothing approximated but the rounding of the float.
//!
//!
//! Each flight is solved by the damped oscillator of `physics::flight`; this tier carries the
//! impacts between them, sums the tails and states the rounding.
//!
//! A preload's Zeno tail (zeta <= 1) is summed as a power series in the departure speed
//! (`tail.rs`: the rest of the bounce S solves S(a) = t(a) + S(R v(a)), t and v the flight
//! and its return speed as series), once its last two terms say that the truncation is below
//! an epsilon of the bounce (f64: near 0.005 Omega |Delta|, 0.004-0.007 on the catalogue,
//! where the first-order sum below waits for 6e-6 Omega |Delta|: ln(800) / ln(1 / R) flights
//! later). Below
//! [`Tuning::SERIES_EXACT_DEPARTURE`](crate::numeric::Tuning) Omega |Delta| (f64: 0.02) a flight
//! is its series to rounding: the flights from there to where S is summed are walked by their
//! series, no root solved. Over-damped
//! (zeta > 1), it is summed to first order once the departure speed a is below
//! [`Tuning::TAIL_CUTOFF`](crate::numeric::Tuning::TAIL_CUTOFF) Omega |Delta| and the damping's
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

mod flights;
mod kernel;
mod tail;

pub use kernel::KERNEL_FLIGHT_STEPS;

use crate::numeric::c;
use crate::numeric::quadrature::{Compensated, Nodes};
use crate::physics::duration::{Count, Time};
use crate::physics::flight::{Landing, Oscillator, HALLEY_STEPS, ROOT_STEPS};
use crate::physics::mechanisms::restitution::rebound;
use crate::physics::mechanisms::Dissipation;
use crate::physics::regime::Regime;
use crate::scene::OffsetSign;
use crate::tiers::accuracy;
use crate::tiers::approximations::Approximations;
use crate::tiers::averaged::Averaged;
use crate::tiers::closed;
use crate::tiers::prediction::{Course, Prediction, Tier};
use crate::tiers::walk::Walk;
use crate::{Float, Scene};
use flights::Flights;

/// The exact tier's default cap on solved flights: past it the averaged model finishes the
/// sum (flagged [`Approximations::MAP_CONTINUED_AVERAGED`]).
pub const EXACT_MAX_IMPACTS: u32 = 100_000;

/// Auto's estimate of the exact tier's work with a relaxation kernel before its first flight,
/// in map impacts (see [`cost`]).
const KERNEL_BASE: f64 = 15.0;
/// ... and a flight.
const KERNEL_FLIGHT: f64 = 10.0;

/// Relative rounding the exact tier promises per solved flight, in units of epsilon: its
/// expected error is this times epsilon times the flights solved (errors of successive
/// departures compound at worst linearly). Measured against the host reference: see
/// host-tests `against_reference`.
pub(crate) const ROUNDING_PER_FLIGHT: f64 = 8.0;
/// Rounding of a tail summed as a series, in epsilons of the tail: its coefficients are found
/// in about 12 steps that each round, and summed as a polynomial.
const TAIL_ROUNDING: f64 = 16.0;

/// [`Method::Auto`](crate::Method::Auto)'s estimate of this tier's work on `scene`, before it
/// runs, in Auto's unit: an impact of the map, about 300 instructions on a Cortex-M4F in f32.
/// Measured there (f32, the catalogue's switches and the tactile dome with a relaxation kernel,
/// `docs/reports/cost-report.md`): with viscous damping about 3,500 instructions before the first
/// flight (the regime's closed forms, the tail's series) and 850-900 a flight (2 to 6 flights
/// solved on the catalogue's switches), so 12 + 3 a flight;
/// with a kernel, whose flights are solved mode by mode, about 4,500 and 2,900 a flight (5 to 37
/// flights; a flight that does not return scans its whole bracket, up to 40,000), so 15 + 10.
/// Flights are counted from the first impulse down to the threshold or to where the tail is
/// walked by their series (the series' departure, [`Tuning::SERIES_EXACT_DEPARTURE`](crate::numeric::Tuning),
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
        let preload = crate::physics::sign::preload::<F, S>(delta);
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
    if let Some(p) = crate::tiers::settled::answer(scene) {
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
    let gap = crate::physics::sign::narrow::<S>(scene.regime()) == Regime::LastImpact;
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

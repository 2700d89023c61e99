//! The exact tier's flights under an exponential relaxation kernel (docs/physics.md sec. 3):
//! x'' + 2 zeta Omega x' + Omega^2 x = u, u' = kappa x - u / tau, with u = kappa y the kernel's
//! force per unit mass (y = integral of exp(-(t - s) / tau) x(s) ds). The state (x, x', u) is
//! linear between impacts; an impact reverses x' (times R) and leaves u as it is.
//!
//! **Modes.** The characteristic polynomial s^3 + a2 s^2 + a1 s + a0, a2 = 2 zeta Omega + beta,
//! a1 = Omega^2 + 2 zeta Omega beta, a0 = beta (Omega^2 - kappa tau), beta = 1 / tau, has one
//! real root r1 in (-beta, 0), found as its distance d = r1 + beta from -beta (no cancellation
//! when the kernel is weak and r1 is within rounding of -beta), and a pair alpha +- i w, with
//! alpha = -(2 zeta Omega + d) / 2 < 0 and alpha^2 + w^2 = a0 / (beta - d). So
//! x(t) = c1 e^(r1 t) + e^(alpha t) (p cos w t + q sin w t) in closed form, and u follows mode
//! by mode (u's part of a mode e^(s t) is kappa / (s + beta) times x's). Where the pair is
//! real or nearly so (its damping ratio above 0.995) the modal form loses digits: the tier
//! answers with the averaged model there, and says so.
//!
//! **Short flights** are evaluated from the Taylor series of (x - Delta) / t, whose
//! coefficients follow from the characteristic polynomial's recurrence, so the Zeno tail's tiny
//! flights keep their digits (as in the viscous flights).
//!
//! **Returns.** A flight is scanned in steps of 1/16 of the pair's period: a return is bracketed
//! where x - Delta turns non-negative, or at a maximum (x' falling through 0) that reaches the
//! stop, and solved by Newton steps kept inside the bracket. A gap's flight ends without return
//! once max(c1, 0) e^(r1 t) + e^(alpha t) hypot(p, q), a bound on x from then on, is below Delta
//! with the modes' rounding added (a bound within rounding of the stop decides nothing: the scan
//! goes on). A maximum within rounding of the stop is a graze: the flight is taken to return or
//! stay as the float says, with no figure, and a last flight that stays ends the bounce at the
//! latest such maximum, not at its departure.
//! All of it spends at most [`KERNEL_FLIGHT_STEPS`] evaluations per flight; beyond, the return is
//! undecided and the prediction gives no expected error.
//!
//! **Zeno tail.** Near the stop the body falls back at g = -Omega^2 Delta + u, which drifts at
//! g' = kappa Delta - u / tau. To first order in the flights' size (the series of one flight
//! gives t = (2a/g)(1 - 2 zeta Omega (2a/g) / 6 - g' (2a/g) / (3 g)) and a return speed
//! a (1 - 2 zeta Omega (2a/g) / 3 + g' (2a/g) / (3 g))), the rest of the accumulation lasts
//! T = (q / r)(1 - (q / r)(zeta Omega / 3 + g' / (3 g))), q = 2a / g, r = 1 - R. It is summed
//! once q / r times those rates and Omega a / g are below
//! [`Tuning::TAIL_CUTOFF`](crate::numeric::Tuning::TAIL_CUTOFF); what is left
//! out is of their squares' order.

use super::flights::Flights;
use crate::numeric::c;
use crate::physics::flight::{
    bracketed_root, sin_cos_small, Landing, TaylorSum, GRAZING_EPSILONS, ROOT_STEPS, SERIES_LIMIT,
};
use crate::physics::mechanisms::Dissipation;
use crate::scene::OffsetSign;
use crate::{Float, Scene};

/// Most evaluations of the motion per flight with a kernel: the scan for the return (steps of
/// 1/16 of a period), its maxima and the root, together.
pub const KERNEL_FLIGHT_STEPS: u32 = 4096;

/// Steps of the scan per period of the pair.
const STEPS_PER_PERIOD: f64 = 16.0;
/// The pair's damping ratio beyond which the modal form is not used (see the module docs).
const PAIR_DAMPING_LIMIT: f64 = 0.995;
/// Most terms of the short-time series.
const SERIES_TERMS: u32 = 48;
/// Most bisections of a maximum's time.
const PEAK_STEPS: u32 = 64;

/// The free motion with a kernel, and the kernel's force at the next departure.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Kernel<F> {
    omega2: F,
    /// 2 zeta Omega (1/s).
    damping: F,
    kappa: F,
    /// 1 / tau (1/s).
    beta: F,
    delta: F,
    /// 1 - R.
    loss: F,
    /// The real root r1 and its distance r1 + beta from -beta.
    real: F,
    shifted: F,
    /// The pair alpha +- i w.
    alpha: F,
    w: F,
    /// The fastest rate of the free motion (1/s): the series serves below SERIES_LIMIT / lambda.
    lambda: F,
    /// The characteristic polynomial's coefficients (a2 = 2 zeta Omega + beta, a1 = Omega^2 +
    /// 2 zeta Omega beta, a0) in the series' scaled time lambda t: a2 / lambda, a1 / lambda^2,
    /// a0 / lambda^3.
    scaled: [F; 3],
    /// The scan's step (s).
    step: F,
    /// u at the next departure (m/s^2).
    force: F,
    /// The last return's rounding beyond a well-conditioned flight's (see
    /// [`Flights::rounding`]).
    rounding: (F, F),
}

/// One flight's modal coefficients: x = c1 e^(r1 t) + e^(alpha t) (p cos + q sin), and u's.
#[derive(Debug, Clone, Copy)]
struct Modes<F> {
    c1: F,
    p: F,
    q: F,
    u1: F,
    uc: F,
    us: F,
    /// x''(0) (m/s^2).
    x2: F,
    /// The rounding of c1, and of p and q together (m, absolute): each a difference whose
    /// terms may be far larger than itself (p = Delta - c1 keeps 1 % of Delta where c1 is near
    /// it, and u's modes, kappa / (s + beta) times x's, carry that).
    c1_error: F,
    pq_error: F,
}

/// The real root's distance d = r1 + beta in (0, beta), the root of
/// d ((d - beta)(d - beta + 2 zeta Omega) + Omega^2) = kappa, by the flights' guarded Newton
/// ([`bracketed_root`]: the left side is -kappa at 0 and beta Omega^2 - kappa > 0 at
/// beta). `None` if it does not settle in 200 evaluations.
fn real_root<F: Float>(omega2: F, damping: F, kappa: F, beta: F) -> Option<F> {
    const STEPS: u32 = 200;
    let quadratic = |d: F| (d - beta) * (d - beta + damping) + omega2;
    let (spent, _, d) = bracketed_root(
        |d| {
            (
                d * quadratic(d) - kappa,
                quadratic(d) + d * (F::TWO * (d - beta) + damping),
            )
        },
        (F::ZERO, beta),
        kappa / quadratic(F::ZERO),
        STEPS,
    );
    (spent < STEPS).then_some(d)
}

impl<F: Float> Kernel<F> {
    /// The scene's kernel flights, from the steady kernel force of the generating orbit at the
    /// first impact (the state a contact that has bounced this way long enough would hold).
    /// `None` without exactly one kernel, where the pair is (nearly) real, or where a constant
    /// overflows the float.
    pub(crate) fn new<D: Dissipation<F>, S: OffsetSign>(scene: &Scene<F, D, S>) -> Option<Self> {
        let dissipation = scene.dissipation();
        let (kappa, tau) = dissipation.kernel()?;
        let omega = scene.omega();
        let omega2 = omega * omega;
        let damping = F::TWO * dissipation.damping_ratio() * omega;
        let beta = F::ONE / tau;
        let delta = scene.delta();
        let shifted = real_root(omega2, damping, kappa, beta)?;
        let a0 = beta * (omega2 - kappa * tau);
        let e1 = damping + shifted;
        let e0 = a0 / (beta - shifted);
        let disc = e0 - e1 * e1 * c::<F>(0.25);
        let limit = c::<F>(1.0 - PAIR_DAMPING_LIMIT * PAIR_DAMPING_LIMIT);
        if disc.is_nan() || disc < limit * e0 {
            return None;
        }
        let w = disc.sqrt();
        let lambda = (beta - shifted).max(e0.sqrt());
        // The steady kernel state of the generating orbit with J = 2 v0, leaving the stop at v0
        // and back after its period T: y = (beta Delta - v0 coth(beta T / 2)) / (beta^2 +
        // Omega^2), coth(x) = 1 + 2 / expm1(2 x).
        let v0 = scene.closing_speed();
        let period = scene.orbit().at(F::TWO * v0).period();
        let coth = F::ONE + F::TWO / (beta * period).exp_m1();
        let (tilt, lag) = (beta * delta, v0 * coth);
        let force = kappa * (tilt - lag) / (beta * beta + omega2);
        // That force rounds, and the first flight falls back at the pull -Omega^2 Delta + u,
        // which may cancel it: its relative error, carried by the first flight's time (f32 at a
        // static share of 0.89, the pull 1/9 of the spring's: the first flight 2.2e-6 off where
        // the bounce stated 2.0e-6). In epsilons (each rounding half of one): Beta Delta 1, v0
        // coth up to 4 (the period and exp_m1 beside the product), the denominator 2, the
        // difference, product and quotient half each; the pull's own sum and spring one more.
        // A bound, not taken again in `solve` (measured there: 19 epsilons of a bound of 83,
        // the lag's 4 epsilons most of it: v0 coth is 400 times Beta Delta on that scene).
        let eps = F::EPSILON;
        let spring = omega2 * delta.abs();
        let force_error = eps
            * (kappa * (tilt.abs() + c::<F>(4.0) * lag.abs()) / (beta * beta + omega2)
                + c::<F>(4.0) * force.abs());
        let pull = (force - omega2 * delta).abs();
        let start = if pull > F::ZERO {
            (force_error + eps * (spring + force.abs())) / pull
        } else {
            F::MAX * F::TWO
        };
        let kernel = Self {
            omega2,
            damping,
            kappa,
            beta,
            delta,
            loss: scene.loss(),
            real: shifted - beta,
            shifted,
            alpha: -e1 * F::HALF,
            w,
            lambda,
            scaled: [
                (damping + beta) / lambda,
                (omega2 + damping * beta) / lambda / lambda,
                a0 / lambda / lambda / lambda,
            ],
            step: F::PI / (c::<F>(STEPS_PER_PERIOD / 2.0) * w),
            force,
            rounding: (F::ZERO, start),
        };
        let finite = [
            a0,
            e0,
            w,
            lambda,
            kernel.step,
            force,
            kernel.real,
            kernel.scaled[0],
            kernel.scaled[1],
            kernel.scaled[2],
        ]
        .iter()
        .all(|x| x.is_finite());
        finite.then_some(kernel)
    }

    /// The modes of the flight leaving the stop at speed `a` with the kernel force `force`.
    fn modes(&self, a: F) -> Modes<F> {
        let (x0, x1) = (self.delta, -a);
        let x2 = -self.omega2 * self.delta + self.damping * a + self.force;
        let (alpha, w, r1) = (self.alpha, self.w, self.real);
        let denominator = (r1 - alpha) * (r1 - alpha) + w * w;
        // c1's numerator x''(0) - 2 alpha x'(0) + e0 x(0), with -2 alpha = 2 zeta Omega + d
        // and e0 - Omega^2 = d (2 zeta Omega + d - beta) (the characteristic polynomial's
        // a1 = e0 + 2 alpha r1), is u(0) + d ((2 zeta Omega + d - beta) Delta - a): summed as
        // written it cancelled 2 zeta Omega a against itself (f32, zeta 0.35 on a kernel of
        // static share 0.7: c1 and so the kernel's force 2.6e-5 off after one flight).
        let d = self.shifted;
        let (static_part, departure) = (d * ((self.damping + d - self.beta) * x0), d * a);
        let c1 = (self.force + static_part - departure) / denominator;
        let p = x0 - c1;
        let q = (x1 - r1 * c1 - alpha * p) / w;
        // Each difference rounds to an epsilon of its terms' sizes, and carries its inputs'.
        let eps = F::EPSILON;
        let c1_error = eps * (self.force.abs() + static_part.abs() + departure.abs()) / denominator;
        let p_error = eps * (x0.abs() + c1.abs()) + c1_error;
        let q_error = (eps * (x1.abs() + (r1 * c1).abs() + (alpha * p).abs())
            + r1.abs() * c1_error
            + alpha.abs() * p_error)
            / w;
        // u's part of a mode e^(s t) is kappa / (s + beta) times x's.
        let u1 = self.kappa * c1 / self.shifted;
        let (re, im) = (alpha + self.beta, w);
        let m = self.kappa / (re * re + im * im);
        let (gr, gi) = (m * re, -m * im);
        Modes {
            c1,
            p,
            q,
            u1,
            uc: gr * p + gi * q,
            us: gr * q - gi * p,
            x2,
            c1_error,
            pq_error: p_error + q_error,
        }
    }

    /// (x - Delta, x', u) at `t` in closed form. x - Delta is summed from the modes' departures,
    /// c1 expm1(r1 t) + p (expm1(alpha t) cos + (cos - 1)) + q e^(alpha t) sin, with
    /// cos - 1 = -sin^2 / (1 + cos) where cos > 0: no term is the difference of two numbers near
    /// Delta, so a flight just past the series' reach keeps its digits (x - Delta from x lost
    /// log10(|Delta| / |x - Delta|) of them: 2e-4 of the bounce in f32 on a strong kernel).
    fn closed(&self, m: &Modes<F>, t: F) -> (F, F, F) {
        let e = (self.real * t).exp_m1();
        let decay = (self.alpha * t).exp_m1();
        let (s, co) = sin_cos_small(self.w * t);
        let (alpha, w) = (self.alpha, self.w);
        let versine = if co > F::ZERO {
            -s * s / (F::ONE + co)
        } else {
            co - F::ONE
        };
        let y = m.c1 * e + m.p * (decay * co + versine) + m.q * (decay + F::ONE) * s;
        // u the same way, from the force at the departure (u1 + uc): summed from the modes it
        // rounded to an epsilon of their size every flight, and where the kernel nearly
        // cancels the spring's pull at the stop (a static share of 0.87), the later flights'
        // pull -Omega^2 Delta + u lost 20 times that (f32, 2.9e-4 by the twelfth flight).
        let u = self.force + m.u1 * e + m.uc * (decay * co + versine) + m.us * (decay + F::ONE) * s;
        let (e, decay) = (e + F::ONE, decay + F::ONE);
        let v = m.c1 * self.real * e
            + decay * ((alpha * m.p + w * m.q) * co + (alpha * m.q - w * m.p) * s);
        (y, v, u)
    }

    /// ((x - Delta) / t, x') from the Taylor series about the departure, in the scaled time
    /// s = lambda t (so that no coefficient overflows: unscaled, the n-th grows as lambda^n /
    /// n!, past f32's range by the twentieth on a kernel of lambda 6e4 1/s, where the series
    /// gave NaN and the flight was lost): x = sum E(n) s^n, E0 = Delta, E1 = -a / lambda,
    /// E2 = x''(0) / (2 lambda^2), E(n+3) = -(b2 E(n+2) / (n+3) + b1 E(n+1) / ((n+3)(n+2)) +
    /// b0 E(n) / ((n+3)(n+2)(n+1))), with b2 = a2 / lambda, b1 = a1 / lambda^2 and b0 = a0 /
    /// lambda^3 (each at most a few: lambda is the fastest rate).
    fn series(&self, m: &Modes<F>, a: F, t: F) -> (F, F) {
        let l = self.lambda;
        let [b2, b1, b0] = self.scaled;
        let (mut d0, mut d1, mut d2) = (self.delta, -a / l, m.x2 / l / l * F::HALF);
        let mut sum = TaylorSum::new(d1);
        // d2 is the coefficient of s^2 in x: of s in (x - Delta) / s. (Three quiet terms to
        // stop, not two: with three terms in the recurrence one coefficient can nearly vanish
        // between larger ones.)
        let s = l * t;
        for n in 2..SERIES_TERMS {
            let nf = F::from_u32(n);
            if sum.add(nf, d2, s, 3) {
                break;
            }
            // d(n+1) from d(n), d(n-1), d(n-2): k = n - 2 in the recurrence.
            let (n1, n0, nm) = (nf + F::ONE, nf, nf - F::ONE);
            let next = -(b2 * d2 / n1 + b1 * d1 / (n1 * n0) + b0 * d0 / (n1 * n0 * nm));
            d0 = d1;
            d1 = d2;
            d2 = next;
        }
        // (x - Delta) / t = lambda (x - Delta) / s, and dx/dt = lambda dx/ds.
        (sum.over_t * l, sum.slope * l)
    }

    /// (x - Delta, x'): the series for short times, the closed form beyond.
    fn eval(&self, m: &Modes<F>, a: F, t: F) -> (F, F) {
        if self.lambda * t <= c(SERIES_LIMIT) {
            let (over_t, slope) = self.series(m, a, t);
            (over_t * t, slope)
        } else {
            let (y, v, _) = self.closed(m, t);
            (y, v)
        }
    }

    /// True when `y` at `t` is within rounding of the stop: of Delta, or of the modes it is
    /// the difference of where they are larger (a gap far below the flight's size: f32 at
    /// Delta = 1.3e-15 m and a swing of 1e4 m took a flight that stays for one that returns,
    /// 376 impacts where f64 solves 2).
    fn grazes(&self, m: &Modes<F>, t: F, y: F) -> bool {
        let modes = m.c1.abs() * (self.real * t).exp() + (self.alpha * t).exp() * m.p.hypot(m.q);
        y.abs() <= c::<F>(GRAZING_EPSILONS) * F::EPSILON * (self.delta.abs() + modes)
    }

    /// A bound on x from `t` on (every mode decays; a slow mode below zero only rises towards
    /// it), the modes' coefficients' rounding and its own included: a bound below the stop is
    /// below it for every float near the computed modes.
    fn ceiling(&self, m: &Modes<F>, t: F) -> F {
        let bound = (m.c1 + m.c1_error).max(F::ZERO) * (self.real * t).exp()
            + (self.alpha * t).exp() * (m.p.hypot(m.q) + m.pq_error);
        bound * (F::ONE + c::<F>(GRAZING_EPSILONS) * F::EPSILON)
    }
}

impl<F: Float> Flights<F> for Kernel<F> {
    #[allow(clippy::too_many_lines)] // the scan, its maxima and the root share one budget
    fn land(&mut self, a: F) -> Landing<F> {
        let m = self.modes(a);
        let mut spent = 0;
        let (mut grazing, mut touch) = (false, F::ZERO);
        // Scan for a bracket [low, high] of the return.
        let (mut low, mut rising) = (F::ZERO, false);
        let bracket = loop {
            if spent >= KERNEL_FLIGHT_STEPS {
                return Landing::Stays {
                    grazing: true,
                    touch: F::ZERO,
                };
            }
            spent += 1;
            let t = low + self.step;
            let (y, v) = self.eval(&m, a, t);
            if y >= F::ZERO {
                break (low, t);
            }
            if rising && v <= F::ZERO {
                // A maximum in (low, t): does it reach the stop?
                let (mut up, mut down) = (low, t);
                for _ in 0..PEAK_STEPS {
                    let mid = up + (down - up) * F::HALF;
                    if mid <= up || mid >= down || spent >= KERNEL_FLIGHT_STEPS {
                        break;
                    }
                    spent += 1;
                    if self.eval(&m, a, mid).1 > F::ZERO {
                        up = mid;
                    } else {
                        down = mid;
                    }
                }
                let top = self.eval(&m, a, up).0;
                if self.grazes(&m, up, top) {
                    grazing = true;
                    touch = up;
                }
                if top >= F::ZERO {
                    break (low, up);
                }
            }
            // (The bound carries its rounding: one within rounding of the stop decided a stay
            // the swing could still reach, f32 at a gap of 2e-10 m whose bound fell 1.4e-17 m
            // short, 3 impacts where f64 solves 4. Taken as a graze instead, it turned the
            // creeping approach of a slow mode far below the stop, its bound loose by the
            // mode, into no end that the float could find: 0 s where f64 stays at once.)
            if self.delta > F::ZERO && self.ceiling(&m, t) < self.delta {
                return Landing::Stays { grazing, touch };
            }
            rising = v > F::ZERO;
            low = t;
        };
        // Newton from the free fall 2a / x''(0) (a short flight's return), else the middle.
        let (_, speed, t) = bracketed_root(
            |t| self.eval(&m, a, t),
            bracket,
            F::TWO * a / m.x2,
            ROOT_STEPS.min(KERNEL_FLIGHT_STEPS.saturating_sub(spent)),
        );
        if speed > F::ZERO {
            self.force = self.closed(&m, t).2;
            // The return's conditioning: the modes' sizes in x and x' at the return over its
            // speed. (The series, for short flights, is summed relative to the flight itself.)
            // The kernel's force carried to the next flight (always from the closed form) is
            // a difference of its modes too: its error moves the pull g = -Omega^2 Delta + u
            // the later flights fall back at, and their times with it.
            let (e, decay) = ((self.real * t).exp(), (self.alpha * t).exp());
            let pull = (self.force - self.omega2 * self.delta).abs();
            let moved = m.u1.abs() * (e - F::ONE).abs() + (F::ONE + decay) * m.uc.hypot(m.us);
            // The modes' own rounding, carried into u by kappa / (s + beta) (f32 at zeta 1.9
            // and a static share of 0.45: p kept 1 % of Delta, u's pair was 0.5 % off, the
            // force 48 epsilons, and the bounce 1.03e-5 where 1.01e-5 was stated).
            let (re, im) = (self.alpha + self.beta, self.w);
            let pair_gain = self.kappa / (re * re + im * im) * (re.abs() + im.abs());
            let coefficients = (self.kappa / self.shifted) * m.c1_error * (e - F::ONE).abs()
                + (F::ONE + decay) * pair_gain * m.pq_error;
            // (No pull at the stop: no figure; `solve` takes an infinite error as none.)
            let force = if pull > F::ZERO {
                (F::EPSILON * (self.force.abs() + moved) + coefficients) / pull
            } else {
                F::MAX * F::TWO
            };
            self.rounding = if self.lambda * t > c(SERIES_LIMIT) {
                let (slow, pair) = (m.c1.abs() * e, decay * m.p.hypot(m.q));
                let rates = (self.alpha * self.alpha + self.w * self.w).sqrt();
                let (slow_error, pair_error) = (m.c1_error * e, decay * m.pq_error);
                (
                    (F::EPSILON * (m.c1.abs() + m.p.hypot(m.q) + pair)
                        + m.c1_error
                        + m.pq_error
                        + pair_error)
                        / speed,
                    (F::EPSILON * (slow * self.real.abs() + pair * rates)
                        + slow_error * self.real.abs()
                        + pair_error * rates)
                        / speed
                        + force,
                )
            } else {
                (F::ZERO, force)
            };
            // A return whose time is uncertain by as much as the flight, or its speed by as
            // much as itself (each taken 4 times, as in `solve`), was decided by rounding: a
            // creeping approach to a stop far below the modes' size, which a flight that stays
            // may pass as well as reach (f32 at Delta = 1.3e-15 m and a swing of 1e4 m returned
            // at 7.5e-4 m/s with a rounding of 4 times that, 376 impacts where f64 solves 2).
            let (moved, inherited) = self.rounding;
            let grazing = grazing || c::<F>(4.0) * moved >= t || c::<F>(4.0) * inherited >= F::ONE;
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

    fn rounding(&self) -> (F, F) {
        self.rounding
    }
    const ROUNDED: bool = true;

    fn tail(&mut self, a: F, _elapsed: F) -> Option<(F, F)> {
        let g = -self.omega2 * self.delta + self.force;
        if g.is_nan() || g <= F::ZERO {
            return None;
        }
        let span = F::TWO * a / g / self.loss;
        let growth = (self.kappa * self.delta - self.beta * self.force) / g;
        let third = c::<F>(1.0 / 3.0);
        let first = span * (self.damping * c::<F>(1.0 / 6.0) + growth * third);
        let drift = span * (self.damping * c::<F>(1.0 / 6.0) + growth.abs() * third);
        let small = self.omega2.sqrt() * a / g;
        (drift <= F::TAIL_CUTOFF && small <= F::TAIL_CUTOFF).then(|| {
            let time = span * (F::ONE - first);
            // Beside the series' truncation, two differences round: the pull g (its terms
            // Omega^2 |Delta| and |u|, moving the span) and the growth's kappa Delta - beta u,
            // which cancels where the force has settled to the preload (two roundings of each
            // term and u's own, an epsilon each; f32 at a static share of 0.8 and a memory of
            // 1/360 of the oscillation: 2.7e-6 of the time where the truncation alone stated
            // 1.3e-6).
            let pull = F::EPSILON * (self.omega2 * self.delta.abs() + self.force.abs()) / g;
            let cancelled = (self.kappa * self.delta).abs() + (self.beta * self.force).abs();
            let rounding =
                time * pull + span * span * c::<F>(2.0 / 3.0) * F::EPSILON * cancelled / g;
            (
                time,
                time * c::<F>(4.0) * (drift * drift + small * small) + rounding,
            )
        })
    }
}

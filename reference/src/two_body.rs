//! Exact event-driven simulation of two bodies (the paper's Eq. 1 and Fig. 2a).
//!
//! m_i x_i'' + d_i x_i' + c_i x_i = -/+ N, contact at x = x1 - x2 = Delta. Apart (N = 0) each
//! body is a free damped oscillator in closed form; an impact (x reaches Delta closing) is a
//! momentum-conserving Newton impact, u -> -R u for the relative velocity u = v1 - v2. When the
//! impacts accumulate (relative departure below 1e-8 Omega_rel |Delta|), their geometric tail is
//! summed and the bodies stick: x1 = x2 + Delta, moving together while the contact force N is
//! compressive; when N turns tensile they separate and bounce again (with unequal partial
//! frequencies contacts can reopen).
//!
//! The next impact is searched by stepping 1/64 of the shortest period, watching both a sign
//! change of g = x - Delta and a maximum of g reaching the stop (no grazing impact is missed),
//! then Brent. For short times g(t)/t is summed as a Taylor series (each body's series about the
//! impact, in the faster body's scaled time), so tiny flights keep their digits.

use super::brent::brent;
use super::{Failure, Outcome, Regime, Sum};

/// Two bodies, f64, SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TwoBodies {
    /// Masses (kg).
    pub m: [f64; 2],
    /// Stiffnesses (N/m).
    pub c: [f64; 2],
    /// Damping coefficients (N s/m).
    pub d: [f64; 2],
    /// Contact at x1 - x2 = Delta (m): gap > 0, preload < 0.
    pub delta: f64,
    /// R.
    pub restitution: f64,
    /// Closing speed of body 1 relative to body 2 at the first impact (m/s).
    pub closing_speed: f64,
    /// Body 2's position and velocity at the first impact (body 1 is at x2 + Delta).
    pub x2: f64,
    /// Body 2's velocity at the first impact (m/s).
    pub v2: f64,
    /// P_end (m/s), if any.
    pub threshold: Option<f64>,
}

/// (x, v) of x'' + 2 zeta w x' + w^2 x = 0 after time t from (x0, v0).
pub(crate) fn evolve(w: f64, zeta: f64, x0: f64, v0: f64, t: f64) -> (f64, f64) {
    if zeta < 1.0 {
        let a = zeta * w;
        let wd = w * (1.0 - zeta * zeta).sqrt();
        let (s, c) = (wd * t).sin_cos();
        let e = (-a * t).exp();
        let b = (v0 + a * x0) / wd;
        (
            e * (x0 * c + b * s),
            e * (v0 * c - (a * v0 + w * w * x0) / wd * s),
        )
    } else if zeta == 1.0 {
        let e = (-w * t).exp();
        (
            e * (x0 + (v0 + w * x0) * t),
            e * (v0 - w * (v0 + w * x0) * t),
        )
    } else {
        let root = (zeta * zeta - 1.0).sqrt();
        let slow = -w / (zeta + root);
        let fast = -w * (zeta + root);
        let p = (v0 - fast * x0) / (slow - fast);
        let q = x0 - p;
        let (es, ef) = ((slow * t).exp(), (fast * t).exp());
        (p * es + q * ef, slow * p * es + fast * q * ef)
    }
}

/// Taylor coefficients c_0..c_n of x(t) for x'' + b x' + k x = 0 from (x0, v0).
fn series(b: f64, k: f64, x0: f64, v0: f64, out: &mut [f64]) {
    if out.len() < 2 {
        return;
    }
    out[0] = x0;
    out[1] = v0;
    for n in 0..out.len() - 2 {
        #[allow(clippy::cast_precision_loss)]
        let nf = n as f64;
        out[n + 2] = -(b * (nf + 1.0) * out[n + 1] + k * out[n]) / ((nf + 2.0) * (nf + 1.0));
    }
}

const TERMS: usize = 60;

#[derive(Debug, Clone, Copy)]
struct Body {
    w: f64,
    zeta: f64,
}

impl TwoBodies {
    fn bodies(&self) -> [Body; 2] {
        let body = |i: usize| {
            let w = (self.c[i] / self.m[i]).sqrt();
            Body {
                w,
                zeta: self.d[i] / (2.0 * (self.c[i] * self.m[i]).sqrt()),
            }
        };
        [body(0), body(1)]
    }

    /// The Rayleigh frequency of the relative motion (the scale of the Zeno tail).
    fn omega_rel(&self) -> f64 {
        let [m1, m2] = self.m;
        ((self.c[0] * m2 / m1 + self.c[1] * m1 / m2) / (m1 + m2)).sqrt()
    }
}

/// A free flight from state (x1, v1, x2, v2) at g = x1 - x2 - Delta = 0.
struct Free<'a> {
    s: &'a TwoBodies,
    b: [Body; 2],
    state: [f64; 4],
    /// Taylor coefficients of g = x1 - x2 - Delta (c_0 = 0) in the scaled time u = `scale` t.
    /// (In t itself they grow as the faster body's frequency to the k-th power: beyond f64's
    /// range by the 60th term from a few 1e6 rad/s, where the series summed to NaN and a
    /// preload's first return was lost: one impact, ending at 0.)
    g: [f64; TERMS],
    /// The faster body's frequency (rad/s): the series' time scale.
    scale: f64,
    shortest: f64,
}

impl<'a> Free<'a> {
    fn new(s: &'a TwoBodies, state: [f64; 4]) -> Self {
        let b = s.bodies();
        let scale = b[0].w.max(b[1].w);
        // Each body's x'' + 2 zeta w x' + w^2 x = 0 in u = scale t.
        let (mut a1, mut a2) = ([0.0; TERMS], [0.0; TERMS]);
        for (body, (x, v), out) in [
            (b[0], (state[0], state[1]), &mut a1),
            (b[1], (state[2], state[3]), &mut a2),
        ] {
            let w = body.w / scale;
            series(2.0 * body.zeta * w, w * w, x, v / scale, out);
        }
        let mut g = [0.0; TERMS];
        for k in 0..TERMS {
            g[k] = a1[k] - a2[k];
        }
        g[0] = 0.0; // x1 - x2 = Delta exactly at the start
        let shortest = 2.0 * std::f64::consts::PI / scale;
        Self {
            s,
            b,
            state,
            g,
            scale,
            shortest,
        }
    }

    /// g'(0), the departure's relative speed (m/s).
    fn start_speed(&self) -> f64 {
        self.g[1] * self.scale
    }

    /// g''(0) / 2 (m/s^2).
    fn half_curvature(&self) -> f64 {
        self.g[2] * self.scale * self.scale
    }

    /// (g(t)/t, g'(t)) for t > 0.
    fn eval(&self, t: f64) -> (f64, f64) {
        let wmax = self.b[0].w.max(self.b[1].w) * (1.0 + self.b[0].zeta.max(self.b[1].zeta));
        if wmax * t <= 1.0 {
            let u = self.scale * t;
            let (mut over_u, mut slope, mut p) = (0.0, 0.0, 1.0);
            for k in 1..TERMS {
                #[allow(clippy::cast_precision_loss)]
                let kf = k as f64;
                over_u += self.g[k] * p;
                slope += kf * self.g[k] * p;
                p *= u;
            }
            (over_u * self.scale, slope * self.scale)
        } else {
            let (x1, v1) = evolve(self.b[0].w, self.b[0].zeta, self.state[0], self.state[1], t);
            let (x2, v2) = evolve(self.b[1].w, self.b[1].zeta, self.state[2], self.state[3], t);
            ((x1 - x2 - self.s.delta) / t, v1 - v2)
        }
    }

    fn at(&self, t: f64) -> [f64; 4] {
        let (x1, v1) = evolve(self.b[0].w, self.b[0].zeta, self.state[0], self.state[1], t);
        let (x2, v2) = evolve(self.b[1].w, self.b[1].zeta, self.state[2], self.state[3], t);
        [x1, v1, x2, v2]
    }

    /// Largest possible |x1| + |x2| from time t on (amplitude envelopes), for a gap's end.
    fn reach(&self, t: f64) -> f64 {
        let mut total = 0.0;
        for (i, b) in self.b.iter().enumerate() {
            let (x, v) = (self.state[2 * i], self.state[2 * i + 1]);
            let amp = if b.zeta < 1.0 {
                let wd = b.w * (1.0 - b.zeta * b.zeta).sqrt();
                let k = (v + b.zeta * b.w * x) / wd;
                (x * x + k * k).sqrt() * (-b.zeta * b.w * t).exp() / (1.0 - b.zeta * b.zeta).sqrt()
            } else {
                // Over-damped: bounded by its start plus the distance its speed can carry it.
                x.abs() + v.abs() / b.w
            };
            total += amp;
        }
        total
    }

    /// The next impact time after the start, or `None` if there is none.
    fn next_impact(&self, horizon_steps: u64) -> Result<Option<f64>, Failure> {
        let h = self.shortest / 64.0;
        let (mut t_prev, mut prev): (f64, (f64, f64)) =
            (0.0, (self.start_speed(), self.start_speed()));
        for k in 1..=horizon_steps {
            #[allow(clippy::cast_precision_loss)]
            let t = k as f64 * h;
            let now = self.eval(t);
            if now.0 >= 0.0 {
                return Ok(brent(
                    |s| self.eval(s).0,
                    t_prev.max(f64::MIN_POSITIVE),
                    t,
                    0.0,
                ));
            }
            if prev.1 > 0.0 && now.1 <= 0.0 {
                // A maximum of g in between: does it reach the stop?
                if let Some(peak) = brent(|s| self.eval(s).1, t_prev.max(f64::MIN_POSITIVE), t, 0.0)
                {
                    if self.eval(peak).0 >= 0.0 {
                        return Ok(brent(
                            |s| self.eval(s).0,
                            t_prev.max(f64::MIN_POSITIVE),
                            peak,
                            0.0,
                        ));
                    }
                }
            }
            if self.s.delta > 0.0 && self.reach(t) < self.s.delta {
                return Ok(None);
            }
            if self.s.delta >= 0.0
                && self.b.iter().all(|b| b.zeta >= 1.0)
                && t > 50.0 * self.shortest
            {
                return Ok(None);
            }
            t_prev = t;
            prev = now;
        }
        Err(Failure::Budget(horizon_steps))
    }
}

/// The stuck pair: one body of mass m1 + m2 on both springs and dampers, its rest position
/// shifted by the preload (x1 = x2 + Delta).
struct Pair {
    w: f64,
    zeta: f64,
    /// Body 2's rest position while stuck (m).
    x_eq: f64,
    stiff: f64,
    damp: f64,
}

impl Pair {
    fn of(s: &TwoBodies) -> Self {
        let big_m = s.m[0] + s.m[1];
        let stiff = s.c[0] + s.c[1];
        let damp = s.d[0] + s.d[1];
        Self {
            w: (stiff / big_m).sqrt(),
            zeta: damp / (2.0 * (stiff * big_m).sqrt()),
            x_eq: -s.c[0] * s.delta / stiff,
            stiff,
            damp,
        }
    }

    /// Body 2's position and the pair's velocity after time `t` stuck from (x2, v).
    fn evolve(&self, x2: f64, v: f64, t: f64) -> (f64, f64) {
        let (u, v) = evolve(self.w, self.zeta, x2 - self.x_eq, v, t);
        (u + self.x_eq, v)
    }
}

/// When the stuck pair separates (the contact force turns tensile), if ever.
fn separation(s: &TwoBodies, x2: f64, v: f64) -> Result<Option<f64>, Failure> {
    let [m1, _] = s.m;
    let big_m = s.m[0] + s.m[1];
    let Pair {
        w,
        zeta,
        x_eq,
        stiff,
        damp,
    } = Pair::of(s);
    // N = -c1 x1 - d1 v - m1 a, with x1 = x2 + Delta and a the pair's acceleration.
    let force = |t: f64| {
        let (u, vv) = evolve(w, zeta, x2 - x_eq, v, t);
        let x = u + x_eq;
        let a = -(stiff * x + s.c[0] * s.delta + damp * vv) / big_m;
        -s.c[0] * (x + s.delta) - s.d[0] * vv - m1 * a
    };
    let n_eq = -s.c[0] * s.c[1] * s.delta / stiff;
    // |N - N_eq| <= (c1 + d1 w + m1 w^2 (1 + 2 zeta)) * amplitude(t): beyond that bound, never.
    let (u0, v0) = (x2 - x_eq, v);
    let amp0 = if zeta < 1.0 {
        let wd = w * (1.0 - zeta * zeta).sqrt();
        let k = (v0 + zeta * w * u0) / wd;
        (u0 * u0 + k * k).sqrt() / (1.0 - zeta * zeta).sqrt()
    } else {
        u0.abs() + v0.abs() / w
    };
    let gain = s.c[0] + s.d[0] * w + m1 * w * w * (1.0 + 2.0 * zeta);
    let h = 2.0 * std::f64::consts::PI / w / 64.0;
    if force(0.0) < 0.0 {
        return Ok(Some(0.0));
    }
    for k in 1..=4_000_000_u64 {
        #[allow(clippy::cast_precision_loss)]
        let t = k as f64 * h;
        let bound = gain * amp0 * (-zeta * w * t).exp();
        if n_eq > 0.0 && bound < n_eq {
            return Ok(None);
        }
        if zeta == 0.0 && k > 64 * 8 {
            // Undamped: periodic; eight periods without separation means never.
            return Ok(None);
        }
        if force(t) < 0.0 {
            #[allow(clippy::cast_precision_loss)]
            let t_prev = (k - 1) as f64 * h;
            return Ok(brent(&force, t_prev, t, 0.0));
        }
    }
    Err(Failure::Budget(4_000_000))
}

/// What happens to the contact, in time order, for a trace of the bounce.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contact {
    /// A resolved impact: the contact closes and opens again at once.
    Impact {
        /// When (s).
        time: f64,
        /// Its impulse per unit mass, (1 + R) times the closing speed (m/s).
        impulse: f64,
    },
    /// The impacts accumulated (their summed Zeno tail ends here, s): the bodies stick and move
    /// together, the contact closed.
    Stick(f64),
    /// The stuck pair separates here (s): the contact force turned tensile.
    Separate(f64),
}

/// Simulates two bodies exactly.
///
/// # Errors
/// [`Failure::Invalid`] for parameters outside the model, [`Failure::NeedsThreshold`] when the
/// impacts never end and no threshold is given, [`Failure::Budget`] past `budget` impacts.
pub fn simulate(s: &TwoBodies, budget: u64) -> Result<Outcome, Failure> {
    simulate_traced(s, budget, |_| {})
}

/// [`simulate`], calling `on_contact` at every resolved impact, stick and separation, in time
/// order (not the impacts of a summed Zeno tail).
///
/// # Errors
/// As [`simulate`].
#[allow(clippy::too_many_lines)]
pub fn simulate_traced(
    s: &TwoBodies,
    budget: u64,
    on_contact: impl FnMut(Contact),
) -> Result<Outcome, Failure> {
    simulate_with_tail(s, budget, super::one_body::ZENO_TAIL, on_contact)
}

/// [`simulate_traced`] with the relative departure speed (over Omega_rel |Delta|) below which a
/// Zeno accumulation is summed, `tail`: the answer must not depend on it beyond O(tail^2).
#[allow(clippy::too_many_lines)]
fn simulate_with_tail(
    s: &TwoBodies,
    budget: u64,
    tail: f64,
    mut on_contact: impl FnMut(Contact),
) -> Result<Outcome, Failure> {
    let positive = |x: f64| x.is_finite() && x > 0.0;
    if !(s.m.iter().all(|m| positive(*m)) && s.c.iter().all(|c| positive(*c))) {
        return Err(Failure::Invalid("two_body"));
    }
    if !s.d.iter().all(|d| d.is_finite() && *d >= 0.0) {
        return Err(Failure::Invalid("two_body.d"));
    }
    if !(s.restitution > 0.0
        && s.restitution <= 1.0
        && positive(s.closing_speed)
        && s.delta.is_finite())
    {
        return Err(Failure::Invalid("scene"));
    }
    let undamped = s.d.iter().all(|d| *d == 0.0);
    // The regimes of docs/physics.md sec. 4, for the relative motion.
    let regime = if s.restitution == 1.0 && undamped {
        Regime::Periodic
    } else if s.delta < 0.0 && s.restitution < 1.0 {
        Regime::ZenoAccumulation
    } else if s.delta > 0.0 && !undamped {
        Regime::LastImpact
    } else {
        Regime::Endless
    };
    if regime == Regime::Endless && s.threshold.is_none() {
        return Err(Failure::NeedsThreshold);
    }
    let r = s.restitution;
    let [m1, m2] = s.m;
    let big_m = m1 + m2;
    let mut state = [s.x2 + s.delta, s.v2 + s.closing_speed, s.x2, s.v2];
    let mut time = Sum::default();
    let mut first = Vec::new();
    let mut impacts: u64 = 0;
    let (mut last_above, mut count_above, mut ever_infinite) = (0.0, 0_u64, false);
    let tail = tail * s.omega_rel() * s.delta.abs();
    let pair = Pair::of(s);
    let mut separations = 0;
    loop {
        // An impact now, relative speed u = v1 - v2 > 0.
        let u = state[1] - state[3];
        let p = (1.0 + r) * u;
        impacts += 1;
        on_contact(Contact::Impact {
            time: time.value(),
            impulse: p,
        });
        if first.len() < 5 {
            first.push((time.value(), p));
        }
        // Counted over every burst: the impacts at or above the threshold, wherever they fall
        // (a burst after a separation may rise above it again after an earlier one's tail fell
        // below).
        if s.threshold.is_none_or(|end| p >= end) {
            last_above = time.value();
            count_above += 1;
        } else if regime == Regime::Endless {
            // A decay without an end of its own: all later impacts are below too.
            return Ok(Outcome {
                regime,
                end_time: None,
                impacts_total: None,
                last_above_time: Some(last_above),
                impacts_above: Some(count_above),
                first_impacts: first,
            });
        }
        if regime == Regime::Periodic && impacts >= 5 {
            // No loss at all: the impacts go on as they are (their pattern may be
            // quasi-periodic with unequal frequencies, but their impulses never decay).
            let all_above = s.threshold.is_none_or(|end| p >= end);
            return Ok(Outcome {
                regime,
                end_time: None,
                impacts_total: None,
                last_above_time: if all_above { None } else { Some(last_above) },
                impacts_above: if all_above { None } else { Some(count_above) },
                first_impacts: first,
            });
        }
        if impacts > budget {
            return Err(Failure::Budget(budget));
        }
        state[1] -= (1.0 + r) * m2 / big_m * u;
        state[3] += (1.0 + r) * m1 / big_m * u;
        let departure = r * u;
        let flight = Free::new(s, state);
        if s.delta < 0.0 && r < 1.0 && departure < tail && flight.half_curvature() > 0.0 {
            // Zeno: flights ~ a / g2 shrinking by R; sum them and stick.
            let t_f = departure / flight.half_curvature();
            let t_stick = time.value() + t_f / (1.0 - r);
            ever_infinite = true;
            // The tail's impulses (1 + R) a R^k: those still at or above the threshold.
            let p_next = (1.0 + r) * departure;
            if let Some((more, flights)) = s
                .threshold
                .and_then(|end| crate::tail_above(p_next, r, t_f, end))
            {
                last_above = time.value() + flights;
                count_above += more;
            }
            // The pair sticks at the tail's end: carry the last impact's state (the bodies
            // together, at the centre of mass's velocity) through the tail, whose duration the
            // clock already holds.
            let v = (m1 * state[1] + m2 * state[3]) / big_m;
            let (x2, v) = pair.evolve(state[2], v, t_stick - time.value());
            on_contact(Contact::Stick(t_stick));
            match separation(s, x2, v)? {
                None => {
                    return Ok(Outcome::accumulated(
                        regime,
                        t_stick,
                        s.threshold.is_some(),
                        last_above,
                        count_above,
                        first,
                    ))
                }
                Some(dt) => {
                    separations += 1;
                    if separations > 10_000 {
                        return Err(Failure::Budget(10_000));
                    }
                    // Separate with no relative velocity, then fly to the next impact.
                    let (x2, v2) = pair.evolve(x2, v, dt);
                    time.add(t_stick - time.value() + dt);
                    on_contact(Contact::Separate(time.value()));
                    let apart = Free::new(s, [x2 + s.delta, v2, x2, v2]);
                    match apart.next_impact(400_000_000)? {
                        // A preload always closes again: the search lost the root.
                        None => return Err(Failure::Unresolved("the closing after a separation")),
                        Some(t) => {
                            state = apart.at(t);
                            time.add(t);
                        }
                    }
                    continue;
                }
            }
        }
        match flight.next_impact(400_000_000)? {
            None => {
                return Ok(Outcome {
                    regime,
                    end_time: Some(time.value()),
                    impacts_total: if ever_infinite { None } else { Some(impacts) },
                    last_above_time: Some(last_above),
                    impacts_above: Some(count_above),
                    first_impacts: first,
                });
            }
            Some(t) => {
                state = flight.at(t);
                time.add(t);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{simulate as one, OneBody, DEFAULT_BUDGET};

    fn pair(m: [f64; 2], c: [f64; 2], d: [f64; 2], delta: f64, r: f64, v0: f64) -> TwoBodies {
        TwoBodies {
            m,
            c,
            d,
            delta,
            restitution: r,
            closing_speed: v0,
            x2: 0.0,
            v2: 0.0,
            threshold: None,
        }
    }

    #[test]
    fn a_fast_pair_keeps_its_first_return() {
        // Both frequencies times s (stiffness s^2, damping s, closing speed s, lengths kept):
        // the same motion in a time 1 / s. At s = 1e4 (the faster body at 1e7 rad/s, a MEMS
        // contact's) the flight's Taylor coefficients in t overflowed, the series summed to NaN
        // and the first return was lost: one impact, ending at 0 (`bounce-table` gave a 0-tick
        // window). In the scaled time they are bounded: the ends agree to 3.7e-15 (measured).
        let (m, c, d) = ([1e-3, 4e-3], [1000.0, 1000.0 * 4.0 / 9.0], [0.002, 0.001]);
        let end_at = |s: f64| {
            let out = simulate(
                &pair(
                    m,
                    c.map(|x| x * s * s),
                    d.map(|x| x * s),
                    -1e-4,
                    0.7,
                    0.05 * s,
                ),
                DEFAULT_BUDGET,
            )
            .expect("solves");
            assert_eq!(out.impacts_total, None, "s = {s}: a Zeno accumulation");
            out.end_time.expect("ends") * s
        };
        let base = end_at(1.0);
        for s in [1e-3, 1e2, 1e4, 1e6] {
            let end = end_at(s);
            assert!(
                (end / base - 1.0).abs() < 1e-13,
                "s = {s}: {end:e} vs {base:e}"
            );
        }
    }

    #[test]
    fn equal_partial_frequencies_reproduce_the_one_body_result() {
        // c/m = 1e6 (Omega = 1000), d/m = 40 (zeta = 0.02): the relative motion is exactly the
        // one-body model, whatever the mass ratio and the centre of mass does.
        for (delta, r, v0, x2, v2) in [
            (-1e-3, 0.6, 0.3, 0.0, 0.0),
            (-1e-3, 0.3, 1.0, 2e-4, -0.1),
            (1e-3, 0.9, 3.0, 0.0, 0.05),
        ] {
            let two = TwoBodies {
                x2,
                v2,
                ..pair([1e-3, 3e-3], [1e3, 3e3], [0.04, 0.12], delta, r, v0)
            };
            let a = simulate(&two, DEFAULT_BUDGET).unwrap();
            let b = one(
                &OneBody {
                    omega: 1000.0,
                    delta,
                    restitution: r,
                    zeta: 0.02,
                    closing_speed: v0,
                    threshold: None,
                },
                DEFAULT_BUDGET,
            )
            .unwrap();
            let (ta, tb) = (a.end_time.unwrap(), b.end_time.unwrap());
            assert!(
                (ta / tb - 1.0).abs() < 1e-6,
                "{delta} {r}: two {ta} vs one {tb}"
            );
            assert_eq!(a.impacts_total, b.impacts_total);
            for (x, y) in a.first_impacts.iter().zip(&b.first_impacts) {
                assert!(
                    (x.0 - y.0).abs() <= 1e-9 * tb && (x.1 / y.1 - 1.0).abs() < 1e-8,
                    "{x:?} vs {y:?}"
                );
            }
        }
    }

    #[test]
    fn the_stuck_pair_separates_only_when_the_contact_force_turns_tensile() {
        // Equal partial frequencies: N = mu Omega^2 |Delta| constant, never tensile.
        let equal = pair([1e-3, 3e-3], [1e3, 3e3], [0.04, 0.12], -1e-3, 0.5, 0.3);
        assert_eq!(separation(&equal, 5e-4, 0.2).unwrap(), None);
        // A stiff light body on a soft heavy one, stuck 1 mm below equilibrium with a light
        // preload: compressive at first (N = 9.2 N), the pair's swing to the other side pulls
        // the contact apart within a period. (At +1 mm it is tensile at once: N = -9 N.)
        let unequal = pair([1e-3, 1e-2], [1e4, 1e2], [0.0, 0.0], -1e-5, 0.5, 0.3);
        assert_eq!(separation(&unequal, 1e-3, 0.0).unwrap(), Some(0.0));
        let t = separation(&unequal, -1e-3, 0.0)
            .unwrap()
            .expect("separates");
        let period = 2.0 * std::f64::consts::PI / ((1e4 + 1e2) / 1.1e-2_f64).sqrt();
        assert!(t > 0.0 && t < period, "{t} vs period {period}");
    }

    #[test]
    fn unequal_frequencies_can_reopen_a_stuck_contact() {
        // A stiff light body against a soft heavy one, preloaded lightly: the stuck pair
        // oscillates, the contact force turns tensile and the contact reopens.
        let two = pair([1e-3, 1e-2], [1e4, 1e2], [1e-3, 1e-2], -1e-5, 0.5, 0.5);
        let out = simulate(&two, DEFAULT_BUDGET).unwrap();
        assert_eq!(out.regime, Regime::ZenoAccumulation);
        assert!(out.end_time.unwrap() > 0.0);
    }

    /// A stiff light body on a soft heavy one three times slower, preloaded lightly and damped
    /// a little: the stuck pair reopens, 8 bursts.
    fn reopening() -> TwoBodies {
        let (m, c, zeta): ([f64; 2], [f64; 2], f64) = ([1e-3, 1e-2], [9e3, 1e4], 0.01);
        let d = [
            2.0 * zeta * (c[0] * m[0]).sqrt(),
            2.0 * zeta * (c[1] * m[1]).sqrt(),
        ];
        pair(m, c, d, -1e-5, 0.5, 0.5)
    }

    fn traced(s: &TwoBodies, tail: f64) -> (Outcome, Vec<Contact>) {
        let mut contacts = Vec::new();
        let out = simulate_with_tail(s, DEFAULT_BUDGET, tail, |c| contacts.push(c)).unwrap();
        (out, contacts)
    }

    #[test]
    fn impacts_above_are_counted_over_bursts() {
        let s = TwoBodies {
            threshold: Some(0.04),
            ..reopening()
        };
        let (out, contacts) = traced(&s, super::super::one_body::ZENO_TAIL);
        let above: Vec<f64> = contacts
            .iter()
            .filter_map(|c| match *c {
                Contact::Impact { time, impulse } if impulse >= 0.04 => Some(time),
                _ => None,
            })
            .collect();
        let bursts_above = {
            let mut burst = 0;
            let mut with = std::collections::BTreeSet::new();
            for c in &contacts {
                match *c {
                    Contact::Separate(_) => burst += 1,
                    Contact::Impact { impulse, .. } if impulse >= 0.04 => {
                        with.insert(burst);
                    }
                    _ => {}
                }
            }
            with.len()
        };
        // Impacts above in several bursts, and sub-threshold tails between them.
        assert!(bursts_above >= 3, "{bursts_above}");
        assert!(contacts.len() > above.len() + 50);
        assert_eq!(out.impacts_above, Some(above.len() as u64));
        assert_eq!(out.last_above_time, above.last().copied());
    }

    #[test]
    fn a_threshold_inside_a_summed_tail_counts_its_impacts() {
        // Departures below 1e-8 Omega_rel |Delta| (~1e-10 m/s) are summed; a threshold of
        // 1e-11 m/s falls inside that tail. Resolving 100 times further down must give the
        // same count (to the floor's one impact) and the same last time.
        let s = TwoBodies {
            threshold: Some(1e-11),
            ..reopening()
        };
        let (summed, _) = traced(&s, 1e-8);
        let (resolved, contacts) = traced(&s, 1e-10);
        let resolved_above = contacts
            .iter()
            .filter(|c| matches!(c, Contact::Impact { impulse, .. } if *impulse >= 1e-11))
            .count() as u64;
        assert_eq!(resolved.impacts_above, Some(resolved_above));
        let (a, b) = (summed.impacts_above.unwrap(), resolved_above);
        assert!(a.abs_diff(b) <= 1, "{a} vs {b}");
        let (ta, tb) = (
            summed.last_above_time.unwrap(),
            resolved.last_above_time.unwrap(),
        );
        assert!((ta / tb - 1.0).abs() < 1e-12, "{ta} vs {tb}");
    }

    #[test]
    fn the_stuck_phase_starts_where_the_summed_tail_ends() {
        // The end (the last sticking, after 7 separations) must not depend on where the Zeno
        // tail starts to be summed, beyond the tail's own O(tail^2). Starting the stuck motion
        // from the last resolved impact's state instead, the clock already past the tail,
        // shifted each separation by the tail's duration: 1.7e-6 relative at a 1e-5 cutoff (3e-9 at
        // 1e-4 once fixed: the tail's own second order).
        let s = reopening();
        let (coarse, c) = traced(&s, 1e-5);
        let (fine, f) = traced(&s, 1e-9);
        let separations = |v: &[Contact]| {
            v.iter()
                .filter(|c| matches!(c, Contact::Separate(_)))
                .count()
        };
        assert_eq!(separations(&c), 7);
        assert_eq!(separations(&f), 7);
        let (a, b) = (coarse.end_time.unwrap(), fine.end_time.unwrap());
        assert!((a / b - 1.0).abs() < 1e-9, "{a} vs {b}: {}", a / b - 1.0);
    }
}

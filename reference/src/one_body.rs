//! Exact event-driven simulation of one body against a stop (docs/physics.md sec. 1 and 6).
//!
//! Between impacts the motion is in closed form (under-, critically and over-damped); the
//! next impact is searched between the first minimum of x and the next maximum, where x is
//! monotone, so no grazing re-impact is missed (if x at that maximum is below Delta, impacts
//! have ended); Brent's method finds it to rounding. To avoid cancellation the search works in
//! y = x - Delta and, for short flights (Omega t <= 1.5), on y(t)/t summed as a Taylor series:
//! the trivial root at t = 0 is divided out, so the tiny flights of a Zeno accumulation keep
//! all their digits. Once the departure speed is below 1e-8 Omega |Delta| the remaining flights
//! of a Zeno accumulation are summed as a geometric tail.

use super::brent::brent;

/// Departure speed (relative to Omega |Delta|) below which a Zeno accumulation is summed.
pub const ZENO_TAIL: f64 = 1e-8;
/// Omega t below which y(t)/t is summed as a series.
const SERIES_LIMIT: f64 = 1.5;

/// x'' + 2 zeta Omega x' + Omega^2 x = 0 between impacts at x = Delta.
#[derive(Debug, Clone, Copy)]
pub struct Oscillator {
    /// Omega (rad/s).
    pub omega: f64,
    /// zeta.
    pub zeta: f64,
    /// Delta (m).
    pub delta: f64,
}

/// A flight that leaves the stop at speed `a`.
#[derive(Debug, Clone, Copy)]
pub struct Flight {
    a: f64,
    osc: Oscillator,
}

impl Flight {
    /// x(t) - Delta and x'(t) in closed form.
    fn closed(&self, t: f64) -> (f64, f64) {
        let Oscillator { omega, zeta, delta } = self.osc;
        let v0 = -self.a;
        let (x, v) = if zeta < 1.0 {
            let alpha = zeta * omega;
            let w = omega * (1.0 - zeta * zeta).sqrt();
            let (s, c) = (w * t).sin_cos();
            let e = (-alpha * t).exp();
            (
                e * (delta * c + (v0 + alpha * delta) / w * s),
                e * (v0 * c - (alpha * v0 + omega * omega * delta) / w * s),
            )
        } else if zeta == 1.0 {
            let e = (-omega * t).exp();
            (
                e * (delta + (v0 + omega * delta) * t),
                e * (v0 - omega * (v0 + omega * delta) * t),
            )
        } else {
            let root = (zeta * zeta - 1.0).sqrt();
            let slow = -omega / (zeta + root);
            let fast = -omega * (zeta + root);
            let a = (v0 - fast * delta) / (slow - fast);
            let b = delta - a;
            let (es, ef) = ((slow * t).exp(), (fast * t).exp());
            (a * es + b * ef, slow * a * es + fast * b * ef)
        };
        (x - delta, v)
    }

    /// (y(t)/t, y'(t)) from the Taylor series of y = x - Delta about the impact:
    /// c1 = -a, c2 = (2 zeta Omega a - Omega^2 Delta)/2,
    /// c_{k+2} = -(2 zeta Omega (k+1) c_{k+1} + Omega^2 c_k) / ((k+2)(k+1)).
    fn series(&self, t: f64) -> (f64, f64) {
        let Oscillator { omega, zeta, delta } = self.osc;
        let alpha2 = 2.0 * zeta * omega;
        let w2 = omega * omega;
        let (mut c_prev, mut c) = (-self.a, (alpha2 * self.a - w2 * delta) / 2.0); // c1, c2
        let mut over_t = c_prev; // sum c_k t^(k-1)
        let mut slope = c_prev; // sum k c_k t^(k-1)
        let mut power = 1.0; // t^(k-1) for the current c (k = 2)
        let mut quiet = 0;
        for k in 2..200_u32 {
            power *= t;
            let kf = f64::from(k);
            let term = c * power;
            over_t += term;
            slope += kf * term;
            if term.abs() <= 1e-18 * over_t.abs().max(slope.abs() / kf) {
                quiet += 1;
                if quiet >= 3 {
                    break;
                }
            } else {
                quiet = 0;
            }
            // c_{k+1} from c_k and c_{k-1}: index shift of the recurrence (k-1 -> k+1).
            let next = -(alpha2 * kf * c + w2 * c_prev) / ((kf + 1.0) * kf);
            c_prev = c;
            c = next;
        }
        (over_t, slope)
    }

    /// (y(t)/t, x'(t)), the series for short times and the closed form beyond.
    fn eval(&self, t: f64) -> (f64, f64) {
        if self.osc.omega * t <= SERIES_LIMIT {
            self.series(t)
        } else {
            let (y, v) = self.closed(t);
            (y / t, v)
        }
    }

    /// The first minimum of x after leaving the stop, if x turns.
    fn first_minimum(&self) -> Option<f64> {
        let Oscillator { omega, zeta, delta } = self.osc;
        let a = self.a;
        if zeta < 1.0 {
            let alpha = zeta * omega;
            let w = omega * (1.0 - zeta * zeta).sqrt();
            let k = (omega * omega * delta - alpha * a) / w;
            Some(a.atan2(-k) / w)
        } else if zeta == 1.0 {
            let den = omega * (a - omega * delta);
            (den > 0.0).then(|| a / den)
        } else {
            let root = (zeta * zeta - 1.0).sqrt();
            let slow = -omega / (zeta + root);
            let fast = -omega * (zeta + root);
            let amp_slow = (-a - fast * delta) / (slow - fast);
            let amp_fast = delta - amp_slow;
            let ratio = -fast * amp_fast / (slow * amp_slow);
            (ratio > 1.0).then(|| ratio.ln() / (slow - fast))
        }
    }

    /// The flight's duration and return speed, or `None` if the body never returns.
    ///
    /// Undamped flights are closed-form: (2/Omega) atan2(a, -Omega Delta), returning at a
    /// (energy). Root finding there would lose the return speed near grazing in a gap: y near
    /// its maximum is (a/Omega)^2 / (8 Delta), below the rounding of x - Delta once
    /// a / (Omega Delta) < 1e-8, and the speed error grows like eps / j^2. With damping a
    /// near-grazing return is the last one of a gap, and the sensitivity is physical.
    pub fn land(&self) -> Option<(f64, f64)> {
        let Oscillator { omega, zeta, delta } = self.osc;
        if zeta == 0.0 {
            return Some((2.0 / omega * self.a.atan2(-omega * delta), self.a));
        }
        let t_min = self.first_minimum()?;
        let t_hi = if zeta < 1.0 {
            t_min + std::f64::consts::PI / (omega * (1.0 - zeta * zeta).sqrt())
        } else {
            if delta >= 0.0 {
                return None; // over-damped: no return above the rest position
            }
            let mut hi = 2.0 * t_min.max(1e-300);
            let mut tries = 0;
            while self.eval(hi).0 < 0.0 {
                hi *= 2.0;
                tries += 1;
                if tries > 400 {
                    return None;
                }
            }
            hi
        };
        if self.eval(t_hi).0 < 0.0 {
            return None; // the next maximum stays below the stop: no more impacts
        }
        let t = brent(|t| self.eval(t).0, t_min, t_hi, 0.0)?;
        let speed = self.eval(t).1;
        (speed > 0.0).then_some((t, speed))
    }
}

impl Oscillator {
    /// The flight leaving the stop at speed `a` > 0.
    #[must_use]
    pub fn leave(&self, a: f64) -> Flight {
        Flight { a, osc: *self }
    }

    /// Energy lost to viscous damping over a flight of duration `t` leaving at `a`, by
    /// Gauss-Legendre quadrature of 2 zeta Omega x'^2 (for the self-check against
    /// (a^2 - v^2)/2).
    #[must_use]
    pub fn viscous_loss(&self, a: f64, t: f64) -> f64 {
        // 40 panels of 10-point Gauss-Legendre: the integrand is smooth (entire in t).
        const X: [f64; 5] = [
            0.148_874_338_981_631_2,
            0.433_395_394_129_247_2,
            0.679_409_568_299_024_4,
            0.865_063_366_688_984_5,
            0.973_906_528_517_171_7,
        ];
        const W: [f64; 5] = [
            0.295_524_224_714_752_9,
            0.269_266_719_309_996_4,
            0.219_086_362_515_982,
            0.149_451_349_150_580_6,
            0.066_671_344_308_688_1,
        ];
        let flight = self.leave(a);
        let panels = 40;
        let h = t / f64::from(panels);
        let mut total = 0.0;
        for p in 0..panels {
            let mid = (f64::from(p) + 0.5) * h;
            for (x, w) in X.iter().zip(W) {
                for s in [mid - 0.5 * h * x, mid + 0.5 * h * x] {
                    let v = flight.closed(s).1;
                    total += w * 0.5 * h * 2.0 * self.zeta * self.omega * v * v;
                }
            }
        }
        total
    }
}

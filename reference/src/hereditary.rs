//! Exact event-driven simulation of one body with an exponential relaxation kernel
//! Gamma(t) = kappa exp(-t / tau) (docs/physics.md sec. 3).
//!
//! The kernel is an augmented linear state: y' = x - y / tau, the force kappa y acting on the
//! body (dissipative: its mean power on a harmonic orbit is -A^2 nu Gs(nu) / 2). Between impacts
//! z = (x, v, y) evolves as z(t) = exp(A t) z(0), exactly; impacts reverse v -> -R v with y
//! continuous. The next impact is searched by steps of 1/64 of the natural period (exact step
//! matrix), watching a sign change of x - Delta and a maximum of x reaching the stop; Brent
//! refines it, on the Taylor series of (x - Delta) / t for short times. A Zeno accumulation's
//! tail (departure below 1e-8 Omega |Delta|) is summed geometrically.

use super::brent::brent;
use super::{Failure, Outcome, Regime, Sum};

/// One body, a viscous damper and an exponential relaxation kernel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kernelled {
    /// Omega (rad/s).
    pub omega: f64,
    /// zeta.
    pub zeta: f64,
    /// Delta (m).
    pub delta: f64,
    /// R.
    pub restitution: f64,
    /// v0 (m/s).
    pub closing_speed: f64,
    /// kappa (1/s^3).
    pub kappa: f64,
    /// tau (s).
    pub tau: f64,
    /// The internal state y at the first impact (m s); `None`: the steady state of the
    /// generating orbit with J = 2 v0.
    pub state: Option<f64>,
    /// P_end (m/s), if any.
    pub threshold: Option<f64>,
}

type Mat = [[f64; 3]; 3];

fn mul(a: &Mat, b: &Mat) -> Mat {
    let mut c = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}

fn apply(a: &Mat, z: &[f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| (0..3).map(|k| a[i][k] * z[k]).sum())
}

/// exp(A t) by scaling and squaring of an 18-term Taylor series.
fn expm(a: &Mat, t: f64) -> Mat {
    let norm = a
        .iter()
        .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
        * t.abs();
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let squarings = if norm > 0.5 {
        (norm / 0.5).log2().ceil() as i32
    } else {
        0
    };
    let h = t / 2f64.powi(squarings);
    let scaled: Mat = a.map(|r| r.map(|x| x * h));
    let mut term = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut sum = term;
    for k in 1..=18 {
        term = mul(&term, &scaled).map(|r| r.map(|x| x / f64::from(k)));
        for i in 0..3 {
            for j in 0..3 {
                sum[i][j] += term[i][j];
            }
        }
    }
    for _ in 0..squarings {
        sum = mul(&sum, &sum);
    }
    sum
}

const TERMS: usize = 48;

impl Kernelled {
    /// The state's matrix for (x, v, s), s = kappa y / Omega^2 (y scaled to a length): the same
    /// motion as (x, v, y), but balanced. With y itself the matrix holds kappa (6e9 on the
    /// grid's strongest kernel) beside 1, and the scaling and squaring of [`expm`] lost 5e-9 of
    /// the bounce time there (against the 60-digit solution of `scripts/exact_mp.py`; measured
    /// before this balancing).
    fn matrix(&self) -> Mat {
        let w = self.omega;
        [
            [0.0, 1.0, 0.0],
            [-w * w, -2.0 * self.zeta * w, w * w],
            [self.kappa / (w * w), 0.0, -1.0 / self.tau],
        ]
    }

    /// exp(A t) for the state's matrix A ([`Kernelled::matrix`]), taken in (x, v / Omega, s),
    /// where every entry is of the order of Omega, and brought back to (x, v, s): the similarity
    /// D A D^-1 with D = diag(1, 1 / Omega, 1). In (x, v, s) the entries Omega^2 stand beside 1,
    /// and [`expm`] counts its squarings by the largest: at Omega = 5.5e7 a step of 1/64 of a
    /// period took 25 (none balanced), and the bounce time came out 5.2e-8 off the 60-digit
    /// solution of `scripts/exact_mp.py` (5.4e-14 balanced); on the 5,450-impact gap of
    /// `the_exact_tier_solves_kernels_to_1e_11` 3.0e-10 off (1.1e-12 balanced).
    fn propagator(&self, a: &Mat, t: f64) -> Mat {
        let d = [1.0, 1.0 / self.omega, 1.0];
        let mut balanced = *a;
        for (i, row) in balanced.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x *= d[i] / d[j];
            }
        }
        let mut e = expm(&balanced, t);
        for (i, row) in e.iter_mut().enumerate() {
            for (j, x) in row.iter_mut().enumerate() {
                *x *= d[j] / d[i];
            }
        }
        e
    }

    /// s = kappa y / Omega^2 from y, and back.
    fn scaled(&self, y: f64) -> f64 {
        y * self.kappa / (self.omega * self.omega)
    }
    fn unscaled(&self, s: f64) -> f64 {
        s * (self.omega * self.omega) / self.kappa
    }

    /// The steady internal state at an impact on the generating orbit with impulse J = 2 v:
    /// y = integral_0^T exp(-(T - s)/tau) x(s) ds / (1 - exp(-T/tau)), x the generating orbit.
    fn steady_state(&self, speed: f64) -> f64 {
        let orbit = contact_bounce::physics::Orbit::new(self.omega, self.delta);
        let j = 2.0 * speed;
        let period = orbit.at(j).period();
        let panels = 200;
        let h = period / f64::from(panels);
        // 4-point Gauss-Legendre per panel.
        let nodes = [
            (0.339_981_043_584_856, 0.652_145_154_862_546),
            (0.861_136_311_594_053, 0.347_854_845_137_454),
        ];
        let mut total = 0.0;
        for p in 0..panels {
            let mid = (f64::from(p) + 0.5) * h;
            for (x, w) in nodes {
                for s in [mid - 0.5 * h * x, mid + 0.5 * h * x] {
                    total += w * 0.5 * h * (-(period - s) / self.tau).exp() * orbit.position(j, s);
                }
            }
        }
        total / -(-period / self.tau).exp_m1()
    }
}

struct Flight<'a> {
    k: &'a Kernelled,
    a: Mat,
    z0: [f64; 3],
    /// Taylor coefficients of x(t) about the impact in the scaled time s = Omega t: the n-th is
    /// x^(n)(0) / (n! Omega^n). (In t itself they grow as Omega^n: beyond f64's range at the 40th
    /// for Omega = 5.5e7, where the series then summed to NaN and a return was lost.)
    c: [f64; TERMS],
}

impl<'a> Flight<'a> {
    fn new(k: &'a Kernelled, a: Mat, z0: [f64; 3]) -> Self {
        let scaled = a.map(|row| row.map(|x| x / k.omega));
        let mut c = [0.0; TERMS];
        let mut z = z0;
        let mut factorial = 1.0;
        for (n, slot) in c.iter_mut().enumerate() {
            if n > 0 {
                #[allow(clippy::cast_precision_loss)]
                let nf = n as f64;
                factorial *= nf;
                z = apply(&scaled, &z);
            }
            *slot = z[0] / factorial;
        }
        c[0] = k.delta; // x(0) = Delta exactly
        Self { k, a, z0, c }
    }

    /// x'(0) and x''(0) / 2.
    fn start(&self) -> (f64, f64) {
        let w = self.k.omega;
        (self.c[1] * w, self.c[2] * w * w)
    }

    /// ((x(t) - Delta) / t, x'(t)).
    fn eval(&self, t: f64) -> (f64, f64) {
        let w = self.k.omega;
        if w * t <= 1.0 && t * w.max(1.0 / self.k.tau) <= 4.0 {
            let s = w * t;
            let (mut over_t, mut slope, mut p) = (0.0, 0.0, 1.0);
            for n in 1..TERMS {
                #[allow(clippy::cast_precision_loss)]
                let nf = n as f64;
                over_t += self.c[n] * p;
                slope += nf * self.c[n] * p;
                p *= s;
            }
            (over_t * w, slope * w)
        } else {
            let z = apply(&self.k.propagator(&self.a, t), &self.z0);
            ((z[0] - self.k.delta) / t, z[1])
        }
    }

    fn state(&self, t: f64) -> [f64; 3] {
        apply(&self.k.propagator(&self.a, t), &self.z0)
    }

    /// The next impact, or `None` when the body can no longer reach a gap's stop.
    fn next_impact(&self) -> Result<Option<f64>, Failure> {
        let period = 2.0 * std::f64::consts::PI / self.k.omega;
        let h = period / 64.0;
        let step = self.k.propagator(&self.a, h);
        let mut z = self.z0;
        let (mut t_prev, mut prev): (f64, (f64, f64)) = (0.0, (self.start().0, self.start().0));
        let mut peak_in_period: f64 = f64::NEG_INFINITY;
        let mut quiet_periods = 0;
        for k in 1..=64 * 1_000_000_u64 {
            z = apply(&step, &z);
            #[allow(clippy::cast_precision_loss)]
            let t = k as f64 * h;
            let now = if self.k.omega * t <= 1.0 {
                self.eval(t)
            } else {
                ((z[0] - self.k.delta) / t, z[1])
            };
            let lo = t_prev.max(f64::MIN_POSITIVE);
            if now.0 >= 0.0 {
                return Ok(brent(|s| self.eval(s).0, lo, t, 0.0));
            }
            if prev.1 > 0.0 && now.1 <= 0.0 {
                if let Some(peak) = brent(|s| self.eval(s).1, lo, t, 0.0) {
                    if self.eval(peak).0 >= 0.0 {
                        return Ok(brent(|s| self.eval(s).0, lo, peak, 0.0));
                    }
                }
            }
            peak_in_period = peak_in_period.max(z[0]);
            if k % 64 == 0 {
                // A gap whose swing stays below the stop for 20 periods while it decays has no
                // impact left (the motion is a decaying linear oscillation).
                if self.k.delta > 0.0 && peak_in_period < self.k.delta {
                    quiet_periods += 1;
                    if quiet_periods >= 20 {
                        return Ok(None);
                    }
                } else {
                    quiet_periods = 0;
                }
                peak_in_period = f64::NEG_INFINITY;
            }
            t_prev = t;
            prev = now;
        }
        Err(Failure::Budget(64_000_000))
    }
}

/// Simulates one body with a relaxation kernel exactly.
///
/// # Errors
/// [`Failure::Invalid`] for parameters outside the model (including kappa tau >= Omega^2: the
/// kernel's static stiffness would cancel the spring's), [`Failure::NeedsThreshold`],
/// [`Failure::Budget`].
pub fn simulate(k: &Kernelled, budget: u64) -> Result<Outcome, Failure> {
    let positive = |x: f64| x.is_finite() && x > 0.0;
    if !(positive(k.omega) && positive(k.kappa) && positive(k.tau) && positive(k.closing_speed)) {
        return Err(Failure::Invalid("kernel"));
    }
    if k.kappa * k.tau >= k.omega * k.omega {
        return Err(Failure::Invalid("kernel.kappa"));
    }
    if !(k.restitution > 0.0 && k.restitution <= 1.0 && k.zeta >= 0.0 && k.delta.is_finite()) {
        return Err(Failure::Invalid("scene"));
    }
    let regime = if k.delta < 0.0 && k.restitution < 1.0 {
        Regime::ZenoAccumulation
    } else if k.delta > 0.0 {
        Regime::LastImpact
    } else {
        Regime::Endless
    };
    if regime == Regime::Endless && k.threshold.is_none() {
        return Err(Failure::NeedsThreshold);
    }
    let a = k.matrix();
    let y0 = k.state.unwrap_or_else(|| k.steady_state(k.closing_speed));
    let r = k.restitution;
    let mut speed = k.closing_speed;
    let mut y = y0;
    let mut time = Sum::default();
    let mut first = vec![(0.0, (1.0 + r) * speed)];
    let (mut impacts, mut last_above, mut count_above, mut still_above) = (1_u64, 0.0, 1_u64, true);
    let tail = super::one_body::ZENO_TAIL * k.omega * k.delta.abs();
    loop {
        if impacts > budget {
            return Err(Failure::Budget(budget));
        }
        let departure = r * speed;
        let flight = Flight::new(k, a, [k.delta, -departure, k.scaled(y)]);
        let curvature = flight.start().1;
        if regime == Regime::ZenoAccumulation && departure < tail && curvature > 0.0 {
            let t_f = departure / curvature;
            let end = time.value() + t_f / (1.0 - r);
            // The tail's impulses (1 + R) a R^k: those still at or above the threshold (left
            // out, a threshold below the tail's start was reported crossed where the tail
            // starts: 8,046 impacts where 10,376 are above).
            if still_above {
                let first = (1.0 + r) * departure;
                if let Some((more, flights)) = k
                    .threshold
                    .and_then(|end| crate::tail_above(first, r, t_f, end))
                {
                    last_above = time.value() + flights;
                    count_above += more;
                }
            }
            return Ok(Outcome::accumulated(
                regime,
                end,
                k.threshold.is_some(),
                last_above,
                count_above,
                first,
            ));
        }
        let Some(t) = flight.next_impact()? else {
            return Ok(Outcome {
                regime,
                end_time: Some(time.value()),
                impacts_total: Some(impacts),
                last_above_time: Some(last_above),
                impacts_above: Some(count_above),
                first_impacts: first,
            });
        };
        let z = flight.state(t);
        time.add(t);
        speed = z[1];
        y = k.unscaled(z[2]);
        impacts += 1;
        let p = (1.0 + r) * speed;
        if first.len() < 5 {
            first.push((time.value(), p));
        }
        if still_above {
            if k.threshold.is_none_or(|end| p >= end) {
                last_above = time.value();
                count_above = impacts;
            } else {
                still_above = false;
                if regime == Regime::Endless {
                    return Ok(Outcome {
                        regime,
                        end_time: None,
                        impacts_total: None,
                        last_above_time: Some(last_above),
                        impacts_above: Some(count_above),
                        first_impacts: first,
                    });
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fast_oscillator_keeps_every_return() {
        // Omega = 5.5e7 with a slow kernel (Omega tau = 376): the Taylor coefficients of a flight
        // in t grew as Omega^n, overflowed at the 40th, and the series summed to NaN at the
        // bracket of the 12th flight's return: the return was lost and the Zeno accumulation
        // ended after 137 impacts, 0.32 % early (found beside the fuzzing harness's promises,
        // where the core's exact tier disagreed). The 60-digit solution (`python3
        // scripts/exact_mp.py 5.486653806109846e7 0 -1.6814864496302433e-14 0.6057166618443841
        // 6.335020480151972e-5 6.863989596814425e-6 5.5374275546248675e19`) gives
        // 1.38092452741958214e-5 s. (With every return kept the reference was then 5.2e-8 off,
        // its matrix exponential's rounding: `Kernelled::propagator`. Now 5.4e-14, about the
        // rounding of 137 flights.)
        let k = Kernelled {
            omega: 5.486_653_806_109_846e7,
            zeta: 0.0,
            delta: -1.681_486_449_630_243_3e-14,
            restitution: 0.605_716_661_844_384_1,
            closing_speed: 6.335_020_480_151_972e-5,
            kappa: 5.537_427_554_624_867_5e19,
            tau: 6.863_989_596_814_425e-6,
            state: None,
            threshold: None,
        };
        let out = simulate(&k, 1_000_000).expect("solves");
        let end = out.end_time.expect("ends");
        assert!(
            (end / 1.380_924_527_419_582_1e-5 - 1.0).abs() < 1e-12,
            "{end:e}"
        );
        assert_eq!(
            out.impacts_total, None,
            "an accumulation, not a last impact"
        );
    }
    use crate::{simulate as one, OneBody, DEFAULT_BUDGET};

    #[test]
    fn matrix_exponential_is_accurate() {
        // A decoupled case with known exponentials: x'' = -w^2 x, y' = -y / tau.
        let a = [[0.0, 1.0, 0.0], [-4.0, 0.0, 0.0], [0.0, 0.0, -0.5]];
        let e = expm(&a, 3.0);
        assert!((e[0][0] - 6f64.cos()).abs() < 1e-13 && (e[0][1] - 6f64.sin() / 2.0).abs() < 1e-13);
        assert!((e[2][2] - (-1.5f64).exp()).abs() < 1e-14);
    }

    #[test]
    fn a_vanishing_kernel_reproduces_the_viscous_reference() {
        // kappa -> 0 with the same viscous damping: the one-body result.
        for delta in [-1e-3, 1e-3] {
            let k = Kernelled {
                omega: 1000.0,
                zeta: 0.02,
                delta,
                restitution: 0.7,
                closing_speed: if delta > 0.0 { 3.0 } else { 0.3 },
                kappa: 1e-6,
                tau: 1e-3,
                state: Some(0.0),
                threshold: None,
            };
            let a = simulate(&k, DEFAULT_BUDGET).unwrap();
            let b = one(
                &OneBody {
                    omega: 1000.0,
                    delta,
                    restitution: 0.7,
                    zeta: 0.02,
                    closing_speed: k.closing_speed,
                    threshold: None,
                },
                DEFAULT_BUDGET,
            )
            .unwrap();
            let (ta, tb) = (a.end_time.unwrap(), b.end_time.unwrap());
            assert!((ta / tb - 1.0).abs() < 1e-6, "{delta}: {ta} vs {tb}");
            assert_eq!(a.impacts_total, b.impacts_total);
        }
    }

    #[test]
    fn a_threshold_below_the_summed_tail_is_counted_through_it() {
        // A vanishing kernel on a preload, thresholds above and below the impulse where the
        // tail starts to be summed (a departure of 1e-8 Omega |Delta|, about 5e-8 of the first
        // impulse here): the last impact above and the count are the one-body reference's,
        // whose tail counts them. The tail's were left out: every threshold below its start
        // was reported crossed where the tail starts.
        for fraction in [1e-3, 1e-7, 1e-9, 1e-12] {
            let threshold = Some(fraction * 1.7 * 0.3);
            let k = Kernelled {
                omega: 1000.0,
                zeta: 0.02,
                delta: -1e-3,
                restitution: 0.7,
                closing_speed: 0.3,
                kappa: 1e-6,
                tau: 1e-3,
                state: Some(0.0),
                threshold,
            };
            let a = simulate(&k, DEFAULT_BUDGET).unwrap();
            let b = one(
                &OneBody {
                    omega: 1000.0,
                    delta: -1e-3,
                    restitution: 0.7,
                    zeta: 0.02,
                    closing_speed: 0.3,
                    threshold,
                },
                DEFAULT_BUDGET,
            )
            .unwrap();
            let (ta, tb) = (a.last_above_time.unwrap(), b.last_above_time.unwrap());
            assert!((ta / tb - 1.0).abs() < 1e-6, "{fraction}: {ta} vs {tb}");
            assert_eq!(a.impacts_above, b.impacts_above, "{fraction}");
        }
    }

    #[test]
    fn the_kernel_dissipates_and_its_static_part_softens() {
        // Against the same body without the kernel: the kernel alone (zeta = 0, R = 1, gap)
        // makes a finite bounce (it dissipates), and a preload bounces differently.
        let base = Kernelled {
            omega: 1000.0,
            zeta: 0.0,
            delta: 1e-3,
            restitution: 1.0,
            closing_speed: 3.0,
            kappa: 2e4,
            tau: 1e-3,
            state: None,
            threshold: None,
        };
        let out = simulate(&base, DEFAULT_BUDGET).unwrap();
        assert_eq!(out.regime, Regime::LastImpact);
        assert!(out.impacts_total.unwrap() > 2, "{out:?}");
        let p: Vec<f64> = out.first_impacts.iter().map(|i| i.1).collect();
        assert!(
            p.windows(2).all(|w| w[1] < w[0]),
            "impulses must fall: {p:?}"
        );
        // A kernel whose static stiffness kappa tau reaches Omega^2 is refused.
        assert_eq!(
            simulate(&Kernelled { kappa: 1e9, ..base }, DEFAULT_BUDGET),
            Err(Failure::Invalid("kernel.kappa"))
        );
    }
}

//! Exact event-driven simulation of one body against a compliant stop: a linear spring and
//! dashpot in contact (Kelvin-Voigt), instead of the Newton impact of [`super::one_body`].
//!
//! Per unit mass, with p = x - Delta the penetration:
//!
//! ```text
//! x'' + 2 zeta Omega x' + Omega^2 x = 0                                  apart (p < 0)
//! x'' + 2 zeta Omega x' + Omega^2 x + kappa^2 p + 2 zeta_c kappa x' = 0   in contact
//! ```
//!
//! Contact starts when x reaches Delta moving up and ends when it returns to Delta moving down
//! (the dashpot may pull for the last instants of a contact: the usual linear simplification).
//! In contact the body oscillates at W = sqrt(Omega^2 + kappa^2) about the penetration
//! p_eq = -Omega^2 Delta / W^2 (> 0 for a preload); once its amplitude about p_eq cannot reach
//! p = 0 it stays: the bounce has ended, after finitely many impacts (no Zeno accumulation).
//! Each contact lasts about pi / W, and a stiff contact (kappa >> Omega) restitutes
//! R = exp(-zeta_c pi / sqrt(1 - zeta_c^2)) of the speed.
//!
//! Both phases are damped oscillators in closed form; the next event is searched by steps of
//! 1/64 of the phase's period, watching a sign change and a turning point that reaches the
//! boundary, then Brent.

use super::brent::brent;
use super::two_body::evolve;
use super::Failure;

/// One body against a compliant stop, f64, SI units (per unit mass).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compliant {
    /// Omega (rad/s).
    pub omega: f64,
    /// zeta of the free motion.
    pub zeta: f64,
    /// Delta (m); a preload (< 0).
    pub delta: f64,
    /// kappa (rad/s): the contact's stiffness per unit mass is kappa^2.
    pub kappa: f64,
    /// The contact dashpot's damping ratio zeta_c (0 <= zeta_c < 1).
    pub zeta_contact: f64,
    /// v0 (m/s): the speed at the first contact.
    pub closing_speed: f64,
}

/// One contact: it starts at `start` and ends at `end` (s; `None`: it holds for good).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Touch {
    /// When the body reaches the stop (s).
    pub start: f64,
    /// When it leaves (s), or `None` if it stays.
    pub end: Option<f64>,
}

/// The first root of `g` in (0, horizon], watching a turning point of `g` (from `dg`) that
/// reaches 0 between steps; `None` if `g` stays below 0.
fn first_rise(
    g: impl Fn(f64) -> f64,
    dg: impl Fn(f64) -> f64,
    step: f64,
    steps: u64,
) -> Option<f64> {
    let mut prev_t: f64 = 0.0;
    let mut prev_slope = dg(0.0);
    for k in 1..=steps {
        #[allow(clippy::cast_precision_loss)]
        let t = k as f64 * step;
        if g(t) >= 0.0 {
            return brent(&g, prev_t.max(step * 1e-9), t, 0.0);
        }
        let slope = dg(t);
        if prev_slope > 0.0 && slope <= 0.0 {
            if let Some(peak) = brent(&dg, prev_t, t, 0.0) {
                if g(peak) >= 0.0 {
                    return brent(&g, prev_t.max(step * 1e-9), peak, 0.0);
                }
            }
        }
        prev_t = t;
        prev_slope = slope;
    }
    None
}

/// Simulates the body until it stays in contact; the contacts in order.
///
/// # Errors
/// [`Failure::Invalid`] for parameters outside the model (a gap, which this model does not
/// need, is refused), [`Failure::Budget`] past `budget` contacts.
pub fn simulate(s: &Compliant, budget: usize) -> Result<Vec<Touch>, Failure> {
    let positive = |x: f64| x.is_finite() && x > 0.0;
    if !(positive(s.omega)
        && positive(s.kappa)
        && positive(s.closing_speed)
        && s.delta.is_finite()
        && s.delta < 0.0
        && s.zeta.is_finite()
        && (0.0..1.0).contains(&s.zeta)
        && s.zeta_contact.is_finite()
        && (0.0..1.0).contains(&s.zeta_contact))
    {
        return Err(Failure::Invalid("compliant"));
    }
    let w2 = s.omega * s.omega + s.kappa * s.kappa;
    let w = w2.sqrt();
    let z = (s.zeta * s.omega + s.zeta_contact * s.kappa) / w;
    // Contact equilibrium and the penetration there.
    let x_eq = s.kappa * s.kappa * s.delta / w2;
    let p_eq = x_eq - s.delta;
    let in_contact = 2.0 * std::f64::consts::PI / w / 64.0;
    let apart = 2.0 * std::f64::consts::PI / s.omega / 64.0;
    let mut touches = Vec::new();
    let (mut now, mut speed) = (0.0, s.closing_speed);
    loop {
        if touches.len() >= budget {
            return Err(Failure::Budget(budget as u64));
        }
        // In contact from x = Delta at `speed` up: y = x - x_eq from -p_eq.
        let y = |t: f64| evolve(w, z, -p_eq, speed, t);
        // Amplitude about the equilibrium: it never reaches p = 0 again once below p_eq.
        let wd = w * (1.0 - z * z).sqrt();
        let amp0 =
            ((p_eq * p_eq) + ((speed - z * w * p_eq) / wd).powi(2)).sqrt() / (1.0 - z * z).sqrt();
        let horizon = if z > 0.0 {
            ((amp0 / p_eq).ln().max(0.0) / (z * w) / in_contact).ceil() + 64.0
        } else {
            64.0 * 4.0
        };
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let leave = first_rise(
            |t| -(y(t).0 + p_eq),
            |t| -y(t).1,
            in_contact,
            horizon.min(1e9) as u64,
        );
        let Some(dt) = leave else {
            touches.push(Touch {
                start: now,
                end: None,
            });
            return Ok(touches);
        };
        let out = y(dt).1; // < 0: leaving downwards
        touches.push(Touch {
            start: now,
            end: Some(now + dt),
        });
        now += dt;
        // Apart from x = Delta at `out` (down): the next time x reaches Delta moving up.
        let x = |t: f64| evolve(s.omega, s.zeta, s.delta, out, t);
        let back = first_rise(|t| x(t).0 - s.delta, |t| x(t).1, apart, 64 * 1000)
            .ok_or(Failure::Budget(1000))?;
        speed = x(back).1;
        now += back;
        if speed.is_nan() || speed <= 0.0 {
            // Grazing return: the body rests against the stop.
            touches.push(Touch {
                start: now,
                end: None,
            });
            return Ok(touches);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{simulate_observed, OneBody, DEFAULT_BUDGET};

    #[test]
    fn a_stiff_contact_is_a_newton_impact_with_its_restitution() {
        // kappa = 1e5 Omega: contacts last ~pi / kappa, and each restitutes
        // R = exp(-zeta_c pi / sqrt(1 - zeta_c^2)) of its speed v, up to the contact's offset
        // p_eq over its amplitude v / kappa (Omega^2 |Delta| / (kappa v) = 1.3e-4 at v0, 1e-3
        // at the fifth impact); the flights are the Newton model's.
        let (omega, delta, v0, zc) = (2.0 * std::f64::consts::PI * 1e3, -1e-4, 0.05, 0.2);
        let s = Compliant {
            omega,
            zeta: 0.0,
            delta,
            kappa: 1e5 * omega,
            zeta_contact: zc,
            closing_speed: v0,
        };
        let touches = simulate(&s, 100_000).unwrap();
        let r = (-zc * std::f64::consts::PI / (1.0 - zc * zc).sqrt()).exp();
        let mut impacts = Vec::new();
        simulate_observed(
            &OneBody {
                omega,
                delta,
                restitution: r,
                zeta: 0.0,
                closing_speed: v0,
                threshold: None,
            },
            DEFAULT_BUDGET,
            |t, _| impacts.push(t),
        )
        .unwrap();
        // The first five flights agree to those offsets, summed over the contacts before each
        // (3.4e-3 by the fifth), and the contacts last pi / kappa.
        for k in 0..5 {
            let compliant = touches[k + 1].start - touches[k].end.unwrap();
            let newton = impacts[k + 1] - impacts[k];
            assert!(
                (compliant / newton - 1.0).abs() < 5e-3,
                "flight {k}: {compliant} vs {newton}"
            );
            let contact = touches[k].end.unwrap() - touches[k].start;
            assert!(
                (contact * s.kappa / std::f64::consts::PI - 1.0).abs() < 0.05,
                "{contact}"
            );
        }
        // It ends after finitely many contacts, in contact for good.
        assert!(touches.last().unwrap().end.is_none());
        assert!(touches.len() < 1000, "{}", touches.len());
    }

    #[test]
    fn a_soft_contact_holds_a_slow_body_at_once_and_refuses_a_gap() {
        let s = Compliant {
            omega: 1e3,
            zeta: 0.01,
            delta: -1e-4,
            kappa: 3e3,
            zeta_contact: 0.5,
            closing_speed: 1e-4,
        };
        let touches = simulate(&s, 10).unwrap();
        assert_eq!(touches.len(), 1);
        assert!(touches[0].end.is_none());
        assert!(simulate(&Compliant { delta: 1e-4, ..s }, 10).is_err());
        assert!(simulate(
            &Compliant {
                zeta_contact: 1.0,
                ..s
            },
            10
        )
        .is_err());
    }
}

//! A preload's Zeno tail summed as a power series in the departure speed.
//!
//! In units of the stop (Omega = 1, |Delta| = 1), a flight that leaves at speed eps lasts
//! tau(eps) and returns at rho(eps) (`flight_series.rs`: both as series in eps, each
//! coefficient a polynomial in zeta); the next flight leaves at phi(eps) = R rho(eps). The rest
//! of the bounce from a departure eps, S(eps) = sum of tau over eps, phi(eps), phi(phi(eps)),
//! ..., solves S(eps) = tau(eps) + S(phi(eps)). Written phi(eps) = R eps (1 + p(eps)), the
//! coefficients of S follow one by one:
//!
//! S_k (1 - R^k) = tau_k + sum_{j<k} S_j R^j [eps^(k-j)] (1 + p)^j,
//!
//! with 1 - R^k = (1 - R)(1 + R + ... + R^(k-1)), which keeps its digits as R -> 1. The
//! series converge within the flight series' radius (about 1 for zeta <= 1: 2 atan(eps)'s,
//! undamped); the sum is taken only at eps <= [`REACH`], and only where its last two terms say
//! the truncation is below the rounding of the whole bounce (f64: near eps = 0.03, as
//! 0.03^12 ~ 5e-19). Summed to first order in eps instead, the tail is exact to rounding only
//! below eps ~ epsilon^(1/3) ~ 6e-6: ln(5000) / ln(1 / R) more flights, 24 at R = 0.7.

use super::flight_series::TERMS;
use crate::accuracy::c;
use crate::Float;

/// The largest departure (in units of Omega |Delta|) the series is summed at.
const REACH: f64 = 0.25;

/// The tail's coefficients S_k for one scene (in units of the stop). Not `Copy`: it is
/// prepared in place and borrowed (a copy per impact would link `memcpy` into firmware).
#[derive(Debug)]
pub(super) struct ZenoTail<F> {
    coefficients: [F; TERMS],
    /// The flight's own series, tau_m(zeta).
    flight: [F; TERMS],
}

/// The coefficients of eps^1..eps^TERMS of a packed series (`flight_series.rs`) at `zeta`,
/// into `out`.
fn unpack<F: Float>(packed: &[F], zeta: F, out: &mut [F; TERMS]) {
    let square = zeta * zeta;
    let mut rest = packed;
    for (m, slot) in out.iter_mut().enumerate() {
        // Term m + 1: m / 2 + 1 numbers, a polynomial in zeta^2, times zeta if m is odd.
        let (poly, after) = rest.split_at((m / 2 + 1).min(rest.len()));
        rest = after;
        let even = poly
            .iter()
            .rev()
            .fold(F::ZERO, |sum, coefficient| sum * square + *coefficient);
        *slot = if m % 2 == 1 { even * zeta } else { even };
    }
}

impl<F: Float> ZenoTail<F> {
    /// Nothing yet: [`ZenoTail::prepare`] fills it (in place: no 100-byte moves, which would
    /// link `memcpy` into firmware).
    pub(super) const EMPTY: Self = Self {
        coefficients: [F::ZERO; TERMS],
        flight: [F::ZERO; TERMS],
    };

    /// The tail of a preload with damping ratio `zeta` (<= 1: beyond it the series' radius
    /// shrinks as 1 / zeta^2 and its coefficients are ill-conditioned) and restitution R,
    /// given as R and 1 - R. False for zeta > 1, or where a coefficient overflows (then its
    /// contents are not to be used).
    pub(super) fn prepare(&mut self, zeta: F, restitution: F, loss: F) -> bool {
        if zeta.is_nan() || zeta > F::ONE {
            return false;
        }
        let (flight_time, return_speed) = F::FLIGHT_SERIES;
        unpack(flight_time, zeta, &mut self.flight);
        // p[m] = rho_(m+1) / rho_1 (rho_1 = 1), p[0] = 1: (1 + p) as a series.
        let mut p = [F::ZERO; TERMS];
        unpack(return_speed, zeta, &mut p);
        let (flight, coefficients) = (&self.flight, &mut self.coefficients);
        // 1 / (1 - R^k) as 1 / ((1 - R)(1 + R + ... + R^(k-1))), and R^k, k = 1..=TERMS: off
        // the chain from one S_k to the next, so that their divisions overlap it.
        let (mut inverse, mut r_power) = ([F::ZERO; TERMS], [F::ZERO; TERMS]);
        let (mut power, mut geometric) = (F::ONE, F::ZERO);
        for (inverse, r_power) in inverse.iter_mut().zip(r_power.iter_mut()) {
            geometric = F::ONE + restitution * geometric;
            power *= restitution;
            *inverse = F::ONE / (loss * geometric);
            *r_power = power;
        }
        // sum_{j<k} S_j R^j [eps^(k-j)] (1 + p)^j, gathered as each S_j is found, and
        // (1 + p)^j.
        let mut gathered = [F::ZERO; TERMS];
        let mut raised = [F::ZERO; TERMS];
        if let Some(first) = raised.first_mut() {
            *first = F::ONE;
        }
        #[allow(clippy::indexing_slicing)] // k < TERMS, m < TERMS - k, i < m: within the arrays
        for k in 0..TERMS {
            let coefficient = (flight[k] + gathered[k]) * inverse[k];
            coefficients[k] = coefficient;
            // (1 + p)^(k+1) from (1 + p)^k in place (p[0] = 1), as far as it is still needed,
            // each new term gathered as it is found (read back from the array in a loop of
            // its own, the gathering waited on the stores just made: 3 % of the tier's time).
            let weight = coefficient * r_power[k];
            for m in (1..TERMS - k).rev() {
                let mut sum = raised[m];
                for i in 0..m {
                    sum += raised[i] * p[m - i];
                }
                raised[m] = sum;
                gathered[k + m] += weight * sum;
            }
        }
        // S_k grows like 1 / (1 - R)^k: with R within a few epsilon of 1 (or a loss given
        // below the float's range to the 12th power) it overflows, and the tail is left to
        // the first-order sum.
        self.coefficients.iter().all(|s| s.is_finite())
    }

    /// One flight from a departure `eps` (units of Omega |Delta|), in units of 1 / Omega,
    /// from its series: within about (2.2 eps)^(TERMS + 1) / eps of the flight (tested), a
    /// guess from which one Halley step lands within rounding below eps ~ 0.1; `None` beyond
    /// [`REACH`].
    pub(super) fn flight(&self, eps: F) -> Option<F> {
        (eps <= c::<F>(REACH)).then(|| {
            self.flight
                .iter()
                .rev()
                .fold(F::ZERO, |s, coefficient| (s + *coefficient) * eps)
        })
    }

    /// The rest of the bounce from a departure `eps` (units of Omega |Delta|) in units of
    /// 1 / Omega, and the size of its last two terms (a bound on the truncation where the terms
    /// fall geometrically); `None` beyond [`REACH`].
    pub(super) fn sum(&self, eps: F) -> Option<(F, F)> {
        if eps.is_nan() || eps > c::<F>(REACH) {
            return None;
        }
        let total = self
            .coefficients
            .iter()
            .rev()
            .fold(F::ZERO, |s, coefficient| (s + *coefficient) * eps);
        let mut last = self.coefficients.iter().rev();
        let (top, below) = (
            last.next().copied().unwrap_or(F::ZERO),
            last.next().copied().unwrap_or(F::ZERO),
        );
        let power = (1..TERMS).fold(F::ONE, |power, _| power * eps);
        Some((total, (top * eps).abs() * power + below.abs() * power))
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Landing, Oscillator};
    use super::*;

    #[test]
    fn the_flight_series_is_the_flight_within_its_truncation() {
        // Against the bracketed root of the closed form (Omega = 1, Delta = -1), zeta from 0
        // to 1: the terms left out are at most (2.2 eps)^13 / eps of the flight (the
        // coefficients' polynomials in zeta sum to at most 2.2^m at zeta = 1).
        for zeta in [0.0_f64, 0.03, 0.3, 0.7, 1.0] {
            let mut tail = ZenoTail::EMPTY;
            assert!(tail.prepare(zeta, 0.7, 0.3), "{zeta} <= 1");
            for eps in [1e-3_f64, 1e-2, 0.05, 0.1, 0.25] {
                let landing = Oscillator::new(1.0, zeta, -1.0).land(eps);
                assert!(
                    matches!(landing, Landing::Returns { .. }),
                    "a preload returns"
                );
                let (Landing::Returns { time, .. }, Some(series)) = (landing, tail.flight(eps))
                else {
                    return;
                };
                let bound = (2.2 * eps).powi(13) / eps + 4.0 * f64::EPSILON;
                let error = (series / time - 1.0).abs();
                assert!(error <= bound, "{zeta} {eps}: {error:e} > {bound:e}");
            }
            assert!(tail.flight(0.26).is_none() && tail.sum(0.26).is_none());
        }
        let mut over = ZenoTail::EMPTY;
        assert!(!over.prepare(1.01, 0.7, 0.3));
        // A loss whose 12th power is below the float's range: refused, not summed to inf.
        assert!(!over.prepare(0.03, 1.0 - 1e-30, 1e-30));
        let mut narrow = ZenoTail::<f32>::EMPTY;
        assert!(!narrow.prepare(0.03, 1.0, 6e-8));
        assert!(narrow.prepare(0.03, 0.9, 0.1));
    }
}

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
//! the truncation is below the rounding of the whole bounce (tested against the flights
//! walked one by one). Summed to first order in eps instead, the tail is exact to rounding
//! only below eps ~ epsilon^(1/3) ~ 6e-6: ln(5000) / ln(1 / R) more flights, 24 at R = 0.7.
//!
//! The coefficients S_k cost O(k^3) (the powers of 1 + p), so S is kept to [`SUMMED`]
//! terms, 8 of the flight series' 12: in f64 the sum is then taken near eps = 0.005 (0.004-0.007
//! on the catalogue's switches, after walking 1-3 flights) rather than 0.03. Between the two the flights are their own series to rounding
//! ([`Tuning::SERIES_EXACT_DEPARTURE`](crate::numeric::Tuning)), two polynomials each
//! ([`ZenoTail::exact_flight`]): the few flights walked there, and the few more solved above
//! it, cost less than the terms left out (on the Cortex-M4F, f32, the tier's instructions on
//! the catalogue's switches fell by 14-24 %: `docs/reports/cost-report.md`).

use crate::numeric::c;
use crate::numeric::flight_series::TERMS;
use crate::numeric::float::power_series;
use crate::Float;

/// The largest departure (in units of Omega |Delta|) the series is summed at.
const REACH: f64 = 0.25;
/// Terms of the tail's own series S (at most the flight series' [`TERMS`]: checked below).
const SUMMED: usize = 8;
const _: () = assert!(SUMMED <= TERMS && SUMMED >= 2);

/// The tail's coefficients S_k for one scene (in units of the stop), and the flight's own
/// series. Not `Copy`: it is prepared in place and borrowed (a copy per impact would link
/// `memcpy` into firmware).
#[derive(Debug)]
pub(super) struct ZenoTail<F> {
    coefficients: [F; SUMMED],
    /// The flight's own series, tau_m(zeta).
    flight: [F; TERMS],
    /// The return speed's, rho_m(zeta).
    speed: [F; TERMS],
}

/// The coefficients of eps^1..eps^TERMS of a packed series (`flight_series.rs`) at `zeta`,
/// into `out`: a loop over the terms, on bare metal (`target_os = "none"`), where flash is short
/// (on AVR each float operation is a call).
#[cfg(target_os = "none")]
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

/// The coefficients of eps^1..eps^TERMS of a packed series (`flight_series.rs`) at `zeta`,
/// into `out`, on hosts: each term's length written out, so that each polynomial is a
/// straight line (the loop above, over lengths the compiler does not unroll, took 380
/// instructions a call on x86-64, a fifth of a Zeno prediction's: the same values, fewer
/// instructions, more code).
#[cfg(not(target_os = "none"))]
fn unpack<F: Float>(packed: &[F], zeta: F, out: &mut [F; TERMS]) {
    /// The next polynomial of N numbers in zeta^2, taken off the front of `rest`.
    fn take<F: Float, const N: usize>(rest: &mut &[F], square: F) -> F {
        let Some((poly, after)) = rest.split_first_chunk::<N>() else {
            return F::ZERO;
        };
        *rest = after;
        poly.iter()
            .rev()
            .fold(F::ZERO, |sum, coefficient| sum * square + *coefficient)
    }
    // Term m + 1 has m / 2 + 1 numbers (times zeta if m is odd), m = 0..TERMS.
    const _: () = assert!(TERMS == 12);
    let square = zeta * zeta;
    let mut rest = packed;
    let r = &mut rest;
    *out = [
        take::<F, 1>(r, square),
        take::<F, 1>(r, square) * zeta,
        take::<F, 2>(r, square),
        take::<F, 2>(r, square) * zeta,
        take::<F, 3>(r, square),
        take::<F, 3>(r, square) * zeta,
        take::<F, 4>(r, square),
        take::<F, 4>(r, square) * zeta,
        take::<F, 5>(r, square),
        take::<F, 5>(r, square) * zeta,
        take::<F, 6>(r, square),
        take::<F, 6>(r, square) * zeta,
    ];
}

impl<F: Float> ZenoTail<F> {
    /// Nothing yet: [`ZenoTail::prepare`] fills it (in place: no 100-byte moves, which would
    /// link `memcpy` into firmware).
    pub(super) const EMPTY: Self = Self {
        coefficients: [F::ZERO; SUMMED],
        flight: [F::ZERO; TERMS],
        speed: [F::ZERO; TERMS],
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
        unpack(return_speed, zeta, &mut self.speed);
        // p[m] = rho_(m+1) / rho_1 (rho_1 = 1), p[0] = 1: (1 + p) as a series.
        let Self {
            coefficients,
            flight,
            speed: p,
        } = self;
        // 1 / (1 - R^k) as 1 / ((1 - R)(1 + R + ... + R^(k-1))), and R^k, k = 1..=SUMMED: off
        // the chain from one S_k to the next, so that their divisions overlap it.
        let (mut inverse, mut r_power) = ([F::ZERO; SUMMED], [F::ZERO; SUMMED]);
        let (mut power, mut geometric) = (F::ONE, F::ZERO);
        for (inverse, r_power) in inverse.iter_mut().zip(r_power.iter_mut()) {
            geometric = F::ONE + restitution * geometric;
            power *= restitution;
            *inverse = F::ONE / (loss * geometric);
            *r_power = power;
        }
        // sum_{j<k} S_j R^j [eps^(k-j)] (1 + p)^j, gathered as each S_j is found, and
        // (1 + p)^j.
        let mut gathered = [F::ZERO; SUMMED];
        let mut raised = [F::ZERO; SUMMED];
        if let Some(first) = raised.first_mut() {
            *first = F::ONE;
        }
        // k < SUMMED <= TERMS, m < SUMMED - k, i < m: every index holds. p[m - i] is read by
        // `get` all the same: at opt-level "s" the optimiser did not prove that bound, and the
        // panic path it left linked core's formatting and its messages: a C program calling
        // `cb_preload_seconds_exact`, linked for the Uno as `scripts/c-api.sh` links `uno.c`,
        // took 2.6 KB more flash and 4.9 KB more RAM (the Uno has 2 KB). Its `None` cannot
        // happen. The other bounds the optimiser proves on every target (checked: no tier's
        // firmware links a panic, `scripts/cost-report.sh`).
        // (The index loop over i, not `enumerate`: that was 8 bytes more on the Cortex-M4F and
        // no faster on the host, paired runs.)
        #[allow(clippy::indexing_slicing, clippy::needless_range_loop)]
        for k in 0..SUMMED {
            let coefficient = (flight[k] + gathered[k]) * inverse[k];
            coefficients[k] = coefficient;
            // (1 + p)^(k+1) from (1 + p)^k in place (p[0] = 1), as far as it is still needed,
            // each new term gathered as it is found (read back from the array in a loop of
            // its own, the gathering waited on the stores just made: 3 % of the tier's time).
            let weight = coefficient * r_power[k];
            for m in (1..SUMMED - k).rev() {
                let mut sum = raised[m];
                for i in 0..m {
                    sum += raised[i] * p.get(m - i).copied().unwrap_or(F::ZERO);
                }
                raised[m] = sum;
                gathered[k + m] += weight * sum;
            }
        }
        // S_k grows like 1 / (1 - R)^k: with R within a few epsilon of 1 (or a loss given
        // below the float's range to the 8th power) it overflows, and the tail is left to
        // the first-order sum.
        self.coefficients.iter().all(|s| s.is_finite())
    }

    /// One flight (units of 1 / Omega) and its return speed (units of Omega |Delta|) from a
    /// departure `eps` (units of Omega |Delta|), by their series alone: where their truncation
    /// is below the float's rounding ([`Tuning::SERIES_EXACT_DEPARTURE`](crate::numeric::Tuning),
    /// tested); `None` above.
    pub(super) fn exact_flight(&self, eps: F) -> Option<(F, F)> {
        (eps <= F::SERIES_EXACT_DEPARTURE).then(|| {
            (
                power_series(&self.flight, eps),
                power_series(&self.speed, eps),
            )
        })
    }

    /// One flight from a departure `eps` (units of Omega |Delta|), in units of 1 / Omega,
    /// from its series: within about (2.2 eps)^(TERMS + 1) / eps of the flight (tested), a
    /// guess from which one Halley step lands within rounding below eps ~ 0.1; `None` beyond
    /// [`REACH`].
    pub(super) fn flight(&self, eps: F) -> Option<F> {
        (eps <= c::<F>(REACH)).then(|| power_series(&self.flight, eps))
    }

    /// The rest of the bounce from a departure `eps` (units of Omega |Delta|) in units of
    /// 1 / Omega, and the size of its last two terms (a bound on the truncation where the terms
    /// fall geometrically); `None` beyond [`REACH`].
    pub(super) fn sum(&self, eps: F) -> Option<(F, F)> {
        if eps.is_nan() || eps > c::<F>(REACH) {
            return None;
        }
        let used = &self.coefficients;
        let total = power_series(used, eps);
        let mut last = used.iter().rev();
        let (top, below) = (
            last.next().copied().unwrap_or(F::ZERO),
            last.next().copied().unwrap_or(F::ZERO),
        );
        let power = (1..used.len()).fold(F::ONE, |power, _| power * eps);
        Some((total, (top * eps).abs() * power + below.abs() * power))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::flight::{Landing, Oscillator};

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
        // A loss whose 8th power is below the float's range: refused, not summed to inf.
        assert!(!over.prepare(0.03, 1.0, 1e-40));
        let mut narrow = ZenoTail::<f32>::EMPTY;
        assert!(!narrow.prepare(0.03, 1.0, 6e-8));
        assert!(narrow.prepare(0.03, 0.9, 0.1));
    }
}

#[cfg(test)]
mod sum_tests {
    use super::*;
    use crate::physics::flight::{Landing, Oscillator};

    /// The rest of the bounce from a departure `eps` (Omega = 1, Delta = -1): every flight
    /// solved from the closed form down to eps 1e-9, then the first order (2 eps / (1 - R));
    /// `None` if a flight does not return (a preload's always does).
    fn walked(zeta: f64, restitution: f64, mut eps: f64) -> Option<f64> {
        let oscillator = Oscillator::new(1.0, zeta, -1.0);
        let mut total = 0.0;
        while eps > 1e-9 {
            let Landing::Returns { time, speed, .. } = oscillator.land(eps) else {
                return None;
            };
            total += time;
            eps = restitution * speed;
        }
        Some(total + 2.0 * eps / (1.0 - restitution))
    }

    #[test]
    fn the_sum_is_the_flights_within_its_last_two_terms() {
        // Wherever the tail is taken (its last two terms, doubled, below an epsilon of what
        // precedes it), the sum is the walked flights' within that bound and the rounding of
        // the walk: damping ratios over [0, 1], restitution from 0.05 to 0.95, departures where
        // the series is summed. (Measured: at most 0.21 of the bound.)
        let mut checked = 0;
        for zeta in [0.0_f64, 0.005, 0.03, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0] {
            for restitution in [0.05_f64, 0.3, 0.5, 0.7, 0.9, 0.95] {
                let mut tail = ZenoTail::EMPTY;
                assert!(tail.prepare(zeta, restitution, 1.0 - restitution));
                for eps in [0.03_f64, 0.02, 0.01, 5e-3, 2e-3, 1e-3] {
                    let found = (tail.sum(eps), walked(zeta, restitution, eps));
                    assert!(
                        found.0.is_some() && found.1.is_some(),
                        "zeta {zeta} R {restitution} eps {eps}: no sum"
                    );
                    let (Some((sum, last)), Some(truth)) = found else {
                        return;
                    };
                    // What precedes a tail is at least one flight (about pi).
                    if 2.0 * last > f64::EPSILON * 3.0 {
                        continue;
                    }
                    checked += 1;
                    let bound = 2.0 * last + 64.0 * f64::EPSILON * truth;
                    assert!(
                        (sum - truth).abs() <= bound,
                        "zeta {zeta} R {restitution} eps {eps}: {sum:e} vs {truth:e} (bound {bound:e})"
                    );
                }
            }
        }
        assert!(checked > 100, "{checked}");
    }
}

#[cfg(test)]
mod exact_flight_tests {
    use super::*;
    use crate::numeric::Tuning;
    use crate::physics::flight::{Landing, Oscillator};

    #[test]
    fn below_the_exact_departure_a_flight_is_its_series_to_rounding() {
        // The flight and its return speed by their series against the bracketed root of the
        // closed form (f64, Omega = 1, Delta = -1), up to SERIES_EXACT_DEPARTURE: within a few
        // epsilon of the float in use (f64, and f32 against the f64 flight; in f32 eps itself
        // is rounded, which moves both by about an epsilon).
        for zeta in [0.0_f64, 0.03, 0.3, 0.7, 1.0] {
            let (mut wide, mut narrow) = (ZenoTail::<f64>::EMPTY, ZenoTail::<f32>::EMPTY);
            assert!(wide.prepare(zeta, 0.7, 0.3));
            assert!(narrow.prepare(f32::from_f64(zeta), 0.7, 0.3));
            for fraction in [1e-3_f64, 0.01, 0.1, 0.5, 1.0] {
                let cases = [
                    (f64::SERIES_EXACT_DEPARTURE * fraction, f64::EPSILON),
                    (
                        f64::from(f32::SERIES_EXACT_DEPARTURE) * fraction,
                        f64::from(f32::EPSILON),
                    ),
                ];
                for (eps, epsilon) in cases {
                    let landing = Oscillator::new(1.0, zeta, -1.0).land(eps);
                    let series = if epsilon == f64::EPSILON {
                        wide.exact_flight(eps)
                    } else {
                        narrow
                            .exact_flight(f32::from_f64(eps))
                            .map(|(t, v)| (f64::from(t), f64::from(v)))
                    };
                    assert!(
                        matches!(landing, Landing::Returns { .. }) && series.is_some(),
                        "zeta {zeta} eps {eps:e}: no flight"
                    );
                    let (Landing::Returns { time, speed, .. }, Some((t, v))) = (landing, series)
                    else {
                        return;
                    };
                    for (got, truth) in [(t, time), (v, speed)] {
                        let error = (got / truth - 1.0).abs();
                        assert!(
                            error <= 8.0 * epsilon,
                            "zeta {zeta} eps {eps:e}: {got:e} vs {truth:e} ({error:e})"
                        );
                    }
                }
            }
        }
        assert!(ZenoTail::<f64>::EMPTY.exact_flight(0.0201).is_none());
    }
}

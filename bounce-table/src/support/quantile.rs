//! Quantiles of a distribution known by its CDF.

/// The least t in [e^-60, e^60] s with `cdf(t) >= q`, by bisection in ln t to 1e-9 (`cdf`
/// nondecreasing).
pub fn inverse(cdf: impl Fn(f64) -> f64, q: f64) -> f64 {
    let (mut lo, mut hi) = (-60.0_f64, 60.0_f64);
    for _ in 0..200 {
        if hi - lo <= 1e-9 {
            break;
        }
        let mid = 0.5 * (lo + hi);
        if cdf(mid.exp()) >= q {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi.exp()
}

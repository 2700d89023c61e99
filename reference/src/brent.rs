//! Brent's method: a bracketed root to a relative tolerance (inverse quadratic interpolation,
//! secant and bisection, after R. P. Brent, "Algorithms for Minimization without Derivatives",
//! 1973, ch. 4).

/// The root of `f` in [a, b], where f(a) and f(b) differ in sign (or one is zero), to
/// |x - root| <= 2 eps |x| + abs_tolerance. Returns `None` if the bracket is invalid.
pub fn brent(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, abs_tolerance: f64) -> Option<f64> {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = (f(a), f(b));
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if fa.signum() == fb.signum() || !fa.is_finite() || !fb.is_finite() {
        return None;
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tolerance = 2.0 * f64::EPSILON * b.abs() + 0.5 * abs_tolerance;
        let m = 0.5 * (c - b);
        if m.abs() <= tolerance || fb == 0.0 {
            return Some(b);
        }
        if e.abs() >= tolerance && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qa = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tolerance * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tolerance {
            d
        } else {
            tolerance.copysign(m)
        };
        fb = f(b);
    }
    Some(b)
}

#[cfg(test)]
mod tests {
    use super::brent;

    #[test]
    fn finds_roots_to_rounding() {
        let r = brent(|x| x * x - 2.0, 0.0, 2.0, 0.0).unwrap();
        assert!((r - 2f64.sqrt()).abs() < 4e-16);
        let r = brent(|x| (x - 1e-12).sinh(), 0.0, 1.0, 0.0).unwrap();
        assert!((r / 1e-12 - 1.0).abs() < 1e-12);
        assert!(brent(|x| x * x + 1.0, -1.0, 1.0, 0.0).is_none());
    }
}

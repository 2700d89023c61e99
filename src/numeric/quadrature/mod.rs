//! Composite Gauss-Legendre quadrature and compensated summation.
//!
//! The averaged model integrates in s = ln J (docs/physics.md sec. 3), where its integrands are
//! smooth and bounded: panels at most 0.5 wide, [`Nodes`] points each.

mod nodes;
pub(crate) mod table;

pub use nodes::Nodes;

use crate::Float;

/// Neumaier's compensated sum: the error does not grow with the number of terms.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Compensated<F> {
    sum: F,
    carry: F,
}

impl<F: Float> Compensated<F> {
    pub(crate) const fn new() -> Self {
        Self {
            sum: F::ZERO,
            carry: F::ZERO,
        }
    }
    pub(crate) fn add(&mut self, x: F) {
        let t = self.sum + x;
        if !t.is_finite() {
            // Overflow: the carry would turn inf into NaN ((sum - inf) + inf).
            self.sum = t;
            self.carry = F::ZERO;
            return;
        }
        if self.sum.abs() >= x.abs() {
            self.carry += (self.sum - t) + x;
        } else {
            self.carry += (x - t) + self.sum;
        }
        self.sum = t;
    }
    pub(crate) fn value(&self) -> F {
        self.sum + self.carry
    }
}

/// Widest panel in s = ln J.
pub(crate) const PANEL_WIDTH: f64 = 0.5;
/// Most panels in one integral (ln range 1000: beyond any f64 impulse ratio).
pub(crate) const MAX_PANELS: u32 = 2000;

/// A pair of integrals computed together.
pub(crate) type Pair<F> = (F, F);

/// The integral of `f` (two integrands at once) over [a, b] (a <= b) by one Gauss-Legendre
/// panel of `nodes` points.
pub(crate) fn panel<F: Float, G: FnMut(F) -> Pair<F>>(
    a: F,
    b: F,
    nodes: Nodes,
    f: &mut G,
) -> Pair<F> {
    let mid = (a + b) * F::HALF;
    let half = (b - a) * F::HALF;
    let mut first = Compensated::new();
    let mut second = Compensated::new();
    for &(x, w) in F::gauss_legendre_half(nodes) {
        for s in [mid - half * x, mid + half * x] {
            let (u, v) = f(s);
            first.add(w * u);
            second.add(w * v);
        }
    }
    (first.value() * half, second.value() * half)
}

/// The number of panels at most [`PANEL_WIDTH`] wide covering a length (capped at
/// [`MAX_PANELS`]; the flag says whether the cap was hit).
pub(crate) fn panel_count<F: Float>(length: F) -> (u32, bool) {
    match (length / F::from_f64(PANEL_WIDTH)).ceil_u32() {
        Some(0) => (1, false),
        Some(n) if n <= MAX_PANELS => (n, false),
        _ => (MAX_PANELS, true),
    }
}

/// The integral over s in [a, b] (a <= b) of `f(e^s)` by composite Gauss-Legendre, with one
/// `exp` per panel instead of one per node: a node's e^s is e^(panel middle) times
/// e^(+-offset), the offsets' exponentials computed once (the panels share their width).
/// Within a panel the 2-20 terms are summed plainly (a few ULP), the panels with compensation.
/// The flag says whether the panel cap was hit (the panels are then wider than
/// [`PANEL_WIDTH`]).
pub(crate) fn integrate_exp<F: Float, G: FnMut(F) -> Pair<F>>(
    a: F,
    b: F,
    nodes: Nodes,
    mut f: G,
) -> (Pair<F>, bool) {
    let (n, capped) = panel_count(b - a);
    let width = (b - a) / F::from_u32(n);
    let half = width * F::HALF;
    let rule = F::gauss_legendre_half(nodes);
    // e^(-half x), e^(half x) per node pair (at most 10 pairs: the 20-point rule).
    let mut factors = [(F::ONE, F::ONE); 10];
    for (slot, &(x, _)) in factors.iter_mut().zip(rule) {
        *slot = ((-half * x).exp(), (half * x).exp());
    }
    let mut first = Compensated::new();
    let mut second = Compensated::new();
    for i in 0..n {
        let middle = (a + half + width * F::from_u32(i)).exp();
        let (mut u, mut v) = (F::ZERO, F::ZERO);
        for (&(_, w), &(down, up)) in rule.iter().zip(&factors) {
            let (u1, v1) = f(middle * down);
            let (u2, v2) = f(middle * up);
            u += w * (u1 + u2);
            v += w * (v1 + v2);
        }
        first.add(u * half);
        second.add(v * half);
    }
    ((first.value(), second.value()), capped)
}

/// The inverse tangent integral Ti2(x) = integral_0^x atan(y)/y dy, x > 0: 12-point
/// Gauss-Legendre on [0, min(x, 1/x)] (error below 1e-16: the integrand is analytic in a
/// Bernstein ellipse of radius 4.6), and Ti2(x) = Ti2(1/x) + (pi/2) ln x above 1.
pub(crate) fn inverse_tangent_integral<F: Float>(x: F) -> F {
    if x <= F::ZERO {
        // (The rule's nodes would evaluate atan(0) / 0.)
        return F::ZERO;
    }
    let (inner, reflect) = if x > F::ONE {
        (F::ONE / x, true)
    } else {
        (x, false)
    };
    let mut f = |y: F| (y.atan() / y, F::ZERO);
    let (value, _) = panel(F::ZERO, inner, Nodes::N12, &mut f);
    if reflect {
        value + F::HALF * F::PI * x.ln()
    } else {
        value
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_rule_integrates_its_top_degree_exactly() {
        for nodes in Nodes::ALL {
            let n = nodes.count();
            let degree = 2 * n - 1;
            // x^(2n-2) over [0, 1] is 1/(2n-1); and an odd top-degree term integrates to 0 on
            // the symmetric interval.
            // (Through e^s and back: the nodes reach f as e^s.)
            let ((even, odd), _) = integrate_exp(-1.0_f64, 1.0, nodes, |j: f64| {
                let x = j.ln();
                (
                    x.powi(i32::try_from(degree - 1).unwrap_or(0)),
                    x.powi(i32::try_from(degree).unwrap_or(0)),
                )
            });
            let exact = 2.0 / f64::from(degree);
            assert!(
                (even - exact).abs() < 1e-14 * exact,
                "{n}: {even} vs {exact}"
            );
            assert!(odd.abs() < 1e-14, "{n}: {odd}");
        }
    }

    #[test]
    fn f32_rules_match_f64_rules() {
        // e^s over [0, 3] in one 8-point panel (the rule's own error is ~1e-10 there), with
        // libm's expf whatever the backend.
        let (a, _) = panel(0.0_f32, 3.0, Nodes::N8, &mut |s: f32| (libm::expf(s), 0.0));
        let exact = libm::exp(3.0) - 1.0;
        assert!((f64::from(a) - exact).abs() < 2e-6 * exact);
    }

    #[test]
    #[cfg(not(feature = "micromath"))] // (micromath's exp is good to ~1e-4, not to f32's 1e-7)
    fn the_panels_exponentials_add_only_rounding_in_f32() {
        // e^s over [0, 3] in six panels, each node's e^s a product of two exponentials.
        let ((a, _), _) = integrate_exp(0.0_f32, 3.0, Nodes::N8, |j: f32| (j, 0.0));
        let exact = libm::exp(3.0) - 1.0;
        assert!((f64::from(a) - exact).abs() < 2e-6 * exact);
    }

    #[test]
    fn compensated_sum_keeps_small_terms() {
        let mut s = Compensated::new();
        s.add(1.0_f32);
        for _ in 0..10_000 {
            s.add(1e-8);
        }
        assert!((s.value() - 1.0001).abs() < 1e-7);
    }
}

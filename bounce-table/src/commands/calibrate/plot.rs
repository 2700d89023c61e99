//! The SVG of a switch and kind's bounce distribution against the models.

use crate::capture::EdgeName;
use crate::capture::{self, Edge};
use crate::render::plot::{time, Axis, Marker, Plot, Quantity, Series, Style};
use crate::stats::{sorted, window, BounceModel, ImpactFit};

/// The SVG of one switch and kind: the observed bounce's cumulative distribution against the
/// fitted [`BounceModel`]'s and, where it holds, the impact model's alone (each event's first
/// flight / (1 - R), fitted on all events), on a log time axis, with the window recommended
/// at `percentile` (0..1) marked. Clean edges (no bounce) are left out and counted in the title.
#[must_use]
pub fn plot(switch: &str, kind: Edge, d: &[capture::Description], percentile: f64) -> String {
    let refs: Vec<&capture::Description> = d.iter().collect();
    let fit = ImpactFit::new(&refs);
    let cdf = |v: Vec<f64>| -> Vec<(f64, f64)> {
        let v = sorted(v.into_iter().filter(|t| *t > 0.0).collect());
        #[allow(clippy::cast_precision_loss)]
        let n = v.len() as f64;
        v.iter()
            .enumerate()
            .map(|(i, t)| {
                #[allow(clippy::cast_precision_loss)]
                let rank = (i + 1) as f64;
                (*t, rank / n)
            })
            .collect()
    };
    let observed = cdf(d.iter().map(|x| x.bounce).collect());
    let clean = d.len() - observed.len();
    // The fitted model's distribution of the bouncing events, over the observed decades and
    // one more each side.
    let fitted = BounceModel::fit(&refs);
    let span = observed
        .first()
        .zip(observed.last())
        .map(|(a, b)| (a.0.log10() - 1.0, b.0.log10() + 1.0));
    let curve: Option<Vec<(f64, f64)>> = span.and_then(|(a, b)| {
        (0..=200)
            .map(|i| {
                let x = a + (b - a) * f64::from(i) / 200.0;
                let p = fitted.cdf(10f64.powf(x))?;
                Some((10f64.powf(x), (p - fitted.clean) / (1.0 - fitted.clean)))
            })
            .collect()
    });
    let mut series = vec![Series::new("observed", "#1f77b4", Style::Dots, observed)];
    // Where the flights do not shrink, R near 1 sends the impact model's sums off by decades:
    // drawn, it would only squash the axis.
    let modelled: Option<Vec<f64>> = refs.iter().map(|x| fit.bounce(x)).collect();
    if let Some(m) = modelled.filter(|_| fit.holds()) {
        series.push(Series::new("impact model", "#d62728", Style::Line, cdf(m)));
    }
    if let Some(points) = curve {
        series.push(Series::new("fitted model", "#2ca02c", Style::Line, points));
    }
    let w = window(&refs, percentile);
    // No window is recommended from too few events: none is drawn.
    let markers = if w.too_few() {
        Vec::new()
    } else {
        vec![Marker {
            x: w.recommended(),
            label: format!(
                "window {} (P{} of the fitted model)",
                time(w.recommended()),
                100.0 * percentile
            ),
            colour: "#ff7f0e",
        }]
    };
    Plot {
        title: format!(
            "{switch} {}: bounce CDF ({clean}/{} clean left out)",
            kind.name(),
            d.len()
        ),
        x: Axis::log("bounce", Quantity::Time),
        y: Axis::linear("fraction of bouncing events", Quantity::Plain),
        series,
        markers,
    }
    .svg()
}

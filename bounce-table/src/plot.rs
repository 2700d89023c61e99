//! SVG plots of a scene: the averaged envelope J(t) with the exact impacts over it, and the
//! laws of motion x1(t), x2(t) of the two contacts (the paper's Fig. 3).

use std::fmt::Write as _;

use contact_bounce::Bodies;

use crate::analysis::PLOT_NODES;
use crate::eval::exact_outcome;
use crate::scene_input::{FieldError, SceneInput, Spring};

/// One line or set of points on a plot.
pub(crate) struct Series {
    pub(crate) label: &'static str,
    pub(crate) colour: &'static str,
    pub(crate) points: Vec<(f64, f64)>,
    pub(crate) dots: bool,
}

/// A plot of `series` (lines, or dots) with axes, ticks and a legend.
pub(crate) fn svg(title: &str, x_label: &str, y_label: &str, series: &[Series]) -> String {
    let (w, h, left, right, top, bottom) = (760.0, 380.0, 90.0, 20.0, 40.0, 55.0);
    let all = series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|p| p.0.is_finite() && p.1.is_finite());
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in all {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if x1.partial_cmp(&x0) != Some(std::cmp::Ordering::Greater) {
        x1 = x0 + 1.0;
    }
    if y1.partial_cmp(&y0) != Some(std::cmp::Ordering::Greater) {
        y1 = y0 + 1.0;
    }
    let pad = 0.05 * (y1 - y0);
    let (y0, y1) = (y0 - pad, y1 + pad);
    let sx = |x: f64| left + (x - x0) / (x1 - x0) * (w - left - right);
    let sy = |y: f64| h - bottom - (y - y0) / (y1 - y0) * (h - top - bottom);
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(out, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    let _ = writeln!(
        out,
        r#"<text x="{}" y="22" font-size="15" text-anchor="middle">{}</text>"#,
        w / 2.0,
        escape(title)
    );
    // Axes with five ticks each.
    let _ = writeln!(
        out,
        r#"<line x1="{left}" y1="{}" x2="{}" y2="{}" stroke="black"/>"#,
        h - bottom,
        w - right,
        h - bottom
    );
    let _ = writeln!(
        out,
        r#"<line x1="{left}" y1="{top}" x2="{left}" y2="{}" stroke="black"/>"#,
        h - bottom
    );
    for i in 0..=4 {
        let f = f64::from(i) / 4.0;
        let (xv, yv) = (x0 + f * (x1 - x0), y0 + f * (y1 - y0));
        let _ = writeln!(
            out,
            r#"<line x1="{0}" y1="{1}" x2="{0}" y2="{2}" stroke="black"/><text x="{0}" y="{3}" text-anchor="middle">{4}</text>"#,
            sx(xv),
            h - bottom,
            h - bottom + 5.0,
            h - bottom + 20.0,
            number(xv)
        );
        let _ = writeln!(
            out,
            r#"<line x1="{0}" y1="{1}" x2="{2}" y2="{1}" stroke="black"/><text x="{3}" y="{4}" text-anchor="end">{5}</text>"#,
            left - 5.0,
            sy(yv),
            left,
            left - 8.0,
            sy(yv) + 4.0,
            number(yv)
        );
    }
    let _ = writeln!(
        out,
        r#"<text x="{}" y="{}" text-anchor="middle">{}</text>"#,
        (left + w - right) / 2.0,
        h - 12.0,
        escape(x_label)
    );
    let _ = writeln!(
        out,
        r#"<text x="18" y="{}" text-anchor="middle" transform="rotate(-90 18 {})">{}</text>"#,
        (top + h - bottom) / 2.0,
        (top + h - bottom) / 2.0,
        escape(y_label)
    );
    for (k, s) in series.iter().enumerate() {
        if s.dots {
            for &(x, y) in s
                .points
                .iter()
                .filter(|p| p.0.is_finite() && p.1.is_finite())
            {
                let _ = writeln!(
                    out,
                    r#"<circle cx="{:.2}" cy="{:.2}" r="3" fill="{}"/>"#,
                    sx(x),
                    sy(y),
                    s.colour
                );
            }
        } else {
            let path: Vec<String> = s
                .points
                .iter()
                .filter(|p| p.0.is_finite() && p.1.is_finite())
                .map(|&(x, y)| format!("{:.2},{:.2}", sx(x), sy(y)))
                .collect();
            let _ = writeln!(
                out,
                r#"<polyline fill="none" stroke="{}" stroke-width="1.5" points="{}"/>"#,
                s.colour,
                path.join(" ")
            );
        }
        #[allow(clippy::cast_precision_loss)]
        let ly = top + 8.0 + 16.0 * k as f64;
        let _ = writeln!(
            out,
            r#"<rect x="{}" y="{}" width="12" height="4" fill="{}"/><text x="{}" y="{}">{}</text>"#,
            w - right - 200.0,
            ly,
            s.colour,
            w - right - 182.0,
            ly + 5.0,
            escape(s.label)
        );
    }
    out.push_str("</svg>\n");
    out
}

fn number(x: f64) -> String {
    if x == 0.0 {
        "0".to_owned()
    } else if x.abs() >= 1e-2 && x.abs() < 1e4 {
        format!("{x:.3}")
    } else {
        format!("{x:.2e}")
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The two plots of a scene: (envelope SVG, laws-of-motion SVG), over `span` seconds.
///
/// # Errors
/// The scene's invalid field.
pub fn plots(input: &SceneInput, span: f64) -> Result<(String, String), FieldError> {
    let scene = input.core::<f64>()?;
    let averaged = scene.averaged(PLOT_NODES);
    let r = scene.restitution();
    let steps = 600_u32;
    let times: Vec<f64> = (0..=steps)
        .map(|k| span * f64::from(k) / f64::from(steps))
        .collect();
    let envelope: Vec<(f64, f64)> = times
        .iter()
        .filter_map(|&t| averaged.envelope(t).ok().map(|e| (t * 1e3, e.impulse)))
        .collect();
    // Exact impacts: every one for one body, the first five otherwise.
    let mut impacts = Vec::new();
    if input.kernel.is_none() && !matches!(input.stiffness, Spring::TwoBody(..)) {
        let one = contact_bounce_reference::OneBody {
            omega: scene.omega(),
            delta: scene.delta(),
            restitution: r,
            zeta: contact_bounce::Dissipation::damping_ratio(scene.dissipation()),
            closing_speed: scene.closing_speed(),
            threshold: scene.threshold_impulse(),
        };
        let _ = contact_bounce_reference::simulate_observed(
            &one,
            contact_bounce_reference::DEFAULT_BUDGET,
            |t, p| {
                if t <= span && impacts.len() < 5000 {
                    impacts.push((t * 1e3, p * 2.0 * r / (1.0 + r)));
                }
            },
        );
    } else if let Ok(out) = exact_outcome(input) {
        impacts = out
            .first_impacts
            .iter()
            .map(|&(t, p)| (t * 1e3, p * 2.0 * r / (1.0 + r)))
            .collect();
    }
    let title = format!(
        "{}: generating impulse J(t), averaged model and exact impacts",
        input.name
    );
    let envelope_svg = svg(
        &title,
        "time (ms)",
        "J (m/s)",
        &[
            Series {
                label: "averaged J(t)",
                colour: "#1f77b4",
                points: envelope,
                dots: false,
            },
            Series {
                label: "exact impacts, 2R v_n",
                colour: "#d62728",
                points: impacts,
                dots: true,
            },
        ],
    );
    let bodies = match input.stiffness {
        Spring::TwoBody(b, x2, v2) => Bodies::from_initial(
            b.m1 / (b.m1 + b.m2),
            scene.delta(),
            scene.closing_speed(),
            x2,
            v2,
        ),
        _ => Bodies::equal_at_rest(),
    };
    let (mut x1, mut x2) = (Vec::new(), Vec::new());
    for &t in &times {
        if let Ok(m) = averaged.motion(t, &bodies) {
            x1.push((t * 1e3, m.body1 * 1e3));
            x2.push((t * 1e3, m.body2 * 1e3));
        }
    }
    let motion_svg = svg(
        &format!(
            "{}: laws of motion of the contacts (paper's Fig. 3)",
            input.name
        ),
        "time (ms)",
        "position (mm)",
        &[
            Series {
                label: "x1(t)",
                colour: "#2ca02c",
                points: x1,
                dots: false,
            },
            Series {
                label: "x2(t)",
                colour: "#9467bd",
                points: x2,
                dots: false,
            },
        ],
    );
    Ok((envelope_svg, motion_svg))
}

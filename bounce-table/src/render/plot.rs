//! SVG plots: the desk tool's (a scene's averaged envelope J(t) with the exact impacts over it,
//! and the laws of motion of the two contacts, the paper's Fig. 3), and the small engine that
//! `calibrate` and `replay` draw with too: axes in the quantity's units with round ticks
//! (1, 2 or 5 times a power of ten; decades on a log axis), positive quantities from 0, the
//! legend in a strip of its own above the data, and vertical markers (a window, the end of
//! the bounce) labelled where they stand.

use std::fmt::Write as _;

use contact_bounce::tiers::Bodies;

use crate::scene::input::{FieldError, SceneInput, Spring};
use crate::scene::reference::outcome;
use crate::stats::analysis::{Analysis, PLOT_NODES};

/// What an axis measures, in SI units: it picks the prefix of its labels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Quantity {
    /// Seconds.
    Time,
    /// Metres.
    Length,
    /// Metres per second.
    Speed,
    /// A number without unit (a fraction).
    Plain,
    /// A whole number (ticks at whole steps).
    Count,
}

/// One axis: its name, quantity and scale.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Axis {
    /// The quantity's name ("time", "J"): the unit is added.
    pub(crate) name: &'static str,
    pub(crate) quantity: Quantity,
    /// Logarithmic (data > 0): ticks at decades.
    pub(crate) log: bool,
}

impl Axis {
    pub(crate) const fn linear(name: &'static str, quantity: Quantity) -> Self {
        Self {
            name,
            quantity,
            log: false,
        }
    }
    pub(crate) const fn log(name: &'static str, quantity: Quantity) -> Self {
        Self {
            name,
            quantity,
            log: true,
        }
    }
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Style {
    Line,
    Dots,
    /// A staircase through the points in order (a Pareto front).
    Steps,
    /// A vertical marker (in the legend only).
    Marker,
}

/// One line or set of points on a plot (data in SI units).
pub(crate) struct Series {
    pub(crate) label: String,
    pub(crate) colour: &'static str,
    pub(crate) points: Vec<(f64, f64)>,
    pub(crate) style: Style,
    /// A name written beside each point (empty: none).
    pub(crate) names: Vec<String>,
}

impl Series {
    pub(crate) fn new(
        label: impl Into<String>,
        colour: &'static str,
        style: Style,
        points: Vec<(f64, f64)>,
    ) -> Self {
        Self {
            label: label.into(),
            colour,
            points,
            style,
            names: Vec::new(),
        }
    }
}

/// A vertical line at `x` (data units), named in the legend.
#[derive(Clone)]
pub(crate) struct Marker {
    pub(crate) x: f64,
    pub(crate) label: String,
    pub(crate) colour: &'static str,
}

/// A whole plot.
pub(crate) struct Plot {
    pub(crate) title: String,
    pub(crate) x: Axis,
    pub(crate) y: Axis,
    pub(crate) series: Vec<Series>,
    pub(crate) markers: Vec<Marker>,
}

/// The ticks of an axis over data in [lo, hi] (finite; lo <= hi; both > 0 on a log axis):
/// the axis's range, the tick values, and their labels.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ticks {
    pub(crate) lo: f64,
    pub(crate) hi: f64,
    pub(crate) values: Vec<f64>,
    pub(crate) labels: Vec<String>,
    /// The axis's unit as shown ("us", "mm/s"; empty for plain numbers).
    pub(crate) unit: String,
}

/// The round step (1, 2 or 5 times a power of ten; at least 1 for whole numbers) that
/// divides [a, b] (a < b) into the number of intervals nearest six, the larger step on a tie.
fn round_step(a: f64, b: f64, whole: bool) -> f64 {
    let intervals = |s: f64| (b / s).ceil() - (a / s).floor();
    let top = (b - a).log10().floor();
    let mut best = (f64::INFINITY, 1.0);
    for k in -2..=1 {
        for m in [1.0, 2.0, 5.0] {
            let s = m * 10f64.powf(top + f64::from(k));
            if whole && s < 1.0 {
                continue;
            }
            let miss = (intervals(s) - 6.0).abs();
            if miss <= best.0 {
                best = (miss, s);
            }
        }
    }
    best.1
}

/// The SI prefix for values up to `magnitude` of `quantity`: (factor, unit).
fn prefix(quantity: Quantity, magnitude: f64) -> (f64, String) {
    let base = match quantity {
        Quantity::Time => "s",
        Quantity::Length => "m",
        Quantity::Speed => "m/s",
        Quantity::Plain | Quantity::Count => return (1.0, String::new()),
    };
    let (factor, p) = [(1.0, ""), (1e-3, "m"), (1e-6, "\u{b5}"), (1e-9, "n")]
        .into_iter()
        .find(|(f, _)| magnitude >= *f * (1.0 - 1e-12))
        .unwrap_or((1e-9, "n"));
    (factor, format!("{p}{base}"))
}

/// `x` with the decimals a step of `step` needs (at most 6).
fn decimal(x: f64, step: f64) -> String {
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let digits = (-step.log10().floor()).clamp(0.0, 6.0) as usize;
    let s = format!("{x:.digits$}");
    // "-0" reads as a sign error.
    if s.trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.')
    {
        "0".to_owned()
    } else {
        s
    }
}

impl Ticks {
    /// Linear ticks: about six round steps covering [lo, hi], from 0 when `lo` >= 0.
    pub(crate) fn linear(quantity: Quantity, lo: f64, hi: f64) -> Self {
        let lo = lo.min(0.0).min(hi);
        let hi = if hi > lo { hi } else { lo + 1.0 };
        let (factor, unit) = prefix(quantity, lo.abs().max(hi.abs()));
        let (a, b) = (lo / factor, hi / factor);
        let step = round_step(a, b, quantity == Quantity::Count);
        let (first, last) = ((a / step).floor(), (b / step).ceil());
        #[allow(clippy::cast_possible_truncation)]
        let n = (last - first).round() as i64;
        let values: Vec<f64> = (0..=n).map(|k| (first + k as f64) * step).collect();
        let labels = values.iter().map(|v| decimal(*v, step)).collect();
        Self {
            lo: first * step * factor,
            hi: last * step * factor,
            values: values.iter().map(|v| v * factor).collect(),
            labels,
            unit,
        }
    }

    /// Log ticks: whole decades covering [lo, hi] (> 0), with 2 and 5 between where there
    /// are at most two; each label in its own unit ("100 us", "1 ms").
    pub(crate) fn log(quantity: Quantity, lo: f64, hi: f64) -> Self {
        let a = lo.log10().floor();
        let b = hi.log10().ceil().max(a + 1.0);
        let mut values = Vec::new();
        #[allow(clippy::cast_possible_truncation)]
        for d in (a as i32)..=(b as i32) {
            let p = 10f64.powi(d);
            values.push(p);
            if b - a <= 2.0 && f64::from(d) < b {
                values.extend([2.0 * p, 5.0 * p]);
            }
        }
        let labels = values
            .iter()
            .map(|&v| {
                let (factor, unit) = prefix(quantity, v);
                let x = v / factor;
                let n = if x >= 1.0 {
                    format!("{x:.0}")
                } else {
                    format!("{x}")
                };
                if unit.is_empty() {
                    n
                } else {
                    format!("{n} {unit}")
                }
            })
            .collect();
        Self {
            lo: 10f64.powf(a),
            hi: 10f64.powf(b),
            values,
            labels,
            unit: String::new(),
        }
    }
}

/// A time for a plot's legend: as the tables write it, with the micro sign.
#[must_use]
pub fn time(t: f64) -> String {
    crate::render::output::time(t).replace(" us", " \u{b5}s")
}

/// Approximate width of `s` in pixels at the 12 px sans-serif of the plots.
#[allow(clippy::cast_precision_loss)]
fn text_width(s: &str) -> f64 {
    6.6 * s.chars().count() as f64
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

fn finite(p: &(f64, f64)) -> bool {
    p.0.is_finite() && p.1.is_finite()
}

/// The axis's ticks over `values`, where the scale can show them (> 0 on a log axis).
fn ticks(axis: Axis, values: impl Iterator<Item = f64>) -> Ticks {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|v| v.is_finite() && (!axis.log || *v > 0.0)) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if lo > hi {
        (lo, hi) = if axis.log { (1e-6, 1e-3) } else { (0.0, 1.0) };
    }
    if axis.log {
        Ticks::log(axis.quantity, lo, hi)
    } else {
        Ticks::linear(axis.quantity, lo, hi)
    }
}

impl Plot {
    /// The SVG.
    #[must_use]
    #[allow(clippy::too_many_lines)]
    pub(crate) fn svg(&self) -> String {
        let (w, h) = (760.0, 420.0);
        let (left, right, bottom) = (80.0, 30.0, 50.0);
        // The legend's strip, under the title: entries side by side, wrapped.
        let mut legend = Vec::new();
        let (mut lx, mut ly) = (left, 44.0);
        for (label, colour, style) in self
            .series
            .iter()
            .map(|s| (s.label.as_str(), s.colour, s.style))
            .chain(
                self.markers
                    .iter()
                    .map(|m| (m.label.as_str(), m.colour, Style::Marker)),
            )
            .filter(|(label, ..)| !label.is_empty())
        {
            let width = 22.0 + text_width(label) + 18.0;
            if lx + width > w - right && lx > left {
                lx = left;
                ly += 18.0;
            }
            legend.push((lx, ly, label, colour, style));
            lx += width;
        }
        let top = ly + 20.0;
        let xt = ticks(
            self.x,
            self.series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.0))
                .chain(self.markers.iter().map(|m| m.x)),
        );
        let yt = ticks(
            self.y,
            self.series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.1)),
        );
        let scale = |axis: Axis, t: &Ticks, v: f64| {
            if axis.log {
                (v.max(t.lo).log10() - t.lo.log10()) / (t.hi.log10() - t.lo.log10())
            } else {
                (v - t.lo) / (t.hi - t.lo)
            }
        };
        let sx = |x: f64| left + scale(self.x, &xt, x) * (w - left - right);
        let sy = |y: f64| h - bottom - scale(self.y, &yt, y) * (h - top - bottom);
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
            escape(&self.title)
        );
        for (x, y, label, colour, style) in legend {
            let mark = match style {
                Style::Dots => format!(
                    r#"<circle cx="{}" cy="{}" r="3.5" fill="{colour}"/>"#,
                    x + 8.0,
                    y - 4.0
                ),
                Style::Line | Style::Steps => format!(
                    r#"<line x1="{x}" y1="{0}" x2="{1}" y2="{0}" stroke="{colour}" stroke-width="2"/>"#,
                    y - 4.0,
                    x + 16.0
                ),
                Style::Marker => format!(
                    r#"<line x1="{x}" y1="{0}" x2="{1}" y2="{0}" stroke="{colour}" stroke-width="2" stroke-dasharray="4 3"/>"#,
                    y - 4.0,
                    x + 16.0
                ),
            };
            let _ = writeln!(
                out,
                r#"{mark}<text x="{}" y="{y}">{}</text>"#,
                x + 22.0,
                escape(label)
            );
        }
        // Grid, ticks and their labels.
        for (v, label) in xt.values.iter().zip(&xt.labels) {
            let x = sx(*v);
            let _ = writeln!(
                out,
                r##"<line x1="{x:.2}" y1="{top}" x2="{x:.2}" y2="{}" stroke="#e4e4e4"/><text x="{x:.2}" y="{}" text-anchor="middle">{}</text>"##,
                h - bottom + 5.0,
                h - bottom + 19.0,
                escape(label)
            );
        }
        for (v, label) in yt.values.iter().zip(&yt.labels) {
            let y = sy(*v);
            let _ = writeln!(
                out,
                r##"<line x1="{}" y1="{y:.2}" x2="{}" y2="{y:.2}" stroke="#e4e4e4"/><text x="{}" y="{:.2}" text-anchor="end">{}</text>"##,
                left - 5.0,
                w - right,
                left - 8.0,
                y + 4.0,
                escape(label)
            );
        }
        let _ = writeln!(
            out,
            r#"<rect x="{left}" y="{top}" width="{}" height="{}" fill="none" stroke="black"/>"#,
            w - left - right,
            h - top - bottom
        );
        let name = |axis: Axis, t: &Ticks| {
            if t.unit.is_empty() {
                axis.name.to_owned()
            } else {
                format!("{} ({})", axis.name, t.unit)
            }
        };
        let _ = writeln!(
            out,
            r#"<text x="{}" y="{}" text-anchor="middle">{}</text>"#,
            (left + w - right) / 2.0,
            h - 12.0,
            escape(&name(self.x, &xt))
        );
        let mid = (top + h - bottom) / 2.0;
        let _ = writeln!(
            out,
            r#"<text x="16" y="{mid}" text-anchor="middle" transform="rotate(-90 16 {mid})">{}</text>"#,
            escape(&name(self.y, &yt))
        );
        let inside =
            |p: &&(f64, f64)| finite(p) && (!self.x.log || p.0 > 0.0) && (!self.y.log || p.1 > 0.0);
        for s in &self.series {
            match s.style {
                Style::Dots => {
                    for (k, p) in s.points.iter().enumerate().filter(|(_, p)| inside(p)) {
                        let _ = writeln!(
                            out,
                            r#"<circle cx="{:.2}" cy="{:.2}" r="3.5" fill="{}" fill-opacity="0.8"/>"#,
                            sx(p.0),
                            sy(p.1),
                            s.colour
                        );
                        if let Some(n) = s.names.get(k).filter(|n| !n.is_empty()) {
                            let _ = writeln!(
                                out,
                                r#"<text x="{:.2}" y="{:.2}" font-size="11" fill="{}">{}</text>"#,
                                sx(p.0) + 6.0,
                                sy(p.1) - 6.0,
                                s.colour,
                                escape(n)
                            );
                        }
                    }
                }
                Style::Line | Style::Steps | Style::Marker => {
                    let mut path = Vec::new();
                    let mut last: Option<(f64, f64)> = None;
                    for p in s.points.iter().filter(inside) {
                        if let (Style::Steps, Some(l)) = (s.style, last) {
                            path.push(format!("{:.2},{:.2}", sx(p.0), sy(l.1)));
                        }
                        path.push(format!("{:.2},{:.2}", sx(p.0), sy(p.1)));
                        last = Some(*p);
                    }
                    let dash = if s.style == Style::Marker {
                        r#" stroke-dasharray="4 3""#
                    } else {
                        ""
                    };
                    let _ = writeln!(
                        out,
                        r#"<polyline fill="none" stroke="{}" stroke-width="1.8"{dash} points="{}"/>"#,
                        s.colour,
                        path.join(" ")
                    );
                }
            }
        }
        for m in self.markers.iter().filter(|m| m.x.is_finite()) {
            let x = sx(m.x);
            let _ = writeln!(
                out,
                r#"<line x1="{x:.2}" y1="{top}" x2="{x:.2}" y2="{}" stroke="{}" stroke-width="1.5" stroke-dasharray="4 3"/>"#,
                h - bottom,
                m.colour
            );
        }
        out.push_str("</svg>\n");
        out
    }
}

/// Where the window goes on a scene's plots: beyond this multiple of the bounce it would
/// squash the bounce into the left of the axis, so it is named but not drawn.
const WINDOW_DRAWN_UP_TO: f64 = 4.0;

/// The two plots of a scene (envelope SVG, laws-of-motion SVG): from the first contact to a
/// little past the end of the bounce, or past the window (`analysis`'s, at `percentile` of
/// its Monte Carlo) where that is within a few bounce times, both marked.
///
/// # Errors
/// The scene's invalid field.
pub fn plots(
    input: &SceneInput,
    analysis: &Analysis,
    percentile: f64,
) -> Result<(String, String), FieldError> {
    let scene = input.core::<f64>()?;
    let averaged = scene.averaged(PLOT_NODES);
    let r = scene.restitution();
    let bounce = analysis.nominal.bounce;
    let window = analysis.window;
    let drawn = bounce.is_finite() && window.is_finite() && window <= WINDOW_DRAWN_UP_TO * bounce;
    let span = if !bounce.is_finite() {
        1e-3
    } else if drawn {
        1.1 * bounce.max(window)
    } else {
        1.15 * bounce
    };
    let mut markers = Vec::new();
    if bounce.is_finite() {
        markers.push(Marker {
            x: bounce,
            label: format!("end of bounce {}", time(bounce)),
            colour: "#555555",
        });
    }
    let window_label = match &analysis.monte_carlo {
        Some(mc) => format!(
            "window {} (P{percentile} of {} samples)",
            time(window),
            mc.samples
        ),
        None => format!("window {}", time(window)),
    };
    if drawn {
        markers.push(Marker {
            x: window,
            label: window_label.clone(),
            colour: "#ff7f0e",
        });
    }
    let steps = 600_u32;
    let times: Vec<f64> = (0..=steps)
        .map(|k| span * f64::from(k) / f64::from(steps))
        .collect();
    let envelope: Vec<(f64, f64)> = times
        .iter()
        .filter_map(|&t| averaged.envelope(t).ok().map(|e| (t, e.impulse)))
        .collect();
    // Exact impacts: every one for one body, the first five otherwise.
    let mut impacts = Vec::new();
    if input.kernel.is_none() && !matches!(input.spring, Spring::TwoBody(..)) {
        let _ = contact_bounce_reference::simulate_observed(
            &crate::scene::reference::one_body(&scene),
            contact_bounce_reference::DEFAULT_BUDGET,
            |t, p| {
                if t <= span && impacts.len() < 5000 {
                    impacts.push((t, p * 2.0 * r / (1.0 + r)));
                }
            },
        );
    } else if let Ok(out) = outcome(input) {
        impacts = out
            .first_impacts
            .iter()
            .map(|&(t, p)| (t, p * 2.0 * r / (1.0 + r)))
            .collect();
    }
    let title = |what: &str| {
        if drawn {
            format!("{}: {what}", input.name)
        } else {
            format!("{}: {what} ({window_label}, beyond the axis)", input.name)
        }
    };
    let envelope_svg = Plot {
        title: title("generating impulse J(t)"),
        x: Axis::linear("time", Quantity::Time),
        y: Axis::linear("J", Quantity::Speed),
        series: vec![
            Series::new("averaged model", "#1f77b4", Style::Line, envelope),
            Series::new("exact impacts (2R v_n)", "#d62728", Style::Dots, impacts),
        ],
        markers: markers.clone(),
    }
    .svg();
    let bodies = match input.spring {
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
            x1.push((t, m.body1));
            x2.push((t, m.body2));
        }
    }
    // Each contact's displacement from where it rests at the end of the plot: the bounce is
    // micrometres on a stroke of tenths of a millimetre, so absolute positions would be two
    // flat lines.
    for body in [&mut x1, &mut x2] {
        if let Some(&(_, rest)) = body.last() {
            for p in body.iter_mut() {
                p.1 -= rest;
            }
        }
    }
    let motion_svg = Plot {
        title: title("laws of motion of the contacts (the paper's Fig. 3)"),
        x: Axis::linear("time", Quantity::Time),
        y: Axis::linear("displacement from rest", Quantity::Length),
        series: vec![
            Series::new("x1(t), contact 1", "#2ca02c", Style::Line, x1),
            Series::new("x2(t), contact 2", "#9467bd", Style::Line, x2),
        ],
        markers,
    }
    .svg();
    Ok((envelope_svg, motion_svg))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_are_round_in_the_quantitys_unit_and_start_at_zero() {
        // A bounce over 0..115 us: microseconds, from 0, in round steps, no "-0".
        let t = Ticks::linear(Quantity::Time, 3e-6, 115.3e-6);
        assert_eq!(t.unit, "\u{b5}s");
        assert_eq!(t.lo, 0.0);
        assert_eq!(t.labels, ["0", "20", "40", "60", "80", "100", "120"]);
        // J over 0.03..0.73 m/s: mm/s.
        let j = Ticks::linear(Quantity::Speed, 0.03, 0.73);
        assert_eq!(j.unit, "mm/s");
        assert_eq!(j.labels.first().map(String::as_str), Some("0"));
        assert_eq!(j.labels.last().map(String::as_str), Some("800"));
        // A displacement across 0: both signs, symmetric labels without "-0".
        let x = Ticks::linear(Quantity::Length, -1.2e-6, 1.1e-6);
        assert!(x.labels.contains(&"0".to_owned()) && !x.labels.contains(&"-0".to_owned()));
        assert_eq!(x.labels.first().map(String::as_str), Some("-1.5"), "{x:?}");
        // Fractions and counts.
        assert_eq!(
            Ticks::linear(Quantity::Plain, 0.02, 1.0).labels,
            ["0", "0.2", "0.4", "0.6", "0.8", "1.0"]
        );
        assert_eq!(
            Ticks::linear(Quantity::Count, 0.0, 2.0).labels,
            ["0", "1", "2"]
        );
        // Every tick is inside the axis and the data inside the ticks.
        for t in [&t, &j, &x] {
            assert!(t.values.iter().all(|v| (t.lo..=t.hi).contains(v)));
        }
    }

    #[test]
    fn log_ticks_are_decades_in_their_own_units() {
        let t = Ticks::log(Quantity::Time, 3e-4, 1.1e-3);
        assert_eq!(
            t.labels,
            [
                "100 \u{b5}s",
                "200 \u{b5}s",
                "500 \u{b5}s",
                "1 ms",
                "2 ms",
                "5 ms",
                "10 ms"
            ]
        );
        let wide = Ticks::log(Quantity::Time, 2e-5, 0.3);
        assert_eq!(
            wide.labels,
            [
                "10 \u{b5}s",
                "100 \u{b5}s",
                "1 ms",
                "10 ms",
                "100 ms",
                "1 s"
            ]
        );
    }

    #[test]
    fn the_legend_sits_above_the_data_and_markers_are_drawn() {
        let plot = Plot {
            title: "t".to_owned(),
            x: Axis::linear("time", Quantity::Time),
            y: Axis::linear("J", Quantity::Speed),
            series: vec![Series::new(
                "a long label for the data series",
                "#000",
                Style::Line,
                vec![(0.0, 1.0), (1e-3, 0.0)],
            )],
            markers: vec![Marker {
                x: 5e-4,
                label: "window 500.00 \u{b5}s".to_owned(),
                colour: "#f00",
            }],
        };
        let svg = plot.svg();
        // The frame of the data starts below every legend entry.
        let frame_top: f64 = svg
            .split("<rect x=\"80\" y=\"")
            .nth(1)
            .and_then(|s| s.split('"').next())
            .and_then(|s| s.parse().ok())
            .expect("the data frame");
        let legend_text_y: Vec<f64> = svg
            .lines()
            .filter(|l| l.contains("a long label") || l.contains("window 500"))
            .filter_map(|l| l.split("<text x=\"").nth(1))
            .filter_map(|s| s.split("y=\"").nth(1))
            .filter_map(|s| s.split('"').next())
            .filter_map(|s| s.parse().ok())
            .collect();
        assert_eq!(legend_text_y.len(), 2, "{svg}");
        assert!(legend_text_y.iter().all(|y| *y < frame_top), "{svg}");
        assert!(svg.contains("stroke-dasharray"), "the marker: {svg}");
        assert!(
            svg.contains("time (ms)") && svg.contains("J (m/s)"),
            "{svg}"
        );
    }
}

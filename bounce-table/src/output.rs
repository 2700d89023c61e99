//! The tables and the firmware constants: terminal, markdown, CSV, JSON, a C header and a Rust
//! source file (windows in ticks of the chosen period; both compile as they are).

use std::fmt::Write as _;

use serde_json::json;

use crate::analysis::{Analysis, Settings};

/// An output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Aligned text for a terminal.
    Table,
    /// A markdown table.
    Markdown,
    /// Comma-separated values.
    Csv,
    /// JSON.
    Json,
    /// A C header of `#define`s.
    C,
    /// A Rust source file of `pub const`s.
    Rust,
}

impl Format {
    /// Parses a format name.
    #[must_use]
    pub fn parse(s: &str) -> Option<Self> {
        Some(match s {
            "table" => Self::Table,
            "markdown" | "md" => Self::Markdown,
            "csv" => Self::Csv,
            "json" => Self::Json,
            "c" | "h" => Self::C,
            "rust" | "rs" => Self::Rust,
            _ => return None,
        })
    }
}

/// A time for people: us below 1 ms, ms below 1 s, else s; "endless" when infinite.
pub(crate) fn time(t: f64) -> String {
    if !t.is_finite() {
        "endless".to_owned()
    } else if t < 1e-3 {
        format!("{:.2} us", t * 1e6)
    } else if t < 1.0 {
        format!("{:.3} ms", t * 1e3)
    } else {
        format!("{t:.3} s")
    }
}

fn percent(x: f64) -> String {
    format!("{:.1} %", x * 100.0)
}

/// A switch's name made safe inside a generated comment (C `/* */`, Rust `///`): control
/// characters (a newline would end a `///` comment and start code) become spaces, and `*/`
/// cannot close a C comment.
#[must_use]
pub fn comment(name: &str) -> String {
    name.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect::<String>()
        .replace("*/", "* /")
}

/// The first two names that [`identifier`] maps to the same identifier (which generated code
/// would define twice), with that identifier.
#[must_use]
pub fn clash<'a>(names: impl IntoIterator<Item = &'a str>) -> Option<(String, String, String)> {
    let mut seen: std::collections::HashMap<String, &str> = std::collections::HashMap::new();
    for name in names {
        let id = identifier(name);
        if let Some(first) = seen.get(&id) {
            return Some(((*first).to_owned(), name.to_owned(), id));
        }
        seen.insert(id, name);
    }
    None
}

/// An identifier for C and Rust: upper case letters, digits and underscores, not starting with
/// a digit.
#[must_use]
pub fn identifier(name: &str) -> String {
    let mut out: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_uppercase()
            } else {
                '_'
            }
        })
        .collect();
    while out.contains("__") {
        out = out.replace("__", "_");
    }
    let out = out.trim_matches('_').to_owned();
    if out.is_empty() || out.starts_with(|c: char| c.is_ascii_digit()) {
        format!("S_{out}")
    } else {
        out
    }
}

fn columns(a: &Analysis, settings: &Settings) -> [String; 8] {
    let window_label = match &a.monte_carlo {
        Some(mc) => format!(
            "{} (P{} of {})",
            time(a.window),
            settings.percentile,
            mc.samples
        ),
        None => time(a.window),
    };
    [
        a.name.clone(),
        a.nominal.regime.clone(),
        time(a.nominal.bounce),
        a.nominal
            .impacts
            .map_or_else(|| "infinite".to_owned(), |n| format!("{n:.0}")),
        a.nominal.tier.clone(),
        percent(a.nominal.expected_error),
        window_label,
        a.ticks.to_string(),
    ]
}

const HEADERS: [&str; 8] = [
    "switch",
    "regime",
    "bounce",
    "impacts",
    "tier",
    "expected error",
    "window",
    "ticks",
];

/// The published figures of the catalogue's types beside the windows over the assumed ranges.
fn published_lines(analyses: &[Analysis], out: &mut String) {
    let _ = write!(
        out,
        "\nPublished for these types (a window for a switch nobody measured should cover them too):"
    );
    for a in analyses {
        if let Some(p) = crate::priors::published(&a.name) {
            let verdict = if a.window >= p.max {
                "covers"
            } else {
                "is below"
            };
            let _ = write!(
                out,
                "\n- {}: {}. The window over the ranges ({}) {verdict} their {}.",
                a.name,
                p.evidence,
                time(a.window),
                time(p.max)
            );
        }
    }
    let _ = writeln!(
        out,
        "\n- Any hand-operated switch: `bounce-table replay` takes the survey's P99.9, 157 ms, as its prior."
    );
    let below = analyses
        .iter()
        .filter(|a| crate::priors::published(&a.name).is_some_and(|p| a.window < p.max))
        .count();
    if below > 0 {
        let _ = writeln!(
            out,
            "{below} of these windows are below what is published for their type: real switches vary more \
             than the assumed ranges say. A window that must hold without a capture takes the published \
             figure; `bounce-table calibrate` on a capture of the switch gives one that holds and is short."
        );
    }
}

fn sensitivity_lines(analyses: &[Analysis], out: &mut String) {
    for a in analyses.iter().filter(|a| !a.sensitivity.is_empty()) {
        let _ = write!(
            out,
            "\nSensitivity of {} (tighten first the parameters on the left):",
            a.name
        );
        for s in &a.sensitivity {
            let _ = write!(
                out,
                " {} ({:+.2}, {})",
                s.parameter,
                s.elasticity,
                percent(s.contribution)
            );
        }
        out.push('\n');
    }
}

/// Renders the analyses.
#[must_use]
pub fn render(format: Format, analyses: &[Analysis], settings: &Settings, typical: bool) -> String {
    let mut out = String::new();
    let note = if typical {
        "Typical parameters (assumed values, not a datasheet), each over an assumed range (mass and \
         stiffness +-20 %, preload force +-30 %, R +-0.1, damping ratio +-50 %, closing speed +-50 %): \
         the windows are the P99.9 of the bounce over those ranges.\n"
    } else {
        ""
    };
    let period = time(settings.period);
    match format {
        Format::Table => {
            out.push_str(note);
            let _ = writeln!(out, "Windows in ticks of {period}; tier: the cheapest within {} (else the exact reference).\n", percent(settings.tolerance));
            let rows: Vec<[String; 8]> = analyses.iter().map(|a| columns(a, settings)).collect();
            let widths: Vec<usize> = (0..8)
                .map(|i| {
                    rows.iter()
                        .map(|r| r[i].chars().count())
                        .chain([HEADERS[i].chars().count()])
                        .max()
                        .unwrap_or(0)
                })
                .collect();
            let line = |cells: &[String]| {
                cells
                    .iter()
                    .zip(&widths)
                    // Padded by hand: a width in a format string is limited to 65,535, and a
                    // switch's name is not.
                    .map(|(c, w)| format!("{c}{}", " ".repeat(w.saturating_sub(c.chars().count()))))
                    .collect::<Vec<_>>()
                    .join("  ")
            };
            let _ = writeln!(out, "{}", line(&HEADERS.map(str::to_owned)).trim_end());
            for r in &rows {
                let _ = writeln!(out, "{}", line(r).trim_end());
            }
            if typical {
                published_lines(analyses, &mut out);
            } else {
                sensitivity_lines(analyses, &mut out);
            }
        }
        Format::Markdown => {
            if typical {
                let _ = writeln!(out, "{}", note.trim_end());
                out.push('\n');
            }
            let _ = writeln!(out, "Windows in ticks of {period}.\n");
            let _ = writeln!(out, "| {} |", HEADERS.join(" | "));
            let _ = writeln!(out, "|{}", "---|".repeat(8));
            for a in analyses {
                let _ = writeln!(out, "| {} |", columns(a, settings).join(" | "));
            }
            if typical {
                published_lines(analyses, &mut out);
            } else {
                sensitivity_lines(analyses, &mut out);
            }
        }
        Format::Csv => {
            let _ = writeln!(out, "switch,regime,bounce_s,upper_s,impacts,tier,expected_error,window_s,ticks,tick_period_s,monte_carlo_samples,percentile");
            for a in analyses {
                let mc = a.monte_carlo.as_ref();
                let _ = writeln!(
                    out,
                    "\"{}\",{},{:e},{:e},{},\"{}\",{},{:e},{},{:e},{},{}",
                    a.name.replace('"', "\"\""),
                    a.nominal.regime,
                    a.nominal.bounce,
                    a.nominal.upper,
                    a.nominal
                        .impacts
                        .map_or_else(String::new, |n| format!("{n}")),
                    a.nominal.tier,
                    a.nominal.expected_error,
                    a.window,
                    a.ticks,
                    settings.period,
                    mc.map_or(0, |m| m.samples),
                    mc.map_or(String::new(), |_| settings.percentile.to_string()),
                );
            }
        }
        Format::Json => {
            let rows: Vec<_> = analyses
                .iter()
                .map(|a| {
                    json!({
                        "name": a.name,
                        "regime": a.nominal.regime,
                        "bounce": a.nominal.bounce,
                        "upper": a.nominal.upper,
                        "impacts": a.nominal.impacts,
                        "tier": a.nominal.tier,
                        "expected_error": a.nominal.expected_error,
                        "window": a.window,
                        "ticks": a.ticks,
                        "tick_period": settings.period,
                        "monte_carlo": a.monte_carlo.as_ref().map(|m| json!({
                            "samples": m.samples, "seed": settings.seed, "percentile": settings.percentile,
                            "p50": m.p50, "window": m.window, "max": m.max, "exact_samples": m.exact,
                        })),
                        "sensitivity": a.sensitivity.iter().map(|s| json!({
                            "parameter": s.parameter, "elasticity": s.elasticity, "contribution": s.contribution,
                        })).collect::<Vec<_>>(),
                        "typical": typical,
                    })
                })
                .collect();
            let _ = writeln!(
                out,
                "{}",
                serde_json::to_string_pretty(&rows).unwrap_or_default()
            );
        }
        Format::C => {
            let _ = writeln!(
                out,
                "/* Generated by bounce-table: debounce windows in ticks of {period}. */"
            );
            if typical {
                let _ = writeln!(out, "/* Typical parameters over assumed ranges: assumed values, not a datasheet. */");
            }
            let _ = writeln!(out, "#ifndef BOUNCE_TABLE_H\n#define BOUNCE_TABLE_H\n");
            for a in analyses {
                let id = identifier(&a.name);
                let _ = writeln!(
                    out,
                    "/* {}: bounce {} ({}), window {} */",
                    comment(&a.name),
                    time(a.nominal.bounce),
                    a.nominal.tier,
                    time(a.window)
                );
                let _ = writeln!(out, "#define BOUNCE_{id}_WINDOW_TICKS {}u", a.ticks);
                let ns = (a.window * 1e9).ceil();
                let _ = writeln!(
                    out,
                    "#define BOUNCE_{id}_WINDOW_NS {}ull\n",
                    if ns.is_finite() && ns < 1.8e19 {
                        format!("{ns:.0}")
                    } else {
                        "0".to_owned()
                    }
                );
            }
            let _ = writeln!(out, "#endif /* BOUNCE_TABLE_H */");
        }
        Format::Rust => {
            let _ = writeln!(
                out,
                "//! Generated by bounce-table: debounce windows in ticks of {period}."
            );
            if typical {
                let _ = writeln!(
                    out,
                    "//! Typical parameters over assumed ranges: assumed values, not a datasheet."
                );
            }
            for a in analyses {
                let id = identifier(&a.name);
                let _ = writeln!(
                    out,
                    "\n/// {}: bounce {} ({}), window {}.",
                    comment(&a.name),
                    time(a.nominal.bounce),
                    a.nominal.tier,
                    time(a.window)
                );
                let _ = writeln!(out, "pub const {id}_WINDOW_TICKS: u32 = {};", a.ticks);
                let ns = (a.window * 1e9).ceil();
                let _ = writeln!(out, "/// The same window in nanoseconds, rounded up.");
                let _ = writeln!(
                    out,
                    "pub const {id}_WINDOW_NS: u64 = {};",
                    if ns.is_finite() && ns < 1.8e19 {
                        format!("{ns:.0}")
                    } else {
                        "0".to_owned()
                    }
                );
            }
        }
    }
    out
}

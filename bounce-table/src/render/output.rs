//! The tables and the firmware constants: terminal, markdown, CSV, JSON, a C header and a Rust
//! source file (windows in ticks of the chosen period; both compile as they are).

use std::fmt::Write as _;
use std::io::Write;

use serde_json::json;

use crate::render::emit::Lang;
use crate::stats::analysis::{Analysis, Settings};

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

/// Appends `format!("{x:.places$}")` to `out`, without the general formatter where the answer
/// is plain: `x` scaled by 10^places (at most 3) and rounded, when that is below 10^12 and not
/// within 10^-3 of a tie. The scaled product is then within 6.2e-5 (half an ulp at 10^12) of
/// the exact one, so both round to the same integer: the digits are the general formatter's
/// (tested against it). Near a tie, beyond 10^12, or not finite, it is the general formatter.
/// A table of a million rows formats four numbers a row, twice (once to fit the columns).
pub(crate) fn push_fixed(out: &mut String, x: f64, places: usize) {
    const SCALES: [f64; 4] = [1.0, 10.0, 100.0, 1000.0];
    let scaled = SCALES.get(places).map_or(f64::NAN, |scale| x * scale);
    let rounded = scaled.round();
    if scaled.is_nan() || scaled.abs() >= 1e12 || ((scaled - rounded).abs() - 0.5).abs() <= 1e-3 {
        // Writing to a String does not fail.
        let _ = write!(out, "{x:.places$}");
        return;
    }
    // Below 10^12: a u64 holds it exactly; its digits, last first, at least places + 1.
    #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let mut n = rounded.abs() as u64;
    let mut digits = [b'0'; 24];
    let mut len = 0;
    for slot in &mut digits {
        if n == 0 && len > places {
            break;
        }
        // A digit: below 10.
        #[allow(clippy::cast_possible_truncation)]
        let digit = (n % 10) as u8;
        *slot = b'0' + digit;
        n /= 10;
        len += 1;
    }
    if x.is_sign_negative() {
        out.push('-');
    }
    for (k, d) in digits.iter().take(len).enumerate().rev() {
        if k + 1 == places {
            out.push('.');
        }
        out.push(char::from(*d));
    }
}

/// `format!("{x:.places$}")`: see [`push_fixed`].
#[cfg(test)]
fn fixed(x: f64, places: usize) -> String {
    let mut out = String::new();
    push_fixed(&mut out, x, places);
    out
}

/// Appends a time for people: us below 1 ms, ms below 1 s, s below a million seconds (11
/// days), then in powers of ten; "endless" when infinite.
fn push_time(out: &mut String, t: f64) {
    if !t.is_finite() {
        out.push_str("endless");
    } else if t < 1e-3 {
        push_fixed(out, t * 1e6, 2);
        out.push_str(" us");
    } else if t < 1.0 {
        push_fixed(out, t * 1e3, 3);
        out.push_str(" ms");
    } else if t < 1e6 {
        push_fixed(out, t, 3);
        out.push_str(" s");
    } else {
        let _ = write!(out, "{t:.3e} s");
    }
}

/// A time for people, as [`push_time`] writes it.
pub(crate) fn time(t: f64) -> String {
    let mut out = String::new();
    push_time(&mut out, t);
    out
}

fn push_percent(out: &mut String, x: f64) {
    push_fixed(out, x * 100.0, 1);
    out.push_str(" %");
}

fn percent(x: f64) -> String {
    let mut out = String::new();
    push_percent(&mut out, x);
    out
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

/// One row's cells of the terminal table and the markdown one, written into one string (a
/// million rows are a million strings, not eight million).
struct Cells {
    text: String,
    /// Where each cell ends in `text`.
    ends: [usize; 8],
}

impl Cells {
    fn of(a: &Analysis, settings: &Settings) -> Self {
        let mut text = String::with_capacity(a.name.len() + 96);
        let mut ends = [0; 8];
        let mut cell = 0;
        let mut close = |text: &mut String| {
            if let Some(end) = ends.get_mut(cell) {
                *end = text.len();
            }
            cell += 1;
        };
        text.push_str(&a.name);
        close(&mut text);
        text.push_str(&a.nominal.regime);
        close(&mut text);
        push_time(&mut text, a.nominal.bounce);
        close(&mut text);
        match a.nominal.impacts {
            Some(n) => push_fixed(&mut text, n, 0),
            None => text.push_str("infinite"),
        }
        close(&mut text);
        text.push_str(&a.nominal.tier);
        close(&mut text);
        push_percent(&mut text, a.nominal.expected_error);
        close(&mut text);
        push_time(&mut text, a.window);
        if let Some(mc) = &a.monte_carlo {
            let _ = write!(text, " (P{} of {})", settings.percentile, mc.samples);
        }
        close(&mut text);
        let _ = write!(text, "{}", a.ticks);
        close(&mut text);
        Self { text, ends }
    }

    /// The cells, in order.
    fn cells(&self) -> impl Iterator<Item = &str> {
        let mut start = 0;
        self.ends.iter().map(move |&end| {
            let cell = self.text.get(start..end).unwrap_or("");
            start = end;
            cell
        })
    }
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

/// Where [`render_to`] reads the analyses from: it may read them several times over (a table's
/// column widths need every row before the first is written).
pub trait Rows {
    /// Every analysis, from the first.
    ///
    /// # Errors
    /// The analyses cannot be read (a spool on disk).
    fn rows(&mut self)
        -> std::io::Result<Box<dyn Iterator<Item = std::io::Result<Analysis>> + '_>>;

    /// Every analysis, from the first, in blocks of at most `n` (empty at the end), each
    /// decoded where it is rendered (on the rendering threads).
    ///
    /// # Errors
    /// The analyses cannot be read.
    fn blocks<'a>(&'a mut self, n: usize) -> std::io::Result<Blocks<'a>> {
        let mut rows = self.rows()?;
        Ok(Box::new(move || {
            rows.by_ref()
                .take(n)
                .collect::<std::io::Result<Vec<Analysis>>>()
                .map(Block::Decoded)
        }))
    }

    /// False only where no analysis has sensitivities (their lines need no pass then).
    fn any_sensitivity(&self) -> bool {
        true
    }
}

/// The next block of analyses, each call.
pub type Blocks<'a> = Box<dyn FnMut() -> std::io::Result<Block<'a>> + 'a>;

/// A block of analyses to render.
pub enum Block<'a> {
    /// Decoded already.
    Decoded(Vec<Analysis>),
    /// A spool's records, decoded one by one by the threads that render them.
    Records(crate::render::spool::Records<'a>),
}

impl Block<'_> {
    fn len(&self) -> usize {
        match self {
            Self::Decoded(v) => v.len(),
            Self::Records(r) => r.len(),
        }
    }

    fn get(&self, i: usize) -> std::io::Result<std::borrow::Cow<'_, Analysis>> {
        match self {
            Self::Decoded(v) => v.get(i).map(std::borrow::Cow::Borrowed).ok_or_else(|| {
                std::io::Error::new(std::io::ErrorKind::InvalidInput, "no such row")
            }),
            Self::Records(r) => r.get(i).map(std::borrow::Cow::Owned),
        }
    }
}

impl Rows for &[Analysis] {
    fn rows(
        &mut self,
    ) -> std::io::Result<Box<dyn Iterator<Item = std::io::Result<Analysis>> + '_>> {
        Ok(Box::new(self.iter().cloned().map(Ok)))
    }
}

impl Rows for crate::render::spool::Spool {
    fn rows(
        &mut self,
    ) -> std::io::Result<Box<dyn Iterator<Item = std::io::Result<Analysis>> + '_>> {
        Ok(Box::new(crate::render::spool::Spool::rows(self)?))
    }

    fn blocks<'a>(&'a mut self, n: usize) -> std::io::Result<Blocks<'a>> {
        let mut rows = crate::render::spool::Spool::rows(self)?;
        Ok(Box::new(move || rows.next_records(n).map(Block::Records)))
    }

    fn any_sensitivity(&self) -> bool {
        crate::render::spool::Spool::any_sensitivity(self)
    }
}

/// The published figures of the catalogue's types beside the windows over the assumed ranges.
fn published_lines(analyses: &mut dyn Rows, out: &mut dyn Write) -> std::io::Result<()> {
    write!(
        out,
        "\nPublished for these types (a window for a switch nobody measured should cover them too):"
    )?;
    let mut below = 0_usize;
    for a in analyses.rows()? {
        let a = a?;
        if let Some(p) = crate::scene::priors::published(&a.name) {
            let verdict = if a.window >= p.max {
                "covers"
            } else {
                below += 1;
                "is below"
            };
            write!(
                out,
                "\n- {}: {}. The window over the ranges ({}) {verdict} their {}.",
                a.name,
                p.evidence,
                time(a.window),
                time(p.max)
            )?;
        }
    }
    writeln!(
        out,
        "\n- Any hand-operated switch: `bounce-table replay` takes the survey's P99.9, 157 ms, as its prior."
    )?;
    if below > 0 {
        writeln!(
            out,
            "{below} of these windows are below what is published for their type: real switches vary more \
             than the assumed ranges say. A window that must hold without a capture takes the published \
             figure; `bounce-table calibrate` on a capture of the switch gives one that holds and is short."
        )?;
    }
    Ok(())
}

fn sensitivity_lines(analyses: &mut dyn Rows, out: &mut dyn Write) -> std::io::Result<()> {
    for a in analyses.rows()? {
        let a = a?;
        if a.sensitivity.is_empty() {
            continue;
        }
        write!(
            out,
            "\nSensitivity of {} (tighten first the parameters on the left):",
            a.name
        )?;
        for s in &a.sensitivity {
            write!(
                out,
                " {} ({:+.2}, {})",
                s.parameter,
                s.elasticity,
                percent(s.contribution)
            )?;
        }
        writeln!(out)?;
    }
    Ok(())
}

/// The after-table lines: the published figures for the catalogue, else the sensitivities.
fn closing_lines(
    analyses: &mut dyn Rows,
    out: &mut dyn Write,
    typical: bool,
) -> std::io::Result<()> {
    if typical {
        published_lines(analyses, out)
    } else if analyses.any_sensitivity() {
        sensitivity_lines(analyses, out)
    } else {
        Ok(())
    }
}

/// A window in whole nanoseconds (rounded up) for generated code; `None` beyond a `u64`
/// (about 585 years), which the caller refuses rather than write a wrong number.
#[must_use]
pub fn window_ns(window: f64) -> Option<u64> {
    let ns = (window * 1e9).ceil();
    // 18_446_744_073_709_549_568 is the largest f64 below 2^64.
    if ns.is_finite() && (0.0..=18_446_744_073_709_549_568.0).contains(&ns) {
        format!("{ns:.0}").parse().ok()
    } else {
        None
    }
}

/// The column widths of the terminal table, fitted to rows as they arrive (so a spool need not
/// be read twice to lay it out).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout([usize; 8]);

impl Default for Layout {
    fn default() -> Self {
        Self(HEADERS.map(|h| h.chars().count()))
    }
}

impl Layout {
    /// The widths of one row's cells.
    #[must_use]
    pub fn of(a: &Analysis, settings: &Settings) -> Self {
        let cells = Cells::of(a, settings);
        let mut widths = [0; 8];
        for (w, c) in widths.iter_mut().zip(cells.cells()) {
            *w = c.chars().count();
        }
        Self(widths)
    }

    /// Widened to hold `other`'s cells too.
    pub fn fit(&mut self, other: Self) {
        for (w, o) in self.0.iter_mut().zip(other.0) {
            *w = (*w).max(o);
        }
    }
}

/// Renders the analyses to `out` as they are read from `analyses` (each row is read when it is
/// written, so a spool of a million switches is never held in memory). `source` names the
/// scene file (or the catalogue) in generated code. The table's `layout`,
/// if the caller fitted it to every row, else it is fitted here (one more read).
///
/// # Errors
/// Reading the analyses or writing fails; `InvalidData` for a window beyond a `u64` of
/// nanoseconds in generated code.
#[allow(clippy::too_many_lines)]
pub fn render_to(
    out: &mut dyn Write,
    format: Format,
    analyses: &mut dyn Rows,
    settings: &Settings,
    typical: bool,
    source: &str,
    layout: Option<Layout>,
) -> std::io::Result<()> {
    let note = if typical {
        "Typical parameters (assumed values, not a datasheet), each over an assumed range (mass and \
         stiffness +-20 %, preload force +-30 %, R +-0.1, damping ratio +-50 %, closing speed +-50 %): \
         the windows are the P99.9 of the bounce over those ranges.\n"
    } else {
        ""
    };
    let period = time(settings.period);
    let threads = settings.threads;
    match format {
        Format::Table => {
            write!(out, "{note}")?;
            writeln!(out, "Windows in ticks of {period}; tier: the cheapest within {} (else the exact reference).\n", percent(settings.tolerance))?;
            let widths = match layout {
                Some(l) => l.0,
                None => {
                    let mut l = Layout::default();
                    for a in analyses.rows()? {
                        l.fit(Layout::of(&a?, settings));
                    }
                    l.0
                }
            };
            // Every cell but the last padded to its column's width (by hand: a width in a
            // format string is limited to 65,535, and a switch's name is not).
            let line = |cells: &mut dyn Iterator<Item = &str>| {
                let mut text = String::with_capacity(widths.iter().sum::<usize>() + 2 * 8);
                let mut cells = cells.zip(widths).peekable();
                while let Some((c, w)) = cells.next() {
                    if cells.peek().is_none() {
                        text.push_str(c.trim_end());
                        text.push('\n');
                    } else {
                        text.push_str(c);
                        let pad = w.saturating_sub(c.chars().count()) + 2;
                        text.extend(std::iter::repeat_n(' ', pad));
                    }
                }
                text
            };
            out.write_all(line(&mut HEADERS.into_iter()).as_bytes())?;
            write_rows(out, analyses, threads, &|a, _| {
                Ok(line(&mut Cells::of(a, settings).cells()))
            })?;
            closing_lines(analyses, out, typical)?;
        }
        Format::Markdown => {
            if typical {
                writeln!(out, "{}", note.trim_end())?;
                writeln!(out)?;
            }
            writeln!(out, "Windows in ticks of {period}.\n")?;
            writeln!(out, "| {} |", HEADERS.join(" | "))?;
            writeln!(out, "|{}", "---|".repeat(8))?;
            write_rows(out, analyses, threads, &|a, _| {
                Ok(format!(
                    "| {} |\n",
                    Cells::of(a, settings)
                        .cells()
                        .collect::<Vec<_>>()
                        .join(" | ")
                ))
            })?;
            closing_lines(analyses, out, typical)?;
        }
        Format::Csv => {
            writeln!(out, "switch,regime,bounce_s,upper_s,impacts,tier,expected_error,window_s,ticks,tick_period_s,monte_carlo_samples,percentile")?;
            write_rows(out, analyses, threads, &|a, _| Ok(csv_row(a, settings)))?;
        }
        Format::Json => {
            // A pretty-printed array, one element at a time: each element as serde_json prints
            // it inside an array (indented by two spaces).
            let any = write_rows(out, analyses, threads, &|a, i| {
                let text = serde_json::to_string_pretty(&json_row(a, settings, typical))
                    .map_err(std::io::Error::other)?;
                Ok(format!(
                    "{}\n  {}",
                    if i == 0 { "[" } else { "," },
                    text.replace('\n', "\n  ")
                ))
            })?;
            writeln!(out, "{}", if any { "\n]" } else { "[]" })?;
        }
        Format::C | Format::Rust => {
            let (lang, prefix) = if format == Format::C {
                (Lang::C, "BOUNCE_")
            } else {
                (Lang::Rust, "")
            };
            let guard = "BOUNCE_TABLE_H";
            let mut head = String::new();
            for line in provenance(settings, source) {
                head.push_str(&lang.comment(&line));
            }
            if typical {
                head.push_str(&lang.comment(
                    "Typical parameters over assumed ranges: assumed values, not a datasheet.",
                ));
            }
            head.push_str(&lang.open(guard));
            write!(out, "{head}")?;
            write_rows(out, analyses, threads, &|a, _| {
                let id = format!("{prefix}{}", identifier(&a.name));
                let ns = window_ns(a.window).ok_or_else(|| too_long(a))?;
                let mut row = format!(
                    "\n{}",
                    lang.doc(&format!(
                        "{}: bounce {} ({}), window {}.",
                        comment(&a.name),
                        time(a.nominal.bounce),
                        a.nominal.tier,
                        time(a.window)
                    ))
                );
                if let Some(w) = &a.warning {
                    row.push_str(&lang.doc(&format!("WARNING: {}.", comment(w))));
                }
                row.push_str(&lang.u32(&format!("{id}_WINDOW_TICKS"), a.ticks));
                row.push_str(&lang.doc("The same window in nanoseconds, rounded up."));
                row.push_str(&lang.u64(&format!("{id}_WINDOW_NS"), ns));
                Ok(row)
            })?;
            if lang == Lang::C {
                write!(out, "\n{}", lang.close(guard))?;
            }
        }
    }
    Ok(())
}

/// The first lines of generated code: the tool and its version, the scene file, the tick, and
/// how each window was reached (tolerance, margin, percentile, samples, seed), so a header
/// found in a firmware says where it came from.
fn provenance(settings: &Settings, source: &str) -> [String; 2] {
    let margin = if (settings.margin - 1.0).abs() > 0.0 {
        format!(", times a margin of {}", settings.margin)
    } else {
        String::new()
    };
    [
        format!(
            "Generated by bounce-table {} from {}: debounce windows in ticks of {}.",
            env!("CARGO_PKG_VERSION"),
            comment(source),
            time(settings.period)
        ),
        format!(
            "Each window: the model's bound within {} (else the exact reference){margin}; for a switch with ranges, P{} of {} Monte Carlo samples, seed {}.",
            percent(settings.tolerance),
            settings.percentile,
            settings.samples,
            settings.seed
        ),
    ]
}

/// A window with no nanosecond form in generated code.
fn too_long(a: &Analysis) -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::InvalidData,
        format!(
            "{}: the window, {}, is beyond a 64-bit count of nanoseconds",
            a.name,
            time(a.window)
        ),
    )
}

fn csv_row(a: &Analysis, settings: &Settings) -> String {
    let mc = a.monte_carlo.as_ref();
    format!(
        "\"{}\",{},{:e},{:e},{},\"{}\",{},{:e},{},{:e},{},{}\n",
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
    )
}

fn json_row(a: &Analysis, settings: &Settings, typical: bool) -> serde_json::Value {
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
}

/// Writes `row(analysis, its index)` for every analysis, in order: read a block at a time and
/// formatted on `threads` threads (a million rows are formatting, not writing), the next block
/// read and the last one written while this one is formatted. True if there was any row.
fn write_rows(
    out: &mut dyn Write,
    analyses: &mut dyn Rows,
    threads: usize,
    row: &(dyn Fn(&Analysis, usize) -> std::io::Result<String> + Sync),
) -> std::io::Result<bool> {
    const BLOCK: usize = 4096;
    let mut read = analyses.blocks(BLOCK)?;
    let write = |out: &mut dyn Write, texts: Vec<std::io::Result<Vec<String>>>| {
        for part in texts {
            for text in part? {
                out.write_all(text.as_bytes())?;
            }
        }
        Ok::<(), std::io::Error>(())
    };
    let (mut block, mut first, mut formatted) = (read()?, 0, Vec::new());
    let any = block.len() > 0;
    while block.len() > 0 {
        let workers = threads.clamp(1, block.len().div_ceil(256));
        let share = block.len().div_ceil(workers);
        let format_part = |k: usize| {
            (k * share..block.len().min((k + 1) * share))
                .map(|i| row(&*block.get(i)?, first + i))
                .collect::<std::io::Result<Vec<String>>>()
        };
        let (texts, (written, next)) =
            crate::support::workers::each_while(workers, &format_part, || {
                (write(out, std::mem::take(&mut formatted)), read())
            });
        written?;
        first += block.len();
        formatted = texts;
        block = next?;
    }
    write(out, formatted)?;
    Ok(any)
}

#[cfg(test)]
mod tests {
    use super::fixed;

    #[test]
    fn fixed_point_text_is_the_general_formatters() {
        // Random magnitudes from 1e-8 to 1e14 and both signs, exact ties (0.125, 2.5), values
        // near ties, zeros, the edges of the fast path, and what is not finite.
        let mut state = 0x9E37_79B9_7F4A_7C15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut values = vec![
            0.0,
            -0.0,
            0.125,
            2.5,
            -2.5,
            0.005,
            1.005,
            0.0005,
            999.9995,
            1e12,
            1e12 - 0.5,
            -1e12,
            9.999e11,
            0.049_999_999,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MIN_POSITIVE,
            1e300,
        ];
        for _ in 0..400_000 {
            #[allow(clippy::cast_precision_loss)]
            let unit = (next() >> 11) as f64 / (1_u64 << 53) as f64;
            let magnitude = 10_f64.powf(-8.0 + 22.0 * unit);
            let sign = if next() % 2 == 0 { 1.0 } else { -1.0 };
            // Every fourth a short decimal (1.25, 0.375): ties and exact values.
            #[allow(clippy::cast_precision_loss)]
            let short = (next() % 100_000) as f64 / 8.0;
            values.push(if next() % 4 == 0 {
                sign * short
            } else {
                sign * magnitude
            });
        }
        for x in values {
            for places in 0..=4 {
                assert_eq!(fixed(x, places), format!("{x:.places$}"), "{x:e} .{places}");
            }
        }
    }
}

//! The table mode's command line: `bounce-table [OPTIONS] [SCENE_FILE]` (the subcommands parse
//! their own: `eval::options`, `replay::options`, `calibrate::options`).

use crate::analysis::Settings;
use crate::output::Format;

/// The most worker threads `--threads` takes: each is a stack, and a run asks for no more
/// than its work can use.
pub const MAX_THREADS: u64 = 1024;
/// At most this many Monte Carlo samples: each keeps 16 bytes of results, so a run takes at
/// most 1.6 GB (and minutes), not an allocation the system refuses.
pub const MAX_SAMPLES: u64 = 100_000_000;

/// The table mode's options (`bounce-table [OPTIONS] [SCENE_FILE]`).
#[derive(Debug, Clone)]
pub struct Options {
    /// How to analyse.
    pub settings: Settings,
    /// The output format.
    pub format: Format,
    /// Where to write (else standard output).
    pub output: Option<String>,
    /// Where to write plots.
    pub plot: Option<String>,
    /// The scene file (else the catalogue).
    pub file: Option<String>,
}

fn positive(name: &str, value: &str) -> Result<f64, String> {
    value
        .parse::<f64>()
        .ok()
        .filter(|x| x.is_finite() && *x > 0.0)
        .ok_or(format!("{name}: '{value}' is not a positive number"))
}

/// Parses the table mode's arguments.
///
/// # Errors
/// A one-line message naming the option at fault.
pub fn parse(args: &[String]) -> Result<Options, String> {
    // Arguments echoed in a message have their control characters escaped: one line.
    parse_unescaped(args).map_err(|m| crate::strict::printable(&m).into_owned())
}

fn parse_unescaped(args: &[String]) -> Result<Options, String> {
    let mut o = Options {
        settings: Settings::default(),
        format: Format::Table,
        output: None,
        plot: None,
        file: None,
    };
    o.settings.progress = std::io::IsTerminal::is_terminal(&std::io::stderr());
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().cloned().ok_or(format!("{name} needs a value"));
        match arg.as_str() {
            "--period" | "--sample-period" => {
                o.settings.period = positive("--period", &value("--period")?)?
            }
            "--tolerance" => {
                o.settings.tolerance = positive("--tolerance", &value("--tolerance")?)?
            }
            "--margin" => {
                let m = positive("--margin", &value("--margin")?)?;
                if m < 1.0 {
                    return Err(format!(
                        "--margin: {m} is below 1 (a factor the window is multiplied by)"
                    ));
                }
                o.settings.margin = m;
            }
            "--percentile" => {
                let p = positive("--percentile", &value("--percentile")?)?;
                if p > 100.0 {
                    return Err(format!("--percentile: {p} is above 100"));
                }
                o.settings.percentile = p;
            }
            "--samples" | "--seed" | "--threads" => {
                let v = value(arg)?;
                let n = v
                    .parse::<u64>()
                    .ok()
                    .filter(|n| *n > 0 || arg == "--seed")
                    .ok_or(format!("{arg}: '{v}' is not a whole number above 0"))?;
                match arg.as_str() {
                    "--samples" if n > MAX_SAMPLES => {
                        return Err(format!("--samples: {n} is above {MAX_SAMPLES}"))
                    }
                    "--samples" => o.settings.samples = n,
                    "--seed" => o.settings.seed = n,
                    _ if n > MAX_THREADS => {
                        return Err(format!("--threads: {n} is above {MAX_THREADS}"))
                    }
                    _ => o.settings.threads = usize::try_from(n).unwrap_or(1),
                }
            }
            "--format" => {
                let v = value("--format")?;
                o.format = Format::parse(&v).ok_or(format!(
                    "--format: '{v}' is not table, markdown, csv, json, c or rust"
                ))?;
            }
            "--output" => o.output = Some(value("--output")?),
            "--plot" => o.plot = Some(value("--plot")?),
            other if other.starts_with('-') => return Err(format!("unknown option '{other}'")),
            file => {
                if o.file.replace(file.to_owned()).is_some() {
                    return Err("give one scene file".to_owned());
                }
            }
        }
    }
    Ok(o)
}

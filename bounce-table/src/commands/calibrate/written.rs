//! What `calibrate` writes, from what it read: the events as CSV, the windows as C or Rust, or
//! the report. The desk tool and anything else that has the capture in memory call this.

use crate::capture::EdgeName;
use crate::capture::{Loaded, Options};
use crate::render::output::clash;
use crate::stats;
use crate::support::strict::printable;

/// `calibrate`'s text for `options` (`--format`): every event as CSV, the windows as C or
/// Rust constants, or the Markdown report (the SVG plots are written apart). `tapped` gives
/// the report's section on the windows tapped like a key (`replay`'s
/// [`window_costs`](crate::commands::replay::taps::window_costs) of the same capture and
/// options); it is called only for the report.
///
/// # Errors
/// Switch names that become one identifier in generated code, or windows that cannot be
/// written: the message, naming the capture.
pub fn written(
    options: &Options,
    loaded: &Loaded,
    tapped: impl FnOnce() -> String,
) -> Result<String, String> {
    let Loaded {
        events,
        skipped,
        analog,
    } = loaded;
    if options.events {
        return Ok(stats::events_csv(
            events,
            options.resolution,
            options.burst_gap,
        ));
    }
    let groups = stats::group(events, options.resolution, options.burst_gap);
    if let Some(rust) = options.export {
        let names: Vec<String> = groups
            .keys()
            .map(|(switch, kind)| format!("{switch} {}", kind.name()))
            .collect();
        if let Some((a, b, id)) = clash(names.iter().map(String::as_str)) {
            return Err(format!(
                "{}: '{}' and '{}' both become {id} in generated code: rename a switch",
                printable(&options.file),
                printable(&a),
                printable(&b)
            ));
        }
        let lang = if rust {
            crate::render::emit::Lang::Rust
        } else {
            crate::render::emit::Lang::C
        };
        return super::export(
            &groups,
            options.percentile,
            options.min_tap,
            lang,
            &options.file,
        )
        .map_err(|e| format!("{}: {}", printable(&options.file), printable(&e)));
    }
    let mut report = format!(
        "# Summary\n\n{}\n{}\n## Description\n\n{}",
        super::summary(
            &groups,
            options.percentile,
            options.burst_gap,
            options.min_tap
        ),
        tapped(),
        super::describe(&groups, options.resolution)
    );
    if skipped.total() > 0 {
        report.push_str(&format!("\n{}\n", skipped.describe(options.quiet)));
    }
    for a in analog {
        report.push_str(&format!("\n{}", a.markdown()));
    }
    report.push_str(&super::by_section(&groups));
    report.push_str(&super::assess(&groups, options.percentile, options.seed));
    if options.contact_models {
        report.push_str(&stats::contact::report(&groups, options.seed));
    }
    Ok(report)
}

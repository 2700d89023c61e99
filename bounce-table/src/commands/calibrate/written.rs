//! What `calibrate` writes, from what it read: the events as CSV, the windows as C or Rust, or
//! the report. The desk tool and anything else that has the capture in memory call this.

use super::{Request, Written};
use crate::capture::EdgeName;
use crate::capture::Loaded;
use crate::render::output::clash;
use crate::stats;
use crate::support::strict::printable;

/// `calibrate`'s text for `request` (`--format`): every event as CSV, the windows as C or
/// Rust constants, or the Markdown report (the SVG plots are written apart). `tapped` gives
/// the report's section on the windows tapped like a key (`replay`'s
/// [`window_costs`](crate::commands::replay::taps::window_costs) of the same capture and
/// options); it is called only for the report.
///
/// # Errors
/// Switch names that become one identifier in generated code, or windows that cannot be
/// written: the message, naming the capture.
pub fn written(
    request: &Request,
    loaded: &Loaded,
    tapped: impl FnOnce() -> String,
) -> Result<String, String> {
    let Loaded {
        events,
        skipped,
        analog,
    } = loaded;
    let (c, file) = (&request.calibration, &request.capture.file);
    let lang = match request.written {
        Written::Events => return Ok(stats::events_csv(events, c.resolution, c.burst_gap)),
        Written::Report => None,
        Written::C => Some(crate::render::emit::Lang::C),
        Written::Rust => Some(crate::render::emit::Lang::Rust),
    };
    let groups = stats::group(events, c.resolution, c.burst_gap);
    if let Some(lang) = lang {
        let names: Vec<String> = groups
            .keys()
            .map(|(switch, kind)| format!("{switch} {}", kind.name()))
            .collect();
        if let Some((a, b, id)) = clash(names.iter().map(String::as_str)) {
            return Err(format!(
                "{}: '{}' and '{}' both become {id} in generated code: rename a switch",
                printable(file),
                printable(&a),
                printable(&b)
            ));
        }
        return super::export(&groups, c.percentile, c.min_tap, lang, file)
            .map_err(|e| format!("{}: {}", printable(file), printable(&e)));
    }
    let mut report = format!(
        "# Summary\n\n{}\n{}\n## Description\n\n{}",
        super::summary(&groups, c.percentile, c.burst_gap, c.min_tap),
        tapped(),
        super::describe(&groups, c.resolution)
    );
    if skipped.total() > 0 {
        report.push_str(&format!(
            "\n{}\n",
            skipped.describe(request.capture.event_gap)
        ));
    }
    for a in analog {
        report.push_str(&format!("\n{}", a.markdown()));
    }
    report.push_str(&super::by_section(&groups));
    report.push_str(&super::assess(&groups, c.percentile, c.seed));
    if request.contact_models {
        report.push_str(&stats::contact::report(&groups, c.seed));
    }
    Ok(report)
}

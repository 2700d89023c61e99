//! A CSV of edges: `switch,time,level` a line.

use super::event::*;

pub(crate) fn level(text: &str) -> Option<bool> {
    match text.trim() {
        "1" | "high" | "H" => Some(true),
        "0" | "low" | "L" => Some(false),
        _ => None,
    }
}

/// Reads a CSV of level changes: one `time,level` row per change (time in seconds, level 0 or
/// 1); an optional header row, blank lines and `#` comments are skipped. The first row gives
/// the level at the start of the capture (not a change).
///
/// # Errors
/// A row that is not two fields, a time that is not a finite number or goes back, a level
/// other than 0/1, or a file with no rows: the error names the line.
pub fn read_csv(file: &str, text: &str, polarity: Polarity) -> Result<Stream, CaptureError> {
    let mut start: Option<bool> = None;
    let mut closed = false;
    let mut changes = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let row = raw.trim();
        if row.is_empty() || row.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = row.split(',').map(str::trim).collect();
        let [time, value] = fields[..] else {
            return Err(error(
                file,
                line,
                format!("expected `time,level`, found {row:?}"),
            ));
        };
        let Ok(t) = time.parse::<f64>() else {
            if start.is_none() && changes.is_empty() && level(value).is_none() {
                continue; // a header row
            }
            return Err(error(file, line, format!("time {time:?} is not a number")));
        };
        let Some(high) = level(value) else {
            return Err(error(file, line, format!("level {value:?} is not 0 or 1")));
        };
        let now_closed = is_closed(polarity, high);
        if start.is_none() {
            if !t.is_finite() {
                return Err(error(
                    file,
                    line,
                    format!("time {t} is not a finite number"),
                ));
            }
            start = Some(now_closed);
            closed = now_closed;
            continue;
        }
        push_change(&mut changes, &mut closed, now_closed, t)
            .map_err(|reason| error(file, line, reason))?;
    }
    let Some(closed_before) = start else {
        return Err(error(file, 0, "no rows: expected `time,level` rows"));
    };
    Ok(Stream {
        closed_before,
        changes,
    })
}

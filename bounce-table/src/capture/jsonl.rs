//! JSON Lines in the bouncy-button format: one test a line.

use serde_json::Value;

use super::event::*;

/// Reads the JSON Lines of the bouncy-button capture: one test per line, `dataset`, `kind`,
/// `events` `[[t_ns, level], ...]` (the first entry is the level before the test; level 1 =
/// open), `section`, `section_invalid`. Tests are left out, and counted per reason, when their
/// section is marked invalid, when a section of the same name is marked invalid for another
/// dataset of the file (the same protocol, logged by an instrument that did not yet mark it),
/// or when `skip` names the section.
///
/// # Errors
/// A line that is not JSON, or misses a field, or whose events do not start with a level, go
/// back in time or disagree with `kind`: the error names the line.
pub fn read_jsonl(
    file: &str,
    text: &str,
    skip: &[String],
) -> Result<(Vec<Event>, Skipped), CaptureError> {
    // Every line parsed once; then the sections marked invalid anywhere in the file.
    let mut lines = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        if raw.trim().is_empty() {
            continue;
        }
        let v: Value = crate::support::strict::json(raw)
            .map_err(|(_, message)| error(file, i + 1, message))?;
        lines.push((i + 1, v));
    }
    let mut invalid: Vec<String> = Vec::new();
    for (_, v) in &lines {
        if v.get("section_invalid").and_then(Value::as_bool) == Some(true) {
            if let Some(name) = v.get("section").and_then(Value::as_str) {
                if !invalid.iter().any(|s| s == name) {
                    invalid.push(name.to_owned());
                }
            }
        }
    }
    let mut events = Vec::new();
    let mut skipped = Skipped {
        sections: invalid.clone(),
        ..Skipped::default()
    };
    for (line, v) in lines {
        let section = v.get("section").and_then(Value::as_str);
        if v.get("section_invalid").and_then(Value::as_bool) == Some(true) {
            skipped.marked_invalid += 1;
            continue;
        }
        if section.is_some_and(|name| invalid.iter().any(|s| s == name)) {
            skipped.marked_invalid_elsewhere += 1;
            continue;
        }
        if section.is_some_and(|name| skip.iter().any(|s| s == name)) {
            skipped.named += 1;
            continue;
        }
        let field = |name: &str| {
            v.get(name)
                .ok_or_else(|| error(file, line, format!("no `{name}`")))
        };
        let switch = field("dataset")?
            .as_str()
            .ok_or_else(|| error(file, line, "`dataset` is not a string"))?;
        let kind = match field("kind")?.as_str() {
            Some("press") => Edge::Press,
            Some("release") => Edge::Release,
            _ => return Err(error(file, line, "`kind` is not \"press\" or \"release\"")),
        };
        let entries = field("events")?
            .as_array()
            .ok_or_else(|| error(file, line, "`events` is not an array"))?;
        let mut pairs = entries.iter().map(|e| {
            let t = e.get(0).and_then(Value::as_f64);
            let l = e.get(1).and_then(Value::as_u64);
            match (t, l) {
                (Some(t), Some(l @ (0 | 1))) => Ok((t * 1e-9, l == 1)),
                _ => Err(error(file, line, format!("event {e} is not [t_ns, 0|1]"))),
            }
        });
        let Some(first) = pairs.next() else {
            return Err(error(file, line, "`events` is empty: no starting level"));
        };
        let mut closed = is_closed(Polarity::ActiveLow, first?.1);
        let closed_before = closed;
        if (kind == Edge::Press) == closed_before {
            return Err(error(
                file,
                line,
                format!(
                    "a {} that starts {}",
                    kind.name(),
                    if closed { "closed" } else { "open" }
                ),
            ));
        }
        let mut changes = Vec::new();
        for p in pairs {
            let (t, high) = p?;
            push_change(
                &mut changes,
                &mut closed,
                is_closed(Polarity::ActiveLow, high),
                t,
            )
            .map_err(|reason| error(file, line, reason))?;
        }
        let test = v
            .get("test")
            .map_or_else(String::new, |t| format!(" test {t}"));
        events.push(Event {
            switch: switch.to_owned(),
            origin: format!("line {line}{test}"),
            kind,
            changes,
            section: section.map(str::to_owned),
        });
    }
    Ok((events, skipped))
}

//! A Value Change Dump (VCD): one signal per switch.

use super::event::*;

/// Reads a Value Change Dump (IEEE 1364 sec. 18: what sigrok/PulseView and most logic
/// analyzers export) and returns the changes of one 1-bit signal: the one named `signal`, or
/// the only 1-bit signal when `signal` is `None`. The value at the first time stamp (or in
/// `$dumpvars`) is the starting level. Value changes may share a line with their time stamp
/// (as PulseView and sigrok-cli write them); a first line `META ...`, which sigrok-cli 0.7 writes
/// ahead of the header, is skipped.
///
/// # Errors
/// A malformed header or time stamp, an unknown or ambiguous signal, a signal wider than one
/// bit, an `x`/`z` value on the signal, or a signal with no value: the error names the line.
pub fn read_vcd(
    file: &str,
    text: &str,
    signal: Option<&str>,
    polarity: Polarity,
) -> Result<Stream, CaptureError> {
    // Tokens with their line numbers.
    let tokens: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .filter(|(i, l)| !(*i == 0 && l.starts_with("META ")))
        .flat_map(|(i, l)| l.split_whitespace().map(move |t| (i + 1, t)))
        .collect();
    let mut scale = None;
    let mut vars: Vec<(String, String, u32, usize)> = Vec::new(); // (id, name, width, line)
    let mut k = 0;
    let block_end = |from: usize| -> Result<usize, CaptureError> {
        tokens[from..]
            .iter()
            .position(|&(_, t)| t == "$end")
            .map(|p| from + p)
            .ok_or_else(|| error(file, tokens[from - 1].0, "a `$` section without `$end`"))
    };
    // The header, up to $enddefinitions.
    loop {
        let Some(&(line, tok)) = tokens.get(k) else {
            return Err(error(file, 0, "no `$enddefinitions $end`: not a VCD file"));
        };
        match tok {
            "$enddefinitions" => {
                k = block_end(k + 1)? + 1;
                break;
            }
            "$timescale" => {
                let end = block_end(k + 1)?;
                let spec: String = tokens[k + 1..end].iter().map(|&(_, t)| t).collect();
                scale = Some(timescale(&spec).ok_or_else(|| {
                    error(
                        file,
                        line,
                        format!("timescale {spec:?} is not 1/10/100 s|ms|us|ns|ps|fs"),
                    )
                })?);
                k = end + 1;
            }
            "$var" => {
                let end = block_end(k + 1)?;
                let fields: Vec<&str> = tokens[k + 1..end].iter().map(|&(_, t)| t).collect();
                let [_, width, id, name, ..] = fields[..] else {
                    return Err(error(
                        file,
                        line,
                        "`$var` needs a type, a width, an id and a name",
                    ));
                };
                let width = width
                    .parse()
                    .map_err(|_| error(file, line, format!("width {width:?} is not a number")))?;
                vars.push((id.to_owned(), name.to_owned(), width, line));
                k = end + 1;
            }
            t if t.starts_with('$') => k = block_end(k + 1)? + 1,
            other => {
                return Err(error(
                    file,
                    line,
                    format!("{other:?} before `$enddefinitions`"),
                ));
            }
        }
    }
    let scale = scale.ok_or_else(|| error(file, 0, "no `$timescale`"))?;
    let (id, name) = match signal {
        Some(wanted) => {
            let (id, name, width, line) = vars
                .iter()
                .find(|(_, n, _, _)| n == wanted)
                .ok_or_else(|| error(file, 0, format!("no signal named {wanted:?}")))?;
            if *width != 1 {
                return Err(error(
                    file,
                    *line,
                    format!("signal {name:?} is {width} bits wide, not 1"),
                ));
            }
            (id.clone(), name.clone())
        }
        None => {
            let one_bit: Vec<_> = vars.iter().filter(|v| v.2 == 1).collect();
            match one_bit[..] {
                [(id, name, _, _)] => (id.clone(), name.clone()),
                [] => return Err(error(file, 0, "no 1-bit signal")),
                _ => {
                    let names: Vec<&str> = one_bit.iter().map(|v| v.1.as_str()).collect();
                    return Err(error(
                        file,
                        0,
                        format!("several 1-bit signals ({}): name one", names.join(", ")),
                    ));
                }
            }
        }
    };
    let mut now: Option<f64> = None;
    let mut start: Option<bool> = None;
    let mut closed = false;
    let mut changes = Vec::new();
    while let Some(&(line, tok)) = tokens.get(k) {
        k += 1;
        if let Some(stamp) = tok.strip_prefix('#') {
            let ticks: u64 = stamp.parse().map_err(|_| {
                error(
                    file,
                    line,
                    format!("time stamp {tok:?} is not a whole number"),
                )
            })?;
            #[allow(clippy::cast_precision_loss)]
            let t = ticks as f64 * scale;
            if now.is_some_and(|n| t < n) {
                return Err(error(
                    file,
                    line,
                    format!("time stamp {tok:?} goes back in time"),
                ));
            }
            now = Some(t);
            continue;
        }
        if matches!(
            tok,
            "$dumpvars" | "$dumpall" | "$dumpon" | "$dumpoff" | "$end"
        ) {
            continue;
        }
        if tok.starts_with('$') {
            k = block_end(k)? + 1;
            continue;
        }
        // A vector or real value: `b0101 id` / `r1.5 id`, on another signal (ours is 1-bit).
        if tok.starts_with(['b', 'B', 'r', 'R']) {
            let Some(&(_, target)) = tokens.get(k) else {
                return Err(error(file, line, format!("{tok:?} without a signal id")));
            };
            if target == id {
                return Err(error(
                    file,
                    line,
                    format!("a vector value on the 1-bit signal {name:?}"),
                ));
            }
            k += 1;
            continue;
        }
        let mut chars = tok.chars();
        let value = chars.next().unwrap_or('?');
        if chars.as_str() != id {
            continue;
        }
        let high = match value {
            '1' => true,
            '0' => false,
            'x' | 'X' | 'z' | 'Z' => {
                return Err(error(
                    file,
                    line,
                    format!("signal {name:?} is {value} (unknown) here"),
                ));
            }
            other => {
                return Err(error(
                    file,
                    line,
                    format!("value {other:?} is not 0, 1, x or z"),
                ))
            }
        };
        let now_closed = is_closed(polarity, high);
        let Some(t) = now else {
            return Err(error(file, line, "a value before the first time stamp"));
        };
        if start.is_none() {
            start = Some(now_closed);
            closed = now_closed;
            continue;
        }
        push_change(&mut changes, &mut closed, now_closed, t)
            .map_err(|reason| error(file, line, reason))?;
    }
    let closed_before =
        start.ok_or_else(|| error(file, 0, format!("signal {name:?} never has a value")))?;
    Ok(Stream {
        closed_before,
        changes,
    })
}

/// Seconds per tick of a VCD `$timescale` such as `1ns`, `10 us`.
pub(crate) fn timescale(spec: &str) -> Option<f64> {
    let digits: String = spec.chars().take_while(char::is_ascii_digit).collect();
    let unit = &spec[digits.len()..];
    let n: f64 = match digits.as_str() {
        "1" => 1.0,
        "10" => 10.0,
        "100" => 100.0,
        _ => return None,
    };
    let unit = match unit {
        "s" => 1.0,
        "ms" => 1e-3,
        "us" => 1e-6,
        "ns" => 1e-9,
        "ps" => 1e-12,
        "fs" => 1e-15,
        _ => return None,
    };
    Some(n * unit)
}

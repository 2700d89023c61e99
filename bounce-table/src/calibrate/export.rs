//! The windows as C `#define`s or Rust constants.

use super::window::{window, MIN_EVENTS};
use super::Groups;
use crate::capture;

/// The windows as C `#define`s or Rust constants (nanoseconds, rounded up).
///
/// # Errors
/// A switch and kind with fewer than [`MIN_EVENTS`] events, or a window beyond a 64-bit count
/// of nanoseconds (about 585 years: a capture whose times are
/// not seconds), naming its switch and kind.
pub fn export(groups: &Groups<'_>, percentile: f64, rust: bool) -> Result<String, String> {
    let mut out = String::new();
    let guard = "BOUNCE_CALIBRATED_H";
    if rust {
        out.push_str(&format!(
            "// Debounce windows from a capture (bounce-table calibrate, P{}).\n\n",
            percentile * 100.0
        ));
    } else {
        out.push_str(&format!(
            "/* Debounce windows from a capture (bounce-table calibrate, P{}). */\n#ifndef {guard}\n#define {guard}\n\n",
            percentile * 100.0
        ));
    }
    for ((switch, kind), d) in groups {
        let refs: Vec<&capture::Description> = d.iter().collect();
        let fitted = window(&refs, percentile);
        if fitted.too_few() {
            return Err(format!(
                "{switch} {}: {} events are too few for a window (at least {MIN_EVENTS}): capture more",
                kind.name(),
                fitted.events
            ));
        }
        let w = fitted.recommended();
        let ns = crate::output::window_ns(w).ok_or_else(|| {
            format!(
                "{switch} {}: the window, {w:e} s, is beyond a 64-bit count of nanoseconds",
                kind.name()
            )
        })?;
        let id = crate::output::identifier(&format!("{switch} {}", kind.name()));
        if rust {
            out.push_str(&format!("pub const {id}_WINDOW_NS: u64 = {ns};\n"));
        } else {
            out.push_str(&format!("#define {id}_WINDOW_NS {ns}ull\n"));
        }
    }
    if !rust {
        out.push_str(&format!("\n#endif /* {guard} */\n"));
    }
    Ok(out)
}

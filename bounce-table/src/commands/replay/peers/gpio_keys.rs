//! Linux `gpio-keys` (its binding, `debounce-interval` 5 ms): every edge interrupt restarts a
//! 5 ms timer; when it expires the pin is read and reported if it changed. Zephyr `gpio-keys`
//! (input subsystem; `debounce-interval-ms`, default 30): the same algorithm, at 30 ms.

use crate::commands::replay::{Sampling, Row};

/// Linux's and Zephyr's `gpio-keys`, at their defaults.
pub fn rows(_period: f64) -> Vec<Row> {
    [("linux gpio-keys", 5e-3), ("zephyr gpio-keys", 30e-3)]
        .into_iter()
        .map(|(name, delay)| Row {
            name: name.to_owned(),
            window: Some(delay),
            sampling: Sampling::Interrupt(delay),
            settle: delay,
        })
        .collect()
}

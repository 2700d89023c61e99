//! QMK (its documentation page `feature_debounce_type.md`), `DEBOUNCE` 5 ms: `sym_defer_pk`
//! reports a key's change once it has not changed for 5 ms; `sym_eager_pk` reports at once and
//! then ignores the key for 5 ms; `asym_eager_defer_pk` reports a press at once (then ignores
//! the key for 5 ms) and a release once the key has not changed for 5 ms.

use super::{passed, polled, LockOut};
use crate::commands::replay::{Polled, Row};

/// QMK's default `DEBOUNCE` (s).
const DEBOUNCE: f64 = 5e-3;

/// QMK's three per-key algorithms, at their default.
pub fn rows(period: f64) -> Vec<Row> {
    vec![
        polled(
            "qmk sym_defer_pk",
            DEBOUNCE,
            period,
            Box::new(SymDefer {
                debounce: DEBOUNCE,
                cooked: false,
                raw: false,
                changed_at: None,
            }),
        ),
        polled(
            "qmk sym_eager_pk",
            DEBOUNCE,
            period,
            Box::new(LockOut::new(DEBOUNCE)),
        ),
        polled(
            "qmk asym_eager_defer_pk",
            DEBOUNCE,
            period,
            Box::new(AsymEagerDefer::new(DEBOUNCE)),
        ),
    ]
}

/// QMK's `sym_defer_pk`.
#[derive(Debug, Clone)]
pub struct SymDefer {
    debounce: f64,
    cooked: bool,
    raw: bool,
    changed_at: Option<f64>,
}

impl Polled for SymDefer {
    fn reset(&mut self, closed: bool) {
        (self.cooked, self.raw, self.changed_at) = (closed, closed, None);
    }
    fn sample(&mut self, now: f64, closed: bool) -> Option<bool> {
        if closed != self.raw {
            self.raw = closed;
            self.changed_at = Some(now);
        }
        let t0 = self.changed_at?;
        if !passed(now, t0, self.debounce) {
            return None;
        }
        self.changed_at = None;
        (self.cooked != self.raw).then(|| {
            self.cooked = self.raw;
            self.cooked
        })
    }
}

/// QMK's `asym_eager_defer_pk`: presses eager, releases deferred, with QMK's one timer per key.
///
/// A change of the pin starts the key's timer if it is not running: a press is reported at
/// once and locks the key out for the window; a release is reported when the timer runs out,
/// and the timer is cancelled if the pin reads pressed again before. Only one timer runs per
/// key, so a release during a press's lock-out cannot start its own until the lock-out has
/// ended: the scan where it ends looks at the pin again (QMK: pressed at 0 ms, released at 1,
/// the release is reported at 10, not at 6).
#[derive(Debug, Clone)]
pub struct AsymEagerDefer {
    debounce: f64,
    cooked: bool,
    raw: bool,
    /// The running timer: when it started, and whether it times a press (else a release).
    timer: Option<(f64, bool)>,
}

impl AsymEagerDefer {
    /// At `debounce` (s), settled released.
    #[must_use]
    pub fn new(debounce: f64) -> Self {
        Self {
            debounce,
            cooked: false,
            raw: false,
            timer: None,
        }
    }

    /// QMK's `transfer_matrix_values` for this key, at `now`.
    fn transfer(&mut self, now: f64) -> Option<bool> {
        match self.timer {
            None if self.raw != self.cooked => {
                self.timer = Some((now, self.raw));
                if self.raw {
                    self.cooked = true;
                    return Some(true);
                }
                None
            }
            // The pin reads the reported state again during a release's timer: cancelled.
            Some((_, false)) if self.raw == self.cooked => {
                self.timer = None;
                None
            }
            _ => None,
        }
    }
}

impl Polled for AsymEagerDefer {
    fn reset(&mut self, closed: bool) {
        (self.cooked, self.raw, self.timer) = (closed, closed, None);
    }
    fn sample(&mut self, now: f64, closed: bool) -> Option<bool> {
        let changed = closed != self.raw;
        self.raw = closed;
        let mut reported = None;
        let mut look_again = false;
        // The timer first (QMK's counters, counted in whole milliseconds of elapsed time).
        if let Some((started, press)) = self.timer {
            if passed(now, started, self.debounce) {
                self.timer = None;
                if press {
                    look_again = true;
                } else if self.cooked != self.raw {
                    self.cooked = self.raw;
                    reported = Some(self.raw);
                }
            }
        }
        if changed || look_again {
            if let Some(edge) = self.transfer(now) {
                reported = Some(edge);
            }
        }
        reported
    }
}


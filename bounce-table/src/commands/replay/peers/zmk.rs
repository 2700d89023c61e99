//! ZMK (`kscan` debouncing docs): an integrator per key, counting up the milliseconds the key
//! differs from its debounced state and down the milliseconds it agrees; it flips at
//! `debounce-press-ms` / `debounce-release-ms`, both 5 by default, at 1 ms scans.

use super::{passed, polled};
use crate::commands::replay::{Polled, Row};

/// ZMK's default `debounce-press-ms` and `debounce-release-ms` (s).
const DEBOUNCE: f64 = 5e-3;

/// ZMK's integrator, at its defaults.
pub fn rows(period: f64) -> Vec<Row> {
    vec![polled(
        "zmk integrator",
        DEBOUNCE,
        period,
        Box::new(Integrator::new(DEBOUNCE, DEBOUNCE, period)),
    )]
}

/// ZMK's integrator: a counter per key, in milliseconds, up by the scan's elapsed time while the
/// pin differs from the key's state and down while it agrees; the state flips at the scan that
/// finds the counter already at the threshold (ZMK's `zmk_debounce_update`: the counter is
/// compared before it is incremented).
#[derive(Debug, Clone)]
pub struct Integrator {
    press: f64,
    release: f64,
    period: f64,
    pressed: bool,
    counter: f64,
}

impl Integrator {
    /// `press` and `release` thresholds (s) at scans `period` (s) apart, settled released.
    #[must_use]
    pub fn new(press: f64, release: f64, period: f64) -> Self {
        Self {
            press,
            release,
            period,
            pressed: false,
            counter: 0.0,
        }
    }
}

impl Polled for Integrator {
    fn reset(&mut self, closed: bool) {
        (self.pressed, self.counter) = (closed, 0.0);
    }
    fn sample(&mut self, _now: f64, closed: bool) -> Option<bool> {
        if closed == self.pressed {
            self.counter = (self.counter - self.period).max(0.0);
            return None;
        }
        let threshold = if self.pressed {
            self.release
        } else {
            self.press
        };
        // (the counter is a sum of whole periods: compared to rounding)
        if !passed(self.counter, 0.0, threshold) {
            self.counter += self.period;
            return None;
        }
        self.pressed = !self.pressed;
        self.counter = 0.0;
        Some(self.pressed)
    }
}


//! Bounce2 (its README), `interval` 10 ms: the default mode reports once the input has been
//! stable for the interval; `BOUNCE_LOCK_OUT` reports at once and ignores the input for the
//! interval.

use super::{passed, polled, LockOut};
use crate::commands::replay::{Polled, Row};

/// Bounce2's default `interval` (s).
const INTERVAL: f64 = 10e-3;

/// Bounce2's two modes, at its default interval.
pub fn rows(period: f64) -> Vec<Row> {
    vec![
        polled(
            "bounce2 stable",
            INTERVAL,
            period,
            Box::new(Stable {
                interval: INTERVAL,
                debounced: false,
                unstable: false,
                since: 0.0,
            }),
        ),
        polled(
            "bounce2 lock-out",
            INTERVAL,
            period,
            Box::new(LockOut::new(INTERVAL)),
        ),
    ]
}

/// Bounce2's default mode: report once the input has been stable for the interval.
#[derive(Debug, Clone)]
pub struct Stable {
    interval: f64,
    debounced: bool,
    unstable: bool,
    since: f64,
}

impl Polled for Stable {
    fn reset(&mut self, closed: bool) {
        (self.debounced, self.unstable, self.since) = (closed, closed, f64::NEG_INFINITY);
    }
    fn sample(&mut self, now: f64, closed: bool) -> Option<bool> {
        if closed != self.unstable {
            self.unstable = closed;
            self.since = now;
            return None;
        }
        if passed(now, self.since, self.interval) && closed != self.debounced {
            self.since = now;
            self.debounced = closed;
            return Some(closed);
        }
        None
    }
}


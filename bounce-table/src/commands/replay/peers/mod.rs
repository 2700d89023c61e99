//! The peer debouncers `replay` scores ours against, each re-implemented from its documentation
//! at its documented default, one file each:
//!
//! - [`qmk`]: QMK's `sym_defer_pk`, `sym_eager_pk` and `asym_eager_defer_pk`;
//! - [`zmk`]: ZMK's integrator;
//! - [`bounce2`]: Bounce2's stable and lock-out modes;
//! - [`debouncr`]: the debouncr crate, 4, 8 and 16 samples;
//! - [`gpio_keys`]: Linux's and Zephyr's `gpio-keys`.
//!
//! To add a peer: write `<peer>.rs` here with its module docs (where its algorithm and default
//! come from) and `pub fn rows(period: f64) -> Vec<Row>` (a polled debouncer implements
//! [`Polled`] and is wrapped by [`polled`]; an interrupt-driven one is a
//! [`Sampling::Interrupt`]), then add its name to the
//! `peers!` line below. Its rows appear in every table, plot and tap replay, in that order.

use crate::commands::replay::{Polled, Row, Sampling};

/// Declares each peer's module and lists their rows, in the order given.
macro_rules! peers {
    ($($peer:ident),+ $(,)?) => {
        $(pub mod $peer;)+
        /// The peers, each at its documented default, at `period` (s) between samples.
        #[must_use]
        pub fn peers(period: f64) -> Vec<Row> {
            let mut rows = Vec::new();
            $(rows.extend($peer::rows(period));)+
            rows
        }
    };
}

peers!(qmk, zmk, bounce2, debouncr, gpio_keys);

/// A polled debouncer's row: its name, its window (s), sampled every `period` (s), as a peer's
/// `rows` builds it.
pub fn polled(name: &str, window: f64, period: f64, d: Box<dyn Polled>) -> Row {
    Row {
        name: name.to_owned(),
        window: Some(window),
        sampling: Sampling::Polled(d),
        settle: window + 2.0 * period,
    }
}

/// Whether `span` (s) has passed from `start` to `now`, to rounding: sample times are
/// `(phase + k) * period`, whose differences are whole periods only to within an ulp.
pub(crate) fn passed(now: f64, start: f64, span: f64) -> bool {
    now - start >= span * (1.0 - 1e-9)
}

/// QMK's `sym_eager_pk` and Bounce2's lock-out mode: report at once, then ignore the pin for
/// the window.
#[derive(Debug, Clone)]
pub struct LockOut {
    window: f64,
    cooked: bool,
    since: f64,
}

impl LockOut {
    /// Ignoring the pin for `window` (s) after each report.
    pub fn new(window: f64) -> Self {
        Self {
            window,
            cooked: false,
            since: 0.0,
        }
    }
}

impl Polled for LockOut {
    fn reset(&mut self, closed: bool) {
        (self.cooked, self.since) = (closed, f64::NEG_INFINITY);
    }
    fn sample(&mut self, now: f64, closed: bool) -> Option<bool> {
        if !passed(now, self.since, self.window) || closed == self.cooked {
            return None;
        }
        self.cooked = closed;
        self.since = now;
        Some(closed)
    }
}

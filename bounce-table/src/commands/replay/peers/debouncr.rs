//! debouncr (the crate itself, `debounce_stateful_4/8/16`): a change is reported after 4, 8 or
//! 16 consecutive equal samples.

use super::polled;
use crate::commands::replay::{Polled, Row};

/// debouncr's three sizes.
pub fn rows(period: f64) -> Vec<Row> {
    [
        (4.0, Debouncr::Four(debouncr::debounce_stateful_4(false))),
        (8.0, Debouncr::Eight(debouncr::debounce_stateful_8(false))),
        (
            16.0,
            Debouncr::Sixteen(debouncr::debounce_stateful_16(false)),
        ),
    ]
    .into_iter()
    .map(|(n, d)| polled(&format!("debouncr {n:.0} samples"), n * period, period, Box::new(d)))
    .collect()
}

/// debouncr's stateful debouncer of 4, 8 or 16 samples (the crate itself).
pub enum Debouncr {
    /// 4 samples.
    Four(debouncr::DebouncerStateful<u8, debouncr::Repeat4>),
    /// 8 samples.
    Eight(debouncr::DebouncerStateful<u8, debouncr::Repeat8>),
    /// 16 samples.
    Sixteen(debouncr::DebouncerStateful<u16, debouncr::Repeat16>),
}

impl Polled for Debouncr {
    fn reset(&mut self, closed: bool) {
        *self = match self {
            Debouncr::Four(_) => Debouncr::Four(debouncr::debounce_stateful_4(closed)),
            Debouncr::Eight(_) => Debouncr::Eight(debouncr::debounce_stateful_8(closed)),
            Debouncr::Sixteen(_) => Debouncr::Sixteen(debouncr::debounce_stateful_16(closed)),
        };
    }
    fn sample(&mut self, _now: f64, closed: bool) -> Option<bool> {
        let edge = match self {
            Debouncr::Four(d) => d.update(closed),
            Debouncr::Eight(d) => d.update(closed),
            Debouncr::Sixteen(d) => d.update(closed),
        };
        edge.map(|e| e == debouncr::Edge::Rising)
    }
}


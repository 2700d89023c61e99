//! What `calibrate` is asked for: the capture, its calibration and what to write.

use crate::{capture, stats};

/// What `calibrate` writes (`--format`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Written {
    /// The Markdown report (`report`, `markdown`).
    Report,
    /// The windows as C constants (`c`).
    C,
    /// The windows as Rust constants (`rust`).
    Rust,
    /// Every event's description as CSV (`csv`).
    Events,
}

/// What `calibrate` was asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct Request {
    /// The capture and how to read it.
    pub capture: capture::Options,
    /// How its events are timed and the windows fitted.
    pub calibration: stats::Calibration,
    /// What to write.
    pub written: Written,
    /// Write it there, completely or not at all (else standard output).
    pub output: Option<String>,
    /// Write one SVG per switch and kind there.
    pub plot: Option<String>,
    /// Also fit the real-contact models (slow: tens of seconds).
    pub contact_models: bool,
}

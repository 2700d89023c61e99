//! What the tool writes: the table mode's formats (text, Markdown, CSV, JSON), generated C and
//! Rust, the SVG plots, and a long table kept on disk in blocks.

pub mod emit;
pub mod output;
pub mod plot;
pub mod spool;

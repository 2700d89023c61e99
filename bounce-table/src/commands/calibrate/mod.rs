//! `bounce-table calibrate`: read a capture of a real switch and describe its bounce, per switch
//! and per kind (press, release), at the instrument's resolution: the report, the windows as C
//! or Rust, the plots. The fits and windows it reports are `stats`'; the capture's reading,
//! `capture`'s.

mod export;
mod plot;
mod report;
mod request;
mod written;

pub use export::export;
pub use plot::plot;
pub use report::{assess, by_section, describe, summary};
pub use request::{Request, Written};
pub use written::written;

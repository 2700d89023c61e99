//! `bounce-table`, the desk tool: predicted bounce and debounce windows for switches, from the
//! built-in catalogue or a scene file (TOML or JSON, with ranges), with Monte Carlo
//! analysis over parameter ranges, sensitivities, tables, firmware constants and plots; and `eval`, the
//! JSON Lines interface to the model and the exact reference.

pub mod analysis;
pub mod calibrate;
pub mod capture;
pub mod cli;
pub mod emit;
pub mod eval;
pub mod output;
pub mod plot;
pub mod priors;
pub mod replay;
pub mod scene_input;
pub mod scenes;
pub mod scope;
pub mod spool;
pub mod spreads;
pub mod strict;
pub mod table;
pub mod taps;
pub mod workers;

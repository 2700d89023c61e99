//! `bounce-table`, the desk tool: predicted bounce and debounce windows for switches, from the
//! built-in catalogue or a scene file (TOML or JSON, with ranges), with Monte Carlo
//! analysis over parameter ranges, sensitivities, tables, firmware constants and plots; and `eval`, the
//! JSON Lines interface to the model and the exact reference.

// The layers, lowest first: each module uses only its own layer and those below it, and the
// subcommands never use each other (`scripts/layers.py` checks it).
pub mod capture;
pub mod cli;
pub mod commands;
pub mod render;
pub mod scene;
pub mod stats;
pub mod support;

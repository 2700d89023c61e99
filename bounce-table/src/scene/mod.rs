//! The switches the table mode and `eval` read: a scene file (TOML or JSON) or the built-in
//! catalogue, each scene checked field by field, its ranges and their samples, the published
//! priors of a switch type, and the host's exact reference on a scene.

pub mod file;
pub mod input;
pub mod priors;
pub mod reference;
pub mod spreads;

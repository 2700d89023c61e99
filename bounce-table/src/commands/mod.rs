//! The subcommands (and the table mode), each over the shared layers below it (`capture`,
//! `scene`, `stats`, `render`, `support`) and never over another subcommand.

pub mod calibrate;
pub mod eval;
pub mod replay;
pub mod table;

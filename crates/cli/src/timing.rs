//! The whole-process laps (read, weld, extract, check, write) shown by
//! `-v` beside the library's own stage times ([`crate::summary`]).

pub use dualex::steps::Laps;

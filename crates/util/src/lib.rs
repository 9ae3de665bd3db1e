//! # dualex-util — small shared utilities
//!
//! Pieces with no knowledge of maps or meshes, used by several stages. The
//! crate depends on rayon only, so that the light crates (the checker)
//! may use it.
//!
//! Input: plain numbers and slices. Output: plain numbers and vectors.
//! Invariant: every function gives the same result whatever the number of
//! threads and the run (no hashing with random state, no timing in
//! results).
//!
//! - [`bucket`]: a counting sort into buckets, each then sorted (edges
//!   or faces grouped by their least vertex without hashing);
//! - [`par`]: deterministic parallel building blocks (CSR building in
//!   fixed-size chunks joined in input order);
//! - [`rng`]: a seeded splitmix64 generator;
//! - [`timing`]: wall-clock laps (the stats' `time_ms`, the CLI's `-v`);
//! - [`round`]: `f64::round` / `ceil` / `floor` bit for bit without a
//!   library call;
//! - [`union_find`]: the one union–find (path halving) of the workspace;
//! - [`union_find_par`]: its twin that threads share (atomic parents,
//!   the same representatives);
//! - [`used`]: how many vertices a list of simplices uses, in parallel.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bucket;
pub mod par;
pub mod rng;
pub mod round;
pub mod timing;
pub mod union_find;
pub mod union_find_par;
pub mod used;

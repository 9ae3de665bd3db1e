//! `dualex-bench` as a library: the benchmark cases (generated maps of any
//! size, or files), shared by the `dualex-bench` binary (whole extraction,
//! one child process per case) and the divan benches of single stages
//! (`cargo bench -p dualex-bench`).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod cases;

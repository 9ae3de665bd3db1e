//! Generators of test maps (valid and messy) in 2D and 3D
#![forbid(unsafe_code)]
#![warn(missing_docs)]

//! Independent validity checkers for quad and hex meshes
#![forbid(unsafe_code)]
#![warn(missing_docs)]

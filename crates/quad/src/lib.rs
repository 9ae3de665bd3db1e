//! Quad extraction: sanitization, nodes, tracing, fairing, geometry (D = 2)
#![forbid(unsafe_code)]
#![warn(missing_docs)]

//! Step 1: local shifted coordinates (integer offset per triangle, shift by
//! ½) — the dimension-generic [`dualex_segment::local::LocalMap`] at D = 2.

/// Triangle map in local shifted coordinates.
pub type LocalMap = dualex_segment::local::LocalMap<3, 2>;

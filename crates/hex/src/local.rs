//! Step 1: local shifted coordinates (integer offset per tet, shift by ½) —
//! the dimension-generic [`dualex_segment::local::LocalMap`] at D = 3.

/// Tet map in local shifted coordinates.
pub type LocalMap = dualex_segment::local::LocalMap<4, 3>;

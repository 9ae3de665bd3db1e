//! The face numbering of a tet for sanitization and the split (face `f`
//! opposite corner `f`, corners `(f+1, f+2, f+3) mod 4`); the predicates
//! of the walks live in [`dualex_segment::simplex`].

pub use dualex_segment::simplex::face_corners;

//! Readers and writers: OBJ, PLY, .hexex in; OBJ, PLY, VTK, MEDIT out
#![forbid(unsafe_code)]
#![warn(missing_docs)]

//! # dualex-capi — the C API of dualex
//!
//! Quad and hex extraction behind a plain C header
//! (`crates/capi/include/dualex.h`), shaped like HexHex's simple call:
//! flat arrays in (positions, simplices, per-corner map coordinates), a
//! plain struct out, freed by the library.
//!
//! | C function | what it does |
//! |---|---|
//! | `dualex_options_default` | fills a [`DualexOptions`] with the defaults (welding on) |
//! | `dualex_quad_extract` | triangles + per-corner `uv` → [`DualexQuadMesh`] |
//! | `dualex_hex_extract` | tets + per-corner `uvw` → [`DualexHexMesh`] |
//! | `dualex_quad_mesh_free`, `dualex_hex_mesh_free` | release an output |
//! | `dualex_last_error` | the last error message of this thread |
//! | `dualex_version` | the library version |
//!
//! Invariants at the boundary:
//! - every entry point returns a [`DualexStatus`] code: 0 ok, nonzero an
//!   error whose one-line message `dualex_last_error()` gives (the same
//!   text as the CLI's, e.g. `triangle 17: corner 2 refers to vertex 9, but
//!   there are 4 vertices`);
//! - null pointers, misaligned pointers and sizes whose byte counts
//!   overflow are errors, not undefined behaviour (what the pointers point
//!   to must still hold the stated number of values);
//! - no panic crosses the boundary: each entry point runs under
//!   `catch_unwind`, a caught panic is [`DualexStatus::Internal`] with the
//!   message `internal error (bug): …`;
//! - on error the output struct is zeroed, so freeing it is always safe.
#![deny(unsafe_op_in_unsafe_fn)]
#![warn(missing_docs)]

mod error;
mod extract;
mod mesh;
mod slices;

pub use error::{dualex_last_error, DualexStatus};
pub use extract::{dualex_hex_extract, dualex_quad_extract};
pub use mesh::{
    dualex_hex_mesh_free, dualex_options_default, dualex_quad_mesh_free, DualexHexMesh,
    DualexOptions, DualexQuadMesh, DUALEX_GRID_AUTO, DUALEX_GRID_HALF, DUALEX_GRID_ZERO,
    DUALEX_NO_SOURCE,
};

use std::ffi::c_char;

/// The library version (`"0.1.0"`), a static NUL-terminated string.
#[no_mangle]
pub extern "C" fn dualex_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}

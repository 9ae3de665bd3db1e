//! The C structs: options in, meshes out, and the functions that fill
//! the defaults and free an output.
//!
//! Layout: `#[repr(C)]`, field for field as in `include/dualex.h` (the
//! integration test `tests/c_api.rs` compares every offset with a C
//! compiler's). Ownership: the arrays of an output are allocated here, as
//! boxed slices whose lengths follow from the counts (`3·n_vertices`
//! positions, `4·n_cells` or `8·n_cells` indices, `n_cells` sources), and
//! only the `*_free` functions release them; a zeroed struct holds nothing.

use std::ffi::c_int;
use std::ptr;

/// `DualexOptions::grid_offset`: choose from the singular vertices.
pub const DUALEX_GRID_AUTO: c_int = 0;
/// `DualexOptions::grid_offset`: nodes at the map's half-integers.
pub const DUALEX_GRID_HALF: c_int = 1;
/// `DualexOptions::grid_offset`: nodes at the map's integer points.
pub const DUALEX_GRID_ZERO: c_int = 2;
/// A `sources` entry of a quad that closes a hole (no input triangle).
pub const DUALEX_NO_SOURCE: u32 = u32::MAX;

/// Extraction options (`DualexOptions` in C); the flags are 0 or nonzero.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DualexOptions {
    /// Merge coincident boundary vertices (cut meshes) first. Default 1.
    pub weld: c_int,
    /// Index fairing after untangling (quads only). Default 1.
    pub fairing: c_int,
    /// Round transition translations of any residual. Default 0.
    pub round_transitions: c_int,
    /// `DUALEX_GRID_AUTO` (default), `_HALF` or `_ZERO`.
    pub grid_offset: c_int,
    /// An output whose topology differs from the input's is an error.
    /// Default 0.
    pub strict: c_int,
    /// Seed of the sanitization perturbations. Default 1.
    pub seed: u64,
}

impl Default for DualexOptions {
    fn default() -> Self {
        let q = dualex::QuadOptions::default();
        DualexOptions {
            weld: q.weld.into(),
            fairing: q.fairing.into(),
            round_transitions: q.round_transitions.into(),
            grid_offset: DUALEX_GRID_AUTO,
            strict: q.strict.into(),
            seed: q.seed,
        }
    }
}

impl DualexOptions {
    /// The facade's grid offset, or the message for an unknown value.
    pub(crate) fn grid_offset(&self) -> Result<dualex::GridOffset, String> {
        match self.grid_offset {
            DUALEX_GRID_AUTO => Ok(dualex::GridOffset::Auto),
            DUALEX_GRID_HALF => Ok(dualex::GridOffset::Half),
            DUALEX_GRID_ZERO => Ok(dualex::GridOffset::Zero),
            g => Err(format!(
                "options: grid_offset {g} is not DUALEX_GRID_AUTO (0), _HALF (1) or _ZERO (2)"
            )),
        }
    }
}

/// Fills `*opts` with the defaults (welding and fairing on, automatic grid
/// offset, seed 1). A null `opts` is ignored.
///
/// # Safety
/// `opts` is null or points to writable memory for one `DualexOptions`.
#[no_mangle]
pub unsafe extern "C" fn dualex_options_default(opts: *mut DualexOptions) {
    if !opts.is_null() && opts.is_aligned() {
        // SAFETY: non-null and aligned; the caller vouches for the memory
        unsafe { opts.write(DualexOptions::default()) };
    }
}

/// A quad mesh and its main counts (`DualexQuadMesh` in C).
#[repr(C)]
#[derive(Debug)]
pub struct DualexQuadMesh {
    /// Output vertices.
    pub n_vertices: usize,
    /// `3·n_vertices` coordinates, x y z per vertex.
    pub positions: *mut f64,
    /// Output quads.
    pub n_cells: usize,
    /// `4·n_cells` vertex indices, counter-clockwise.
    pub cells: *mut u32,
    /// `n_cells` input triangle indices (`DUALEX_NO_SOURCE` for a quad
    /// that closes a hole).
    pub sources: *mut u32,
    /// Connected components of the output.
    pub n_components: usize,
    /// Boundary loops of the output.
    pub n_boundary_loops: usize,
    /// Euler characteristic V − E + F of the output.
    pub euler: i64,
    /// Singular vertices of the input map.
    pub n_singular_vertices: usize,
    /// Boundary vertices welded before extraction.
    pub n_welded_vertices: usize,
    /// 1 when the output's topology equals the input's.
    pub topology_matches: c_int,
}

/// A hex mesh and its main counts (`DualexHexMesh` in C).
#[repr(C)]
#[derive(Debug)]
pub struct DualexHexMesh {
    /// Output vertices.
    pub n_vertices: usize,
    /// `3·n_vertices` coordinates, x y z per vertex.
    pub positions: *mut f64,
    /// Output hexes.
    pub n_cells: usize,
    /// `8·n_cells` vertex indices, VTK order.
    pub cells: *mut u32,
    /// `n_cells` input tet indices (the tet holding each hex's centre).
    pub sources: *mut u32,
    /// Connected components of the output.
    pub n_components: usize,
    /// Boundary surfaces of the output.
    pub n_boundary_surfaces: usize,
    /// Euler characteristic V − E + F − C of the output.
    pub euler: i64,
    /// Singular interior edges of the input map.
    pub n_singular_edges: usize,
    /// Boundary vertices welded before extraction.
    pub n_welded_vertices: usize,
    /// 1 when the output's topology equals the input's.
    pub topology_matches: c_int,
}

/// Hands a vector to C: a pointer to its boxed slice (freed by [`release`]).
pub(crate) fn leak<T>(v: Vec<T>) -> *mut T {
    Box::into_raw(v.into_boxed_slice()).cast()
}

/// Frees what [`leak`] made of a vector of `len` values; null is a no-op.
///
/// # Safety
/// `p` is null or came from [`leak`] of exactly `len` values, not yet freed.
unsafe fn release<T>(p: *mut T, len: usize) {
    if !p.is_null() {
        // SAFETY: the caller's contract: a boxed slice of `len` values
        drop(unsafe { Box::from_raw(ptr::slice_from_raw_parts_mut(p, len)) });
    }
}

impl DualexQuadMesh {
    /// A struct holding nothing.
    pub(crate) fn zeroed() -> Self {
        DualexQuadMesh {
            n_vertices: 0,
            positions: ptr::null_mut(),
            n_cells: 0,
            cells: ptr::null_mut(),
            sources: ptr::null_mut(),
            n_components: 0,
            n_boundary_loops: 0,
            euler: 0,
            n_singular_vertices: 0,
            n_welded_vertices: 0,
            topology_matches: 0,
        }
    }
}

impl DualexHexMesh {
    /// A struct holding nothing.
    pub(crate) fn zeroed() -> Self {
        DualexHexMesh {
            n_vertices: 0,
            positions: ptr::null_mut(),
            n_cells: 0,
            cells: ptr::null_mut(),
            sources: ptr::null_mut(),
            n_components: 0,
            n_boundary_surfaces: 0,
            euler: 0,
            n_singular_edges: 0,
            n_welded_vertices: 0,
            topology_matches: 0,
        }
    }
}

/// Frees the arrays of a quad mesh filled by `dualex_quad_extract` and
/// zeroes it; null and zeroed structs are ignored (freeing twice is safe).
///
/// # Safety
/// `mesh` is null or a struct filled by `dualex_quad_extract` (or zeroed),
/// whose counts and pointers the caller has not changed.
#[no_mangle]
pub unsafe extern "C" fn dualex_quad_mesh_free(mesh: *mut DualexQuadMesh) {
    if mesh.is_null() || !mesh.is_aligned() {
        return;
    }
    // SAFETY: non-null, aligned, and by the contract filled by this library
    let m = unsafe { &mut *mesh };
    // SAFETY: the arrays were leaked with these lengths (see `leak`)
    unsafe {
        release(m.positions, 3 * m.n_vertices);
        release(m.cells, 4 * m.n_cells);
        release(m.sources, m.n_cells);
    }
    *m = DualexQuadMesh::zeroed();
}

/// Frees the arrays of a hex mesh filled by `dualex_hex_extract` and
/// zeroes it; null and zeroed structs are ignored (freeing twice is safe).
///
/// # Safety
/// As [`dualex_quad_mesh_free`].
#[no_mangle]
pub unsafe extern "C" fn dualex_hex_mesh_free(mesh: *mut DualexHexMesh) {
    if mesh.is_null() || !mesh.is_aligned() {
        return;
    }
    // SAFETY: non-null, aligned, and by the contract filled by this library
    let m = unsafe { &mut *mesh };
    // SAFETY: the arrays were leaked with these lengths (see `leak`)
    unsafe {
        release(m.positions, 3 * m.n_vertices);
        release(m.cells, 8 * m.n_cells);
        release(m.sources, m.n_cells);
    }
    *m = DualexHexMesh::zeroed();
}

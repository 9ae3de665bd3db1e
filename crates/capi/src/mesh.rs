//! The C structs: options in, meshes out, and the functions that fill
//! the defaults and free an output.
//!
//! Layout: `#[repr(C)]`, field for field as in `include/dualex.h` (the
//! integration test `tests/c_api.rs` compares every offset with a C
//! compiler's); fields added later go at the end of a struct (the ABI of
//! the earlier ones stays). Ownership: the arrays of an output are
//! allocated here, as boxed slices whose lengths follow from the counts
//! (`3·n_vertices` positions, `4·n_cells` or `8·n_cells` indices,
//! `n_cells` sources), and only the `*_free` functions release them; a
//! zeroed struct holds nothing.

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
    /// Index fairing after untangling (hexes: on columns, extruded maps).
    /// Default 1.
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
    /// The geometric stage after the extraction: 1 (default) puts boundary
    /// vertices on the input's boundary and untangles inverted elements
    /// (moving only the vertices near them); 0 keeps the map's positions
    /// (the quality is still measured).
    pub untangle: c_int,
    /// 0 (default): no smoothing; `n > 0`: optimise the shape of every
    /// element in at most `n` rounds (needs `untangle` on).
    pub smooth_rounds: c_int,
}

impl Default for DualexOptions {
    fn default() -> Self {
        let q = dualex::Options::default();
        DualexOptions {
            weld: q.weld.into(),
            fairing: q.fairing.into(),
            round_transitions: q.round_transitions.into(),
            grid_offset: DUALEX_GRID_AUTO,
            strict: q.strict.into(),
            seed: q.seed,
            untangle: 1,
            smooth_rounds: 0,
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

    /// The facade's geometric stage options, or the message for a negative
    /// `smooth_rounds` or smoothing with `untangle` off.
    pub(crate) fn geometry(&self) -> Result<dualex::GeometryOptions, String> {
        use dualex::GeometryMode;
        let mode = match (self.untangle != 0, self.smooth_rounds) {
            (_, n) if n < 0 => {
                return Err(format!(
                    "options: smooth_rounds {n} is negative (0: no smoothing)"
                ))
            }
            (false, 0) => GeometryMode::Off,
            (false, n) => {
                return Err(format!(
                    "options: smooth_rounds {n} with untangle 0: smoothing moves the vertices that untangle 0 keeps"
                ))
            }
            (true, 0) => GeometryMode::Auto,
            // positive and at most c_int::MAX: fits usize
            (true, n) => GeometryMode::Smooth(n.unsigned_abs() as usize),
        };
        Ok(dualex::GeometryOptions {
            mode,
            ..Default::default()
        })
    }
}

/// Fills `*opts` with the defaults (welding and fairing on, automatic grid
/// offset, seed 1, untangling on, no smoothing). A null `opts` is ignored.
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

/// A mesh and its main counts: `DualexQuadMesh` (`K` = 4) and
/// `DualexHexMesh` (`K` = 8) in C, one struct for both dimensions (two
/// fields have their own names in each C struct: `n_boundary_loops` /
/// `n_boundary_surfaces`, `n_singular_vertices` / `n_singular_edges`; the
/// layouts are the same).
#[repr(C)]
#[derive(Debug)]
pub struct DualexMesh<const K: usize> {
    /// Output vertices.
    pub n_vertices: usize,
    /// `3·n_vertices` coordinates, x y z per vertex.
    pub positions: *mut f64,
    /// Output cells (quads, hexes).
    pub n_cells: usize,
    /// `K·n_cells` vertex indices: quads counter-clockwise, hexes in VTK
    /// order.
    pub cells: *mut u32,
    /// `n_cells` input simplex indices: the triangle or tet holding each
    /// cell's node (`DUALEX_NO_SOURCE` for a quad that closes a hole).
    pub sources: *mut u32,
    /// Connected components of the output.
    pub n_components: usize,
    /// Boundary loops (quads) or surfaces (hexes) of the output.
    pub n_boundary_components: usize,
    /// Euler characteristic of the output: V − E + F (quads), V − E + F −
    /// C (hexes).
    pub euler: i64,
    /// Singular vertices (quads) or singular interior edges (hexes) of the
    /// input map.
    pub n_singular: usize,
    /// Boundary vertices welded before extraction.
    pub n_welded_vertices: usize,
    /// 1 when the output's topology equals the input's.
    pub topology_matches: c_int,
    /// Least scaled Jacobian of the elements as the map placed them
    /// (1 for an empty mesh).
    pub sj_min_before: f64,
    /// Least scaled Jacobian after the geometric stage (of `positions`).
    pub sj_min_after: f64,
    /// 5th percentile of the scaled Jacobian, before the stage.
    pub sj_p5_before: f64,
    /// 5th percentile of the scaled Jacobian, after the stage.
    pub sj_p5_after: f64,
    /// Elements with a scaled Jacobian ≤ 0 before the stage.
    pub inverted_before: usize,
    /// Elements with a scaled Jacobian ≤ 0 after the stage.
    pub inverted_after: usize,
    /// Vertices the stage moved.
    pub moved_vertices: usize,
}

/// A quad mesh and its main counts (`DualexQuadMesh` in C).
pub type DualexQuadMesh = DualexMesh<4>;
/// A hex mesh and its main counts (`DualexHexMesh` in C).
pub type DualexHexMesh = DualexMesh<8>;

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

impl<const K: usize> DualexMesh<K> {
    /// A struct holding nothing.
    pub(crate) fn zeroed() -> Self {
        DualexMesh {
            n_vertices: 0,
            positions: ptr::null_mut(),
            n_cells: 0,
            cells: ptr::null_mut(),
            sources: ptr::null_mut(),
            n_components: 0,
            n_boundary_components: 0,
            euler: 0,
            n_singular: 0,
            n_welded_vertices: 0,
            topology_matches: 0,
            sj_min_before: 0.0,
            sj_min_after: 0.0,
            sj_p5_before: 0.0,
            sj_p5_after: 0.0,
            inverted_before: 0,
            inverted_after: 0,
            moved_vertices: 0,
        }
    }

    /// The facade's output handed to C (its arrays leaked, see [`leak`]).
    pub(crate) fn from_output<const D: usize>(r: dualex::Output<K, D>, singular: usize) -> Self {
        let s = &r.stats;
        let g = &s.geometry;
        DualexMesh {
            n_vertices: r.mesh.positions.len(),
            positions: leak(r.mesh.positions.concat()),
            n_cells: r.mesh.cells.len(),
            cells: leak(r.mesh.cells.concat()),
            sources: leak(
                r.sources
                    .iter()
                    .map(|t| t.unwrap_or(DUALEX_NO_SOURCE))
                    .collect(),
            ),
            n_components: s.components,
            n_boundary_components: s.boundary_components,
            euler: s.euler,
            n_singular: singular,
            n_welded_vertices: s.welded_vertices,
            topology_matches: s.topology.matches().into(),
            sj_min_before: g.before.min,
            sj_min_after: g.after.min,
            sj_p5_before: g.before.p5,
            sj_p5_after: g.after.p5,
            inverted_before: g.before.inverted,
            inverted_after: g.after.inverted,
            moved_vertices: g.moved_vertices,
        }
    }

    /// Frees the arrays and zeroes the struct at `mesh`; null and zeroed
    /// structs are ignored.
    ///
    /// # Safety
    /// As [`dualex_quad_mesh_free`].
    unsafe fn free(mesh: *mut Self) {
        if mesh.is_null() || !mesh.is_aligned() {
            return;
        }
        // SAFETY: non-null, aligned, and by the contract filled by this library
        let m = unsafe { &mut *mesh };
        // SAFETY: the arrays were leaked with these lengths (see `leak`)
        unsafe {
            release(m.positions, 3 * m.n_vertices);
            release(m.cells, K * m.n_cells);
            release(m.sources, m.n_cells);
        }
        *m = Self::zeroed();
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
    // SAFETY: the caller's contract above
    unsafe { DualexMesh::free(mesh) }
}

/// Frees the arrays of a hex mesh filled by `dualex_hex_extract` and
/// zeroes it; null and zeroed structs are ignored (freeing twice is safe).
///
/// # Safety
/// As [`dualex_quad_mesh_free`].
#[no_mangle]
pub unsafe extern "C" fn dualex_hex_mesh_free(mesh: *mut DualexHexMesh) {
    // SAFETY: the caller's contract above
    unsafe { DualexMesh::free(mesh) }
}

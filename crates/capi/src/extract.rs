//! The two extraction entry points, shaped like HexHex's
//! `hexhex_extract_simple(n_vertices, vpos, n_tets, tet_vertices, tet_igm)`.
//!
//! Input: flat caller arrays (positions `3·n_vertices` doubles, simplices
//! `3·n` or `4·n` indices, per-corner map coordinates `n·3·2` or `n·4·3`
//! doubles, corner by corner in simplex order), nullable options, and the
//! output struct. Output: a status code; on success the struct owns the
//! mesh (free it with the matching `*_free`), on error it is zeroed and
//! `dualex_last_error()` says why. Each step: check the pointers, build
//! the map through the facade (which validates it), extract (the facade
//! runs the geometric stage too: its quality counts go in the struct),
//! hand over.

use crate::error::{guard, Failure};
use crate::mesh::{leak, DualexHexMesh, DualexOptions, DualexQuadMesh, DUALEX_NO_SOURCE};
use crate::slices::view;
use std::ffi::c_int;

/// The options at `opts`, or the defaults when it is null.
///
/// # Safety
/// `opts` is null or points to a readable `DualexOptions`.
unsafe fn options(opts: *const DualexOptions) -> Result<DualexOptions, Failure> {
    // SAFETY: one item at a nullable pointer, as the caller vouches
    let o: &[DualexOptions] = unsafe { view(opts, usize::from(!opts.is_null()), "opts") }?;
    Ok(o.first().copied().unwrap_or_default())
}

fn flag(x: c_int) -> bool {
    x != 0
}

/// Extracts the quad mesh of a triangle map into `*out`; 0 on success.
///
/// # Safety
/// `vpos` holds `3·n_vertices` doubles, `tri_vertices` `3·n_triangles`
/// indices, `tri_param` `n_triangles·3·2` doubles; `opts` is null or
/// readable; `out` is writable. (Null pointers are reported, not read.)
#[no_mangle]
pub unsafe extern "C" fn dualex_quad_extract(
    n_vertices: usize,
    vpos: *const f64,
    n_triangles: usize,
    tri_vertices: *const u32,
    tri_param: *const f64,
    opts: *const DualexOptions,
    out: *mut DualexQuadMesh,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract above; `view` checks the rest
        let out = unsafe { init(out, DualexQuadMesh::zeroed()) }?;
        // SAFETY: as above
        let (positions, triangles, uv, o) = unsafe {
            (
                view(vpos, n_vertices, "vpos")?,
                view(tri_vertices, n_triangles, "tri_vertices")?,
                view(tri_param, n_triangles, "tri_param")?,
                options(opts)?,
            )
        };
        let map = dualex::tri_map_from_slices(positions, triangles, uv)?;
        let q = dualex::QuadOptions {
            weld: flag(o.weld),
            fairing: flag(o.fairing),
            round_transitions: flag(o.round_transitions),
            grid_offset: o.grid_offset().map_err(Failure::argument)?,
            seed: o.seed,
            strict: flag(o.strict),
            geometry: o.geometry().map_err(Failure::argument)?,
        };
        let r = dualex::quad(&map, &q)?;
        let s = &r.stats;
        *out = DualexQuadMesh {
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
            n_boundary_loops: s.boundary_loops,
            euler: s.euler,
            n_singular_vertices: s.singular_vertices,
            n_welded_vertices: s.welded_vertices,
            topology_matches: s.topology.matches().into(),
            sj_min_before: s.geometry.before.min,
            sj_min_after: s.geometry.after.min,
            sj_p5_before: s.geometry.before.p5,
            sj_p5_after: s.geometry.after.p5,
            inverted_before: s.geometry.before.inverted,
            inverted_after: s.geometry.after.inverted,
            moved_vertices: s.geometry.moved_vertices,
        };
        Ok(())
    })
}

/// Extracts the hex mesh of a tet map into `*out`; 0 on success.
///
/// # Safety
/// `vpos` holds `3·n_vertices` doubles, `tet_vertices` `4·n_tets`
/// indices, `tet_param` `n_tets·4·3` doubles; `opts` is null or
/// readable; `out` is writable. (Null pointers are reported, not read.)
#[no_mangle]
pub unsafe extern "C" fn dualex_hex_extract(
    n_vertices: usize,
    vpos: *const f64,
    n_tets: usize,
    tet_vertices: *const u32,
    tet_param: *const f64,
    opts: *const DualexOptions,
    out: *mut DualexHexMesh,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract above; `view` checks the rest
        let out = unsafe { init(out, DualexHexMesh::zeroed()) }?;
        // SAFETY: as above
        let (positions, tets, uvw, o) = unsafe {
            (
                view(vpos, n_vertices, "vpos")?,
                view(tet_vertices, n_tets, "tet_vertices")?,
                view(tet_param, n_tets, "tet_param")?,
                options(opts)?,
            )
        };
        let map = dualex::tet_map_from_slices(positions, tets, uvw)?;
        let h = dualex::HexOptions {
            weld: flag(o.weld),
            round_transitions: flag(o.round_transitions),
            grid_offset: o.grid_offset().map_err(Failure::argument)?,
            seed: o.seed,
            strict: flag(o.strict),
            geometry: o.geometry().map_err(Failure::argument)?,
        };
        let r = dualex::hex(&map, &h)?;
        let s = &r.stats;
        *out = DualexHexMesh {
            n_vertices: r.mesh.positions.len(),
            positions: leak(r.mesh.positions.concat()),
            n_cells: r.mesh.cells.len(),
            cells: leak(r.mesh.cells.concat()),
            sources: leak(r.sources),
            n_components: s.components,
            n_boundary_surfaces: s.boundary_surfaces,
            euler: s.euler,
            n_singular_edges: s.singular_edges,
            n_welded_vertices: s.welded_vertices,
            topology_matches: s.topology.matches().into(),
            sj_min_before: s.geometry.before.min,
            sj_min_after: s.geometry.after.min,
            sj_p5_before: s.geometry.before.p5,
            sj_p5_after: s.geometry.after.p5,
            inverted_before: s.geometry.before.inverted,
            inverted_after: s.geometry.after.inverted,
            moved_vertices: s.geometry.moved_vertices,
        };
        Ok(())
    })
}

/// The output struct at `out`, first overwritten with `empty` (so that
/// it is zeroed whatever fails next).
///
/// # Safety
/// `out` is null or points to writable memory for one `T`.
unsafe fn init<'a, T>(out: *mut T, empty: T) -> Result<&'a mut T, Failure> {
    if out.is_null() {
        return Err(Failure::argument("out is NULL"));
    }
    if !out.is_aligned() {
        return Err(Failure::argument("out is misaligned"));
    }
    // SAFETY: non-null, aligned, writable by the contract; written before
    // the reference is made, so it never refers to uninitialized memory
    unsafe {
        out.write(empty);
        Ok(&mut *out)
    }
}

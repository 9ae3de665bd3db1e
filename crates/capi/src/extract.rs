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
//! hand over. Both entry points are one template (`extraction_function!`,
//! the C names of each dimension) over one generic [`extract`].

use crate::error::{guard, Failure};
use crate::mesh::{DualexHexMesh, DualexMesh, DualexOptions, DualexQuadMesh};
use crate::slices::view;
use std::ffi::c_int;

/// The options at `opts`, or the defaults when it is null, as the
/// facade's.
///
/// # Safety
/// `opts` is null or points to a readable `DualexOptions`.
unsafe fn options(opts: *const DualexOptions) -> Result<dualex::Options, Failure> {
    // SAFETY: one item at a nullable pointer, as the caller vouches
    let o: &[DualexOptions] = unsafe { view(opts, usize::from(!opts.is_null()), "opts") }?;
    let o = o.first().copied().unwrap_or_default();
    let flag = |x: c_int| x != 0;
    Ok(dualex::Options {
        weld: flag(o.weld),
        fairing: flag(o.fairing),
        round_transitions: flag(o.round_transitions),
        grid_offset: o.grid_offset().map_err(Failure::argument)?,
        seed: o.seed,
        strict: flag(o.strict),
        geometry: o.geometry().map_err(Failure::argument)?,
    })
}

/// The caller's arrays of one extraction: positions (`3·n_vertices`
/// doubles), then `n` simplices of `N` corners (indices, and `D` map
/// coordinates a corner), with their names in messages.
type Arrays = (
    (usize, *const f64),
    (usize, *const u32, *const f64),
    [&'static str; 2],
);

/// The extraction `run` of the map in the caller's arrays into `*out` (one code for
/// both dimensions); 0 on success.
///
/// # Safety
/// The pointers of the arrays, `opts` and `out` as the callers'
/// contracts say.
unsafe fn extract<const N: usize, const D: usize, const K: usize>(
    ((n_vertices, vpos), (n, vertices, param), names): Arrays,
    opts: *const DualexOptions,
    out: *mut DualexMesh<K>,
    run: fn(
        &dualex::map::SimplexMap<N, D>,
        &dualex::Options,
    ) -> Result<dualex::Output<K, D>, dualex::Error>,
    singular: fn(&dualex::Stats) -> usize,
) -> c_int {
    guard(|| {
        // SAFETY: the caller's contract; `view` checks the rest
        let out = unsafe { init(out, DualexMesh::zeroed()) }?;
        // SAFETY: as above
        let (positions, simplices, coords, o) = unsafe {
            (
                view(vpos, n_vertices, "vpos")?,
                view(vertices, n, names[0])?,
                view(param, n, names[1])?,
                options(opts)?,
            )
        };
        let map = dualex::map_from_slices(positions, simplices, coords)?;
        let r = run(&map, &o)?;
        let n_singular = singular(&r.stats);
        *out = DualexMesh::from_output(r, n_singular);
        Ok(())
    })
}

/// `dualex_quad_extract` and `dualex_hex_extract`, one template for both:
/// `$name(n_vertices, vpos, $n, $simplices, $param, opts, out)` with the
/// simplices' and coordinates' names of the dimension (as the C header
/// spells them), the facade's `$run` and the count of `$singular` the
/// struct's `n_singular_*` field holds.
macro_rules! extraction_function {
    ($(#[doc = $doc:literal])* $name:ident($n:ident, $simplices:ident, $param:ident) -> $mesh:ty {
        $run:path, $singular:ident
    }) => {
        $(#[doc = $doc])*
        #[no_mangle]
        pub unsafe extern "C" fn $name(
            n_vertices: usize,
            vpos: *const f64,
            $n: usize,
            $simplices: *const u32,
            $param: *const f64,
            opts: *const DualexOptions,
            out: *mut $mesh,
        ) -> c_int {
            let names = [stringify!($simplices), stringify!($param)];
            let arrays = ((n_vertices, vpos), ($n, $simplices, $param), names);
            // SAFETY: the caller's contract (the doc above)
            unsafe { extract(arrays, opts, out, $run, |s| s.$singular) }
        }
    };
}

extraction_function! {
    /// Extracts the quad mesh of a triangle map into `*out`; 0 on success.
    ///
    /// # Safety
    /// `vpos` holds `3·n_vertices` doubles, `tri_vertices` `3·n_triangles`
    /// indices, `tri_param` `n_triangles·3·2` doubles; `opts` is null or
    /// readable; `out` is writable. (Null pointers are reported, not read.)
    dualex_quad_extract(n_triangles, tri_vertices, tri_param) -> DualexQuadMesh {
        dualex::quad, singular_vertices
    }
}

extraction_function! {
    /// Extracts the hex mesh of a tet map into `*out`; 0 on success.
    ///
    /// # Safety
    /// `vpos` holds `3·n_vertices` doubles, `tet_vertices` `4·n_tets`
    /// indices, `tet_param` `n_tets·4·3` doubles; `opts` is null or
    /// readable; `out` is writable. (Null pointers are reported, not read.)
    dualex_hex_extract(n_tets, tet_vertices, tet_param) -> DualexHexMesh {
        dualex::hex, singular_edges
    }
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

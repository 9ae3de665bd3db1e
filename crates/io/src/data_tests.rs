//! Reads every file of `../shared/data` beside the checkout (listed as
//! ignored with the reason when the folder is absent, see `build.rs`) and
//! checks the counts of its README.

use crate::{read_polygon_obj, read_tet_map, read_tri_map};
use std::path::{Path, PathBuf};

fn data(rel: &str) -> Option<PathBuf> {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data")
        .join(rel);
    if p.exists() {
        Some(p)
    } else {
        eprintln!("notice: {} absent, test skipped", p.display());
        None
    }
}

/// Triangles whose map has negative determinant.
fn flipped<const N: usize, const D: usize>(m: &dualex_map::SimplexMap<N, D>) -> usize {
    (0..m.len()).filter(|&s| m.map_det(s) < 0.0).count()
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn triangle_maps_have_the_readme_counts() {
    let cases = [
        ("qex/fandisk_param.obj", 7229, 14454, 9),
        ("qex/duck_miq_4_param.obj", 9862, 19720, 18),
        ("qex/duck_miq_8_param.obj", 9862, 19720, 92),
        ("directional/spherer-param.obj", 691, 1280, 0),
        ("directional/decimated-knight-param.obj", 691, 1000, 3),
        (
            "directional/dragon-param-full-seamless.obj",
            14485,
            24984,
            549,
        ),
        ("directional/horsers-param-full-seamless.obj", 3236, 6000, 0),
        ("directional/lilium-param.obj", 3473, 6590, 0),
    ];
    for (rel, v, t, f) in cases {
        let Some(p) = data(rel) else { continue };
        let m = read_tri_map(&p).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            (m.positions.len(), m.len(), flipped(&m)),
            (v, t, f),
            "{rel}"
        );
    }
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn reference_quad_meshes_are_closed_quad_meshes() {
    for (rel, quads) in [
        ("qex/fandisk_quad.obj", 897),
        ("qex/duck_miq_4_quad.obj", 1073),
        ("qex/duck_miq_8_quad.obj", 267),
    ] {
        let Some(p) = data(rel) else { continue };
        let m = read_polygon_obj(&p).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.faces.len(), quads, "{rel}");
        assert!(m.faces.iter().all(|f| f.len() == 4), "{rel}");
        // closed genus-0 quad mesh: V - E + F = 2 with E = 2F
        assert_eq!(m.positions.len(), quads + 2, "{rel}");
    }
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn tet_maps_have_the_readme_counts() {
    let cases = [
        ("hexex/hand_q.hexex", 11472),
        ("hexex/fancy_ring_q.hexex", 14640),
        ("hexex/rockerarm_q.hexex", 20988),
        ("hexex/fancy_ring.hexex", 14640),
        ("hexex/minimal.hexex", 5),
        ("hexex/minimal_invalid_charts.hexex", 5),
    ];
    for (rel, t) in cases {
        let Some(p) = data(rel) else { continue };
        let m = read_tet_map(&p).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.len(), t, "{rel}");
    }
    if let Some(p) = data("hexex/sphere.hexex") {
        let m = read_tet_map(&p).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((m.positions.len(), m.len()), (41, 76));
        // "2 degenerate tets" in the README: zero map volume
        assert_eq!((0..m.len()).filter(|&s| m.map_det(s) == 0.0).count(), 2);
    }
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn broken_minimal_files_fail_cleanly() {
    let cases = [
        (
            "hexex/minimal_missing_tets.hexex",
            "line 14: file ends in tet 4: expected 4 vertex indices, found 0",
        ),
        (
            "hexex/minimal_missing_uvw.hexex",
            "line 14: tet 3: corner 1: vertex index `0.0` is not a non-negative integer",
        ),
        (
            "hexex/minimal_missing_vertices.hexex",
            "line 10: tet 0: corner 1: vertex index `0.0` is not a non-negative integer",
        ),
    ];
    for (rel, want) in cases {
        let Some(p) = data(rel) else { continue };
        let e = read_tet_map(&p).unwrap_err().to_string();
        assert!(
            e.starts_with(&format!("{}: {want}", p.display())),
            "{rel}: {e}"
        );
        assert!(!e.contains('\n'));
    }
}

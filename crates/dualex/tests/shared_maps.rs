//! The facade on real maps of `../shared/data` (beside the checkout; listed
//! as ignored with the reason when absent, see `build.rs`): welding by
//! default is what makes Directional's cut dragon one closed mesh.

use std::path::{Path, PathBuf};

fn data(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data")
        .join(rel)
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn the_dragon_is_welded_by_default() {
    let map = dualex::read_tri_map(data("directional/dragon-param-full-seamless.obj")).unwrap();
    let out = dualex::quad(&map, &dualex::Options::default()).unwrap();
    let s = &out.stats;
    assert!(s.welded_vertices > 0);
    // 5077 quads whatever the order of the triangles (fairing breaks its
    // ties without node numbers; 5084 before, other orders gave 5072 …
    // 5084), and L × 5077 hexes from the map extruded (tests/extrude.rs)
    assert_eq!(
        (s.cells, s.components, s.euler, s.boundary_components),
        (5077, 1, 2, 0)
    );
    assert!(s.topology.matches());
    // split edges (knight, dragon) keep the input's triangle numbers
    assert_eq!(out.sources.len(), s.cells);
    assert!(out
        .sources
        .iter()
        .all(|t| t.is_some_and(|t| (t as usize) < map.len())));
    let apart = dualex::Options {
        weld: false,
        ..Default::default()
    };
    // not welded, the charts come apart: many pieces (46 before lone nodes
    // of charts narrower than a grid cell were deleted as slivers, 12 now),
    // and the output's shape is not the input's
    let out = dualex::quad(&map, &apart).unwrap();
    assert!(out.stats.components > 1, "{}", out.stats.components);
    assert!(!out.stats.topology.matches());
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn hexex_hand_gives_the_reference_count() {
    let map = dualex::read_tet_map(data("hexex/hand_q.hexex")).unwrap();
    let out = dualex::hex(&map, &dualex::Options::default()).unwrap();
    assert_eq!(out.stats.cells, 956);
    assert_eq!(out.stats.components, 1);
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn repaired_quads_name_their_parents_triangle() {
    let map = dualex::read_tri_map(data("directional/horsers-param-full-seamless.obj")).unwrap();
    let out = dualex::quad(&map, &dualex::Options::default()).unwrap();
    // its faces that quads cannot represent are repaired locally
    assert!(!out.stats.repairs.subdivided);
    assert_eq!(out.sources.len(), out.stats.cells);
    let known = out.sources.iter().flatten().count();
    assert!(out
        .sources
        .iter()
        .flatten()
        .all(|&t| (t as usize) < map.len()));
    // only the faces closing holes (a k-gon, plus at most one point of a
    // repair path: ⌈k/2⌉ quads) have no node
    let holes = out.stats.repairs.holes_filled;
    let unknown = out.stats.cells - known;
    assert!(
        holes > 0 && unknown >= holes && unknown <= 6 * holes,
        "{unknown} quads without a node, {holes} holes"
    );
}

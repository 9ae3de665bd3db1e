//! The geometric stage through the facade, on messy generated maps
//! (`dualex_gen::from_mesh` with noise 0.6 and folds): the default
//! untangles every inverted element, `GeometryMode::Off` keeps the map's
//! positions (and its inverted elements), `strict` refuses what is left,
//! smoothing does not lower the 5th percentile.

use crate::*;
use dualex_gen::from_mesh::{self, meshes, FromMeshOptions};

/// Noise 0.6 and folds on a mesh refined `scale` times.
fn messy(scale: usize, seed: u64) -> FromMeshOptions {
    FromMeshOptions {
        scale,
        noise: 0.6,
        folds: true,
        seed,
        ..Default::default()
    }
}

/// A noisy map of a quad mesh of `dualex_gen` refined `k` times.
fn messy_tri_map(name: &str, k: usize, seed: u64) -> TriMap {
    let mesh = meshes::quad_mesh_by_name(name).expect("a generated quad mesh");
    from_mesh::from_quads(&mesh, &messy(k, seed))
        .expect("a map")
        .map
}

/// A noisy map of a hex mesh of `dualex_gen` refined `k` times.
fn messy_tet_map(name: &str, k: usize, seed: u64) -> TetMap {
    let mesh = meshes::hex_mesh_by_name(name).expect("a generated hex mesh");
    from_mesh::from_hexes(&mesh, &messy(k, seed))
        .expect("a map")
        .map
}

fn geometry(mode: GeometryMode) -> GeometryOptions {
    GeometryOptions {
        mode,
        ..Default::default()
    }
}

/// A 36-quad disk around a valence-4 centre whose noisy map places some
/// quads inverted.
fn messy_disk() -> TriMap {
    messy_tri_map("ngon4", 3, 2)
}

/// `run` ([`quad()`], [`hex()`]) on `map` by default and with the
/// geometric stage off: the same extraction (cells, quality before); off
/// measures only and leaves the inverted elements, the default untangles
/// them by moving some vertices.
fn auto_and_off<M, const K: usize, const D: usize>(
    map: &M,
    run: fn(&M, &Options) -> Result<Output<K, D>, Error>,
) -> (Output<K, D>, Output<K, D>) {
    let auto = run(map, &Options::default()).unwrap();
    let off_opts = Options {
        geometry: geometry(GeometryMode::Off),
        ..Default::default()
    };
    let off = run(map, &off_opts).unwrap();
    let (a, o) = (&auto.stats.geometry, &off.stats.geometry);
    // the same extraction: the same cells, the same quality before
    assert_eq!(auto.mesh.cells, off.mesh.cells);
    assert_eq!(a.before, o.before);
    assert_eq!(a.before.elements, auto.mesh.cells.len());
    assert!(o.before.inverted > 0, "{o:?}");
    // off: measured only, nothing moved
    assert_eq!((o.mode, o.moved_vertices, o.max_move), ("off", 0, 0.0));
    assert_eq!(o.after, o.before);
    // auto: every inverted element untangled, by moving some vertices
    assert_eq!(a.after.inverted, 0, "{a:?}");
    assert!(a.moved_vertices > 0, "{a:?}");
    (auto, off)
}

#[test]
fn quads_the_default_untangles_what_off_leaves_inverted() {
    let (auto, off) = auto_and_off(&messy_disk(), quad);
    let (a, o) = (&auto.stats.geometry, &off.stats.geometry);
    assert_eq!(a.mode, "auto");
    assert!(a.after.min > 0.0, "{a:?}");
    assert!(a.moved_vertices <= auto.mesh.positions.len());
    let moved = auto
        .mesh
        .positions
        .iter()
        .zip(&off.mesh.positions)
        .filter(|(p, q)| p != q)
        .count();
    assert_eq!(moved, a.moved_vertices);
    // the JSON is the CLI's section
    let j = a.to_json();
    assert_eq!(j["after"]["inverted"], 0);
    assert_eq!(j["before"]["inverted"], o.before.inverted);
}

#[test]
fn quads_strict_refuses_inverted_quads_left() {
    let map = messy_disk();
    let strict_off = Options {
        strict: true,
        geometry: geometry(GeometryMode::Off),
        ..Default::default()
    };
    let off = quad(
        &map,
        &Options {
            strict: false,
            ..strict_off.clone()
        },
    )
    .unwrap();
    let left = off.stats.geometry.after.inverted;
    assert!(left > 0);
    match quad(&map, &strict_off) {
        Err(Error::InvertedElements { count }) => assert_eq!(count, left),
        other => panic!("expected InvertedElements, got {other:?}"),
    }
    let message = Error::InvertedElements { count: left }.to_string();
    assert_eq!(
        message,
        format!("{left} inverted elements (scaled Jacobian ≤ 0) remain after the geometric stage")
    );
    assert_eq!(
        Error::InvertedElements { count: 1 }.to_string(),
        "1 inverted element (scaled Jacobian ≤ 0) remains after the geometric stage"
    );
    // untangled by default: strict passes
    let strict = Options {
        strict: true,
        ..Default::default()
    };
    let out = quad(&map, &strict).unwrap();
    assert_eq!(out.stats.geometry.after.inverted, 0);
}

#[test]
fn quads_smoothing_raises_the_low_percentile() {
    let map = messy_disk();
    let smooth = Options {
        geometry: geometry(GeometryMode::Smooth(5)),
        ..Default::default()
    };
    let out = quad(&map, &smooth).unwrap();
    let g = &out.stats.geometry;
    assert_eq!(g.mode, "smooth");
    assert!(g.rounds >= 1 && g.rounds <= 5, "{g:?}");
    assert!(g.after.p5 >= g.before.p5, "{g:?}");
    assert_eq!(g.after.inverted, 0, "{g:?}");
}

#[test]
fn a_clean_map_is_left_as_placed() {
    // a 4 × 4 grid mapped onto [0, 8]²: squares, on the boundary already
    let p: Vec<[f64; 3]> = (0..25)
        .map(|i| [(i % 5) as f64, (i / 5) as f64, 0.0])
        .collect();
    let mut t = Vec::new();
    for j in 0..4u32 {
        for i in 0..4u32 {
            let v = j * 5 + i;
            t.push([v, v + 1, v + 6]);
            t.push([v, v + 6, v + 5]);
        }
    }
    let uv: Vec<[[f64; 2]; 3]> = t
        .iter()
        .map(|s: &[u32; 3]| s.map(|v| [2.0 * p[v as usize][0], 2.0 * p[v as usize][1]]))
        .collect();
    let map = tri_map_from_slices(&p, &t, &uv).unwrap();
    let out = quad(&map, &Options::default()).unwrap();
    let g = &out.stats.geometry;
    assert_eq!(g.before.elements, 64);
    assert_eq!(
        (g.before.inverted, g.after.inverted, g.moved_vertices),
        (0, 0, 0)
    );
    assert_eq!(g.after, g.before);
    assert!((g.after.min - 1.0).abs() < 1e-9, "{g:?}");
}

#[test]
fn hexes_the_default_untangles_what_off_leaves_inverted() {
    // 96 hexes around an interior axis of valence 6
    let map = messy_tet_map("cylinder6", 2, 1);
    let (_, off) = auto_and_off(&map, hex);
    let strict_off = Options {
        strict: true,
        geometry: geometry(GeometryMode::Off),
        ..Default::default()
    };
    match hex(&map, &strict_off) {
        Err(Error::InvertedElements { count }) => {
            assert_eq!(count, off.stats.geometry.before.inverted)
        }
        other => panic!("expected InvertedElements, got {other:?}"),
    }
}

//! OpenVolumeMesh `.ovm` through the public readers and writers: a shared
//! HexEx map converted `.hexex` → `.ovm` (HexHex's
//! `HexHex::Parametrization`, the parameter of the opposite vertex per
//! halfface) reads back as the same map and extracts the same hexes
//! (listed as ignored with the reason when `../shared/data` is absent,
//! see `build.rs`); hex meshes written as `.ovm` share their faces.

use std::path::{Path, PathBuf};

fn data(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data")
        .join(rel)
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("dualex-ovm-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("create the scratch folder");
    d
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn hexex_to_ovm_keeps_the_map_and_the_hexes() {
    let dir = scratch("hand");
    let hexex = dualex::read_tet_map(data("hexex/hand_q.hexex")).expect("read hand_q");
    let ovm = dir.join("hand_q.ovm");
    dualex_io::write_tet_map(&ovm, &hexex).expect("write hand_q.ovm");
    let back = dualex::read_tet_map(&ovm).expect("read hand_q.ovm");
    // the same tets, each corner with its map value; a tet whose first
    // face was written by a neighbour starts at another corner of that face
    assert_eq!(back.positions, hexex.positions);
    assert_eq!(back.len(), hexex.len());
    for (t, (a, b)) in normalized(&hexex).zip(normalized(&back)).enumerate() {
        assert_eq!(a, b, "tet {t}");
    }
    let opts = dualex::Options::default();
    let a = dualex::hex(&hexex, &opts).expect("extract from .hexex");
    let b = dualex::hex(&back, &opts).expect("extract from .ovm");
    assert_eq!(b.stats.cells, 956);
    let shape = |s: &dualex::Stats| {
        (
            s.cells,
            s.vertices,
            s.components,
            s.euler,
            s.boundary_facets,
        )
    };
    assert_eq!(shape(&a.stats), shape(&b.stats));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Each tet as (corner, map value) pairs, its first three corners rotated
/// to start at the smallest vertex (the same tet, the same orientation).
fn normalized(map: &dualex::TetMap) -> impl Iterator<Item = Vec<(u32, [u64; 3])>> + '_ {
    map.simplices.iter().zip(&map.coords).map(|(t, c)| {
        let mut corners: Vec<(u32, [u64; 3])> =
            (0..4).map(|k| (t[k], c[k].map(f64::to_bits))).collect();
        let first = (0..3).min_by_key(|&k| t[k]).unwrap_or(0);
        corners[..3].rotate_left(first);
        corners
    })
}

#[test]
fn hex_meshes_are_written_with_shared_faces() {
    // a unit cube of 6 tets mapped onto [0, 2]³: 2×2×2 hexes
    let positions: Vec<[f64; 3]> = (0..8)
        .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64])
        .collect();
    let tets = [
        [0, 1, 3, 7],
        [0, 3, 2, 7],
        [0, 2, 6, 7],
        [0, 6, 4, 7],
        [0, 4, 5, 7],
        [0, 5, 1, 7],
    ];
    let uvw: Vec<[[f64; 3]; 4]> = tets
        .iter()
        .map(|t| t.map(|v: u32| positions[v as usize].map(|x| 2.0 * x)))
        .collect();
    let map = dualex::tet_map_from_slices(&positions, &tets, &uvw).expect("the map");
    let out = dualex::hex(&map, &dualex::Options::default()).expect("extract");
    let dir = scratch("cube");
    let path = dir.join("cube.ovm");
    dualex::write_hex_mesh(&path, &out.mesh).expect("write cube.ovm");
    let text = std::fs::read_to_string(&path).expect("read cube.ovm");
    // 27 vertices, 54 edges, 36 faces, 8 cells of 6 halffaces
    for section in [
        "Vertices\n27\n",
        "Edges\n54\n",
        "Faces\n36\n",
        "Polyhedra\n8\n",
    ] {
        assert!(text.contains(section), "no {section:?} in\n{text}");
    }
    let cells: Vec<Vec<usize>> = text
        .split("Polyhedra\n8\n")
        .nth(1)
        .unwrap_or_default()
        .lines()
        .map(|l| {
            l.split_whitespace()
                .filter_map(|t| t.parse().ok())
                .collect()
        })
        .collect();
    assert_eq!(cells.len(), 8);
    // every inner face is used once per orientation, boundary faces once
    let mut used = std::collections::HashMap::<usize, usize>::new();
    for c in &cells {
        assert_eq!(c.len(), 7);
        for &hf in &c[1..] {
            *used.entry(hf).or_default() += 1;
        }
    }
    assert!(used.values().all(|&n| n == 1));
    let inner = (0..36).filter(|f| used.contains_key(&(2 * f)) && used.contains_key(&(2 * f + 1)));
    assert_eq!(inner.count(), 12);
    let _ = std::fs::remove_dir_all(&dir);
}

use super::*;

/// `quads` stacked into `layers` layers of hexes (vertex `v` of level `l`
/// is `v + l·nv`), and the lateral faces over the edges `open` (pairs of
/// level-0 vertices) in every layer.
fn stack(
    positions: &[[f64; 3]],
    quads: &[[u32; 4]],
    open: &[(u32, u32)],
    layers: u32,
) -> (HexMesh, Vec<[u32; 4]>) {
    let nv = positions.len() as u32;
    let mut mesh = HexMesh::default();
    for l in 0..=layers {
        mesh.positions
            .extend(positions.iter().map(|p| [p[0], p[1], f64::from(l)]));
    }
    let mut faces = Vec::new();
    for l in 0..layers {
        for q in quads {
            let h = std::array::from_fn(|i| q[i % 4] + (l + i as u32 / 4) * nv);
            mesh.cells.push(h);
        }
        for &(a, b) in open {
            faces.push([a + l * nv, b + l * nv, b + (l + 1) * nv, a + (l + 1) * nv]);
        }
    }
    (mesh, faces)
}

/// A triangular hole `0, 1, 2` in a ring of three quads whose outside is
/// the triangle `3, 4, 5` (the input's boundary).
fn ring() -> (Vec<[f64; 3]>, Vec<[u32; 4]>) {
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.5, 0.8, 0.0],
        [-1.0, -0.6, 0.0],
        [2.0, -0.6, 0.0],
        [0.5, 2.0, 0.0],
    ];
    let quads = vec![[0, 3, 4, 1], [1, 4, 5, 2], [2, 5, 3, 0]];
    (positions, quads)
}

fn check(m: &HexMesh) -> dualex_check::HexReport {
    let r = dualex_check::check_hex_mesh(m.positions.len(), &m.cells, None);
    assert!(r.is_valid(), "{:?}", r.errors());
    r
}

/// The hole column is paired with the boundary (no other odd column): in
/// every layer the hole becomes a hex, the crossed column's hex is split
/// in two, and the boundary gets a point — exactly the 2D repair of one
/// layer, L times (5 quads → 5·L hexes), valid.
#[test]
fn a_triangular_hole_through_all_layers_is_repaired_as_in_2d() {
    let (positions, quads) = ring();
    let flat = QuadMesh {
        positions: positions.clone(),
        cells: quads.clone(),
    };
    let hole = [vec![0, 2, 1]];
    let want = dualex_cells::repair_local::repair(&flat, &hole).expect("2D repair");
    assert_eq!((want.mesh.cells.len(), want.paths), (5, 1));
    for layers in [1, 3] {
        let (m, open) = stack(&positions, &quads, &[(0, 1), (1, 2), (2, 0)], layers);
        let before = check(&m);
        assert_eq!(before.boundary_faces, 6 + 6 * layers as usize);
        let rep = repair(&m, &open).expect("columns");
        assert_eq!(
            rep.report,
            ColumnRepair {
                holes: 1,
                paths: 1,
                split: 1,
                layers: layers as usize,
            }
        );
        assert_eq!(rep.mesh.cells.len(), 5 * layers as usize);
        assert_eq!(rep.origin.len(), rep.mesh.cells.len());
        // V: 6 + 2 new points per level
        assert_eq!(rep.mesh.positions.len(), 8 * (layers as usize + 1));
        let after = check(&rep.mesh);
        // 2·5 caps, 4 outer sides per layer (the boundary edge split)
        assert_eq!(after.boundary_faces, 10 + 4 * layers as usize);
        // every new point of level k lies at its level
        for h in &rep.mesh.cells {
            for i in 0..4 {
                let (lo, hi) = (h[i] as usize, h[i + 4] as usize);
                let dz = rep.mesh.positions[hi][2] - rep.mesh.positions[lo][2];
                assert!((dz - 1.0).abs() < 1e-12, "{h:?}");
            }
        }
    }
}

/// Not columns, or not lateral open faces: nothing is returned.
#[test]
fn preconditions_are_checked_first() {
    let (positions, quads) = ring();
    let (mut m, open) = stack(&positions, &quads, &[(0, 1), (1, 2), (2, 0)], 2);
    // a cap face is not a lateral face
    let cap = [vec![
        m.cells[0][0],
        m.cells[0][1],
        m.cells[0][2],
        m.cells[0][3],
    ]];
    let cap: Vec<[u32; 4]> = cap.iter().map(|c| [c[0], c[1], c[2], c[3]]).collect();
    assert!(repair(&m, &cap).is_none());
    // only one layer's faces of the hole: not L per edge
    assert!(repair(&m, &open[..3]).is_none());
    // a hex removed: stacks of different heights
    m.cells.pop();
    assert!(Columns::find(&m).is_none());
    assert!(repair(&m, &open).is_none());
    // a repeated corner
    let (mut m, open) = stack(&positions, &quads, &[(0, 1), (1, 2), (2, 0)], 1);
    m.cells[0][1] = m.cells[0][0];
    assert!(repair(&m, &open).is_none());
}

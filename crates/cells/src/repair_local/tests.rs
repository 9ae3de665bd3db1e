use super::*;

/// A 1×4 strip whose two end cells are triangles (a cell with a repeated
/// corner): one path through the two quads between them, straight; every
/// cell a quad afterwards, valid, Euler kept.
#[test]
fn two_triangles_joined_by_a_straight_path() {
    // bottom 0..=4, top 5..=9; the end cells collapse one side each
    let mut m = QuadMesh::default();
    for j in 0..2 {
        for i in 0..5 {
            m.positions.push([i as f64, j as f64, 0.0]);
        }
    }
    m.cells = vec![[0, 1, 6, 6], [1, 2, 7, 6], [2, 3, 8, 7], [3, 4, 8, 8]];
    let before = dualex_check::check_quad_mesh(m.positions.len(), &m.cells);
    let Local {
        mesh: out,
        paths,
        origin,
        new_points,
    } = repair(&m, &[]).expect("repaired");
    assert_eq!(paths, 1);
    assert_eq!(origin, [0, 1, 1, 2, 2, 3]);
    // the 3 edge points, each the mean of its edge's ends
    assert_eq!(new_points, [vec![1, 6], vec![2, 7], vec![3, 8]]);
    let after = dualex_check::check_quad_mesh(out.positions.len(), &out.cells);
    assert!(after.is_valid(), "{:?}", after.errors());
    assert_eq!(after.euler, before.euler);
    // 2 end quads + 2 × 2 split quads; 3 new edge points
    assert_eq!((out.cells.len(), out.positions.len()), (6, 13));
}

/// A triangle next to the boundary pairs with the boundary: one point on
/// the boundary edge.
#[test]
fn a_triangle_pairs_with_the_boundary() {
    let m = QuadMesh {
        positions: vec![[0.0; 3]; 5],
        cells: vec![[0, 1, 2, 2], [1, 3, 4, 2]],
    };
    let Local {
        mesh: out, paths, ..
    } = repair(&m, &[]).expect("repaired");
    assert_eq!(paths, 1);
    let r = dualex_check::check_quad_mesh(out.positions.len(), &out.cells);
    assert!(r.is_valid(), "{:?}", r.errors());
    assert_eq!(out.cells.len(), 2);
}

/// An even hole polygon (a hexagon) becomes two quads without any path.
#[test]
fn a_hexagon_is_split() {
    let m = QuadMesh {
        positions: vec![[0.0; 3]; 6],
        cells: vec![],
    };
    let Local {
        mesh: out, paths, ..
    } = repair(&m, &[vec![0, 1, 2, 3, 4, 5]]).expect("repaired");
    assert_eq!(paths, 0);
    assert_eq!(out.cells, vec![[0, 1, 2, 3], [0, 3, 4, 5]]);
}

/// The choice of paths does not depend on the order of the faces or the
/// numbering of the vertices (an extruded hex mesh's layer is the same
/// mesh numbered differently): the strip's cells in reverse order, and
/// its vertices renumbered, give the same counts and valences.
#[test]
fn the_repair_does_not_depend_on_the_numbering() {
    let mut m = QuadMesh::default();
    for j in 0..2 {
        for i in 0..7 {
            m.positions.push([i as f64, j as f64, 0.0]);
        }
    }
    // a longer strip with a triangle at each end
    m.cells = vec![
        [0, 1, 8, 8],
        [1, 2, 9, 8],
        [2, 3, 10, 9],
        [3, 4, 11, 10],
        [4, 5, 12, 11],
        [5, 6, 12, 12],
    ];
    let counts = |m: &QuadMesh| {
        let l = repair(m, &[]).expect("repaired");
        let r = dualex_check::check_quad_mesh(l.mesh.positions.len(), &l.mesh.cells);
        assert!(r.is_valid(), "{:?}", r.errors());
        (
            l.mesh.cells.len(),
            l.paths,
            r.interior_valence.clone(),
            r.euler,
        )
    };
    let want = counts(&m);
    let mut reversed = m.clone();
    reversed.cells.reverse();
    assert_eq!(counts(&reversed), want);
    let n = m.positions.len() as u32;
    let mut renumbered = m.clone();
    for c in &mut renumbered.cells {
        *c = c.map(|v| n - 1 - v);
    }
    renumbered.positions.reverse();
    assert_eq!(counts(&renumbered), want);
}

/// The fan of a hexagon starts where it leaves no corner of valence ≤ 2
/// if it can: corner 1 and 4 have one edge less than the others.
#[test]
fn a_hexagon_is_fanned_from_its_lowest_corners() {
    // degrees of the hexagon's corners 0..6: 3, 2, 3, 3, 2, 3
    let degree = [3, 2, 3, 3, 2, 3];
    let p: Vec<u32> = (0..6).collect();
    let r = fan_corner(&p, &degree);
    assert!(r == 1 || r == 4, "{r}");
}

//! Nodes in both dimensions: the points strictly inside, in order; the
//! size check naming the largest simplex.

use super::*;

fn one_triangle(p: [[f64; 2]; 3]) -> SimplexMap<3, 2> {
    SimplexMap {
        positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        simplices: vec![[0, 1, 2]],
        coords: vec![p],
    }
}

fn one_tet(p: [[f64; 3]; 4]) -> SimplexMap<4, 3> {
    SimplexMap {
        positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        simplices: vec![[0, 1, 2, 3]],
        coords: vec![p],
    }
}

const UNIT: [[f64; 3]; 4] = [[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// A local map of one simplex with the image `p` (as is, not shifted).
fn local_of<const N: usize, const D: usize>(p: [[f64; D]; N]) -> LocalMap<N, D> {
    let mut local = crate::testmap::local_of(&SimplexMap {
        positions: vec![[0.0; 3]; N],
        simplices: vec![std::array::from_fn(|c| c as u32)],
        coords: vec![p],
    })
    .2;
    local.coords[0] = p;
    local
}

#[test]
fn nodes_are_the_points_strictly_inside_in_lexicographic_order() {
    // a triangle over (0,0), (3,0), (0,3), shifted off the grid points
    let local = local_of([[-0.1, -0.2], [3.3, -0.2], [-0.1, 3.2]]);
    let nodes = Nodes::find(&local);
    let want: Vec<[i64; 2]> = (0..4)
        .flat_map(|i| (0..4 - i).map(move |j| [i, j]))
        .collect();
    assert_eq!(want.len(), 10);
    assert_eq!(nodes.point, want);
    assert_eq!(nodes.of_simplex(0), 0..want.len());
    for (w, x) in nodes.bary.iter().zip(&nodes.point) {
        assert!(w.iter().all(|&v| v > 0.0), "{x:?}: {w:?}");
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-12);
    }
    assert!(nodes.reverted.iter().all(|&r| !r));
    // the mirrored triangle: the same points, reverted
    let local = local_of([[-0.1, -0.2], [-0.1, 3.2], [3.3, -0.2]]);
    let mirrored = Nodes::find(&local);
    assert_eq!(mirrored.point, want);
    assert!(mirrored.reverted.iter().all(|&r| r));
}

#[test]
fn a_tet_holds_the_points_of_its_corner_and_a_flat_one_none() {
    let p = UNIT.map(|c| c.map(|x| x * 2.9 - 0.1));
    let nodes = Nodes::find(&local_of(p));
    let mut want = vec![];
    for i in 0..3i64 {
        for j in 0..3i64 {
            for k in 0..3i64 {
                if i + j + k <= 2 {
                    want.push([i, j, k]);
                }
            }
        }
    }
    assert_eq!(nodes.point, want);
    assert_eq!(nodes.len(), nodes.bary.len());
    let flat = [p[0], p[1], p[2], [0.7, 0.7, -0.1]];
    assert!(Nodes::find(&local_of(flat)).is_empty());
}

#[test]
fn the_estimate_is_the_boxes_grid_points() {
    let m = one_triangle([[0.5, 0.5], [3.5, 0.5], [0.5, 2.5]]);
    assert_eq!(check_size(&m), Ok(4.0 * 3.0));
    let m = one_tet([[0.5; 3], [3.5, 0.5, 0.5], [0.5, 2.5, 0.5], [0.5, 0.5, 1.5]]);
    assert_eq!(check_size(&m), Ok(4.0 * 3.0 * 2.0));
}

#[test]
fn an_absurd_map_is_refused_naming_its_largest_triangle() {
    let mut m = one_triangle([[0.0, 0.0], [1e9, 0.0], [0.0, 1e9]]);
    m.simplices.push([0, 1, 2]);
    m.coords.insert(0, [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    let e = check_size(&m).err().unwrap_or_else(|| panic!("accepted"));
    assert_eq!(e.element(), Some(&dualex_map::ElementKind::Triangle.at(1)));
    assert!(
        e.to_string().starts_with("triangle 1: map too large"),
        "{e}"
    );
    let nan = one_triangle([[0.0, 0.0], [f64::INFINITY, 0.0], [0.0, 1.0]]);
    assert!(check_size(&nan).is_err());
}

#[test]
fn an_absurd_map_is_refused_naming_its_largest_tet() {
    let mut m = one_tet(UNIT.map(|c| c.map(|x| x * 1e6)));
    m.simplices.push([0, 1, 2, 3]);
    m.coords.insert(0, UNIT);
    let e = check_size(&m).err().unwrap_or_else(|| panic!("accepted"));
    assert_eq!(e.element(), Some(&dualex_map::ElementKind::Tet.at(1)));
    assert!(e.to_string().starts_with("tet 1: map too large"), "{e}");
}

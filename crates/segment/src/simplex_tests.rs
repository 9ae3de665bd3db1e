//! The predicates in both dimensions: weights summing to `det` and
//! vanishing on facets, axis lines piercing two facets.

use super::*;

const TRI: [[f64; 2]; 3] = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
const TET: [[f64; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
];

#[test]
fn weights_sum_to_det_and_vanish_on_faces() {
    let q = [0.1, 0.2, 0.3];
    let w = Dim::<4, 3>::bary_weights(&TET, &q);
    let det = dualex_map::mesh::det_of::<4, 3>(&TET);
    assert!((w.iter().sum::<f64>() - det).abs() < 1e-15);
    assert!((w[1] - 0.1).abs() < 1e-15 && (w[2] - 0.2).abs() < 1e-15);
    assert!((w[3] - 0.3).abs() < 1e-15 && (w[0] - 0.4).abs() < 1e-15);
    let w = Dim::<3, 2>::bary_weights(&TRI, &[0.25, 0.5]);
    let det = dualex_map::mesh::det_of::<3, 2>(&TRI);
    assert!((w.iter().sum::<f64>() - det).abs() < 1e-15);
    assert!((w[0] - 0.25).abs() < 1e-15 && (w[1] - 0.25).abs() < 1e-15);
    assert!((w[2] - 0.5).abs() < 1e-15);
    // on an edge: that edge's weight vanishes
    assert_eq!(Dim::<3, 2>::bary_weights(&TRI, &[0.5, 0.0])[2], 0.0);
}

fn line<const D: usize>(axis: usize, val: [i64; D]) -> Line<D> {
    Line {
        axis,
        sgn: 1.0,
        val,
    }
}

#[test]
fn axis_line_pierces_two_faces_in_every_direction() {
    // a tet shifted so no line below hits an edge
    let p = TET.map(|c| [c[0] * 4.0 - 0.3, c[1] * 4.0 - 0.2, c[2] * 4.0 - 0.1]);
    for a in 0..3 {
        let (hits, n) = Dim::<4, 3>::pierced(&p, &line(a, [0, 0, 0]));
        assert_eq!(n, 2, "axis {a}");
        // the two points are on the line through the origin, inside the tet
        let (lo, hi) = (hits[0].at.min(hits[1].at), hits[0].at.max(hits[1].at));
        assert!(lo < 0.0 && hi > 0.0, "axis {a}: {hits:?}");
    }
    // a mirrored tet gives the same faces
    let mut m = p;
    m.swap(0, 1);
    assert_eq!(Dim::<4, 3>::pierced(&m, &line(0, [0, 0, 0])).1, 2);
    // a line outside the tet pierces nothing
    assert_eq!(Dim::<4, 3>::pierced(&p, &line(2, [5, 5, 0])).1, 0);
}

#[test]
fn iso_line_crosses_two_edges_of_a_triangle() {
    let p = TRI.map(|c| [c[0] * 4.0 - 0.3, c[1] * 4.0 - 0.2]);
    for a in 0..2 {
        let (hits, n) = Dim::<3, 2>::pierced(&p, &line(a, [0, 0]));
        assert_eq!(n, 2, "axis {a}");
        let (lo, hi) = (hits[0].at.min(hits[1].at), hits[0].at.max(hits[1].at));
        assert!(lo < 0.0 && hi > 0.0, "axis {a}: {hits:?}");
        assert!(hits[..n].iter().all(|h| !h.at_corner));
    }
    assert_eq!(Dim::<3, 2>::pierced(&p, &line(0, [0, 7])).1, 0);
    // an iso through corners is flagged
    let (hits, n) = Dim::<3, 2>::pierced(&TRI, &line(0, [0, 0]));
    assert!(n == 2 && hits[..n].iter().all(|h| h.at_corner), "{hits:?}");
}

#[test]
fn every_sign_pattern_of_a_triangle_gives_zero_or_two_crossings() {
    // the corners' fixed coordinates below, on or above the iso y = 0
    for code in 0..27 {
        let ys = [code % 3, code / 3 % 3, code / 9].map(|c| c as f64 - 1.0);
        let p = [[0.0, ys[0]], [1.0, ys[1]], [0.5, ys[2]]];
        let n = Dim::<3, 2>::pierced(&p, &line(0, [0, 0])).1;
        assert!(n == 0 || n == 2, "case {code}: {ys:?} gives {n}");
    }
}

use super::*;
use crate::testing::{gp_residual, interior_edges, position_det, reverted_fraction};

fn both() -> [Diagonal; 2] {
    [Diagonal::Fixed, Diagonal::Alternating]
}

#[test]
fn identity_counts_and_orientation() {
    for d in both() {
        let (m, e) = square_identity(6, 0.2, 7.2, d);
        assert!(m.validate().is_ok());
        assert_eq!((m.positions.len(), m.len()), (49, 72));
        assert_eq!(interior_edges(&m).len(), 3 * 36 - 2 * 6);
        assert!((0..m.len()).all(|s| position_det(&m, s) > 0.0 && m.map_det(s) > 0.0));
        assert_eq!(gp_residual(&m), 0.0);
        assert_eq!(e, Expected::grid(7, 7));
    }
}

#[test]
fn diagonals_differ() {
    let (a, _) = square_identity(2, 0.0, 2.0, Diagonal::Fixed);
    let (b, _) = square_identity(2, 0.0, 2.0, Diagonal::Alternating);
    assert_eq!(a.simplices[0], b.simplices[0]);
    assert_ne!(a.simplices[2], b.simplices[2]);
}

#[test]
fn fold_reverts_5_to_15_percent() {
    for d in both() {
        let (m, e) = square_fold(28, 0.2, 7.2, 1.5, d);
        assert!(m.validate().is_ok());
        let f = reverted_fraction(&m);
        assert!((0.05..=0.15).contains(&f), "{d:?}: {f}");
        assert_eq!(e.quads, Some(49));
    }
    let (m, _) = square_fold(28, 0.2, 7.2, 0.5, Diagonal::Alternating);
    assert_eq!(reverted_fraction(&m), 0.0, "weak fold: no reversal");
}

#[test]
fn noise_reverts_about_40_percent_and_keeps_boundary() {
    let (id, _) = square_identity(14, 0.2, 7.2, Diagonal::Alternating);
    for seed in 0..3 {
        let (m, e) = square_noise(14, 0.2, 7.2, 1.0, seed, Diagonal::Alternating);
        assert!(m.validate().is_ok());
        let f = reverted_fraction(&m);
        assert!((0.3..=0.5).contains(&f), "seed {seed}: {f}");
        assert_eq!(gp_residual(&m), 0.0);
        assert_eq!(e.quads, Some(49));
        // boundary corners untouched
        for (s, t) in m.simplices.iter().enumerate() {
            for (c, &v) in t.iter().enumerate() {
                let p = m.positions[v as usize];
                if p[0] == 0.0 || p[0] == 1.0 || p[1] == 0.0 || p[1] == 1.0 {
                    assert_eq!(m.coords[s][c], id.coords[s][c]);
                }
            }
        }
    }
    let (a, _) = square_noise(14, 0.2, 7.2, 1.0, 1, Diagonal::Alternating);
    let (b, _) = square_noise(14, 0.2, 7.2, 1.0, 2, Diagonal::Alternating);
    assert_ne!(a, b);
}

#[test]
fn collapsed_interior_is_one_point() {
    let (m, e) = square_collapsed(8, 0.2, 7.2, Diagonal::Fixed);
    assert!(m.validate().is_ok());
    let degenerate = (0..m.len()).filter(|&s| m.map_det(s) == 0.0).count();
    // triangles with 3 interior corners: those of the 6 × 6 inner cells
    let interior_only = m
        .coords
        .iter()
        .filter(|c| c.iter().all(|p| *p == [3.7, 3.7]))
        .count();
    assert_eq!(interior_only, 72);
    // plus one triangle (2 interior corners) per non-corner ring cell
    assert_eq!(degenerate, 72 + 4 * 6);
    assert_eq!(e.quads, Some(49));
}

#[test]
fn half_rotated_is_exactly_gp_with_a_seam() {
    let (m, e) = square_half_rotated(14, 0.2, 7.2, 0.5, 3, Diagonal::Alternating);
    assert!(m.validate().is_ok());
    assert_eq!(gp_residual(&m), 0.0);
    // edges whose two corner sets differ (the seam): one per row of cells
    let seam = interior_edges(&m)
        .into_iter()
        .filter(|&[s, ca, cb, t, ta, tb]| {
            m.coords[s][ca] != m.coords[t][ta] || m.coords[s][cb] != m.coords[t][tb]
        })
        .count();
    assert_eq!(seam, 14);
    let f = reverted_fraction(&m);
    assert!(f > 0.05, "noise reverts some triangles: {f}");
    assert_eq!(e.quads, Some(49));
}

use super::*;
use crate::testing::{angle_sum, gp_residual, interior_edges, reverted_fraction};

const INDICES: [i32; 6] = [1, -1, -2, -3, -4, -5];

#[test]
fn disks_are_exactly_gp_with_the_cone_angle_at_the_centre() {
    for k in INDICES {
        let (m, e) = singular_disk(k, false, 12, 40, 6.3).expect("valid parameters");
        assert!(m.validate().is_ok(), "k={k}");
        assert_eq!(
            (m.positions.len(), m.len()),
            (1 + 12 * 40, 40 + 11 * 80),
            "k={k}"
        );
        assert_eq!(interior_edges(&m).len(), 40 + 11 * 40 + 11 * 80, "k={k}");
        assert_eq!(gp_residual(&m), 0.0, "k={k}");
        assert_eq!(reverted_fraction(&m), 0.0, "k={k}");
        let alpha = 1.0 - f64::from(k) / 4.0;
        let s = angle_sum(&m, 0);
        assert!((s - TAU * alpha).abs() < 1e-9, "k={k}: {s}");
        // an ordinary interior vertex on the seam
        let v = 1 + 3 * 40;
        assert!((angle_sum(&m, v) - TAU).abs() < 1e-9, "k={k}");
        // the seam: corners differ on exactly the 1 + 2·11 edges at θ = 0
        let seam = interior_edges(&m)
            .into_iter()
            .filter(|&[s, a, _, t, b, _]| m.coords[s][a] != m.coords[t][b])
            .count();
        let expect_seam = if (4 - k) % 4 == 0 { 0 } else { 12 };
        assert!(seam >= expect_seam.min(1) * 11, "k={k}: {seam}");
        let hist = e.interior_valence.expect("known");
        assert_eq!(hist.get(&((4 - k) as u32)), Some(&1), "k={k}: {hist:?}");
        assert_eq!(hist.keys().count(), 2, "k={k}: {hist:?}");
        // the quad count is close to the area of the cone disk
        let q = e.quads.expect("known") as f64;
        let area = std::f64::consts::PI * alpha * 6.3 * 6.3;
        assert!((q / area - 1.0).abs() < 0.15, "k={k}: {q} vs {area}");
    }
}

#[test]
fn reverted_disks_fold_the_middle_rings() {
    for k in INDICES {
        let (m, e) = singular_disk(k, true, 20, 32, 6.3).expect("valid parameters");
        assert!(m.validate().is_ok());
        assert_eq!(gp_residual(&m), 0.0, "k={k}");
        // rings 6..11 of 20 (r in 0.3..0.55) are reverted: 5 bands of 64
        let reverted = (0..m.len()).filter(|&s| m.map_det(s) < 0.0).count();
        assert_eq!(reverted, 5 * 64, "k={k}");
        assert_eq!((e.euler, e.boundary_loops), (Some(1), Some(1)));
        let (plain, pe) = singular_disk(k, false, 20, 32, 6.3).expect("valid");
        assert_eq!(m.positions, plain.positions);
        assert_eq!(e, pe, "same boundary, same expectation");
    }
}

#[test]
fn expected_counts_of_small_cones() {
    // α = 1 (index 0) is the plain disk: count the cells by brute force
    let e = cone_expected(4, 2.2, 400);
    let mut cells = 0;
    for i in -3..3 {
        for j in -3..3 {
            let (x, y) = (f64::from(i) + 0.5, f64::from(j) + 0.5);
            cells += usize::from(x.hypot(y) < 2.2 * (TAU / 800.0).cos());
        }
    }
    assert_eq!(e.quads, Some(cells));
    assert_eq!(cells, 16);
    // interior vertices: the 3 × 3 around (0,0) have their 4 cells inside
    assert_eq!(e.interior_valence, Some([(4, 9)].into_iter().collect()));
}

#[test]
fn invalid_parameters() {
    assert!(singular_disk(4, false, 10, 32, 5.0).is_none());
    assert!(singular_disk(1, false, 1, 32, 5.0).is_none());
    assert!(singular_disk(1, false, 10, 4, 5.0).is_none());
    assert!(singular_disk(1, false, 10, 32, f64::NAN).is_none());
}

#[test]
fn invalid_quantization_splits_the_centre() {
    let (m, e) = invalid_quantization(-2, 10, 32, 6.3).expect("valid parameters");
    let (d, de) = singular_disk(-2, false, 10, 32, 6.3).expect("valid parameters");
    assert!(m.validate().is_ok());
    assert_eq!(e, de);
    let b = d.positions.len() as u32;
    assert_eq!(
        (m.positions.len(), m.len()),
        (d.positions.len() + 1, d.len() + 2)
    );
    assert_eq!(interior_edges(&m).len(), interior_edges(&d).len() + 3);
    assert_eq!(gp_residual(&m), 0.0);
    // A and B are both at the origin in every chart; the two new triangles
    // are degenerate, the others keep their shape
    for (t, c) in m.simplices.iter().zip(&m.coords) {
        for (k, &v) in t.iter().enumerate() {
            if v == 0 || v == b {
                assert_eq!(c[k], [0.0, 0.0]);
            }
        }
    }
    let zero = (0..m.len()).filter(|&s| m.map_det(s) == 0.0).count();
    assert_eq!(zero, 2);
    assert!(invalid_quantization(-2, 10, 30, 6.3).is_none());
    assert!(invalid_quantization(4, 10, 32, 6.3).is_none());
}

#[test]
fn multi_boundary_has_a_disk_and_an_annulus_in_the_centre_cell() {
    let (m, e) = multi_boundary(24, 48, 6.3).expect("valid parameters");
    assert!(m.validate().is_ok());
    assert_eq!(gp_residual(&m), 0.0);
    // rings 6..12 (r in 0.25..0.5) are reverted: 6 bands of 96 triangles
    let reverted = (0..m.len()).filter(|&s| m.map_det(s) < 0.0).count();
    assert_eq!(reverted, 6 * 96);
    // rings whose map radius is inside the centre's dual cell's disk
    let inside: Vec<usize> = (1..=24)
        .filter(|k| {
            let v = 1 + (k - 1) * 48;
            let p = m
                .simplices
                .iter()
                .zip(&m.coords)
                .find_map(|(t, c)| t.iter().position(|&x| x as usize == v).map(|i| c[i]))
                .expect("every vertex is used");
            p[0].hypot(p[1]) < 0.5
        })
        .collect();
    assert_eq!(inside, vec![1, 2, 11, 12]);
    let (_, plain) = singular_disk(0, false, 24, 48, 6.3).expect("valid");
    assert_eq!(e, plain);
    assert!(multi_boundary(24, 48, 20.0).is_none());
    assert!(multi_boundary(24, 48, 3.0).is_none());
}

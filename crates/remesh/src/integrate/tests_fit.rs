//! The area fit of [`super::IntegrateOptions::fit_area`].

use super::test_meshes::*;
use super::*;
use crate::field::CrossField;

#[test]
fn area_fit_reuses_the_continuous_solve_exactly() {
    // the scaled first solve (no solve) equals a solve at the fitted
    // scale, on a field with rotated seams and a boundary
    let s = square(16, 0.2);
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let angles = (0..s.triangles.len())
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % 1000) as f64 / 1000.0 * 1.2
        })
        .collect();
    let field = CrossField::from_angles(&s, angles);
    let singular = singular_by_matchings(&s, &field);
    let cut = test_cut::cut(&s, &singular);
    for align in [None, Some(0.3)] {
        let o = IntegrateOptions {
            align_boundary: align,
            gauge_offset: [0.3, 0.7],
            quads: Some(200),
            rounding: Rounding::Continuous,
            ..IntegrateOptions::default()
        };
        let (fitted, report) = integrate_report(&s, &field, &cut, &singular, &o).unwrap();
        // one solve: the fit's, scaled
        assert_eq!(report.quantize.solves, 1, "{report:?}");
        assert!((report.map_area - 200.0).abs() < 1e-6, "{report:?}");
        let direct = IntegrateOptions {
            scale: Some(report.scale),
            fit_area: false,
            ..o
        };
        let (solved, _) = integrate_report(&s, &field, &cut, &singular, &direct).unwrap();
        for (a, b) in fitted.coords.iter().zip(&solved.coords) {
            for i in 0..3 {
                for c in 0..2 {
                    assert!((a[i][c] - b[i][c]).abs() < 1e-8, "{a:?} vs {b:?}");
                }
            }
        }
    }
}

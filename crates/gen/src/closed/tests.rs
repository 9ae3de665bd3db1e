use super::*;
use crate::testing::{angle_sum, gp_residual, interior_edges, reverted_fraction};
use std::f64::consts::{FRAC_PI_2, TAU};

fn variants() -> [Perturb; 3] {
    [
        Perturb::None,
        Perturb::Fold { strength: 1.5 },
        Perturb::Noise {
            amplitude: 0.4,
            seed: 5,
        },
    ]
}

#[test]
fn cube_is_closed_exactly_gp_with_8_corners() {
    for p in variants() {
        let (m, e) = cube_surface(3, 6, p, Diagonal::Alternating);
        assert!(m.validate().is_ok(), "{p:?}");
        // V = 6·res² + 2, T = 12·res², every edge interior
        assert_eq!((m.positions.len(), m.len()), (218, 432), "{p:?}");
        assert_eq!(interior_edges(&m).len(), 3 * 432 / 2, "{p:?}");
        assert_eq!(gp_residual(&m), 0.0, "{p:?}");
        assert_eq!(e.quads, Some(54));
        assert_eq!(
            e.interior_valence,
            Some([(3, 8), (4, 48)].into_iter().collect())
        );
    }
}

#[test]
fn cube_corners_are_singular_grid_points() {
    let (m, _) = cube_surface(2, 4, Perturb::None, Diagonal::Fixed);
    let mut corners = 0;
    for v in 0..m.positions.len() as u32 {
        let s = angle_sum(&m, v);
        let p = m.positions[v as usize];
        let is_corner = p.iter().all(|&x| x == 0.0 || x == 1.0);
        if is_corner {
            corners += 1;
            assert!((s - 3.0 * FRAC_PI_2).abs() < 1e-12, "corner {v}: {s}");
        } else {
            assert!((s - TAU).abs() < 1e-12, "vertex {v}: {s}");
        }
    }
    assert_eq!(corners, 8);
    // corner map values are integers
    for (t, c) in m.simplices.iter().zip(&m.coords) {
        for (k, &v) in t.iter().enumerate() {
            if m.positions[v as usize]
                .iter()
                .all(|&x| x == 0.0 || x == 1.0)
            {
                assert!(c[k].iter().all(|x| x.fract() == 0.0));
            }
        }
    }
}

#[test]
fn cube_perturbations_revert_and_spare_the_corners() {
    let (clean, _) = cube_surface(3, 6, Perturb::None, Diagonal::Alternating);
    let (fold, _) = cube_surface(3, 6, Perturb::Fold { strength: 1.5 }, Diagonal::Alternating);
    let f = reverted_fraction(&fold);
    assert!(f > 0.0 && f < 0.05, "fold on one face of six: {f}");
    let (noise, _) = cube_surface(
        3,
        6,
        Perturb::Noise {
            amplitude: 0.4,
            seed: 1,
        },
        Diagonal::Alternating,
    );
    let f = reverted_fraction(&noise);
    assert!(f > 0.1, "noise: {f}");
    for (s, t) in clean.simplices.iter().enumerate() {
        for (k, &v) in t.iter().enumerate() {
            if clean.positions[v as usize]
                .iter()
                .all(|&x| x == 0.0 || x == 1.0)
            {
                assert_eq!(noise.coords[s][k], clean.coords[s][k]);
            }
        }
    }
}

#[test]
fn torus_is_exactly_gp_without_singularity() {
    for p in variants() {
        let (m, e) = torus(8, 4, 16, 8, p, Diagonal::Alternating);
        assert!(m.validate().is_ok());
        assert_eq!((m.positions.len(), m.len()), (128, 256));
        assert_eq!(interior_edges(&m).len(), 384);
        assert_eq!(gp_residual(&m), 0.0, "{p:?}");
        assert_eq!((e.quads, e.euler), (Some(32), Some(0)));
        if p == Perturb::None {
            assert_eq!(reverted_fraction(&m), 0.0);
            for v in 0..128 {
                assert!((angle_sum(&m, v) - TAU).abs() < 1e-12);
            }
        } else {
            assert!(reverted_fraction(&m) > 0.0, "{p:?}");
        }
    }
}

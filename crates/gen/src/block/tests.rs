use super::*;
use std::collections::HashMap;

/// Largest GP residual over interior faces (best of the 24 rotations).
fn gp_residual(m: &TetMap) -> f64 {
    let mut faces: HashMap<[u32; 3], Vec<(usize, [usize; 3])>> = HashMap::new();
    for (s, t) in m.simplices.iter().enumerate() {
        for f in 0..4 {
            let mut c: Vec<usize> = (0..4).filter(|&c| c != f).collect();
            c.sort_by_key(|&c| t[c]);
            let key = [t[c[0]], t[c[1]], t[c[2]]];
            faces.entry(key).or_default().push((s, [c[0], c[1], c[2]]));
        }
    }
    let mut worst: f64 = 0.0;
    for uses in faces.values() {
        assert!(uses.len() <= 2);
        if let [(s, cs), (t, ct)] = uses.as_slice() {
            let best = Rot3::all()
                .iter()
                .map(|r| {
                    let tr = |i: usize| -> [f64; 3] {
                        let p = r.apply(&m.coords[*s][cs[i]]);
                        let q = m.coords[*t][ct[i]];
                        [q[0] - p[0], q[1] - p[1], q[2] - p[2]]
                    };
                    let t0 = tr(0);
                    let mut e: f64 = t0.iter().map(|x| (x - x.round()).abs()).fold(0.0, f64::max);
                    for i in 1..3 {
                        let ti = tr(i);
                        e = e.max((0..3).map(|k| (ti[k] - t0[k]).abs()).fold(0.0, f64::max));
                    }
                    e
                })
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(best);
        }
    }
    worst
}

fn position_volume(m: &TetMap, s: usize) -> f64 {
    let p = m.simplices[s].map(|v| m.positions[v as usize]);
    let e = |i: usize| [p[i][0] - p[0][0], p[i][1] - p[0][1], p[i][2] - p[0][2]];
    let (a, b, c) = (e(1), e(2), e(3));
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

fn reverted(m: &TetMap) -> usize {
    (0..m.len()).filter(|&s| m.map_det(s) < 0.0).count()
}

#[test]
fn block_is_positive_and_conforming() {
    let (m, e) = block(2, 3, 4, 0.2, 5.2);
    assert!(m.validate().is_ok());
    assert_eq!((m.positions.len(), m.len()), (3 * 4 * 5, 6 * 24));
    let vol: f64 = (0..m.len()).map(|s| position_volume(&m, s)).sum();
    assert!((0..m.len()).all(|s| position_volume(&m, s) > 0.0 && m.map_det(s) > 0.0));
    // 6 × volume of the unit box
    assert!((vol - 6.0).abs() < 1e-12, "{vol}");
    assert_eq!(gp_residual(&m), 0.0);
    assert_eq!(e, ExpectedHex::grid(5));
}

#[test]
fn noise_fold_and_half_rotation_stay_gp() {
    let (m, _) = block_noise(6, 0.2, 6.2, 0.8, 3);
    assert!(m.validate().is_ok());
    assert_eq!(gp_residual(&m), 0.0);
    let r = reverted(&m) as f64 / m.len() as f64;
    assert!(r > 0.1, "{r}");
    let (m, _) = block_fold(10, 0.2, 6.2, 1.5);
    assert_eq!(gp_residual(&m), 0.0);
    let r = reverted(&m) as f64 / m.len() as f64;
    assert!(r > 0.0 && r < 0.1, "{r}");
    let (m, _) = block_half_rotated(6, 0.2, 6.2, 0.3, 4);
    assert!(m.validate().is_ok());
    assert_eq!(gp_residual(&m), 0.0);
    let (r, t) = half_rotation();
    assert_eq!(r.apply(&[1.0, 0.0, 0.0]), [0.0, 1.0, 0.0]);
    assert!(t.iter().all(|x| x.fract() == 0.0));
}

#[test]
fn degenerate_block_has_zero_volume_tets() {
    let (m, _) = block_degenerate(5, 0.2, 5.2, 3, 9);
    assert!(m.validate().is_ok());
    let zero = (0..m.len()).filter(|&s| m.map_det(s) == 0.0).count();
    // each moved vertex shares an edge with its +x neighbour in 6 tets
    assert!((6..=18).contains(&zero), "{zero}");
    assert_eq!(gp_residual(&m), 0.0);
}

#[test]
fn dualex_map_sees_exact_transitions_and_no_singular_edge() {
    let opts = dualex_map::InspectOptions {
        weld: false,
        ..Default::default()
    };
    for (m, _) in [
        block_noise(4, 0.2, 4.2, 0.5, 1),
        block_half_rotated(4, 0.2, 4.2, 0.3, 2),
        block_fold(6, 0.2, 4.2, 1.5),
    ] {
        let r = dualex_map::inspect(&m, &opts).expect("valid map");
        assert_eq!(r.max_transition_residual, 0.0);
        assert!(r.singular_edges.is_empty(), "{r:?}");
    }
}

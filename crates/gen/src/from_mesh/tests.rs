//! Unit tests of the maps from meshes: conformity of the splits, exact GP,
//! validity, hand-counted expectations, classes, perturbation effects.

use super::meshes::*;
use super::*;
use crate::testing::{gp_residual, interior_edges};
use dualex_map::InspectOptions;
use std::collections::{BTreeMap, HashMap};

fn opts(k: usize) -> FromMeshOptions {
    FromMeshOptions {
        scale: k,
        ..Default::default()
    }
}

fn quads(name: &str, o: &FromMeshOptions) -> FromQuads {
    let m = quad_mesh_by_name(name).unwrap_or_else(|| panic!("{name}"));
    from_quads(&m, o).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn hexes(name: &str, o: &FromMeshOptions) -> FromHexes {
    let m = hex_mesh_by_name(name).unwrap_or_else(|| panic!("{name}"));
    from_hexes(&m, o).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn inspect_opts() -> InspectOptions {
    InspectOptions {
        weld: false,
        ..Default::default()
    }
}

/// Largest GP residual over interior tet faces (as `testing::gp_residual`):
/// for the best rotation, how far `q − R·p` is from one integer vector.
pub(crate) fn gp_residual_3d(map: &TetMap) -> f64 {
    let mut faces: HashMap<[u32; 3], Vec<usize>> = HashMap::new();
    for (s, t) in map.simplices.iter().enumerate() {
        for f in 0..4 {
            let mut c: Vec<u32> = t.iter().copied().filter(|&v| v != t[f]).collect();
            c.sort_unstable();
            faces.entry([c[0], c[1], c[2]]).or_default().push(s);
        }
    }
    let at = |s: usize, v: u32| {
        let c = map.simplices[s].iter().position(|&x| x == v).unwrap();
        map.coords[s][c]
    };
    let mut worst: f64 = 0.0;
    for (f, ts) in &faces {
        let [s, t] = ts[..] else { continue };
        let best = dualex_map::Rot3::all()
            .iter()
            .map(|r| {
                let tr: Vec<[f64; 3]> = f
                    .iter()
                    .map(|&v| {
                        let (p, q) = (r.apply(&at(s, v)), at(t, v));
                        [q[0] - p[0], q[1] - p[1], q[2] - p[2]]
                    })
                    .collect();
                let mut e: f64 = 0.0;
                for x in &tr {
                    for k in 0..3 {
                        e = e
                            .max((x[k] - tr[0][k]).abs())
                            .max((x[k] - x[k].round()).abs());
                    }
                }
                e
            })
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(best);
    }
    worst
}

/// Tet faces: every sorted triple in at most 2 tets, traversed oppositely;
/// returns the number of boundary faces.
fn tet_conformity(map: &TetMap, what: &str) -> usize {
    let mut faces: HashMap<[u32; 3], Vec<bool>> = HashMap::new();
    for t in &map.simplices {
        for f in 0..4 {
            let mut c: Vec<u32> = (1..4).map(|i| t[(f + i) % 4]).collect();
            // parity of the sort = orientation of the face seen from t
            let mut parity = f % 2 == 1;
            for i in 0..3 {
                for j in 0..2 - i {
                    if c[j] > c[j + 1] {
                        c.swap(j, j + 1);
                        parity = !parity;
                    }
                }
            }
            faces.entry([c[0], c[1], c[2]]).or_default().push(parity);
        }
    }
    let mut boundary = 0;
    for (f, sides) in &faces {
        match sides.len() {
            1 => boundary += 1,
            2 => assert_ne!(sides[0], sides[1], "{what}: face {f:?} misoriented"),
            n => panic!("{what}: face {f:?} in {n} tets"),
        }
    }
    boundary
}

#[test]
fn every_2d_map_is_valid_conformal_and_exactly_gp() {
    for name in quad_mesh_names() {
        for k in 1..=3 {
            for diagonal in [Diagonal::Fixed, Diagonal::Alternating] {
                for (noise, folds, half_shift) in
                    [(0.0, false, false), (0.6, true, false), (0.3, false, true)]
                {
                    let o = FromMeshOptions {
                        diagonal,
                        noise,
                        folds,
                        half_shift,
                        ..opts(k)
                    };
                    let g = quads(&name, &o);
                    let what = format!("{name} k={k} {diagonal:?} noise {noise} {half_shift}");
                    assert!(g.map.validate().is_ok(), "{what}");
                    assert_eq!(g.map.len(), 2 * g.refined.cells.len(), "{what}");
                    // panics on an edge in 3 triangles or misoriented
                    let interior = interior_edges(&g.map).len();
                    // triangle edges = M_k's edges + one diagonal per quad
                    let e = expected_quad(&g.refined);
                    let edges = g.refined.positions.len() as i64 + e.quads.unwrap() as i64
                        - e.euler.unwrap();
                    let tri_edges = 3 * g.map.len() as i64 - interior as i64;
                    assert_eq!(tri_edges, edges + g.refined.cells.len() as i64, "{what}");
                    assert_eq!(gp_residual(&g.map), 0.0, "{what}");
                    let r = dualex_map::inspect(&g.map, &inspect_opts())
                        .unwrap_or_else(|e| panic!("{what}: {e}"));
                    assert_eq!(r.max_transition_residual, 0.0, "{what}");
                    assert_eq!(r.components, 1, "{what}");
                }
            }
        }
    }
}

#[test]
fn every_3d_map_is_valid_conformal_and_exactly_gp() {
    for name in hex_mesh_names() {
        for k in 1..=3 {
            for split in [TetSplit::LeastVertex, TetSplit::Centre] {
                for (noise, folds) in [(0.0, false), (0.6, true)] {
                    let o = FromMeshOptions {
                        tet_split: split,
                        noise,
                        folds,
                        ..opts(k)
                    };
                    let g = hexes(&name, &o);
                    let what = format!("{name} k={k} {split:?} noise {noise}");
                    assert!(g.map.validate().is_ok(), "{what}");
                    let per = if split == TetSplit::Centre { 12 } else { 6 };
                    assert_eq!(g.map.len(), per * g.refined.cells.len(), "{what}");
                    let boundary = tet_conformity(&g.map, &what);
                    let b = dualex_check::check_hex_mesh(
                        g.refined.positions.len(),
                        &g.refined.cells,
                        Some(&g.refined.positions),
                    );
                    assert!(b.is_valid(), "{what}: {:?}", b.errors());
                    assert_eq!(boundary, 2 * b.boundary_faces, "{what}");
                    let r = dualex_map::inspect(&g.map, &inspect_opts())
                        .unwrap_or_else(|e| panic!("{what}: {e}"));
                    assert_eq!(r.max_transition_residual, 0.0, "{what}");
                    assert_eq!(gp_residual_3d(&g.map), 0.0, "{what}");
                    if noise == 0.0 {
                        assert_eq!(r.reverted, 0, "{what}");
                    }
                }
            }
        }
    }
}

fn hist(pairs: &[(u32, usize)]) -> Option<BTreeMap<u32, usize>> {
    Some(pairs.iter().copied().collect())
}

#[test]
fn expected_counts_by_hand() {
    let e = quads("cube6", &opts(1)).expected;
    assert_eq!(e, Expected::closed(6, &[(3, 8)], 2));
    let e = quads("cube6", &opts(2)).expected;
    assert_eq!(e, Expected::closed(24, &[(3, 8), (4, 18)], 2));
    let e = quads("ngon5", &opts(1)).expected;
    assert_eq!(
        (e.quads, e.interior_valence.clone()),
        (Some(5), hist(&[(5, 1)]))
    );
    assert_eq!((e.euler, e.boundary_loops), (Some(1), Some(1)));
    // k = 3: 45 quads; interior: centre (5), 4 per quad inside, 2 per spoke
    let e = quads("ngon5", &opts(3)).expected;
    assert_eq!(e.quads, Some(45));
    assert_eq!(e.interior_valence, hist(&[(4, 5 * 4 + 5 * 2), (5, 1)]));
    let e = quads("annulus", &opts(1)).expected;
    assert_eq!(e.quads, Some(16));
    assert_eq!(e.interior_valence, hist(&[(4, 8)]));
    assert_eq!((e.euler, e.boundary_loops), (Some(0), Some(2)));
    // pentagonal prism split: 10 corners (3), 15 edges + 5 quads (4), 2 caps (5)
    let e = quads("prism5_poles", &opts(1)).expected;
    assert_eq!(e, Expected::closed(30, &[(3, 10), (4, 20), (5, 2)], 2));
    // half shift: the map still carries M_k
    let o = FromMeshOptions {
        half_shift: true,
        ..opts(1)
    };
    assert_eq!(
        quads("cube6", &o).expected,
        Expected::closed(6, &[(3, 8)], 2)
    );
    for (name, k, hexes_, euler) in [
        ("cubed_ball", 1, 7, 2),
        ("cubed_ball", 2, 56, 2),
        ("cylinder3", 1, 6, 2),
        ("cylinder5", 2, 80, 2),
        ("polycube_l", 3, 81, 2),
    ] {
        let e = hexes(name, &opts(k)).expected;
        assert_eq!(e.hexes, Some(hexes_), "{name} {k}");
        assert_eq!(e.boundary_components, Some(1), "{name} {k}");
        assert_eq!(e.boundary_euler, Some(euler), "{name} {k}");
    }
}

fn class_counts(c: &[VertexClass]) -> BTreeMap<VertexClass, usize> {
    let mut h = BTreeMap::new();
    for &x in c {
        *h.entry(x).or_insert(0) += 1;
    }
    h
}

#[test]
fn classes_and_singularities_are_the_meshes() {
    use VertexClass::*;
    let g = quads("cube6", &opts(2));
    assert_eq!(
        class_counts(&g.classes),
        BTreeMap::from([(Regular, 18), (Singular, 8)])
    );
    let r = dualex_map::inspect(&g.map, &inspect_opts()).unwrap();
    assert_eq!(r.singularities, BTreeMap::from([("1/4".to_string(), 8)]));
    let g = quads("prism5_poles", &opts(1));
    let r = dualex_map::inspect(&g.map, &inspect_opts()).unwrap();
    let total: usize = r.singularities.values().sum();
    assert_eq!(total, 12, "{r:?}");
    assert_eq!(class_counts(&g.classes)[&Singular], 12);
    // cubed ball, k = 2: 8 inner corners; the midpoints of its 20 singular
    // edges (valence 3: the inner cube's 12, the 8 radial ones); regular:
    // the centres of the 7 hexes, of the 6 inner faces, of the 12 faces
    // between frustums
    for split in [TetSplit::LeastVertex, TetSplit::Centre] {
        let o = FromMeshOptions {
            tet_split: split,
            ..opts(2)
        };
        let g = hexes("cubed_ball", &o);
        let c = class_counts(&g.classes);
        assert_eq!(c[&Singular], 8, "{split:?}");
        assert_eq!(c[&SingularEdge], 20, "{split:?}");
        let regular = if split == TetSplit::Centre {
            25 + 56
        } else {
            25
        };
        assert_eq!(c[&Regular], regular, "{split:?}");
        let r = dualex_map::inspect(&g.map, &inspect_opts()).unwrap();
        let edges: usize = r.singular_edges.values().sum();
        assert_eq!(edges, 40, "{split:?}: {r:?}");
    }
    // a whole turn of excess (valence 8): trivial holonomy, still singular
    let g = quads("ngon8", &opts(1));
    assert_eq!(class_counts(&g.classes).get(&Singular), Some(&1));
    // cylinder of 3 wedges, 2 layers, k = 1: one interior axis vertex
    let g = hexes("cylinder3", &opts(1));
    assert_eq!(class_counts(&g.classes).get(&SingularEdge), Some(&1));
}

/// Fraction of reverted simplices.
fn flipped<const N: usize, const D: usize>(m: &dualex_map::SimplexMap<N, D>) -> f64 {
    (0..m.len()).filter(|&s| m.map_det(s) < 0.0).count() as f64 / m.len() as f64
}

#[test]
fn noise_flips_some_simplices_and_folds_more() {
    let mut report = Vec::new();
    for noise in [0.3, 0.6] {
        let mut f2 = 0.0;
        for name in ["cube6", "prism5_poles", "annulus"] {
            let o = FromMeshOptions { noise, ..opts(3) };
            f2 += flipped(&quads(name, &o).map) / 3.0;
        }
        let o = FromMeshOptions { noise, ..opts(3) };
        let f3 = flipped(&hexes("cubed_ball", &o).map);
        report.push(format!(
            "noise {noise}: 2D {:.1}%, 3D {:.1}%",
            100.0 * f2,
            100.0 * f3
        ));
        if noise > 0.5 {
            assert!(f2 > 0.0 && f3 > 0.0, "{report:?}");
        }
    }
    eprintln!("flipped simplices: {report:?}");
    let base = flipped(&quads("cube6", &opts(3)).map);
    let o = FromMeshOptions {
        folds: true,
        ..opts(3)
    };
    assert_eq!(base, 0.0);
    assert!(flipped(&quads("cube6", &o).map) > 0.0);
}

#[test]
fn slivers_stay_exact_and_jitter_does_not() {
    let o = FromMeshOptions {
        noise: 0.3,
        slivers: Some(Slivers {
            count: 6,
            lambda: 1e-15,
        }),
        ..opts(2)
    };
    let g = quads("cube6", &o);
    assert!(g.map.validate().is_ok());
    assert_eq!(g.map.len(), 48 + 2 * 6);
    assert_eq!(gp_residual(&g.map), 0.0);
    let g = hexes("cubed_ball", &o);
    assert!(g.map.validate().is_ok());
    assert_eq!(gp_residual_3d(&g.map), 0.0);
    let r = dualex_map::inspect(&g.map, &inspect_opts()).unwrap();
    eprintln!(
        "dualex-map's residual with slivers: {:e}",
        r.max_transition_residual
    );
    assert!(g.map.len() > 6 * 56);
    let o = FromMeshOptions {
        jitter: Some(Jitter {
            amplitude: 1e-6,
            classes: vec![VertexClass::Singular],
            fraction: 1.0,
        }),
        ..opts(2)
    };
    let g = quads("cube6", &o);
    let res = gp_residual(&g.map);
    assert!(res > 0.0 && res <= 4e-6, "{res}");
}

#[test]
fn bad_input_is_an_error() {
    let mut m = cube6();
    m.cells[2][1] = 99;
    assert_eq!(
        from_quads(&m, &opts(1)).err(),
        Some(FromMeshError::BadElement { element: 2 })
    );
    assert_eq!(
        from_quads(&cube6(), &opts(0)).err(),
        Some(FromMeshError::Scale(0))
    );
    let o = FromMeshOptions {
        half_shift: true,
        ..opts(1)
    };
    assert!(from_hexes(&cubed_ball(), &o).is_err());
}

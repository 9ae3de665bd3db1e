//! Cross field, singularities and cut on the generated test surfaces.

use dualex_remesh::shapes::{
    annulus, bumpy_square, cube, disjoint_union, flat_disk, icosphere, plate_with_holes, torus,
};
use dualex_remesh::singularity::vertex_turning;
use dualex_remesh::smooth::field_energy;
use dualex_remesh::{
    cross_field, cut_to_disk, Cut, FieldOptions, FieldResult, RemeshError, Surface,
};
use std::f64::consts::FRAC_PI_2;

fn field(s: &Surface) -> FieldResult {
    cross_field(s, &FieldOptions::default()).unwrap()
}

fn quarters(r: &FieldResult) -> i64 {
    r.singularities.iter().map(|&(_, q)| i64::from(q)).sum()
}

/// Every vertex's turning is a whole number of quarter turns (up to
/// rounding): the field and the index formula agree.
fn check_turning(name: &str, s: &Surface, r: &FieldResult) {
    for (v, t) in vertex_turning(s, &r.field).into_iter().enumerate() {
        // (a vertex of no triangle turns 2π: a whole number too)
        let off = (t / FRAC_PI_2 - (t / FRAC_PI_2).round()).abs();
        assert!(off < 1e-6, "{name}: vertex {v} turns {t}");
    }
}

/// Poincaré–Hopf with boundary: Σ interior + Σ boundary = χ.
fn check_poincare_hopf(name: &str, s: &Surface, r: &FieldResult) {
    let mut used = vec![false; s.positions.len()];
    s.triangles
        .iter()
        .flatten()
        .for_each(|&v| used[v as usize] = true);
    let unused = used.iter().filter(|&&u| !u).count() as i64;
    let boundary: i64 = r
        .boundary_singularities
        .iter()
        .map(|&(_, q)| i64::from(q))
        .sum();
    assert_eq!(
        quarters(r) + boundary,
        4 * (s.euler_characteristic() - unused),
        "{name}: {:?} + boundary {:?}",
        r.singularities,
        r.boundary_singularities
    );
    check_turning(name, s, r);
}

/// The field combs on the cut surface: after the per-face quarter turns
/// every uncut interior edge has matching 0.
fn check_comb(name: &str, s: &Surface, r: &FieldResult, cut: &Cut) {
    let rot = cut
        .comb(s, &r.field)
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    for (e, &[f0, f1]) in s.edge_faces.iter().enumerate() {
        if f1 != dualex_remesh::NO_FACE && !cut.is_cut[e] {
            let p = r.field.matching[e];
            assert_eq!(
                (rot[f0 as usize] + p) % 4,
                rot[f1 as usize],
                "{name}: edge {e}"
            );
        }
    }
}

/// Poincaré–Hopf on a closed surface and a valid cut.
fn check_closed(name: &str, s: &Surface) -> FieldResult {
    let r = field(s);
    check_turning(name, s, &r);
    assert!(r.boundary_singularities.is_empty());
    assert_eq!(
        quarters(&r),
        4 * s.euler_characteristic(),
        "{name}: Σ index ≠ χ; singularities {:?}",
        r.singularities
    );
    let cut = cut_to_disk(s, &r.singularities).unwrap();
    cut.check(s, &r.singularities)
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    check_comb(name, s, &r, &cut);
    r
}

#[test]
fn sphere_has_eight_quarter_singularities() {
    let s = icosphere(3);
    let r = check_closed("icosphere", &s);
    assert!(r.fixed.iter().all(|&f| !f) && r.sharp.iter().all(|&e| !e));
    assert_eq!(r.singularities.len(), 8, "{:?}", r.singularities);
    assert!(r.singularities.iter().all(|&(_, q)| q == 1));
}

#[test]
fn torus_index_sum_is_zero() {
    // the relaxed smoothest field of a torus of revolution has ± pairs on
    // the inner side (see the `smooth` module docs): check they pair up
    let r = check_closed("torus", &torus(3.0, 1.0, 48, 16));
    let plus = r.singularities.iter().filter(|&&(_, q)| q == 1).count();
    let minus = r.singularities.iter().filter(|&&(_, q)| q == -1).count();
    assert_eq!(plus + minus, r.singularities.len(), "{:?}", r.singularities);
    assert_eq!(plus, minus);
    assert!(r.singularities.len() <= 16, "{:?}", r.singularities);
}

#[test]
fn cube_field_follows_the_edges_with_a_singularity_per_corner() {
    let s = cube(4);
    let r = check_closed("cube", &s);
    assert_eq!(r.sharp.iter().filter(|&&e| e).count(), 12 * 4);
    let mut corners: Vec<u32> = r
        .singularities
        .iter()
        .map(|&(v, q)| {
            assert_eq!(q, 1, "vertex {v}");
            v
        })
        .collect();
    corners.sort_unstable();
    let mut want: Vec<u32> = (0..s.positions.len() as u32)
        .filter(|&v| {
            s.positions[v as usize]
                .iter()
                .all(|&c| c == 0.0 || c == 1.0)
        })
        .collect();
    want.sort_unstable();
    assert_eq!(corners, want);
    // every face of the cube is flat: the field is axis-aligned everywhere
    for (f, &a) in r.field.angle.iter().enumerate() {
        assert!(field_axis_aligned(&s, f as u32, a), "face {f}: angle {a}");
    }
}

/// The direction `a` of face `f` is along a coordinate axis.
fn field_axis_aligned(s: &Surface, f: u32, a: f64) -> bool {
    let [e1, e2, _] = s.frames[f as usize];
    let d: Vec<f64> = (0..3).map(|i| a.cos() * e1[i] + a.sin() * e2[i]).collect();
    d.iter().filter(|c| c.abs() > 1e-6).count() == 1
}

#[test]
fn sharp_threshold_decides_which_creases_the_field_follows() {
    // a strip folded along x = 0 by `bend` degrees: sharp iff bend > 35
    let hinge = |bend: f64| {
        let a = bend.to_radians();
        let mut p = Vec::new();
        for j in 0..=4 {
            for i in 0..=8 {
                let x = f64::from(i) / 4.0 - 1.0;
                let (x, z) = if x <= 0.0 {
                    (x, 0.0)
                } else {
                    (x * a.cos(), x * a.sin())
                };
                p.push([x, f64::from(j) / 4.0, z]);
            }
        }
        let id = |i: u32, j: u32| j * 9 + i;
        let mut t = Vec::new();
        for j in 0..4 {
            for i in 0..8 {
                t.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
                t.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
        Surface::new(p, t).unwrap()
    };
    for (bend, sharp) in [(20.0, 0), (50.0, 4), (90.0, 4)] {
        let s = hinge(bend);
        let r = field(&s);
        assert_eq!(
            r.sharp.iter().filter(|&&e| e).count(),
            sharp,
            "bend {bend}°"
        );
        check_poincare_hopf(&format!("hinge {bend}°"), &s, &r);
    }
    // with a higher threshold nothing is sharp on a cube: the field is
    // free (no boundary either) and still obeys Poincaré–Hopf
    let s = cube(3);
    let opts = FieldOptions {
        sharp_degrees: 100.0,
        ..FieldOptions::default()
    };
    let r = cross_field(&s, &opts).unwrap();
    assert!(r.sharp.iter().all(|&e| !e) && r.fixed.iter().all(|&f| !f));
    assert_eq!(quarters(&r), 8);
}

#[test]
fn genus_three_plate_index_sum() {
    let s = plate_with_holes(3, 2);
    let r = check_closed("plate with 3 holes", &s);
    // the convex corners are +1/4, the concave ones (inside the holes'
    // corners meet the plate faces) −1/4
    // 8 outer corners, 8 concave corners per hole (top and bottom)
    let plus = r.singularities.iter().filter(|&&(_, q)| q == 1).count();
    let minus = r.singularities.iter().filter(|&&(_, q)| q == -1).count();
    assert_eq!((plus, minus, r.singularities.len()), (8, 24, 32));
}

#[test]
fn square_patch_field_follows_the_boundary_and_is_smooth() {
    let s = bumpy_square(16, 0.15);
    let r = field(&s);
    assert!(r.singularities.is_empty(), "{:?}", r.singularities);
    check_poincare_hopf("square", &s, &r);
    let mut corners: Vec<u32> = r
        .boundary_singularities
        .iter()
        .map(|&(v, q)| {
            assert_eq!(q, 1);
            v
        })
        .collect();
    corners.sort_unstable();
    assert_eq!(corners, [0, 16, 17 * 16, 17 * 17 - 1]);
    for (f, &fixed) in r.fixed.iter().enumerate() {
        let on_boundary = s.face_edges[f].iter().any(|&e| s.is_boundary_edge(e));
        assert_eq!(fixed, on_boundary, "face {f}");
        for &e in &s.face_edges[f] {
            if s.is_boundary_edge(e) {
                let d = r.field.angle[f] - s.edge_angle(e, f as u32);
                let off = (d / FRAC_PI_2 - (d / FRAC_PI_2).round()).abs();
                assert!(off < 1e-9, "face {f} edge {e}: {d}");
            }
        }
    }
    // a minimiser: turning any free face increases the energy
    let e0 = field_energy(&s, &r.field.angle);
    for f in (0..s.triangles.len()).filter(|&f| !r.fixed[f]).step_by(37) {
        for da in [-0.05, 0.05] {
            let mut a = r.field.angle.clone();
            a[f] += da;
            assert!(field_energy(&s, &a) > e0, "face {f} turned by {da}");
        }
    }
    let cut = cut_to_disk(&s, &r.singularities).unwrap();
    cut.check(&s, &r.singularities).unwrap();
    assert!(cut.is_cut.iter().all(|&c| !c), "a disk needs no cut");
    check_comb("square", &s, &r, &cut);
}

#[test]
fn unit_steps_lower_the_energy_of_the_unit_field() {
    for s in [icosphere(3), torus(3.0, 1.0, 48, 16)] {
        let energy = |steps| {
            // the energy of the input surface: no denoising
            let opts = FieldOptions {
                unit_steps: steps,
                denoise_steps: 0,
                ..FieldOptions::default()
            };
            let r = cross_field(&s, &opts).unwrap();
            field_energy(&s, &r.field.angle)
        };
        let (linear, unit) = (energy(0), energy(10));
        assert!(unit < 0.95 * linear, "{unit} vs {linear}");
    }
}

#[test]
fn l_shape_has_five_convex_and_one_concave_boundary_corner() {
    // an 8 × 8 grid of unit cells without its upper right 4 × 4 quarter
    let id = |i: u32, j: u32| j * 9 + i;
    let p: Vec<[f64; 3]> = (0..81)
        .map(|v| [f64::from(v % 9), f64::from(v / 9), 0.0])
        .collect();
    let mut t = Vec::new();
    for j in 0..8 {
        for i in 0..8 {
            if i >= 4 && j >= 4 {
                continue;
            }
            t.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            t.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    // the vertices of the missing quarter's inside are used by no triangle
    let s = Surface::new(p, t).unwrap();
    let r = field(&s);
    assert!(r.singularities.is_empty(), "{:?}", r.singularities);
    let mut b = r.boundary_singularities.clone();
    b.sort_unstable();
    let want = [
        (id(0, 0), 1),
        (id(8, 0), 1),
        (id(0, 8), 1),
        (id(8, 4), 1),
        (id(4, 4), -1),
        (id(4, 8), 1),
    ];
    let mut want = want.to_vec();
    want.sort_unstable();
    assert_eq!(b, want);
    check_poincare_hopf("L", &s, &r);
}

#[test]
fn round_disk_cut_reaches_the_inner_singularities_from_the_boundary() {
    let s = flat_disk(24);
    let r = field(&s);
    check_poincare_hopf("disk", &s, &r);
    assert!(
        r.boundary_singularities.is_empty(),
        "{:?}",
        r.boundary_singularities
    );
    assert_eq!(quarters(&r), 4, "{:?}", r.singularities);
    assert!(!r.singularities.is_empty());
    let cut = cut_to_disk(&s, &r.singularities).unwrap();
    cut.check(&s, &r.singularities).unwrap();
    check_comb("disk", &s, &r, &cut);
    // every cut edge is on a path from a singularity to the boundary: the
    // cut touches the boundary
    assert!((0..s.edges.len())
        .any(|e| cut.is_cut[e] && s.edges[e].iter().any(|&v| s.boundary_vertex[v as usize])));
}

#[test]
fn annulus_cut_joins_the_two_boundaries() {
    let s = annulus(48, 8);
    let r = field(&s);
    assert!(r.singularities.is_empty(), "{:?}", r.singularities);
    assert!(r.boundary_singularities.is_empty());
    check_poincare_hopf("annulus", &s, &r);
    let cut = cut_to_disk(&s, &r.singularities).unwrap();
    cut.check(&s, &r.singularities).unwrap();
    check_comb("annulus", &s, &r, &cut);
    let cut_edges: Vec<usize> = (0..s.edges.len()).filter(|&e| cut.is_cut[e]).collect();
    // one path from the inner loop (radius 1) to the outer one (radius 2)
    assert!(!cut_edges.is_empty());
    let radius = |v: u32| {
        let p = s.positions[v as usize];
        (p[0] * p[0] + p[1] * p[1]).sqrt()
    };
    let ends: Vec<f64> = cut_edges
        .iter()
        .flat_map(|&e| s.edges[e])
        .filter(|&v| s.boundary_vertex[v as usize])
        .map(radius)
        .collect();
    assert!(ends.iter().any(|&r| (r - 1.0).abs() < 1e-9), "{ends:?}");
    assert!(ends.iter().any(|&r| (r - 2.0).abs() < 1e-9), "{ends:?}");
}

#[test]
fn components_with_and_without_constraints() {
    // a closed sphere (inverse iteration) beside a patch (fixed faces)
    let s = disjoint_union(&icosphere(3), &bumpy_square(12, 0.1));
    let r = field(&s);
    let sphere_vertices = icosphere(3).positions.len() as u32;
    let on_sphere: i64 = r
        .singularities
        .iter()
        .filter(|&&(v, _)| v < sphere_vertices)
        .map(|&(_, q)| i64::from(q))
        .sum();
    assert_eq!(on_sphere, 8);
    check_poincare_hopf("sphere + square", &s, &r);
    let cut = cut_to_disk(&s, &r.singularities).unwrap();
    cut.check(&s, &r.singularities).unwrap();
    check_comb("sphere + square", &s, &r, &cut);
}

#[test]
fn non_manifold_vertices_are_errors() {
    // two triangles sharing only vertex 0
    let p = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, -1.0, 0.0],
    ];
    let s = Surface::new(p, vec![[0, 1, 2], [0, 3, 4]]).unwrap();
    let e = cross_field(&s, &FieldOptions::default()).unwrap_err();
    assert_eq!(e, RemeshError::NonManifoldVertex { vertex: 0 }, "{e}");
    assert!(e.to_string().contains("vertex 0 is not manifold"), "{e}");
}

#[test]
fn the_checker_rejects_bad_cuts() {
    let s = torus(3.0, 1.0, 24, 8);
    let none = Cut {
        is_cut: vec![false; s.edges.len()],
    };
    let e = none.check(&s, &[]).unwrap_err();
    assert!(
        matches!(e, RemeshError::ComponentNotDisk { euler: 0, .. }),
        "{e}"
    );
    let s = icosphere(1);
    let r = field(&s);
    let cut = cut_to_disk(&s, &r.singularities[..1]).unwrap();
    let e = cut.check(&s, &r.singularities).unwrap_err();
    assert!(matches!(e, RemeshError::SingularOffCut { .. }), "{e}");
    // a singularity inside the cut-open surface: the field does not comb
    let e = cut.comb(&s, &r.field).unwrap_err();
    assert!(matches!(e, RemeshError::NotCombed { .. }), "{e}");
    assert!(e.to_string().contains("does not comb"), "{e}");
    assert_eq!(
        cut_to_disk(&s, &[(9999, 1)]).unwrap_err(),
        RemeshError::CutVertexOutOfRange {
            vertex: 9999,
            vertices: s.positions.len()
        }
    );
}

#[test]
fn bad_options_are_errors() {
    let s = icosphere(0);
    let opts = FieldOptions {
        sharp_degrees: f64::NAN,
        ..FieldOptions::default()
    };
    assert!(cross_field(&s, &opts).is_err());
    let opts = FieldOptions {
        unit_shift: 0.0,
        ..FieldOptions::default()
    };
    assert!(cross_field(&s, &opts).is_err());
}

/// `cargo test -p dualex-remesh --profile ci --test field_cut -- --ignored --nocapture`
#[test]
#[ignore]
fn timing_on_a_large_icosphere() {
    type Make = fn() -> Surface;
    let shapes: [(&str, Make); 3] = [
        ("icosphere(6)", || icosphere(6)),
        ("torus 224 × 224", || torus(3.0, 1.0, 224, 224)),
        ("icosphere(7)", || icosphere(7)),
    ];
    for (name, make) in shapes {
        let t0 = std::time::Instant::now();
        let s = make();
        let t1 = std::time::Instant::now();
        let r = field(&s);
        let t2 = std::time::Instant::now();
        let cut = cut_to_disk(&s, &r.singularities).unwrap();
        cut.comb(&s, &r.field).unwrap();
        let t3 = std::time::Instant::now();
        cut.check(&s, &r.singularities).unwrap();
        println!(
            "{name}: {} triangles; surface {:.3} s, field {:.3} s, cut + comb {:.3} s; {} singularities, {} cut edges",
            s.triangles.len(),
            (t1 - t0).as_secs_f64(),
            (t2 - t1).as_secs_f64(),
            (t3 - t2).as_secs_f64(),
            r.singularities.len(),
            cut.is_cut.iter().filter(|&&c| c).count()
        );
        for (lap, ms) in &r.laps {
            println!("  {lap}: {ms:.0} ms");
        }
    }
}

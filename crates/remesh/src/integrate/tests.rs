//! End-to-end tests: integrate, check the transitions, extract with the
//! real `dualex quad`.

use super::test_checks::*;
use super::test_meshes::*;
use super::*;
use crate::field::CrossField;

#[test]
fn flat_square_is_affine_with_integer_boundary() {
    let s = square(12, 0.3);
    // the same with an interior triangle first (where the gauge goes)
    let mut t = s.triangles.clone();
    t.rotate_left(12 * 5 + 5);
    let moved = Surface::new(s.positions.clone(), t).unwrap();
    assert!(!moved.boundary_vertex[moved.triangles[0][0] as usize]);
    for s in [s, moved] {
        let field = field_along(&s, |_| [1.0, 0.0, 0.0]);
        let cut = test_cut::cut(&s, &[]);
        assert!(cut.iter().all(|&c| !c), "a disk needs no cut");
        let (map, report) =
            integrate_report(&s, &field, &cut, &[], &opts(100, Rounding::Direct)).unwrap();
        assert_eq!(report.aligned_edges, 48);
        // u = 10·x + u₀, v = 10·y + v₀ at every corner, u₀, v₀ integers
        let p0 = s.positions[0];
        let [u0, v0] = map.coords[0][0];
        let q0 = s.positions[s.triangles[0][0] as usize];
        let (u0, v0) = (u0 - 10.0 * (q0[0] - p0[0]), v0 - 10.0 * (q0[1] - p0[1]));
        let integer = |x: f64| (x - x.round()).abs() < 1e-9;
        assert!(integer(u0) && integer(v0), "{u0} {v0}");
        for (f, t) in s.triangles.iter().enumerate() {
            for (i, &vertex) in t.iter().enumerate() {
                let q = s.positions[vertex as usize];
                let [u, v] = map.coords[f][i];
                assert!((u - u0 - 10.0 * (q[0] - p0[0])).abs() < 1e-9, "face {f}");
                assert!((v - v0 - 10.0 * (q[1] - p0[1])).abs() < 1e-9, "face {f}");
            }
        }
        let (quads, _, chi) = extract(&map);
        assert_eq!((quads, chi), (100, 1));
    }
}

#[test]
fn cube_transitions_are_grid_rotations() {
    let s = cube(5);
    let field = cube_field(&s);
    let corners = cube_corners(&s);
    assert_eq!(corners.len(), 8);
    let cut = test_cut::cut(&s, &corners);
    for rounding in [Rounding::Direct, Rounding::Greedy { rounds: 4 }] {
        let (map, report) =
            integrate_report(&s, &field, &cut, &corners, &opts(54, rounding)).unwrap();
        assert!(report.rotated_seams > 0, "{report:?}");
        assert_eq!(
            (report.quantize.conflicts, report.quantize.off_grid),
            (0, 0)
        );
        assert!(assert_grid_transitions(&s, &map) > 0);
        assert_eq!(reverted(&map), 0);
        let (quads, valence, chi) = extract(&map);
        assert_eq!((quads, chi), (54, 2), "{rounding:?}");
        assert_eq!(valence.iter().filter(|&&v| v == 3).count(), 8);
        assert!(valence.iter().all(|&v| v == 3 || v == 4));
    }
}

/// Sharp edges given to the integration lie on integer iso-lines of both
/// faces' charts, at a scale where the cube's corners alone would not put
/// them there; without them, not every one does.
#[test]
fn sharp_edges_are_aligned_to_iso_lines() {
    let s = cube(5);
    let field = cube_field(&s);
    let corners = cube_corners(&s);
    let cut = test_cut::cut(&s, &corners);
    let sharp = crate::features::sharp_edges(&s, 35.0);
    let n_sharp = sharp.iter().filter(|&&b| b).count();
    assert_eq!(n_sharp, 12 * 5);
    let aligned = |o: &IntegrateOptions| {
        let (map, report) = integrate_report(&s, &field, &cut, &corners, o).unwrap();
        let on = (0..s.edges.len())
            .filter(|&e| sharp[e])
            .filter(|&e| {
                s.edge_faces[e]
                    .iter()
                    .all(|&f| on_integer_iso_line(&s, &map, e, f))
            })
            .count();
        (report.aligned_edges, on, map)
    };
    let mut o = opts(80, Rounding::Direct);
    o.round_singularities = false;
    let (before, on_before, _) = aligned(&o);
    assert_eq!(before, 0);
    assert!(on_before < n_sharp, "{on_before}");
    o.sharp = sharp.clone();
    let (after, on_after, map) = aligned(&o);
    assert_eq!((after, on_after), (n_sharp, n_sharp));
    assert_eq!(reverted(&map), 0);
    let (_, _, chi) = extract(&map);
    assert_eq!(chi, 2);
}

#[test]
fn representative_angles_do_not_matter() {
    // the same cross field with each face's angle turned by k·π/2
    let s = cube(4);
    let mut field = cube_field(&s);
    for (f, a) in field.angle.iter_mut().enumerate() {
        *a += ((f * 7 + f / 3) % 4) as f64 * std::f64::consts::FRAC_PI_2;
    }
    let field = CrossField::from_angles(&s, field.angle);
    let corners = cube_corners(&s);
    let cut = test_cut::cut(&s, &corners);
    let map = integrate(&s, &field, &cut, &corners, &opts(96, Rounding::Direct)).unwrap();
    assert_grid_transitions(&s, &map);
    let (quads, valence, _) = extract(&map);
    assert_eq!(quads, 96);
    assert_eq!(valence.iter().filter(|&&v| v == 3).count(), 8);
}

#[test]
fn torus_gives_a_closed_quad_mesh() {
    let s = torus(72, 24);
    let field = field_along(&s, |c| [-c[1], c[0], 0.0]);
    let cut = test_cut::cut(&s, &[]);
    let n = 400;
    let (map, report) =
        integrate_report(&s, &field, &cut, &[], &opts(n, Rounding::Direct)).unwrap();
    assert_eq!(report.rotated_seams, 0);
    assert_grid_transitions(&s, &map);
    assert_eq!(reverted(&map), 0);
    let (quads, valence, chi) = extract(&map);
    assert_eq!(chi, 0);
    assert!(valence.iter().all(|&v| v == 4));
    assert!(quads.abs_diff(n) * 10 <= n, "{quads} quads for {n}");
}

#[test]
fn continuous_map_is_seamless_but_off_the_grid() {
    let s = cube(4);
    let field = cube_field(&s);
    let corners = cube_corners(&s);
    let cut = test_cut::cut(&s, &corners);
    let o = opts(60, Rounding::Continuous);
    let (map, report) = integrate_report(&s, &field, &cut, &corners, &o).unwrap();
    assert_eq!(report.quantize.solves, 1);
    // corners sit at multiples of sqrt(10): not integers
    let off = map
        .coords
        .iter()
        .flatten()
        .flatten()
        .any(|x| (x - x.round()).abs() > 1e-3);
    assert!(off);
}

#[test]
fn bad_cuts_are_refused() {
    let s = cube(3);
    let field = cube_field(&s);
    let corners = cube_corners(&s);
    let none = vec![false; s.edges.len()];
    let e = integrate(&s, &field, &none, &corners, &IntegrateOptions::default()).unwrap_err();
    assert!(matches!(e, RemeshError::CutMissesSingularity { .. }), "{e}");
    let t = torus(12, 6);
    let tf = field_along(&t, |c| [-c[1], c[0], 0.0]);
    let none = vec![false; t.edges.len()];
    let e = integrate(&t, &tf, &none, &[], &IntegrateOptions::default()).unwrap_err();
    assert!(matches!(e, RemeshError::NotDisks { .. }), "{e}");
    let mut nan = tf.clone();
    nan.angle[3] = f64::NAN;
    let e = integrate(&t, &nan, &none, &[], &IntegrateOptions::default()).unwrap_err();
    assert_eq!(e.to_string(), "integrate: face 3 has angle NaN");
    let o = IntegrateOptions {
        quads: Some(0),
        ..IntegrateOptions::default()
    };
    let e = integrate(&t, &tf, &none, &[], &o).unwrap_err();
    assert_eq!(e, RemeshError::Scale(0.0), "{e}");
}

/// Speed on ~100k triangles (README.md, "Speed"):
/// `cargo test -p dualex-remesh --profile ci -- --ignored --nocapture timing`.
#[test]
#[ignore = "a measurement, run by hand"]
fn timing_100k_triangles() {
    use std::time::Instant;
    let wavy = |s: &Surface| {
        // ±¼ turn around 40 points: about 40 singularities
        let mut state = 0x9e3779b97f4a7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % 10_000) as f64 / 10_000.0
        };
        let points: Vec<(f64, f64, f64)> = (0..40)
            .map(|i| (next(), next(), if i % 2 == 0 { 0.25 } else { -0.25 }))
            .collect();
        field_along(s, move |c| {
            let a: f64 = points
                .iter()
                .map(|&(x, y, k)| k * (c[1] - y).atan2(c[0] - x))
                .sum();
            [a.cos(), a.sin(), 0.0]
        })
    };
    let cases: Vec<(&str, Surface)> = vec![
        ("cube 6·91²·2", cube(91)),
        ("torus 354×141·2", torus(354, 141)),
        ("square 224²·2, 40 point singularities", square(224, 0.2)),
    ];
    for (name, s) in cases {
        let t0 = Instant::now();
        let (field, singular) = if name.starts_with("cube") {
            (cube_field(&s), cube_corners(&s))
        } else if name.starts_with("torus") {
            (field_along(&s, |c| [-c[1], c[0], 0.0]), Vec::new())
        } else {
            let f = wavy(&s);
            let sing = singular_by_matchings(&s, &f);
            (f, sing)
        };
        let cut = test_cut::cut(&s, &singular);
        let prep = t0.elapsed().as_secs_f64();
        for rounding in [
            Rounding::Continuous,
            Rounding::Direct,
            Rounding::Greedy { rounds: 4 },
        ] {
            let t1 = Instant::now();
            let (map, r) =
                integrate_report(&s, &field, &cut, &singular, &opts(20_000, rounding)).unwrap();
            let dt = t1.elapsed().as_secs_f64();
            let t2 = Instant::now();
            let quads = if rounding == Rounding::Continuous {
                0
            } else {
                extract(&map).0
            };
            println!(
                "{name}: {} triangles, {} singular, {} wedges, {} seams; field+cut {prep:.2} s; {rounding:?}: integrate {dt:.2} s ({} solves, {} rounded, {} off grid); extraction {:.2} s, {quads} quads",
                s.triangles.len(),
                singular.len(),
                r.wedges,
                r.seams,
                r.quantize.solves,
                r.quantize.rounded,
                r.quantize.off_grid,
                t2.elapsed().as_secs_f64()
            );
        }
    }
}

#[test]
fn singularities_may_stay_off_the_grid() {
    // sqrt(10) quads per cube edge: the continuous corners are off the grid
    let s = cube(4);
    let field = cube_field(&s);
    let corners = cube_corners(&s);
    let cut = test_cut::cut(&s, &corners);
    let mut o = opts(60, Rounding::Direct);
    o.round_singularities = false;
    let (map, report) = integrate_report(&s, &field, &cut, &corners, &o).unwrap();
    assert!(report.quantize.rounded > 0);
    // the translations are integers all the same…
    assert!(assert_grid_transitions(&s, &map) > 0);
    // …which puts the corners (quarter-turn fixed points) on the
    // half-integer lattice (the energy happens to prefer integers here)
    for (f, t) in s.triangles.iter().enumerate() {
        for (i, v) in t.iter().enumerate() {
            if corners.contains(v) {
                for x in map.coords[f][i] {
                    assert!((2.0 * x - (2.0 * x).round()).abs() < 1e-9, "{x}");
                }
            }
        }
    }
}

#[test]
fn boundary_alignment_follows_the_tolerance() {
    let s = square(10, 0.0);
    let cut = test_cut::cut(&s, &[]);
    // 10° off the boundary: still aligned, the boundary on iso-lines
    let turned = field_along(&s, |_| {
        [10f64.to_radians().cos(), 10f64.to_radians().sin(), 0.0]
    });
    let (map, report) =
        integrate_report(&s, &turned, &cut, &[], &opts(100, Rounding::Direct)).unwrap();
    assert_eq!(report.aligned_edges, 40);
    for (e, &[f, f1]) in s.edge_faces.iter().enumerate() {
        if f1 != crate::NO_FACE {
            continue;
        }
        assert!(on_integer_iso_line(&s, &map, e, f), "boundary edge {e}");
    }
    let (quads, _, chi) = extract(&map);
    assert_eq!(chi, 1);
    assert!(quads.abs_diff(100) <= 10, "{quads}");
    // 45° off: no edge is aligned
    let diagonal = field_along(&s, |_| [1.0, 1.0, 0.0]);
    let (_, report) =
        integrate_report(&s, &diagonal, &cut, &[], &opts(100, Rounding::Direct)).unwrap();
    assert_eq!(report.aligned_edges, 0);
    // no alignment asked
    let mut o = opts(100, Rounding::Direct);
    o.align_boundary = None;
    let (_, report) = integrate_report(&s, &turned, &cut, &[], &o).unwrap();
    assert_eq!(report.aligned_edges, 0);
}

#[test]
fn sphere_with_projected_cube_field() {
    let k = 12;
    let mut s = cube(k);
    for p in &mut s.positions {
        let c = p.map(|x| x - 0.5);
        let n = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
        *p = c.map(|x| x / n);
    }
    let s = Surface::new(s.positions, s.triangles).unwrap();
    let per_side = 4 * k * k;
    let angles = (0..s.triangles.len())
        .map(|f| {
            let mut d = [0.0; 3];
            d[(f / per_side + 1) % 3] = 1.0;
            let [x, y] = s.in_frame(f as u32, d);
            y.atan2(x)
        })
        .collect();
    let field = CrossField::from_angles(&s, angles);
    let singular = singular_by_matchings(&s, &field);
    assert_eq!(singular.len(), 8);
    let cut = test_cut::cut(&s, &singular);
    let n = 300;
    for rounding in [Rounding::Direct, Rounding::Greedy { rounds: 3 }] {
        let (map, report) =
            integrate_report(&s, &field, &cut, &singular, &opts(n, rounding)).unwrap();
        assert_eq!(
            (report.quantize.conflicts, report.quantize.off_grid),
            (0, 0)
        );
        assert!(assert_grid_transitions(&s, &map) > 0);
        assert_eq!(reverted(&map), 0, "{rounding:?}");
        let (quads, valence, chi) = extract(&map);
        assert_eq!(chi, 2, "{rounding:?}");
        assert_eq!(valence.iter().filter(|&&v| v == 3).count(), 8);
        assert!(
            quads.abs_diff(n) * 10 <= n,
            "{quads} quads for {n}, {rounding:?}"
        );
    }
}

#[test]
fn square_with_a_hole_needs_a_seam() {
    // hole [1/3, 2/3]², 10 quads per unit: its sides at 3.33 and 6.67
    let s = square_with_hole(15, 5, 10);
    assert_eq!(s.euler_characteristic(), 0);
    let field = field_along(&s, |_| [1.0, 0.0, 0.0]);
    let cut = test_cut::cut(&s, &[]);
    assert!(cut.iter().any(|&c| c), "an annulus needs a cut");
    // every side rounds to its nearest line (3 and 7: a hole of 4 × 4),
    // greedy too: rounding one side hardly moves the opposite one
    for (rounding, solves) in [
        (Rounding::Direct, 2..=2),
        (Rounding::Greedy { rounds: 1 }, 2..=2),
        (Rounding::Greedy { rounds: 20 }, 3..=21),
    ] {
        // the scale as asked: no fit to the area
        let o = IntegrateOptions {
            fit_area: false,
            ..opts(89, rounding)
        };
        let (map, report) = integrate_report(&s, &field, &cut, &[], &o).unwrap();
        assert!((report.scale - 10.0).abs() < 0.01, "{report:?}");
        assert_eq!((report.aligned_edges, report.rotated_seams), (80, 0));
        assert_grid_transitions(&s, &map);
        assert_eq!(reverted(&map), 0);
        let (quads, valence, chi) = extract(&map);
        assert_eq!((quads, chi), (84, 0), "{rounding:?}");
        assert!(solves.contains(&report.quantize.solves), "{report:?}");
        assert!(valence.iter().all(|&v| v <= 4));
    }
}

#[test]
fn noisy_field_with_many_singularities() {
    // random angles: a singularity at most vertices, a long cut, rounding
    // in every order still lands every integer unknown on the integers
    let s = square(24, 0.2);
    let mut state = 0x2545f4914f6cdd1du64;
    let angles = (0..s.triangles.len())
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % 1000) as f64 / 1000.0 * 1.6
        })
        .collect();
    let field = CrossField::from_angles(&s, angles);
    let singular = singular_by_matchings(&s, &field);
    assert!(singular.len() > 100, "{}", singular.len());
    let cut = test_cut::cut(&s, &singular);
    for rounding in [Rounding::Direct, Rounding::Greedy { rounds: 5 }] {
        for align in [None, Some(0.3)] {
            for round_singularities in [false, true] {
                let o = IntegrateOptions {
                    align_boundary: align,
                    round_singularities,
                    ..opts(400, rounding)
                };
                let (map, report) = integrate_report(&s, &field, &cut, &singular, &o).unwrap();
                let q = &report.quantize;
                assert_eq!((q.conflicts, q.off_grid), (0, 0), "{report:?}");
                assert!(report.rotated_seams > 0);
                assert_grid_transitions(&s, &map);
                // messy, but a map the extraction takes
                dualex::quad(&map, &dualex::Options::default()).expect("extraction");
            }
        }
    }
}

#[test]
fn two_components_each_get_a_gauge() {
    // two unit squares side by side, not connected; cut flags on the
    // boundary are ignored
    let a = square(8, 0.25);
    let n = a.positions.len() as u32;
    let mut p = a.positions.clone();
    p.extend(a.positions.iter().map(|q| [q[0] + 3.0, q[1], q[2]]));
    let mut t = a.triangles.clone();
    t.extend(a.triangles.iter().map(|f| f.map(|v| v + n)));
    let s = Surface::new(p, t).unwrap();
    let field = field_along(&s, |_| [0.0, 1.0, 0.0]);
    let cut: Vec<bool> = (0..s.edges.len() as u32)
        .map(|e| s.is_boundary_edge(e))
        .collect();
    let (map, report) =
        integrate_report(&s, &field, &cut, &[], &opts(200, Rounding::Direct)).unwrap();
    assert_eq!((report.seams, report.quantize.off_grid), (0, 0));
    assert_eq!(reverted(&map), 0);
    let (quads, _, chi) = extract(&map);
    assert_eq!((quads, chi), (200, 2));
}

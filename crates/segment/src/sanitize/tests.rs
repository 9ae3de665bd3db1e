//! Tests of [`super::sanitize`] and its per-dimension tests, one module
//! per dimension.

mod dim2 {
    use crate::grid::{
        box_bounds, box_spans, grid_point_near_segment as grid_point_near_edge, near_int, EPS,
    };
    /// The local map at D = 2.
    type LocalMap = crate::local::LocalMap<3, 2>;
    use crate::sanitize::{sanitize, Scan as BadScan};
    use dualex_map::{Stars, Topology};
    use dualex_util::rng::SplitMix;

    fn edge_near_grid_point(a: &[f64; 2], b: &[f64; 2]) -> bool {
        grid_point_near_edge(a, b).is_some()
    }

    /// Whether `[lo, hi]` of `a`, `b` on `axis`, grown by `2·EPS`, holds an
    /// integer (the reference formulation of the test in [`tri_mask`]).
    fn spans_integer(a: &[f64; 2], b: &[f64; 2], axis: usize) -> bool {
        (a[axis].min(b[axis]) - 2.0 * EPS).ceil() <= a[axis].max(b[axis]) + 2.0 * EPS
    }

    /// The incremental scan equals a full unfiltered scan (every triangle,
    /// every edge tested) after moves onto isos, through grid points, and
    /// random steps.
    #[test]
    fn incremental_scan_equals_full_scan() {
        use dualex_map::{Topology, Transitions};
        let alt = dualex_gen::Diagonal::Alternating;
        let (map, _) = dualex_gen::square_noise(12, 0.2, 6.2, 0.3, 4, alt);
        let topo = Topology::build(&map).unwrap_or_else(|e| panic!("{e}"));
        let (trans, _) =
            Transitions::derive(&map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
        let stars = Stars::build(&map, &topo, &trans);
        let mut local = LocalMap::new(&map, &topo, &trans);
        // every triangle tested without the box filters, as in the paper
        let full = |local: &LocalMap| {
            let mut bad = vec![false; map.positions.len()];
            for (tri, c) in map.simplices.iter().zip(&local.coords) {
                for k in 0..3 {
                    let l = (k + 1) % 3;
                    bad[tri[k] as usize] |= near_int(c[k][0]) || near_int(c[k][1]);
                    if let Some(g) = grid_point_near_edge(&c[k], &c[l]) {
                        let dist = crate::grid::dist2d;
                        let (at_k, at_l) = (dist(&g, &c[k]) < EPS, dist(&g, &c[l]) < EPS);
                        bad[tri[k] as usize] |= at_k || !at_l;
                        bad[tri[l] as usize] |= at_l || !at_k;
                    }
                }
            }
            (0..bad.len() as u32)
                .filter(|&v| bad[v as usize])
                .collect::<Vec<u32>>()
        };
        let mut scan = BadScan::new(&map, &local.coords);
        assert_eq!(scan.list(), full(&local));
        let mut rng = SplitMix::new(9);
        let nv = map.positions.len();
        for round in 0..24 {
            let v = ((rng.angle() / std::f64::consts::TAU).abs() * nv as f64) as usize % nv;
            let e = stars.of(v)[0];
            let x = local.coords[e.simplex as usize][e.corner as usize];
            let d = match round % 3 {
                0 => [x[0].round() - x[0], 0.0],
                1 => [x[0].round() - x[0], x[1].round() - x[1]],
                _ => [0.3 * rng.angle().cos(), 0.3 * rng.angle().sin()],
            };
            local.move_vertex(&stars, v, &d);
            scan.update(&map, &stars, &local.coords, &[v as u32]);
            let want = full(&local);
            assert!(
                round % 3 == 2 || want.contains(&(v as u32)),
                "round {round}"
            );
            assert_eq!(scan.list(), want, "round {round}");
        }
        // many vertices at once (the update's one pass over everything),
        // some of them onto isos
        for round in 0..4 {
            let moved: Vec<u32> = (0..nv as u32).filter(|v| v % 4 != round).collect();
            for &v in &moved {
                let e = stars.of(v as usize)[0];
                let x = local.coords[e.simplex as usize][e.corner as usize];
                let d = if v % 3 == 0 {
                    [x[0].round() - x[0], 0.0]
                } else {
                    [0.2 * rng.angle().cos(), 0.2 * rng.angle().sin()]
                };
                local.move_vertex(&stars, v as usize, &d);
            }
            scan.update(&map, &stars, &local.coords, &moved);
            assert_eq!(scan.list(), full(&local), "many, round {round}");
        }
    }

    /// The box prefilter of [`tri_mask`] never hides a grid point.
    #[test]
    fn edges_whose_box_holds_no_grid_point_are_never_near_one() {
        let mut rng = SplitMix::new(3);
        let mut near = 0;
        for k in 0..20000 {
            let mut p = || 4.0 * rng.angle().sin();
            let (a, b) = ([p(), p()], [p(), p()]);
            // every other edge starts exactly on a grid point
            let a = if k % 2 == 0 { a.map(f64::round) } else { a };
            if grid_point_near_edge(&a, &b).is_some() {
                near += 1;
                assert!(spans_integer(&a, &b, 0) && spans_integer(&a, &b, 1));
            }
        }
        assert!(near >= 10000);
    }

    /// The box test of [`tri_mask`] equals [`spans_integer`], also for
    /// ends within a few `EPS` of integers.
    #[test]
    fn box_test_equals_reference() {
        let mut rng = SplitMix::new(5);
        for _ in 0..50000 {
            let mut p = || {
                let x = 6.0 * rng.unit() - 3.0;
                match (rng.unit() * 4.0) as u32 {
                    0 => x.round() + EPS * (rng.unit() * 6.0 - 3.0).round(),
                    1 => x.round(),
                    _ => x,
                }
            };
            let (a, b) = ([p(), p()], [p(), p()]);
            for axis in 0..2 {
                let fast = box_spans(box_bounds(a[axis]), box_bounds(b[axis]));
                assert_eq!(fast, spans_integer(&a, &b, axis), "{a:?} {b:?}");
            }
        }
    }

    /// A stuck cluster (the first ring of a 90° cone disk collapsed onto
    /// the cone, a node: its collapsed edges go once around the cone, so
    /// their rotations disagree) cannot move as one; the extra rounds move
    /// its members one by one, and nothing non-singular is left on the grid.
    #[test]
    fn extra_rounds_move_a_stuck_cluster_apart() {
        use crate::grid_offset::GridOffset;
        use dualex_map::Transitions;
        let (map, _) = dualex_gen::singular_disk(1, false, 3, 8, 3.0).expect("disk");
        let topo = Topology::build(&map).unwrap_or_else(|e| panic!("{e}"));
        let (trans, _) =
            Transitions::derive(&map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
        let stars = Stars::build(&map, &topo, &trans);
        let mut local = LocalMap::with_grid(&map, &topo, trans, GridOffset::Zero);
        let radius = |v: u32| {
            let p = map.positions[v as usize];
            (p[0] * p[0] + p[1] * p[1]).sqrt()
        };
        let ring: Vec<bool> = (0..map.positions.len() as u32)
            .map(|v| (0.1..0.5).contains(&radius(v)))
            .collect();
        assert_eq!(ring.iter().filter(|&&r| r).count(), 8);
        for (s, tri) in map.simplices.iter().enumerate() {
            // the cone (map origin) in this chart
            let shift = [0, 1].map(|a| local.coords[s][0][a] - map.coords[s][0][a]);
            for k in 0..3 {
                if ring[tri[k] as usize] {
                    local.coords[s][k] = shift;
                }
            }
        }
        let rep = sanitize(&map, &topo, &stars, &[], &mut local, 7);
        assert_eq!(rep.clusters, 1, "{rep:?}");
        assert_eq!(rep.stuck_clusters, 1, "{rep:?}");
        assert_eq!(rep.clusters_moved_apart, 1, "{rep:?}");
        assert!(rep.extra_rounds >= 1, "{rep:?}");
        assert_eq!(rep.unresolved, 0, "{rep:?}");
        // the cone itself stays on its node
        assert_eq!(rep.singular_on_iso.len(), 1, "{rep:?}");
        assert_eq!(rep.singular_kinds.get("90_node"), Some(&1), "{rep:?}");
        assert!(rep.leftovers().is_some_and(|l| l.contains("1 singular")));
        // every ring vertex moved off the node, consistently in its charts
        for v in (0..ring.len()).filter(|&v| ring[v]) {
            let first = stars.of(v)[0];
            let x = local.coords[first.simplex as usize][first.corner as usize];
            assert!(!near_int(x[0]) && !near_int(x[1]), "{v}: {x:?}");
        }
    }

    #[test]
    fn edge_through_grid_point_is_detected() {
        assert!(edge_near_grid_point(&[0.5, 0.5], &[1.5, 1.5]));
        assert!(!edge_near_grid_point(&[0.5, 0.6], &[1.5, 1.7]));
        assert!(!edge_near_grid_point(&[2.0, 0.3], &[2.0, 0.3]));
        assert!(edge_near_grid_point(&[3.0, -1.5], &[3.0, 1.5]));
        // vertical edge crossing a grid point
        assert!(edge_near_grid_point(&[-2.0, 0.5], &[-2.0, 3.5]));
        // a point edge exactly on a grid point
        assert!(edge_near_grid_point(&[4.0, 4.0], &[4.0, 4.0]));
    }
}

mod dim3 {
    /// The local map at D = 3.
    type LocalMap = crate::local::LocalMap<4, 3>;
    use crate::near::{
        face_corners, near_int, segment_near_iso_line, triangle_near_grid_point, EDGES, EPS,
        FACE_EDGES,
    };
    use crate::sanitize::{free_axes, sanitize, singular_free_axis};
    use dualex_map::{Stars, TetMap, Topology, Transitions};
    use dualex_util::rng::SplitMix;

    /// Whether the box of `pts` (grown by `2·EPS`) holds an integer on `axis`
    /// (the reference formulation of [`crate::boxes::Boxes::spans`]).
    fn spans_integer(pts: &[&[f64; 3]], axis: usize) -> bool {
        let x = pts.iter().map(|p| p[axis]);
        let (lo, hi) = (
            x.clone().fold(f64::INFINITY, f64::min),
            x.fold(-f64::INFINITY, f64::max),
        );
        (lo - 2.0 * EPS).ceil() <= hi + 2.0 * EPS
    }

    /// The box prefilter of [`tet_mask`] never hides an iso-line or a grid
    /// point: whenever the exact tests find one, the box spans integers.
    #[test]
    fn boxes_without_integers_are_never_near_the_grid() {
        let mut rng = SplitMix::new(11);
        let (mut edges, mut faces) = (0, 0);
        for k in 0..20000 {
            let mut p = || rng.direction().map(|x| 3.0 * x);
            let mut t = [p(), p(), p()];
            // a grid point on an edge, or inside the face
            let g = t[0].map(f64::round);
            t[0] = g;
            if k % 2 == 1 {
                t[0] = std::array::from_fn(|a| 3.0 * g[a] - t[1][a] - t[2][a]);
            }
            let count = |pts: &[&[f64; 3]]| (0..3).filter(|&a| spans_integer(pts, a)).count();
            if segment_near_iso_line(&t[0], &t[1]).is_some() {
                edges += 1;
                assert!(count(&[&t[0], &t[1]]) >= 2);
            }
            if triangle_near_grid_point(&t) {
                faces += 1;
                assert_eq!(count(&[&t[0], &t[1], &t[2]]), 3);
            }
        }
        assert!(edges >= 5000 && faces >= 1000, "{edges} {faces}");
    }

    /// [`crate::boxes::Boxes::spans`] equals [`spans_integer`] on every edge, and so does
    /// the union over its edges on every face, also for corners within a
    /// few `EPS` of integers; [`FACE_EDGES`] are the edges of each face.
    #[test]
    fn box_test_equals_reference() {
        for (f, edges) in FACE_EDGES.iter().enumerate() {
            let mut want: Vec<[usize; 2]> = edges.iter().map(|&e| EDGES[e]).collect();
            let fc = face_corners(f);
            let mut got = vec![[fc[0], fc[1]], [fc[0], fc[2]], [fc[1], fc[2]]];
            for e in want.iter_mut().chain(got.iter_mut()) {
                e.sort_unstable();
            }
            want.sort_unstable();
            got.sort_unstable();
            assert_eq!(want, got, "face {f}");
        }
        let mut rng = SplitMix::new(17);
        for _ in 0..20000 {
            let c: [[f64; 3]; 4] = std::array::from_fn(|_| {
                rng.direction().map(|x| {
                    let x = 3.0 * x;
                    match (rng.unit() * 4.0) as u32 {
                        0 => x.round() + EPS * (rng.unit() * 6.0 - 3.0).round(),
                        1 => x.round(),
                        _ => x,
                    }
                })
            });
            let boxes = crate::boxes::Boxes::of(&c);
            let span = boxes.edge_spans(&EDGES);
            for a in 0..3 {
                for (e, &[k, l]) in EDGES.iter().enumerate() {
                    let want = spans_integer(&[&c[k], &c[l]], a);
                    assert_eq!(span[e] >> a & 1 != 0, want, "{c:?}");
                }
                for (f, edges) in FACE_EDGES.iter().enumerate() {
                    let want = spans_integer(&face_corners(f).map(|i| &c[i]), a);
                    let got = edges.iter().any(|&e| span[e] >> a & 1 != 0);
                    assert_eq!(got, want, "{c:?}");
                }
            }
        }
    }

    /// The scan's tet test ([`Predicates::mask`], with its box filters)
    /// equals the unfiltered tests of [`crate::near::bad_vertices`] on tets
    /// near integers, on isos, through grid points and spanning 0–3 axes.
    #[test]
    fn mask_equals_unfiltered_tests() {
        use crate::sanitize::{Dim, Predicates};
        let mut rng = SplitMix::new(23);
        let mut kinds = [0usize; 4];
        for _ in 0..40000 {
            let base: [f64; 3] = std::array::from_fn(|_| {
                [0.2, 0.6, 0.97][(rng.unit() * 3.0) as usize] + (rng.unit() * 4.0).floor()
            });
            let size = [0.05, 0.3, 0.5, 1.5][(rng.unit() * 4.0) as usize];
            let c: [[f64; 3]; 4] = std::array::from_fn(|_| {
                std::array::from_fn(|a| {
                    let x = base[a] + size * rng.unit();
                    match (rng.unit() * 20.0) as u32 {
                        0 => x.round() + EPS * (rng.unit() * 6.0 - 3.0).round(),
                        1 => x.round(),
                        _ => x,
                    }
                })
            });
            let want = crate::sanitize::mask_tests::mask_unfiltered(&c);
            assert_eq!(<Dim<4, 3>>::mask(&c), want, "{c:?}");
            let axes = crate::boxes::Boxes::of(&c).spanned();
            kinds[axes.count_ones() as usize] += 1;
        }
        assert!(kinds.iter().all(|&n| n > 500), "{kinds:?}");
    }

    /// Two fans of `k` tets around the vertical edges A–M and M–B (A, M, B
    /// = vertices 0, 1, 2, then the rim), each tet right-angled at the
    /// edge in its own chart: for `k ≠ 4` one singular edge A–M–B through
    /// the inner vertex M (whose link, `A`, `B` and the rim, is a sphere).
    /// Map coordinates `w` shifted by ½: under the offset ½ (local
    /// coordinates + ½) M lies on the iso-surface `w = 1` across the edge,
    /// off the isos along it.
    fn double_fan(k: u32) -> TetMap {
        let mut m = TetMap::default();
        m.positions
            .extend([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 2.0]]);
        for i in 0..k {
            let a = std::f64::consts::TAU * f64::from(i) / f64::from(k);
            m.positions.push([a.cos(), a.sin(), 1.0]);
        }
        let (u, v) = ([1.0, 0.0, 0.5], [0.0, 1.0, 0.5]);
        for i in 0..k {
            let (r, s) = (i + 3, (i + 1) % k + 3);
            m.simplices.push([0, 1, r, s]);
            m.coords.push([[0.0, 0.0, -0.5], [0.0, 0.0, 0.5], u, v]);
            m.simplices.push([1, 2, r, s]);
            m.coords.push([[0.0, 0.0, 0.5], [0.0, 0.0, 1.5], u, v]);
        }
        m
    }

    /// A vertex inside a singular edge, on an iso-surface across it, moves
    /// along the edge's axis only: its other coordinates are bit-identical
    /// in every chart, and it leaves the iso.
    #[test]
    fn singular_vertex_moves_along_its_edge_only() {
        let map = double_fan(3);
        let topo = Topology::build(&map).unwrap_or_else(|e| panic!("{e}"));
        let (trans, _) =
            Transitions::derive(&map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
        let stars = Stars::build(&map, &topo, &trans);
        let mut local = LocalMap::new(&map, &topo, &trans);
        let m = 1;
        assert!(stars.singular[m]);
        assert_eq!(singular_free_axis(&topo, &stars, &local.trans, m), Some(2));
        let corners = |local: &LocalMap| -> Vec<[f64; 3]> {
            stars
                .of(m)
                .iter()
                .map(|e| local.coords[e.simplex as usize][e.corner as usize])
                .collect()
        };
        let before = corners(&local);
        assert_eq!(before.len(), 6);
        assert!(before
            .iter()
            .all(|x| near_int(x[2]) && !near_int(x[0]) && !near_int(x[1])));
        let free = free_axes(&topo, &stars, &local);
        let rep = sanitize(&map, &topo, &stars, &free, &mut local, 3);
        let after = corners(&local);
        for (b, a) in before.iter().zip(&after) {
            assert_eq!(a[0].to_bits(), b[0].to_bits(), "{b:?} → {a:?}");
            assert_eq!(a[1].to_bits(), b[1].to_bits(), "{b:?} → {a:?}");
            assert!(a[2] != b[2] && !near_int(a[2]), "{b:?} → {a:?}");
        }
        // the same move in every chart (the charts' w axes agree; charts
        // differ by integer offsets, so up to rounding)
        let dw = after[0][2] - before[0][2];
        let same = |(b, a): (&[f64; 3], &[f64; 3])| (a[2] - b[2] - dw).abs() < 1e-12;
        assert!(
            before.iter().zip(&after).all(same),
            "{before:?} → {after:?}"
        );
        assert!(rep.singular_moved >= 1, "{rep:?}");
        assert!(rep.singular_on_iso.is_empty(), "{rep:?}");
        assert_eq!(rep.unresolved, 0, "{rep:?}");
        assert_eq!(rep.leftovers(), None, "{rep:?}");
    }
}

/// The steps of a round drawn at their places ([`SplitMix::ahead`], as
/// `Mover::round` draws them in parallel) are those drawn one after the
/// other, in both dimensions.
mod steps_ahead {
    use crate::sanitize::mover::STEP_DRAWS;
    use crate::sanitize::{Dim, Predicates};
    use dualex_util::rng::SplitMix;

    fn same_steps<const N: usize, const D: usize>()
    where
        Dim<N, D>: Predicates<N, D>,
    {
        let step = <Dim<N, D>>::step;
        let rng = SplitMix::new(5);
        let per = rng.draws_of(STEP_DRAWS, |r| {
            step(r, 1e-5);
        });
        let per = per.expect("a step draws at most STEP_DRAWS values");
        let mut in_turn = rng.clone();
        for i in 0..100 {
            let want = step(&mut in_turn, 1e-5);
            assert_eq!(step(&mut rng.ahead(i * per), 1e-5), want, "step {i}");
        }
    }

    #[test]
    fn steps_drawn_ahead_are_drawn_in_turn() {
        same_steps::<3, 2>();
        same_steps::<4, 3>();
    }
}

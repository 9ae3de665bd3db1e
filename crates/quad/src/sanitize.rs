//! Step 2: sanitization of the local shifted map (paper appendix,
//! "Sanitization"; DESIGN §3.1).
//!
//! Input: [`LocalMap`], vertex [`Stars`]. Output: the same map with
//! - every non-singular vertex's corners **snapped** to one exactly-GP value
//!   (the reference corner carried through the star's rotations plus the
//!   nearest integer translation), so sign tests agree between charts;
//! - every vertex, edge and node at least `eps` away from the dual isos:
//!   no corner coordinate within `eps` of an integer, no edge within `eps`
//!   of an integer point. Offending vertices are moved by one small vector
//!   in their reference chart, carried to every corner through the star's
//!   rotations (translations untouched: no transition changes). Vertices
//!   joined by zero-length map edges (collapsed regions) move as one cluster.
//!
//! The amplitude follows [`dualex_segment::sanitize_report::amplitude`]: 40
//! ordinary rounds, then extra rounds of growing amplitude (up to 0.1) while
//! a non-singular vertex is still on the grid. A stuck cluster (its
//! rotations disagree: it surrounds a singularity) waits for the extra
//! rounds, where its members move one by one (the last resort: each is
//! non-singular, so consistent in its own charts; the collapsed region
//! opens into slivers). Whatever is left is in
//! [`SanitizeReport::leftovers`].
//!
//! Singular vertices cannot move (their charts disagree around them, so no
//! single vector moves all their corners consistently); in an exactly GP map
//! a 90° singularity sits on a grid point or on a node, a 180° one possibly
//! on one iso. Those left on an iso are reported in
//! [`SanitizeReport::singular_on_iso`] by kind; walks that reach them end
//! unmatched and the repair step (`crate::repair`) closes what they leave.
//!
//! Coordinates are local (see [`crate::local`]), so `eps` is absolute.

use crate::local::LocalMap;
use crate::rng::SplitMix;
use dualex_map::{Stars, Topology, TriMap};

/// The collapsed clusters of a triangle map (moved as one).
type Clusters = dualex_segment::cluster::Clusters<2>;

pub use dualex_segment::grid::EPS;
use dualex_segment::sanitize_report::{amplitude, ROUNDS};
pub use dualex_segment::sanitize_report::{SanitizeReport, AMPLITUDE};

/// Sanitizes `local` in place.
pub fn sanitize(
    map: &TriMap,
    topo: &Topology<3>,
    stars: &Stars<2>,
    local: &mut LocalMap,
    seed: u64,
) -> SanitizeReport {
    let mut rep = SanitizeReport::default();
    (rep.snapped_vertices, rep.max_snap) = local.snap(stars);
    let clusters = Clusters::build(map, stars, &local.coords);
    rep.clusters = clusters.count_nontrivial();
    let mut rng = SplitMix::new(seed);
    let mut moved = vec![false; map.positions.len()];
    let mut scan = BadScan::new(map, stars, local);
    let mut touched = Vec::new();
    // the last round in which each cluster root moved
    let mut done_round = vec![usize::MAX; map.positions.len()];
    let mut stuck = std::collections::BTreeSet::new();
    let mut apart = std::collections::BTreeSet::new();
    let mut bad = scan.list();
    let mut executed: usize = 0;
    for round in 0.. {
        let movable: Vec<u32> = bad
            .iter()
            .copied()
            .filter(|&v| !stars.singular[v as usize])
            .collect();
        if movable.is_empty() {
            rep.rounds = round;
            break;
        }
        let Some(amp) = amplitude(round) else {
            break;
        };
        rep.rounds = round;
        executed += 1;
        for v in movable {
            let root = clusters.root(v);
            let members = clusters.members_rot(root);
            if members.is_none() && round >= ROUNDS {
                // the last resort for a stuck cluster: its members one by
                // one (each is non-singular: consistent in its own charts)
                apart.insert(root);
                let a = rng.angle();
                moved[v as usize] = true;
                touched.push(v);
                local.move_vertex(stars, v as usize, &[amp * a.cos(), amp * a.sin()]);
                continue;
            }
            if done_round[root as usize] == round {
                continue;
            }
            done_round[root as usize] = round;
            let a = rng.angle();
            let delta = [amp * a.cos(), amp * a.sin()];
            let Some(members) = members else {
                stuck.insert(root);
                continue;
            };
            for (w, r) in members {
                moved[w as usize] = true;
                touched.push(w);
                local.move_vertex(stars, w as usize, &r.apply(&delta));
            }
        }
        scan.update(map, stars, local, &touched);
        touched.clear();
        bad = scan.list();
    }
    rep.extra_rounds = executed.saturating_sub(ROUNDS);
    rep.stuck_clusters = stuck.len();
    rep.clusters_moved_apart = apart.len();
    rep.unresolved = bad.iter().filter(|&&v| !stars.singular[v as usize]).count();
    rep.singular_on_iso = bad
        .into_iter()
        .filter(|&v| stars.singular[v as usize])
        .collect();
    rep.singular_kinds = classify(topo, stars, local, &rep.singular_on_iso);
    rep.perturbed_vertices = moved.iter().filter(|&&m| m).count();
    rep
}

/// Kinds of the singular vertices left on isos (see [`SanitizeReport`]).
fn classify(
    topo: &Topology<3>,
    stars: &Stars<2>,
    local: &LocalMap,
    left: &[u32],
) -> std::collections::BTreeMap<String, usize> {
    let mut out = std::collections::BTreeMap::new();
    for &v in left {
        let v = v as usize;
        let Some(first) = stars.of(v).first() else {
            continue;
        };
        let x = local.coords[first.simplex as usize][first.corner as usize];
        let on = (0..2).filter(|&k| near_int(x[k])).count();
        let turns = dualex_map::holonomy::ridge_rotation(
            topo,
            &local.trans,
            first.simplex as usize,
            &[first.corner as usize],
        )
        .map_or(0, |h| h.turns());
        let angle = [0, 90, 180, 90][turns as usize];
        let place = ["edge", "iso", "node"][on];
        *out.entry(format!("{angle}_{place}")).or_insert(0) += 1;
    }
    out
}

/// Whether segment `a`–`b` passes within [`EPS`] of an integer point.
pub fn edge_near_grid_point(a: &[f64; 2], b: &[f64; 2]) -> bool {
    grid_point_near_edge(a, b).is_some()
}

/// An integer point within [`EPS`] of segment `a`–`b`, if any.
pub use dualex_segment::grid::grid_point_near_segment as grid_point_near_edge;
use dualex_segment::grid::{
    box_bounds, box_spans, dist2d_below_eps as below_eps, near_int, segment_clear_of_grid,
};

/// [`dualex_segment::bad_scan::BadScan`] with the triangle test.
struct BadScan(dualex_segment::bad_scan::BadScan);

/// Triangles per parallel task: below this, splitting costs more than it
/// saves.
const MIN_TASK: usize = 1024;

impl BadScan {
    fn new(map: &TriMap, stars: &Stars<2>, local: &LocalMap) -> Self {
        BadScan(dualex_segment::bad_scan::BadScan::new(
            map,
            stars,
            &local.coords,
            tri_mask,
            MIN_TASK,
        ))
    }

    /// The bad vertices, in increasing order.
    fn list(&self) -> Vec<u32> {
        self.0.list()
    }

    /// Re-tests after the vertices `moved` (corners in their stars) moved.
    fn update(&mut self, map: &TriMap, stars: &Stars<2>, local: &LocalMap, moved: &[u32]) {
        self.0.update(map, stars, &local.coords, tri_mask, moved);
    }
}

/// Whether `[lo, hi]` of `a`, `b` on `axis`, grown by `2·EPS`, holds an
/// integer (the reference formulation of the test in [`tri_mask`]).
#[cfg(test)]
fn spans_integer(a: &[f64; 2], b: &[f64; 2], axis: usize) -> bool {
    (a[axis].min(b[axis]) - 2.0 * EPS).ceil() <= a[axis].max(b[axis]) + 2.0 * EPS
}

/// The corners that triangle `c` makes bad, as a mask: corners on an iso,
/// endpoints of an edge through a grid point (a grid point at an endpoint
/// is that endpoint's problem only). An edge is skipped unless its box,
/// grown by `2·EPS`, holds an integer on both axes ([`box_spans`]) and one
/// of those integer points is near its line ([`segment_clear_of_grid`]).
fn tri_mask(c: &[[f64; 2]; 3]) -> u8 {
    let mut b = [[[0.0; 2]; 2]; 3];
    for k in 0..3 {
        for a in 0..2 {
            b[k][a] = box_bounds(c[k][a]);
        }
    }
    let mut mask = 0u8;
    for k in 0..3 {
        if near_int(c[k][0]) || near_int(c[k][1]) {
            mask |= 1 << k;
        }
        let l = (k + 1) % 3;
        if !(box_spans(b[k][0], b[l][0]) && box_spans(b[k][1], b[l][1])) {
            continue;
        }
        // the integer range of the edge's grown box per axis
        let (mut lo, mut hi) = ([0.0; 2], [0.0; 2]);
        for a in 0..2 {
            let (bk, bl) = (b[k][a], b[l][a]);
            lo[a] = if bl[0] < bk[0] { bl[0] } else { bk[0] };
            hi[a] = if bl[1] > bk[1] { bl[1] } else { bk[1] };
        }
        if segment_clear_of_grid(&c[k], &c[l], lo, hi) {
            continue;
        }
        if let Some(g) = grid_point_near_edge(&c[k], &c[l]) {
            let (at_k, at_l) = (below_eps(&g, &c[k]), below_eps(&g, &c[l]));
            mask |= u8::from(at_k || !at_l) << k | u8::from(at_l || !at_k) << l;
        }
    }
    mask
}

#[cfg(test)]
mod tests {
    use super::*;

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
                        let dist = dualex_segment::grid::dist2d;
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
        let mut scan = BadScan::new(&map, &stars, &local);
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
            scan.update(&map, &stars, &local, &[v as u32]);
            let want = full(&local);
            assert!(
                round % 3 == 2 || want.contains(&(v as u32)),
                "round {round}"
            );
            assert_eq!(scan.list(), want, "round {round}");
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
        use dualex_map::Transitions;
        use dualex_segment::grid_offset::GridOffset;
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
        let rep = sanitize(&map, &topo, &stars, &mut local, 7);
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

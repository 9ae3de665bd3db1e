//! Step 2: sanitization of the local shifted map (paper appendix,
//! "Sanitization"; DESIGN §3.1).
//!
//! Input: [`LocalMap`], vertex [`Stars`]. Output: the same map with
//! - every non-singular vertex's corners **snapped** to one exactly-GP value
//!   (the reference corner carried through the star's rotations plus the
//!   nearest integer translation), so sign tests agree between charts;
//! - no vertex on an iso-surface, no edge on an iso-line, no face on a grid
//!   point (see [`crate::near`]). Offending vertices are moved by one small
//!   random vector in their reference chart, carried to every corner
//!   through the star's rotations (translations untouched: no transition
//!   changes). Collapsed clusters move as one ([`crate::clusters`]).
//!
//! Vertices on singular edges cannot move freely: when all the holonomies
//! around such a vertex fix one axis (a vertex inside one singular edge,
//! whose direction is that axis), it moves along that axis only, which
//! clears an iso-surface across the edge. What remains is reported in
//! [`SanitizeReport::singular_on_iso`]; the tracer stops the walks that
//! meet them ("inconsistent") and leaves those sides unmatched.
//!
//! The rounds and the last resort for stuck clusters are those of the 2D
//! sanitizer (`dualex_quad::sanitize`): extra rounds of growing amplitude
//! for non-singular vertices only, stuck clusters moved apart in them.

use crate::clusters::Clusters;
use crate::local::LocalMap;
use crate::near::{
    corner_bounds, edge_range, edge_spans, near_int, segment_near_iso_line_in_box,
    triangle_near_grid_point, EDGES, FACE_EDGES,
};
use crate::rng::SplitMix;
use crate::simplex::face_corners;
use dualex_map::{Rot3, Stars, TetMap, Topology, Transitions};
use std::collections::{BTreeSet, HashSet};

use dualex_segment::sanitize_report::{amplitude, ROUNDS};
pub use dualex_segment::sanitize_report::{SanitizeReport, AMPLITUDE};

/// The free axis (reference chart) of every singular vertex that has one
/// ([`singular_free_axis`]; `None` for the others).
pub fn free_axes(topo: &Topology<4>, stars: &Stars<3>, local: &LocalMap) -> Vec<Option<usize>> {
    (0..stars.singular.len())
        .map(|v| {
            stars.singular[v]
                .then(|| singular_free_axis(topo, stars, &local.trans, v))
                .flatten()
        })
        .collect()
}

/// Sanitizes `local` in place; `free_axis` as [`free_axes`] (the driver
/// computes it once for the split and for this step).
pub fn sanitize(
    map: &TetMap,
    stars: &Stars<3>,
    free_axis: &[Option<usize>],
    local: &mut LocalMap,
    seed: u64,
) -> SanitizeReport {
    let mut rep = SanitizeReport::default();
    (rep.snapped_vertices, rep.max_snap) = local.snap(stars);
    let clusters = Clusters::build(map, stars, &local.coords);
    rep.clusters = clusters.count_nontrivial();
    let mut mv = Mover {
        stars,
        clusters: &clusters,
        free_axis,
        rng: SplitMix::new(seed),
        moved: vec![false; map.positions.len()],
        moved_singular: HashSet::new(),
        touched: Vec::new(),
        done_epoch: vec![0; map.positions.len()],
        epoch: 0,
        stuck: BTreeSet::new(),
        apart: BTreeSet::new(),
    };
    let mut scan = BadScan::new(map, stars, &local.coords);
    let mut bad = scan.list();
    let mut executed: usize = 0;
    for round in 0.. {
        let Some(amp) = amplitude(round) else {
            break;
        };
        rep.rounds = round;
        mv.touched.clear();
        if !mv.round(local, &bad, amp, round >= ROUNDS) {
            break;
        }
        executed += 1;
        scan.update(map, stars, &local.coords, &mv.touched);
        bad = scan.list();
    }
    rep.extra_rounds = executed.saturating_sub(ROUNDS);
    rep.stuck_clusters = mv.stuck.len();
    rep.clusters_moved_apart = mv.apart.len();
    rep.unresolved = bad.iter().filter(|&&v| !stars.singular[v as usize]).count();
    rep.singular_on_iso = bad
        .into_iter()
        .filter(|&v| stars.singular[v as usize])
        .collect();
    rep.singular_moved = mv.moved_singular.len();
    rep.perturbed_vertices = mv.moved.iter().filter(|&&m| m).count();
    rep
}

/// The state of the perturbation rounds.
struct Mover<'a> {
    stars: &'a Stars<3>,
    clusters: &'a Clusters,
    /// Per vertex: the only axis a singular vertex may move along.
    free_axis: &'a [Option<usize>],
    rng: SplitMix,
    moved: Vec<bool>,
    moved_singular: HashSet<u32>,
    /// Vertices moved in the current round.
    touched: Vec<u32>,
    /// Per cluster root: the last round (epoch) in which it moved.
    done_epoch: Vec<u32>,
    epoch: u32,
    /// Roots of the clusters that could not move as one.
    stuck: BTreeSet<u32>,
    /// Roots of the stuck clusters whose members moved one by one.
    apart: BTreeSet<u32>,
}

impl Mover<'_> {
    /// Moves every movable vertex of `bad` (its whole cluster, once) by a
    /// random vector of length `amp`; `false` when none is movable. With
    /// `last_resort` (the extra rounds), the members of a stuck cluster
    /// move one by one (each is non-singular: consistent in its own
    /// charts).
    fn round(&mut self, local: &mut LocalMap, bad: &[u32], amp: f64, last_resort: bool) -> bool {
        // the extra rounds are for non-singular vertices only: a singular
        // vertex still on the grid after the ordinary rounds is on an iso
        // its free axis does not cross
        let movable = |v: &&u32| {
            !self.stars.singular[**v as usize]
                || (!last_resort && self.free_axis[**v as usize].is_some())
        };
        let todo: Vec<u32> = bad.iter().filter(movable).copied().collect();
        self.epoch += 1;
        for &v in &todo {
            if let Some(axis) = self.free_axis[v as usize] {
                let mut d = [0.0; 3];
                d[axis] = if self.rng.unit() < 0.5 { amp } else { -amp };
                local.move_vertex(self.stars, v as usize, &d);
                self.touched.push(v);
                self.moved_singular.insert(v);
                continue;
            }
            let root = self.clusters.root(v);
            let members = self.clusters.members_rot(root);
            if members.is_none() && last_resort {
                self.apart.insert(root);
                let d = self.rng.direction().map(|x| x * amp);
                self.moved[v as usize] = true;
                self.touched.push(v);
                local.move_vertex(self.stars, v as usize, &d);
                continue;
            }
            if self.done_epoch[root as usize] == self.epoch {
                continue;
            }
            self.done_epoch[root as usize] = self.epoch;
            let delta = self.rng.direction().map(|x| x * amp);
            let Some(members) = members else {
                self.stuck.insert(root);
                continue;
            };
            for (w, r) in members {
                self.moved[w as usize] = true;
                self.touched.push(w);
                local.move_vertex(self.stars, w as usize, &r.apply(&delta));
            }
        }
        !todo.is_empty()
    }
}

/// Holonomies around vertex `v`, as rotations of its reference chart: one
/// per face of its star where the star's rotations disagree.
fn holonomies(
    topo: &Topology<4>,
    stars: &Stars<3>,
    trans: &Transitions<4, 3>,
    v: usize,
) -> Vec<Rot3> {
    let star = stars.of(v);
    let mut out = Vec::new();
    for e in star {
        let s = e.simplex as usize;
        for f in (0..4).filter(|&f| f != e.corner as usize) {
            let Some((n, _)) = topo.neighbour(s, f) else {
                continue;
            };
            let expected = e.rot.then(&trans.rot[s][f]);
            if let Some(o) = star.iter().find(|o| o.simplex as usize == n) {
                if o.rot != expected {
                    out.push(expected.then(&o.rot.inverse()));
                }
            }
        }
    }
    out
}

/// The axis (of `v`'s reference chart) that every holonomy around `v`
/// fixes with its sign, if exactly one does: moving along it is consistent
/// in every chart.
pub(crate) fn singular_free_axis(
    topo: &Topology<4>,
    stars: &Stars<3>,
    trans: &Transitions<4, 3>,
    v: usize,
) -> Option<usize> {
    let h = holonomies(topo, stars, trans, v);
    if h.is_empty() {
        return None;
    }
    let fixed: Vec<usize> = (0..3)
        .filter(|&a| h.iter().all(|r| r.apply_dir(2 * a) == 2 * a))
        .collect();
    match fixed[..] {
        [a] => Some(a),
        _ => None,
    }
}

/// [`dualex_segment::bad_scan::BadScan`] with the tet test
/// ([`crate::near::bad_vertices`] kept up to date incrementally).
struct BadScan(dualex_segment::bad_scan::BadScan);

/// Tets per parallel task.
const MIN_TASK: usize = 512;

impl BadScan {
    fn new(map: &TetMap, stars: &Stars<3>, coords: &[[[f64; 3]; 4]]) -> Self {
        BadScan(dualex_segment::bad_scan::BadScan::new(
            map, stars, coords, tet_mask, MIN_TASK,
        ))
    }

    /// The bad vertices, in increasing order.
    fn list(&self) -> Vec<u32> {
        self.0.list()
    }

    /// Re-tests after the vertices `moved` (corners in their stars) moved.
    fn update(&mut self, map: &TetMap, stars: &Stars<3>, coords: &[[[f64; 3]; 4]], moved: &[u32]) {
        self.0.update(map, stars, coords, tet_mask, moved);
    }
}

/// The corners that a tet (corners `c`) makes bad, as a mask, with the
/// tests of [`crate::near::bad_vertices`] (edges whose box holds an integer
/// on fewer than two axes, faces whose box misses one, skipped: they cannot
/// be near an iso-line or a grid point).
fn tet_mask(c: &[[f64; 3]; 4]) -> u8 {
    let mut mask = 0u8;
    for (k, p) in c.iter().enumerate() {
        if p.iter().any(|&x| near_int(x)) {
            mask |= 1 << k;
        }
    }
    let bounds = corner_bounds(c);
    let span = edge_spans(&bounds);
    for (&[k, l], &bits) in EDGES.iter().zip(&span) {
        // fewer than two axes
        if bits & bits.wrapping_sub(1) == 0 {
            continue;
        }
        let range = edge_range(&bounds, k, l);
        if let Some((at_k, at_l)) = segment_near_iso_line_in_box(&c[k], &c[l], &range) {
            mask |= u8::from(at_k || !at_l) << k | u8::from(at_l || !at_k) << l;
        }
    }
    for (f, [e0, e1, e2]) in FACE_EDGES.into_iter().enumerate() {
        if span[e0] | span[e1] | span[e2] != 0b111 {
            continue;
        }
        let [i, j, k] = face_corners(f);
        if triangle_near_grid_point(&[c[i], c[j], c[k]]) {
            mask |= 1 << i | 1 << j | 1 << k;
        }
    }
    mask
}

#[cfg(test)]
mod scan_tests {
    use super::*;
    use crate::near::{bad_vertices, segment_near_iso_line, EPS};

    /// Whether the box of `pts` (grown by `2·EPS`) holds an integer on `axis`
    /// (the reference formulation of [`edge_spans`]).
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

    /// [`edge_spans`] equals [`spans_integer`] on every edge, and so does
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
            let span = edge_spans(&corner_bounds(&c));
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

    /// The incremental scan equals a full scan after arbitrary moves,
    /// including moves onto isos, grid lines and grid points.
    #[test]
    fn incremental_scan_equals_full_scan() {
        use crate::testblock::{block, even, identity};
        // 0.2 + 0.7·4 = 3: a grid plane of vertices on isos
        let map = block(
            &[even(0.2, 3.7, 5), even(0.2, 3.7, 5), even(0.2, 3.7, 5)],
            identity,
        );
        let topo = Topology::build(&map).unwrap_or_else(|e| panic!("{e}"));
        let (trans, _) =
            Transitions::derive(&map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
        let stars = Stars::build(&map, &topo, &trans);
        let mut local = LocalMap::new(&map, &topo, &trans);
        let mut scan = BadScan::new(&map, &stars, &local.coords);
        assert_eq!(scan.list(), bad_vertices(&map, &local.coords));
        assert!(!scan.list().is_empty());
        let mut rng = SplitMix::new(5);
        let nv = map.positions.len();
        for round in 0..20 {
            let moved: Vec<u32> = (0..1 + round % 4)
                .map(|_| (rng.unit() * nv as f64) as u32 % nv as u32)
                .collect();
            for &v in &moved {
                let first = stars.of(v as usize)[0];
                let x = local.coords[first.simplex as usize][first.corner as usize];
                // alternately onto an integer coordinate, or a random step
                let d = if round % 2 == 0 {
                    [x[0].round() - x[0], 0.0, 0.0]
                } else {
                    rng.direction().map(|t| t * 0.4)
                };
                local.move_vertex(&stars, v as usize, &d);
            }
            scan.update(&map, &stars, &local.coords, &moved);
            let full = bad_vertices(&map, &local.coords);
            assert!(!full.is_empty() || round % 2 == 1);
            assert_eq!(scan.list(), full, "round {round}");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_map::TetMap;

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
        let rep = sanitize(&map, &stars, &free, &mut local, 3);
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

//! Step 9b: digons — two glued edges between the same two vertices —
//! pinched off.
//!
//! On maps with many folds, the glued graph can join two vertices by two
//! distinct edges (pairs of glued sides): the checker sees an edge of four
//! faces. The two edges make a loop of two edges on the surface. Where the
//! loop separates (it bounds a small pocket of the fold), regluing the four
//! sides crosswise pinches the surface along it into two closed pieces,
//! each with a single edge there; the smaller piece is then a bubble that
//! `crate::bubbles` deletes.
//!
//! The crosswise pairing is the one that keeps the orientation: each new
//! pair traverses the edge in opposite directions in its two cells. Its
//! rotations are those that match the corners (as for the zipped holes of
//! step 9a). Preconditions, checked before any write: exactly two pairs on
//! the vertex pair, both new pairs oriented and with a matching rotation.
//! A loop that does not separate (around a handle) is left as it is:
//! pinching it would change the topology (the re-pairing is undone when
//! the graph has no more components after it) — unless the input is
//! closed and connected and the glued surface, its holes closed, has more
//! handles than the input ([`excess_handles`]): a loop of two edges round
//! a handle is then the handle a fold made, and as many such digons as
//! there are surplus handles are pinched, each cutting one. Invariant: only the four
//! sides change; each end of a pinched digon becomes one vertex per piece.

use crate::gluing::side_corners;
use dualex_check::QuadReport;
use dualex_graph::{Glued, NodeGraph, Side};
use dualex_map::Rot2;

/// The rotation ρ that glues side `s` to side `t` by the label rule with
/// matching corners (the corner of X between s and p ↔ the corner of Y
/// between t and ρ(p)), if any.
pub(crate) fn matching_rotation(
    graph: &NodeGraph<2>,
    glued: &Glued<2>,
    s: Side,
    t: Side,
) -> Option<Rot2> {
    let (x, y) = (graph.node_of(s), graph.node_of(t));
    let (ds, dt) = (graph.dir_of(s), graph.dir_of(t));
    Rot2::all().into_iter().find(|r| {
        let want = if graph.is_reverted(x) == graph.is_reverted(y) {
            ds ^ 1
        } else {
            ds
        };
        if r.apply_dir(want) != dt {
            return false;
        }
        let p = 2 * (1 - (ds >> 1)); // + direction of the other axis
        let [_, xp] = side_corners(glued, x, ds);
        let q = r.apply_dir(p);
        let [yq0, yq1] = side_corners(glued, y, dt);
        xp == if q & 1 == 0 { yq1 } else { yq0 }
    })
}

/// Whether the cell of side `s` traverses it from the smaller vertex to
/// the larger.
fn ascending(graph: &NodeGraph<2>, glued: &Glued<2>, s: Side) -> Option<bool> {
    let node = graph.node_of(s);
    let [a, b] = side_corners(glued, node, graph.dir_of(s));
    // the cells are in node id order
    let cell = glued.cell(glued.nodes.binary_search(&node).ok()?)?;
    let forward = (0..4).any(|k| cell[k] == a && cell[(k + 1) % 4] == b);
    Some(forward == (a < b))
}

/// Re-pairs the sides of every digon (see the module docs); returns how
/// many digons were pinched. Up to `handles(graph)` digons that do not
/// separate are pinched too (each removes a handle: the caller allows it
/// only for the handles the graph has beyond its input's, see
/// [`excess_handles`]; asked once, before any change, when the graph has
/// a digon at all).
pub fn pinch_digons(
    graph: &mut NodeGraph<2>,
    glued: &Glued<2>,
    handles: impl FnOnce(&NodeGraph<2>) -> usize,
) -> usize {
    let by_edge = pairs_by_edge(graph, glued);
    let any = any_in(&by_edge);
    let mut left = if any { handles(graph) } else { 0 };
    let mut pinched = 0;
    for run in by_edge.chunk_by(|x, y| x.0 == y.0) {
        let [(_, p1), (_, p2)] = run[..] else {
            continue;
        };
        let (Some(q1), Some(q2)) = (graph.opposite(p1), graph.opposite(p2)) else {
            continue;
        };
        let up = |s| ascending(graph, glued, s);
        let (Some(u1), Some(v1), Some(u2), Some(v2)) = (up(p1), up(q1), up(p2), up(q2)) else {
            continue;
        };
        // each new pair runs the edge both ways
        let new = if u1 != v2 && u2 != v1 {
            [(p1, q2), (p2, q1)]
        } else if u1 != u2 && v1 != v2 {
            [(p1, p2), (q1, q2)]
        } else {
            continue;
        };
        let rots = new.map(|(s, t)| matching_rotation(graph, glued, s, t));
        let [Some(r1), Some(r2)] = rots else { continue };
        let (Some(o1), Some(o2)) = (graph.rotation(p1), graph.rotation(p2)) else {
            continue;
        };
        let before = graph.component_labels().1;
        repair(graph, [p1, p2], new, [r1, r2]);
        if graph.component_labels().1 > before {
            pinched += 1;
        } else if left > 0 {
            // a handle the input does not have: cut through
            left -= 1;
            pinched += 1;
        } else {
            // the loop does not separate (a handle): pinching would change
            // the topology, so the digon stays
            repair(graph, [new[0].0, new[1].0], [(p1, q1), (p2, q2)], [o1, o2]);
        }
    }
    pinched
}

/// The checker's report of the glued cells (as placed: the same cells and
/// vertex count).
pub(crate) fn check(glued: &Glued<2>) -> QuadReport {
    dualex_check::check_quad_mesh(glued.n_vertices, glued.cell_array())
}

/// Whether the check `c` of the `glued` cells ([`check`]) shows that no
/// two glued pairs join the same two vertices: every pair's corners
/// matched, every cell judged (no repeated or missing vertex), no edge of
/// more than two cells (two pairs would be four uses of one edge).
pub(crate) fn none_by_check(glued: &Glued<2>, c: &QuadReport) -> bool {
    glued.corner_mismatches == 0
        && c.non_manifold_edges.is_empty()
        && c.degenerate_faces.is_empty()
        && c.out_of_range_faces.is_empty()
}

/// Whether two glued pairs join the same two vertices (asserted against
/// the output check's judgement where the crate's tests extract).
#[cfg(test)]
pub(crate) fn any_digon(graph: &NodeGraph<2>, glued: &Glued<2>) -> bool {
    any_in(&pairs_by_edge(graph, glued))
}

/// Whether two entries of [`pairs_by_edge`]'s list share their edge.
fn any_in(by_edge: &[(u64, Side)]) -> bool {
    by_edge.windows(2).any(|w| w[0].0 == w[1].0)
}

/// One entry per glued pair between two distinct vertices, keyed by the
/// two (smaller vertex in the high half), from its smaller side; sorted
/// (bucketed by the smaller vertex, each bucket sorted: no sort of them
/// all).
fn pairs_by_edge(graph: &NodeGraph<2>, glued: &Glued<2>) -> Vec<(u64, Side)> {
    let (_, by_edge) = dualex_util::bucket::sorted(glued.n_vertices, |emit| {
        for &node in &glued.nodes {
            for d in 0..4 {
                let s = graph.side(node, d);
                let Some(t) = graph.opposite(s) else { continue };
                let [a, b] = side_corners(glued, node, d);
                if s.0 < t.0 && a != b {
                    let key = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
                    emit(a.min(b) as usize, (key, s.0));
                }
            }
        }
    });
    by_edge.into_iter().map(|(k, s)| (k, Side(s))).collect()
}

/// The handles the glued surface has beyond a closed connected input of
/// Euler characteristic `input_euler`, once step 10 closed its holes:
/// `(χ_input − χ) / 2` when positive, where χ = V − E + F counts every
/// glued pair and every hole side as an edge, and every cycle of hole
/// sides as one more face (its fill); an unmatched side whose two corners
/// are one vertex (the collapsed side of a triangle) is no edge at all.
pub fn excess_handles(graph: &NodeGraph<2>, glued: &Glued<2>, input_euler: i64) -> usize {
    let slots = crate::slots::cell_slots(graph, glued);
    let pairs = slots
        .side
        .iter()
        .filter(|&&s| {
            graph
                .opposite(s)
                .is_some_and(|t| s < t || !graph.is_alive(graph.node_of(t)))
        })
        .count() as i64;
    // on a closed input every unmatched side is a hole (collapsed ones
    // left out)
    let cells: Vec<[u32; 4]> = glued.cells().map(|(_, q)| q).collect();
    let holes: Vec<(u32, u32)> = crate::slots::hole_slots(graph, glued, &slots, &[], true)
        .into_iter()
        .map(|s| crate::ambiguous::ends(&cells, s))
        .collect();
    let (fills, open) = dualex_cells::polygons::hole_polygons(&holes);
    let v = glued.n_vertices as i64;
    let f = glued.nodes.len() as i64 + (fills.len() + open) as i64;
    let euler = v - pairs - holes.len() as i64 + f;
    let excess = input_euler - euler;
    if excess > 0 && excess % 2 == 0 {
        (excess / 2) as usize
    } else {
        0
    }
}

/// Unglues `old` (one side of each pair) and glues the `new` pairs with
/// their rotations; the sides were checked glued and alive before.
fn repair(graph: &mut NodeGraph<2>, old: [Side; 2], new: [(Side, Side); 2], rots: [Rot2; 2]) {
    for s in old {
        if graph.unlink(s).is_err() {
            unreachable_pair();
        }
    }
    for ((s, t), r) in new.into_iter().zip(rots) {
        if graph.link(s, t, r).is_err() {
            unreachable_pair();
        }
    }
}

/// The four sides were checked glued and alive before any write.
fn unreachable_pair() -> ! {
    panic!("bug: a digon's sides changed while it was pinched")
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_graph::testgrid::GridSpec;
    use dualex_graph::Node;

    /// Two copies of a regular 4×3 grid (nodes 0..12, 12..24) whose edges
    /// between the nodes at (1, 1) and (2, 1) (`+u ↔ −u`, both ends
    /// interior vertices) are glued crosswise to the other copy's: the two
    /// copies become one surface along a slit, and the slit's ends are
    /// joined by two edges (a digon that separates).
    fn crossed() -> (NodeGraph<2>, [Side; 4]) {
        let spec = GridSpec::regular([4, 3]);
        let grid = spec.build();
        let n = grid.n_nodes();
        let mut g = NodeGraph::<2>::new(vec![false; 2 * n]);
        for copy in 0..2u32 {
            let off = copy * n as u32;
            for x in 0..n as u32 {
                for d in 0..4 {
                    let s = grid.side(Node(x), d);
                    if let (Some(t), Some(r)) = (grid.opposite(s), grid.rotation(s)) {
                        let (a, b) = (Side(s.0 + 4 * off), Side(t.0 + 4 * off));
                        if s.0 < t.0 && g.link(a, b, r).is_err() {
                            panic!("copy");
                        }
                    }
                }
            }
        }
        let a = g.side(spec.node_at(1, [0, 1]), 0);
        let b = g.opposite(a).unwrap_or_else(|| panic!("glued along u"));
        let (c, e) = (Side(a.0 + 4 * n as u32), Side(b.0 + 4 * n as u32));
        for s in [a, c] {
            g.unlink(s).unwrap_or_else(|e| panic!("{e}"));
        }
        for (s, t) in [(a, e), (c, b)] {
            g.link(s, t, Rot2::IDENTITY)
                .unwrap_or_else(|e| panic!("{e}"));
        }
        (g, [a, b, c, e])
    }

    fn double_edges(glued: &Glued<2>) -> usize {
        let mut e = glued.edges();
        let n = e.len();
        e.sort_unstable();
        e.dedup();
        n - e.len()
    }

    #[test]
    fn a_separating_digon_is_pinched_into_two_pieces() {
        let (mut g, [a, b, c, e]) = crossed();
        g.check().expect("valid before");
        assert_eq!(g.component_labels().1, 1);
        let glued = g.glue();
        let cells: Vec<[u32; 4]> = glued.cells().map(|(_, q)| q).collect();
        let rep = dualex_check::check_quad_mesh(glued.n_vertices, &cells);
        assert!(!rep.is_valid(), "the digon is an edge of four faces");
        assert_eq!(pinch_digons(&mut g, &glued, |_| 0), 1);
        g.check().expect("valid after");
        assert_eq!(g.opposite(a), Some(b));
        assert_eq!(g.opposite(c), Some(e));
        assert_eq!(g.component_labels().1, 2);
        let glued = g.glue();
        let cells: Vec<[u32; 4]> = glued.cells().map(|(_, q)| q).collect();
        let rep = dualex_check::check_quad_mesh(glued.n_vertices, &cells);
        assert!(rep.is_valid(), "{:?}", rep.errors());
        assert_eq!(double_edges(&glued), 0);
    }

    /// A `k`×`k` grid whose opposite boundary sides are glued: a torus.
    fn torus(k: usize) -> NodeGraph<2> {
        let spec = GridSpec::regular([k, k]);
        let mut g = spec.build();
        for j in 0..k {
            for axis in 0..2 {
                let at = |i: usize| {
                    let (u, v) = if axis == 0 { (i, j) } else { (j, i) };
                    spec.node_at(u, [0, v])
                };
                let s = g.side(at(k - 1), 2 * axis);
                let t = g.side(at(0), 2 * axis + 1);
                g.link(s, t, Rot2::IDENTITY)
                    .unwrap_or_else(|e| panic!("{e}"));
            }
        }
        g
    }

    #[test]
    fn a_digon_round_a_surplus_handle_is_pinched_only_when_allowed() {
        // a 2×2 torus: its vertices are joined by two edges round each
        // handle loop; the digons do not separate
        let mut g = torus(2);
        g.check().expect("a valid graph");
        let glued = g.glue();
        let before = g.clone();
        assert_eq!(pinch_digons(&mut g, &glued, |_| 0), 0);
        assert_eq!(g, before, "not allowed: untouched");
        // the input a sphere: one handle too many
        let pinched = pinch_digons(&mut g, &glued, |g| excess_handles(g, &glued, 2));
        g.check().expect("valid after");
        // the first digon cuts the handle (a sphere now), after which the
        // second separates and is pinched as any (its pocket is a bubble
        // for `crate::bubbles`): two pieces, no handle left
        assert_eq!(pinched, 2);
        assert_eq!(g.component_labels().1, 2);
        assert_eq!(excess_handles(&g, &g.glue(), 2), 0);
    }

    #[test]
    fn a_torus_has_one_handle_more_than_a_sphere() {
        let g = torus(3);
        g.check().expect("a valid graph");
        let glued = g.glue();
        assert_eq!((glued.unmatched_sides, glued.boundary_loops), (0, 0));
        assert_eq!(excess_handles(&g, &glued, 2), 1);
        assert_eq!(excess_handles(&g, &glued, 0), 0);
        // the open grid, its hole closed, is a sphere
        let open = GridSpec::regular([3, 3]).build();
        assert_eq!(excess_handles(&open, &open.glue(), 2), 0);
    }

    #[test]
    fn a_regular_grid_has_no_digon() {
        let mut g = GridSpec::regular([3, 3]).build();
        let before = g.clone();
        let glued = g.glue();
        assert_eq!(pinch_digons(&mut g, &glued, |_| 0), 0);
        assert_eq!(g, before);
    }

    /// The output check's clean report says "no digon" only where the
    /// search by edges finds none: on tori of 1 to 6 nodes a side (those
    /// of 2 have digons round their handles, that of 1 only repeated
    /// vertices), grids, the crossed copies, and tori with random pairs
    /// re-glued crosswise (seeded).
    #[test]
    fn a_clean_check_means_no_digon() {
        let mut cases: Vec<NodeGraph<2>> = (1..=6).map(torus).collect();
        cases.push(crossed().0);
        cases.extend((1..=4).map(|k| GridSpec::regular([k, k + 1]).build()));
        let mut rng = dualex_util::rng::SplitMix::new(7);
        for k in 3..=6 {
            for _ in 0..40 {
                let mut g = torus(k);
                let glued: Vec<Side> = (0..g.n_sides() as u32)
                    .map(Side)
                    .filter(|&s| g.opposite(s).is_some_and(|t| s < t))
                    .collect();
                let a = glued[rng.below(glued.len())];
                let c = glued[rng.below(glued.len())];
                let (Some(b), Some(e)) = (g.opposite(a), g.opposite(c)) else {
                    continue;
                };
                if [a, b].contains(&c) || [a, b].contains(&e) {
                    continue;
                }
                for s in [a, c] {
                    g.unlink(s).unwrap_or_else(|e| panic!("{e}"));
                }
                let relinked = [(a, e), (c, b)]
                    .iter()
                    .all(|&(s, t)| g.link(s, t, Rot2::IDENTITY).is_ok());
                if relinked {
                    cases.push(g);
                }
            }
        }
        let (mut clean, mut digons) = (0, 0);
        for (i, g) in cases.iter().enumerate() {
            let glued = g.glue();
            let any = any_digon(g, &glued);
            let ok = none_by_check(&glued, &check(&glued));
            assert!(!(ok && any), "case {i}: a digon the check missed");
            clean += usize::from(ok);
            digons += usize::from(any);
        }
        assert!(
            clean >= 5 && digons >= 20,
            "{clean} clean, {digons} with digons"
        );
    }
}

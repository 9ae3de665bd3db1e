//! Walks along isos and the opposite relation they define (DESIGN §3.3),
//! shared by both dimensions: how a walk from a side ended, the counts of
//! all walks, and the gluing of sides whose walks reached each other.
//!
//! Input: one [`End`] per side (`side = node·2D + dir`), produced by the
//! dimension's tracer. Output: pairs linked in the [`NodeGraph`] and a
//! [`LinkReport`]. Invariant: a pair is linked only when both walks reached
//! each other; the tracer's rule makes that symmetric, and any asymmetry is
//! counted, not hidden.

use crate::graph::NodeGraph;
use crate::graph::NONE;
use crate::ids::Side;
use dualex_map::Rot;

/// How a walk from a side ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End<const D: usize> {
    /// Reached the side `side` of a node; ρ maps the start chart to its chart.
    Node {
        /// The side reached.
        side: u32,
        /// Rotation from the start node's chart to the arrival node's chart.
        rho: Rot<D>,
    },
    /// Left the mesh through a boundary facet.
    Boundary,
    /// The iso did not cross a simplex consistently (it passes through a
    /// vertex or an edge that sanitization could not move: a singular one).
    Inconsistent,
    /// Closed iso loop without node.
    Loop,
}

/// Counts of walk outcomes.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TraceReport {
    /// Walks that reached a node.
    pub to_node: usize,
    /// Walks that left the mesh.
    pub to_boundary: usize,
    /// Walks stopped by an inconsistent crossing.
    pub inconsistent: usize,
    /// Walks on iso loops without node.
    pub loops: usize,
    /// Longest walk, in simplices.
    pub max_steps: usize,
}

impl TraceReport {
    /// The `trace` object of the stats: walk outcomes, then what linking
    /// found and the pairs breaking the label rule.
    pub fn to_json(&self, links: &LinkReport, label_violations: usize) -> serde_json::Value {
        serde_json::json!({
            "to_node": self.to_node,
            "to_boundary": self.to_boundary,
            "inconsistent": self.inconsistent,
            "loops": self.loops,
            "max_steps": self.max_steps,
            "non_mutual": links.non_mutual,
            "rotation_mismatches": links.rotation_mismatches,
            "label_violations": label_violations,
        })
    }
}

/// Walks every side of `n_nodes` nodes with `walk(node, dir) -> (end,
/// steps)` and counts the outcomes; the ends are in side order.
pub fn walk_all<const D: usize>(
    n_nodes: usize,
    walk: impl Fn(usize, usize) -> (End<D>, usize) + Sync,
) -> (Vec<End<D>>, TraceReport) {
    use rayon::prelude::*;
    // walks are independent: in parallel, collected in (node, direction)
    // order, so the result does not depend on the thread count
    let (mut ends, mut steps) = (Vec::new(), Vec::new());
    (0..n_nodes * 2 * D)
        .into_par_iter()
        .with_min_len(1024)
        .map(|i| walk(i / (2 * D), i % (2 * D)))
        .unzip_into_vecs(&mut ends, &mut steps);
    let rep = tally(&ends, &steps);
    (ends, rep)
}

/// A walk's step count marked as reversible ([`walk_all_paired`]; above
/// any count: a walk takes at most `N · simplices + N` steps).
const BACK: usize = 1 << (usize::BITS - 1);
/// A step count marked as derived from the reverse walk.
const DERIVED: usize = 1 << (usize::BITS - 2);
/// The count without its marks.
const STEPS: usize = DERIVED - 1;

/// [`walk_all`] when `walk(node, dir) -> (end, steps, back)` also says
/// whether the walk from the side reached (an [`End::Node`]) is this walk
/// reversed (`back`: the same steps, back to this side, the inverse
/// rotation). The sides of even direction (positive along an axis) are
/// walked first; each odd side one of them reached with `back` is then
/// written as that walk reversed instead of walked; the other odd sides
/// are walked. Each side's end is what walking it gives, as with
/// [`walk_all`], provided `back` is only said when true.
pub fn walk_all_paired<const D: usize>(
    n_nodes: usize,
    walk: impl Fn(usize, usize) -> (End<D>, usize, bool) + Sync,
) -> (Vec<End<D>>, TraceReport) {
    use rayon::prelude::*;
    let sides = n_nodes * 2 * D;
    // 1. the even sides (the odd ones hold a placeholder)
    let (mut ends, mut steps) = (Vec::new(), Vec::new());
    (0..sides)
        .into_par_iter()
        .with_min_len(1024)
        .map(|i| {
            if i % 2 == 1 {
                return (End::Loop, 0);
            }
            let (end, k, back) = walk(i / (2 * D), i % (2 * D));
            (end, k | if back { BACK } else { 0 })
        })
        .unzip_into_vecs(&mut ends, &mut steps);
    // 2. the odd sides they reached, reversed
    for i in (0..sides).step_by(2) {
        let (End::Node { side, rho }, true) = (ends[i], steps[i] & BACK != 0) else {
            continue;
        };
        let j = side as usize;
        if j % 2 == 1 && j < sides {
            ends[j] = End::Node {
                side: i as u32,
                rho: rho.inverse(),
            };
            steps[j] = steps[i] & STEPS | DERIVED;
        }
    }
    // 3. the other odd sides, walked
    ends.par_iter_mut()
        .zip(steps.par_iter_mut())
        .enumerate()
        .with_min_len(1024)
        .filter(|(i, (_, k))| i % 2 == 1 && **k & DERIVED == 0)
        .for_each(|(i, (end, k))| {
            let (e, s, _) = walk(i / (2 * D), i % (2 * D));
            (*end, *k) = (e, s);
        });
    let rep = tally(&ends, &steps);
    (ends, rep)
}

/// The report of `ends`: how many are of each kind (node, boundary,
/// inconsistent, loop), and the most `steps` of a walk (without
/// [`walk_all_paired`]'s marks); in parallel, per chunk.
fn tally<const D: usize>(ends: &[End<D>], steps: &[usize]) -> TraceReport {
    use rayon::prelude::*;
    const CHUNK: usize = 4096;
    let (counts, max_steps) = ends
        .par_chunks(CHUNK)
        .zip(steps.par_chunks(CHUNK))
        .map(|(ends, steps)| {
            let mut counts = [0; 4];
            for end in ends {
                let kind = match end {
                    End::Node { .. } => 0,
                    End::Boundary => 1,
                    End::Inconsistent => 2,
                    End::Loop => 3,
                };
                counts[kind] += 1;
            }
            let most = steps.iter().map(|&k| k & STEPS).max().unwrap_or(0);
            (counts, most)
        })
        .reduce(
            || ([0; 4], 0),
            |(a, m), (b, n)| (std::array::from_fn(|k| a[k] + b[k]), m.max(n)),
        );
    let [to_node, to_boundary, inconsistent, loops] = counts;
    TraceReport {
        to_node,
        to_boundary,
        inconsistent,
        loops,
        max_steps,
    }
}

/// Sides per parallel task of [`NodeGraph::link_mutual`].
const LINK_TASK: usize = 1 << 12;

/// What linking the walks' ends found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LinkReport {
    /// Walks whose target did not walk back to them (or could not be linked).
    pub non_mutual: usize,
    /// Mutual pairs whose two rotations are not inverse (0 expected).
    pub rotation_mismatches: usize,
}

impl<const D: usize> NodeGraph<D> {
    /// Glues every pair of sides whose walks reached each other, with the
    /// rotation of the first walk.
    pub fn link_mutual(&mut self, ends: &[End<D>]) -> LinkReport {
        if ends.len() == self.n_sides() && self.is_fresh() {
            return self.link_mutual_fresh(ends);
        }
        self.link_mutual_serial(ends)
    }

    /// [`Self::link_mutual`] one pair after the other, on any graph.
    fn link_mutual_serial(&mut self, ends: &[End<D>]) -> LinkReport {
        let mut rep = LinkReport::default();
        for (a, end) in ends.iter().enumerate() {
            let End::Node { side: b, rho } = *end else {
                continue;
            };
            let b = b as usize;
            match ends.get(b) {
                // a mutual pair is handled once, from its smaller side
                Some(End::Node { side, .. }) if *side as usize == a && b < a => {}
                Some(End::Node { side, rho: back }) if *side as usize == a => {
                    if *back != rho.inverse() {
                        rep.rotation_mismatches += 1;
                    }
                    if b == a || self.link(Side(a as u32), Side(b as u32), rho).is_err() {
                        rep.non_mutual += 1;
                    }
                }
                _ => rep.non_mutual += 1,
            }
        }
        rep
    }

    /// Whether every node is alive and no side glued (a graph as
    /// [`NodeGraph::new`] makes it); read in parallel.
    fn is_fresh(&self) -> bool {
        use rayon::prelude::*;
        self.alive.par_iter().with_min_len(LINK_TASK).all(|&a| a)
            && self
                .opp
                .par_iter()
                .with_min_len(LINK_TASK)
                .all(|&o| o == NONE)
    }

    /// [`Self::link_mutual`] on a fresh graph ([`Self::is_fresh`]) with one
    /// end per side, each side written by itself, in parallel. There every
    /// side is usable and unmatched, and a side is in at most one mutual
    /// pair (it has one end), so the serial loop links every mutual pair
    /// `a < b` whatever the order: `a` gets `b` and the rotation of `a`'s
    /// walk, `b` gets `a` and its inverse. The counts follow the serial
    /// loop's rule: a mutual pair is counted from its smaller side (a side
    /// reaching itself is counted non-mutual), any other walk to a node is
    /// non-mutual.
    fn link_mutual_fresh(&mut self, ends: &[End<D>]) -> LinkReport {
        use rayon::prelude::*;
        // the walk back of the side a walk from `a` reached, if it is `a`
        let back_of = |a: usize, b: u32| match ends.get(b as usize) {
            Some(&End::Node { side, rho: back }) if side as usize == a => Some(back),
            _ => None,
        };
        let (non_mutual, rotation_mismatches) = self
            .opp
            .par_iter_mut()
            .zip(self.rot.par_iter_mut())
            .zip(ends)
            .enumerate()
            .with_min_len(LINK_TASK)
            .map(|(a, ((opp, rot), end))| {
                let End::Node { side: b, rho } = *end else {
                    return (0, 0);
                };
                let Some(back) = back_of(a, b) else {
                    return (1, 0);
                };
                let b_us = b as usize;
                if b_us != a {
                    *opp = b;
                    *rot = if a < b_us { rho } else { back.inverse() };
                }
                match a.cmp(&b_us) {
                    std::cmp::Ordering::Greater => (0, 0),
                    order => (
                        usize::from(order.is_eq()),
                        usize::from(back != rho.inverse()),
                    ),
                }
            })
            .reduce(|| (0, 0), |x, y| (x.0 + y.0, x.1 + y.1));
        LinkReport {
            non_mutual,
            rotation_mismatches,
        }
    }

    /// Deletes the alive nodes none of whose sides is glued and all of
    /// whose walks got lost (`Inconsistent` or `Loop`): an isolated node
    /// that no iso-line reaches consistently is float noise — e.g. a node
    /// seen inside a sliver next to a singular vertex — not a cell; kept,
    /// it would be a component of one cell. Deleting it changes no other
    /// node (it has no glued side). Returns the number deleted.
    pub fn drop_isolated_lost(&mut self, ends: &[End<D>]) -> usize {
        let lost: Vec<crate::ids::Node> = self
            .alive_nodes()
            .filter(|&n| {
                (0..2 * D).all(|d| {
                    let s = self.side(n, d);
                    self.opposite(s).is_none()
                        && matches!(ends.get(s.0 as usize), Some(End::Inconsistent | End::Loop))
                })
            })
            .collect();
        for n in &lost {
            self.alive[n.idx()] = false;
        }
        lost.len()
    }

    /// Unmatched sides of alive nodes that are not boundary but cracks
    /// (open interior faces / edges): all of them on a closed input (no
    /// boundary facet); otherwise those whose walk got lost (inconsistent
    /// or looping: at a singular vertex or edge). The others reached the
    /// boundary, directly or handed over by a reconnection of untangling.
    pub fn lost_unmatched_sides(&self, ends: &[End<D>], closed: bool) -> usize {
        self.lost_sides(ends, closed).count()
    }

    /// The sides [`Self::lost_unmatched_sides`] counts.
    pub fn lost_sides<'a>(
        &'a self,
        ends: &'a [End<D>],
        closed: bool,
    ) -> impl Iterator<Item = Side> + 'a {
        self.alive_nodes()
            .flat_map(|n| (0..2 * D).map(move |d| (n, d)))
            .map(|(n, d)| self.side(n, d))
            .filter(|&s| self.opposite(s).is_none())
            .filter(move |s| {
                closed || matches!(ends.get(s.0 as usize), Some(End::Inconsistent | End::Loop))
            })
    }
}

#[cfg(test)]
mod link_tests;
#[cfg(test)]
mod paired_tests;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ids::Node;
    use dualex_map::Rot2;

    /// A node whose walks all got lost and that has no glued side is
    /// dropped; one with a glued side, or a walk to the boundary, stays.
    #[test]
    fn isolated_lost_nodes_are_dropped() {
        let mut g = NodeGraph::<2>::new(vec![false; 3]);
        let lost = End::Inconsistent;
        let mut ends = vec![lost; 12];
        // node 1: one walk to the boundary; node 2 glued to node 0
        ends[4] = End::Boundary;
        g.link(Side(8), Side(1), Rot2::IDENTITY).expect("link");
        assert_eq!(g.drop_isolated_lost(&ends), 0);
        g.unlink(Side(8)).expect("unlink");
        assert_eq!(g.drop_isolated_lost(&ends), 2);
        assert!(!g.is_alive(Node(0)) && g.is_alive(Node(1)) && !g.is_alive(Node(2)));
        g.check().expect("invariants");
    }

    #[test]
    fn mutual_walks_are_linked_and_the_rest_counted() {
        // two nodes side by side: 0.+u ↔ 1.-u; 1.+v walks to 0.-v, which walks elsewhere
        let mut g = NodeGraph::<2>::new(vec![false, false]);
        let id = Rot2::IDENTITY;
        let mut ends = vec![End::Boundary; 8];
        ends[0] = End::Node { side: 5, rho: id };
        ends[5] = End::Node { side: 0, rho: id };
        ends[6] = End::Node { side: 3, rho: id };
        let rep = g.link_mutual(&ends);
        assert_eq!(
            rep,
            LinkReport {
                non_mutual: 1,
                rotation_mismatches: 0
            }
        );
        assert_eq!(g.opposite(Side(0)), Some(Side(5)));
        g.check().expect("valid");
        // 6 unmatched sides: all cracks on a closed input, none otherwise
        assert_eq!(g.lost_unmatched_sides(&ends, true), 6);
        assert_eq!(g.lost_unmatched_sides(&ends, false), 0);
        ends[7] = End::Inconsistent;
        assert_eq!(g.lost_unmatched_sides(&ends, false), 1);
    }

    #[test]
    fn outcomes_are_counted() {
        let (ends, rep) = walk_all::<3>(2, |n, d| {
            if d == 0 {
                (End::Boundary, n + 1)
            } else {
                (End::Loop, 0)
            }
        });
        assert_eq!(ends.len(), 12);
        assert_eq!((rep.to_boundary, rep.loops, rep.max_steps), (2, 10, 2));
    }
}

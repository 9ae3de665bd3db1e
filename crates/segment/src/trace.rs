//! Step 6: tracing the sides of every node along its iso-line (all
//! coordinates but one fixed at integers) to the next node, topologically
//! (DESIGN §3.3), in any dimension.
//!
//! Input: sanitized [`LocalMap`], [`Topology`], [`Nodes`]. Output: for
//! each side (`node·2D + dir`, dir as in `dualex_map::rotation`) the side
//! reached and the rotation ρ from the start node's chart to the arrival
//! node's chart, or an end reason ([`End`]), with a [`TraceReport`].
//!
//! The walk of one side:
//! 1. in the start simplex, a node ahead on the line ends the walk;
//!    otherwise leave through the pierced facet ahead
//!    ([`Simplex::pierced`]);
//! 2. cross the facet: carry the fixed integers exactly through the
//!    transition, rotate the moving axis;
//! 3. in the new simplex the line must pierce exactly two facets, one of
//!    them the entry; the walking sense is re-derived from the entry
//!    towards the *other* one (never back through the entry);
//! 4. the nearest node ahead of the entry ends the walk, arriving on the
//!    reverse of the walking direction in that simplex's chart;
//!    otherwise leave through the other facet and go to 2.
//!
//! A line through a corner (2D: a vertex on the iso; after sanitization
//! only a singular one, whose charts disagree around it) or a crossing
//! that is not exactly two facets ends the walk as
//! [`End::Inconsistent`]. Termination: a walk is deterministic and
//! reversible (the entry facet determines the exit facet), so it visits
//! each (simplex, entry facet) at most once before it would cycle back to
//! its first crossing; it is cut after `N · simplices + N` steps (an iso
//! loop without node), reported as [`End::Loop`].

use crate::local::LocalMap;
use crate::nodes::Nodes;
use crate::simplex::{Dim, Line, Pierce, Simplex};
use dualex_map::{Rot, Topology};

/// How a walk ended (the dimension-generic [`dualex_graph::walk::End`]).
pub type End<const D: usize> = dualex_graph::walk::End<D>;
pub use dualex_graph::walk::TraceReport;

/// Traces every side; returns the end of each walk.
pub fn trace_all<const N: usize, const D: usize>(
    local: &LocalMap<N, D>,
    topo: &Topology<N>,
    nodes: &Nodes<N, D>,
) -> (Vec<End<D>>, TraceReport)
where
    Dim<N, D>: Simplex<N, D>,
{
    let max_steps = N * local.coords.len() + N;
    dualex_graph::walk::walk_all(nodes.len(), |n, d| {
        trace(local, topo, nodes, n, d, max_steps)
    })
}

/// Nearest node of simplex `s` on `line`, strictly ahead of `from`.
fn node_ahead<const N: usize, const D: usize>(
    nodes: &Nodes<N, D>,
    s: usize,
    line: &Line<D>,
    from: f64,
) -> Option<usize> {
    let a = line.axis;
    let mut best: Option<(usize, f64)> = None;
    for m in nodes.of_simplex(s) {
        let x = &nodes.point[m];
        if (0..D).any(|k| k != a && x[k] != line.val[k]) {
            continue;
        }
        let ds = (x[a] as f64 - from) * line.sgn;
        if ds > 0.0 && best.is_none_or(|(_, b)| ds < b) {
            best = Some((m, ds));
        }
    }
    best.map(|(m, _)| m)
}

/// Traces side `d` of node `n`; returns the end and the number of steps.
pub fn trace<const N: usize, const D: usize>(
    local: &LocalMap<N, D>,
    topo: &Topology<N>,
    nodes: &Nodes<N, D>,
    n: usize,
    d: usize,
    max_steps: usize,
) -> (End<D>, usize)
where
    Dim<N, D>: Simplex<N, D>,
{
    let mut t = nodes.simplex[n] as usize;
    let axis = d >> 1;
    let mut line = Line {
        axis,
        sgn: if d & 1 == 0 { 1.0 } else { -1.0 },
        val: nodes.point[n],
    };
    line.val[axis] = 0;
    let s0 = nodes.point[n][axis] as f64;
    if let Some(m) = node_ahead(nodes, t, &line, s0) {
        return (node_end(m, line.dir() ^ 1, Rot::<D>::IDENTITY), 0);
    }
    let (hits, nh) = Dim::<N, D>::pierced(&local.coords[t], &line);
    let exit = hits[..nh].iter().find(|h| (h.at - s0) * line.sgn > 0.0);
    let Some(&Pierce {
        face: mut e,
        at_corner: false,
        ..
    }) = exit
    else {
        return (End::Inconsistent, 0);
    };
    let mut rho = Rot::<D>::IDENTITY;
    for step in 1..=max_steps {
        let Some((t2, e2)) = topo.neighbour(t, e) else {
            return (End::Boundary, step);
        };
        let r = local.trans.rot[t][e];
        let line2 = carry(&line, &r, &local.trans.trans[t][e]);
        rho = rho.then(&r);
        let (hits, nh) = Dim::<N, D>::pierced(&local.coords[t2], &line2);
        let Some((inn, out)) = entry_exit(&hits[..nh], e2) else {
            return (End::Inconsistent, step);
        };
        let line2 = Line {
            sgn: if out.at > inn.at { 1.0 } else { -1.0 },
            ..line2
        };
        if let Some(m) = node_ahead(nodes, t2, &line2, inn.at) {
            return (node_end(m, line2.dir() ^ 1, rho), step);
        }
        if out.at_corner {
            // the walk reaches a vertex on its iso
            return (End::Inconsistent, step);
        }
        (t, e, line) = (t2, out.face, line2);
    }
    (End::Loop, max_steps)
}

/// The line in the neighbour's chart across a transition `(r, tr)`: the
/// fixed integers carried exactly, the moving axis rotated.
fn carry<const D: usize>(line: &Line<D>, r: &Rot<D>, tr: &[i64; D]) -> Line<D> {
    let pi = r.apply_i(&line.val);
    let axis = r.apply_dir(line.dir()) >> 1;
    let mut val = [0i64; D];
    for k in (0..D).filter(|&k| k != axis) {
        val[k] = pi[k] + tr[k];
    }
    Line {
        axis,
        sgn: line.sgn,
        val,
    }
}

/// The entry (on facet `e2`) and the exit among exactly two pierced facets.
fn entry_exit(hits: &[Pierce], e2: usize) -> Option<(Pierce, Pierce)> {
    match hits {
        [a, b] if a.face == e2 => Some((*a, *b)),
        [a, b] if b.face == e2 => Some((*b, *a)),
        _ => None,
    }
}

/// The end on side `arrival_dir` of node `m`.
fn node_end<const D: usize>(m: usize, arrival_dir: usize, rho: Rot<D>) -> End<D> {
    End::Node {
        side: (2 * D * m + arrival_dir) as u32,
        rho,
    }
}

#[cfg(test)]
#[path = "trace_tests.rs"]
mod tests;

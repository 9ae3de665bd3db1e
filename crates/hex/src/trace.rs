//! Step 4: tracing the sides of every node along its iso-line (two
//! coordinates fixed at integers) to the next node, topologically
//! (DESIGN §3.3).
//!
//! Input: sanitized [`LocalMap`], [`Topology`], [`Nodes`]. Output: for each
//! side (`node·6 + dir`, dir as in `dualex_map::rotation`) the side reached
//! and the rotation ρ from the start node's chart to the arrival node's
//! chart, or an end reason.
//!
//! The walk: in the start tet use the side's direction and leave through
//! the pierced face ahead (see [`crate::simplex`]); after that, cross the
//! face, carry the two fixed integers exactly through the transition, and
//! leave through the *other* pierced face (never back through the entry),
//! re-deriving the walking direction in each tet's chart. The side reached
//! is the reverse of the current walking direction in the arrival tet's
//! chart. Termination: a walk is deterministic and reversible (the entry
//! face determines the exit face), so it visits each (tet, entry face) at
//! most once before it would cycle back to its first crossing; it is cut
//! after `4 · tets + 4` steps (an iso loop without node), reported as such.

use crate::local::LocalMap;
use crate::nodes::Nodes;
use crate::simplex::{pierced, Pierce};
use dualex_map::{Rot3, Topology};

/// How a walk ended (the dimension-generic [`dualex_graph::walk::End`]).
pub type End = dualex_graph::walk::End<3>;
pub use dualex_graph::walk::TraceReport;

/// Traces every side; returns the end of each walk.
pub fn trace_all(local: &LocalMap, topo: &Topology<4>, nodes: &Nodes) -> (Vec<End>, TraceReport) {
    let max_steps = 4 * local.coords.len() + 4;
    dualex_graph::walk::walk_all(nodes.len(), |n, d| {
        trace(local, topo, nodes, n, d, max_steps)
    })
}

/// The line being walked, in one tet's chart.
#[derive(Clone, Copy, Debug)]
struct Line {
    /// Moving axis.
    axis: usize,
    /// +1 or −1: the walking sense along `axis`.
    sgn: f64,
    /// The fixed integer values (entry `axis` unused, kept 0).
    val: [i64; 3],
}

impl Line {
    fn dir(&self) -> usize {
        2 * self.axis + usize::from(self.sgn < 0.0)
    }
}

/// Nearest node of tet `s` on `line`, strictly ahead of `from`.
fn node_ahead(nodes: &Nodes, s: usize, line: &Line, from: f64) -> Option<usize> {
    let a = line.axis;
    let mut best: Option<(usize, f64)> = None;
    for m in nodes.of_tet(s) {
        let ijk = nodes.ijk[m];
        if (0..3).any(|k| k != a && ijk[k] != line.val[k]) {
            continue;
        }
        let ds = (ijk[a] as f64 - from) * line.sgn;
        if ds > 0.0 && best.is_none_or(|(_, b)| ds < b) {
            best = Some((m, ds));
        }
    }
    best.map(|(m, _)| m)
}

/// Traces side `d` of node `n`; returns the end and the number of steps.
pub fn trace(
    local: &LocalMap,
    topo: &Topology<4>,
    nodes: &Nodes,
    n: usize,
    d: usize,
    max_steps: usize,
) -> (End, usize) {
    let mut t = nodes.tet[n] as usize;
    let axis = d >> 1;
    let mut line = Line {
        axis,
        sgn: if d & 1 == 0 { 1.0 } else { -1.0 },
        val: nodes.ijk[n],
    };
    line.val[axis] = 0;
    let s0 = nodes.ijk[n][axis] as f64;
    if let Some(m) = node_ahead(nodes, t, &line, s0) {
        return (node_end(m, line.dir() ^ 1, Rot3::IDENTITY), 0);
    }
    let (hits, nh) = pierced(&local.coords[t], axis, &line.val);
    let exit = hits[..nh].iter().find(|h| (h.at - s0) * line.sgn > 0.0);
    let Some(&Pierce { face: mut e, .. }) = exit else {
        return (End::Inconsistent, 0);
    };
    let mut rho = Rot3::IDENTITY;
    for step in 1..=max_steps {
        let Some((t2, e2)) = topo.neighbour(t, e) else {
            return (End::Boundary, step);
        };
        let r = local.trans.rot[t][e];
        let line2 = carry(&line, &r, &local.trans.trans[t][e]);
        rho = rho.then(&r);
        let (hits, nh) = pierced(&local.coords[t2], line2.axis, &line2.val);
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
        (t, e, line) = (t2, out.face, line2);
    }
    (End::Loop, max_steps)
}

/// The line in the neighbour's chart across a transition `(r, tr)`: the
/// fixed integers carried exactly, the moving axis rotated.
fn carry(line: &Line, r: &Rot3, tr: &[i64; 3]) -> Line {
    let pi = r.apply_i(&line.val);
    let axis = r.apply_dir(line.dir()) >> 1;
    let mut val = [0i64; 3];
    for k in (0..3).filter(|&k| k != axis) {
        val[k] = pi[k] + tr[k];
    }
    Line {
        axis,
        sgn: line.sgn,
        val,
    }
}

/// The entry (on face `e2`) and the exit among exactly two pierced faces.
fn entry_exit(hits: &[Pierce], e2: usize) -> Option<(Pierce, Pierce)> {
    match hits {
        [a, b] if a.face == e2 => Some((*a, *b)),
        [a, b] if b.face == e2 => Some((*b, *a)),
        _ => None,
    }
}

fn node_end(m: usize, arrival_dir: usize, rho: Rot3) -> End {
    End::Node {
        side: (6 * m + arrival_dir) as u32,
        rho,
    }
}

//! Step 4: tracing the sides of every node along its iso-line to the next
//! node, topologically (DESIGN §3.3).
//!
//! Input: sanitized [`LocalMap`], [`Topology`], [`Nodes`]. Output: for each
//! side (`node·4 + dir`, dir as in `dualex_map::rotation`) the side reached
//! and the rotation ρ from the start node's chart to the arrival node's
//! chart, or an end reason.
//!
//! The walk: in the start triangle use the side's direction; after that,
//! leave through the *other* edge that the iso crosses (never back through
//! the entry), re-deriving the walking direction in each triangle's chart.
//! The side reached is the reverse of the current walking direction in the
//! arrival triangle's chart. Termination: a walk is deterministic and
//! reversible, so it visits each (triangle, entry edge) at most once before
//! it would cycle back to its first crossing; it is cut after
//! `3 · triangles + 3` steps (an iso loop without node), reported as such.

use crate::local::LocalMap;
use crate::nodes::Nodes;
use dualex_map::{Rot2, Topology};

/// How a walk ended (the dimension-generic [`dualex_graph::walk::End`]).
pub type End = dualex_graph::walk::End<2>;
pub use dualex_graph::walk::TraceReport;

/// An iso crossing of an edge: edge index and the moving coordinate there.
type Crossing = (usize, f64);

/// The iso crossings of triangle `p`'s edges, their number, and per
/// crossing whether it is exactly at a corner (a vertex on the iso: after
/// sanitization only a singular vertex, which no walk can pass
/// consistently — its charts disagree around it).
fn crossings(p: &[[f64; 2]; 3], fixed_axis: usize, val: i64) -> ([Crossing; 2], usize, [bool; 2]) {
    let mv = 1 - fixed_axis;
    let v = val as f64;
    let mut out = [(0usize, 0.0f64); 2];
    let mut at_corner = [false; 2];
    let mut n = 0;
    for f in 0..3 {
        // edge f is opposite corner f
        let a = p[(f + 1) % 3];
        let b = p[(f + 2) % 3];
        let (da, db) = (a[fixed_axis] - v, b[fixed_axis] - v);
        if (da > 0.0) != (db > 0.0) {
            if n < 2 {
                out[n] = (f, a[mv] + (b[mv] - a[mv]) * da / (da - db));
                at_corner[n] = da == 0.0 || db == 0.0;
            }
            n += 1;
        }
    }
    (out, n, at_corner)
}

/// Traces every side; returns the end of each walk.
pub fn trace_all(local: &LocalMap, topo: &Topology<3>, nodes: &Nodes) -> (Vec<End>, TraceReport) {
    let max_steps = 3 * local.coords.len() + 3;
    dualex_graph::walk::walk_all(nodes.len(), |n, d| {
        trace(local, topo, nodes, n, d, max_steps)
    })
}

/// Nearest node of triangle `s` on the iso `ij[fixed] == val`, strictly
/// ahead of `from` in direction `sgn` along the moving axis.
fn node_ahead(
    nodes: &Nodes,
    s: usize,
    fixed: usize,
    val: i64,
    from: f64,
    sgn: f64,
) -> Option<usize> {
    let mv = 1 - fixed;
    let mut best: Option<(usize, f64)> = None;
    for m in nodes.of_tri(s) {
        if nodes.ij[m][fixed] != val {
            continue;
        }
        let ds = (nodes.ij[m][mv] as f64 - from) * sgn;
        if ds > 0.0 && best.is_none_or(|(_, b)| ds < b) {
            best = Some((m, ds));
        }
    }
    best.map(|(m, _)| m)
}

/// Direction index of walking along `axis` with sign `sgn`.
#[inline]
fn dir(axis: usize, sgn: f64) -> usize {
    2 * axis + usize::from(sgn < 0.0)
}

/// Traces side `d` of node `n`; returns the end and the number of steps.
pub fn trace(
    local: &LocalMap,
    topo: &Topology<3>,
    nodes: &Nodes,
    n: usize,
    d: usize,
    max_steps: usize,
) -> (End, usize) {
    let mut t = nodes.tri[n] as usize;
    let mut axis = d >> 1; // moving axis
    let mut sgn = if d & 1 == 0 { 1.0 } else { -1.0 };
    let mut fixed = 1 - axis;
    let mut val = nodes.ij[n][fixed];
    let s0 = nodes.ij[n][axis] as f64;
    if let Some(m) = node_ahead(nodes, t, fixed, val, s0, sgn) {
        return (node_end(m, dir(axis, sgn) ^ 1, Rot2::IDENTITY), 0);
    }
    let (cr, nc, at_corner) = crossings(&local.coords[t], fixed, val);
    let exit = (0..nc.min(2)).find(|&k| (cr[k].1 - s0) * sgn > 0.0);
    let Some(k) = exit else {
        return (End::Inconsistent, 0);
    };
    if at_corner[k] {
        return (End::Inconsistent, 0);
    }
    let mut e = cr[k].0;
    let mut rho = Rot2::IDENTITY;
    for step in 1..=max_steps {
        let Some((t2, e2)) = topo.neighbour(t, e) else {
            return (End::Boundary, step);
        };
        let r = local.trans.rot[t][e];
        let tr = local.trans.trans[t][e];
        // the fixed coordinate is an integer: carry it exactly
        let mut p = [0i64; 2];
        p[fixed] = val;
        let pi = r.apply_i(&p);
        let mv_dir = r.apply_dir(dir(axis, sgn));
        let axis2 = mv_dir >> 1;
        let fixed2 = 1 - axis2;
        let val2 = pi[fixed2] + tr[fixed2];
        rho = rho.then(&r);
        let (cr, nc, at_corner) = crossings(&local.coords[t2], fixed2, val2);
        if nc != 2 || (cr[0].0 != e2 && cr[1].0 != e2) {
            return (End::Inconsistent, step);
        }
        let (inn, out, out_at_corner) = if cr[0].0 == e2 {
            (cr[0], cr[1], at_corner[1])
        } else {
            (cr[1], cr[0], at_corner[0])
        };
        let sgn2 = if out.1 > inn.1 { 1.0 } else { -1.0 };
        if let Some(m) = node_ahead(nodes, t2, fixed2, val2, inn.1, sgn2) {
            return (node_end(m, dir(axis2, sgn2) ^ 1, rho), step);
        }
        if out_at_corner {
            // the walk reaches a vertex on its iso
            return (End::Inconsistent, step);
        }
        (t, e, axis, fixed, val, sgn) = (t2, out.0, axis2, fixed2, val2, sgn2);
    }
    (End::Loop, max_steps)
}

fn node_end(m: usize, arrival_dir: usize, rho: Rot2) -> End {
    End::Node {
        side: (4 * m + arrival_dir) as u32,
        rho,
    }
}

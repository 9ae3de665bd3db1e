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
//!    them the entry ([`Simplex::crossed`]); where the simplex holds nodes,
//!    the walking sense is re-derived from the entry's crossing point
//!    towards the *other* one's ([`Simplex::crossing_at`]; never back
//!    through the entry) — elsewhere neither is needed, as the next
//!    moving axis does not depend on the sense;
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
use dualex_map::{Rot, Topology, NONE};

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
    let mut rows = Rows::of(local, topo, t);
    for step in 1..=max_steps {
        if rows.adj[e] == NONE {
            return (End::Boundary, step);
        }
        let (t2, e2, r) = (rows.adj[e] as usize, rows.facet[e] as usize, rows.rot[e]);
        let mut line2 = carry(&line, &r, &local.trans.trans[t][e]);
        if !r.is_identity() {
            rho = rho.then(&r);
        }
        let next = Rows::of(local, topo, t2);
        let p = &local.coords[t2];
        let crossed = Dim::<N, D>::crossed(p, &line2);
        let Some(out) = crossed.exit(e2) else {
            return (End::Inconsistent, step);
        };
        // the walking sense and the crossing points matter only where a
        // node may end the walk (the next axis does not depend on the sense)
        if !nodes.of_simplex(t2).is_empty() {
            let inn_at = Dim::<N, D>::crossing_at(p, &line2, e2);
            let out_at = Dim::<N, D>::crossing_at(p, &line2, out);
            line2.sgn = if out_at > inn_at { 1.0 } else { -1.0 };
            if let Some(m) = node_ahead(nodes, t2, &line2, inn_at) {
                return (node_end(m, line2.dir() ^ 1, rho), step);
            }
        }
        if crossed.corners >> out & 1 == 1 {
            // the walk reaches a vertex on its iso
            return (End::Inconsistent, step);
        }
        (t, e, line, rows) = (t2, out, line2, next);
    }
    (End::Loop, max_steps)
}

/// What a walk step reads of simplex `t` once it knows the exit facet:
/// its neighbours, their facets and the rotations across, read as soon as
/// `t` is known, so that these loads (and its translation row, touched)
/// overlap those of `t`'s image instead of following the
/// crossing test. The walk is bound by memory latency: it reads each
/// simplex's rows at a place of its own.
struct Rows<const N: usize, const D: usize> {
    adj: [u32; N],
    facet: [u8; N],
    rot: [Rot<D>; N],
}

impl<const N: usize, const D: usize> Rows<N, D> {
    /// The rows of simplex `t`.
    #[inline]
    fn of(local: &LocalMap<N, D>, topo: &Topology<N>, t: usize) -> Self {
        let tr = &local.trans.trans[t];
        // the first and last cache lines of the translation row
        std::hint::black_box(tr[0][0] ^ tr[N - 1][D - 1]);
        Rows {
            adj: topo.adj[t],
            facet: topo.adj_facet[t],
            rot: local.trans.rot[t],
        }
    }
}

/// The line in the neighbour's chart across a transition `(r, tr)`: the
/// fixed integers carried exactly, the moving axis rotated.
fn carry<const D: usize>(line: &Line<D>, r: &Rot<D>, tr: &[i64; D]) -> Line<D> {
    if r.is_identity() {
        // the common transition inside one chart: no table to read
        let mut val = line.val;
        for (k, (v, t)) in val.iter_mut().zip(tr).enumerate() {
            *v = if k == line.axis { 0 } else { *v + t };
        }
        return Line { val, ..*line };
    }
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

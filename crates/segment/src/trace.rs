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
//!
//! **Walks derived, not walked.** The walk from the side a walk reached
//! is that walk reversed when nothing on the way tells the two senses
//! apart; [`trace`] says so ([`Traced::back`]) and [`trace_all`] walks
//! only the sides of positive direction first, then writes each side so
//! reached as the reverse ([`dualex_graph::walk::walk_all_paired`]) and
//! walks the rest. The reverse crosses the same simplices through the
//! same facets (the line is carried exactly, and the exit facet is the
//! other of the two crossed, whichever the entry). What can differ, and
//! what [`trace`] checks on the way:
//! - in the first simplex (the reverse's last): exactly two facets
//!   crossed, the sense the reverse takes from the two crossings opposite
//!   the walk's, and the start node the nearest ahead of the exit's
//!   crossing in that sense (computed as the reverse computes them);
//! - in every later simplex: the entry not crossed at a corner (the
//!   reverse leaves through it); where it holds nodes and the walk goes
//!   on, no node on the line at all (the walk found none ahead, the
//!   reverse would stop at one behind);
//! - in the last one (the reverse's first): no node ahead of the arrival
//!   node in the reverse sense, and the entry the first facet in facet
//!   order crossed ahead of it (as the reverse's first step computes).
//!
//! Across each facet the reverse's transition is the inverse (exact:
//! integer translations, grid rotations), so it carries the same lines
//! and composes ρ⁻¹ over the same steps. A walk ended in its first
//! simplex (a node ahead there) is reversible when the start node is the
//! nearest behind the one reached.

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
    dualex_graph::walk::walk_all_paired(nodes.len(), |n, d| {
        let t = trace(local, topo, nodes, n, d, max_steps);
        (t.end, t.steps, t.back)
    })
}

/// How one walk ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Traced<const D: usize> {
    /// The end.
    pub end: End<D>,
    /// The simplices crossed into.
    pub steps: usize,
    /// Whether the walk from the side reached (an [`End::Node`]) is this
    /// walk reversed: the same steps, back to this side, ρ⁻¹ (module docs).
    pub back: bool,
}

/// Nearest node of simplex `s` on `line`, strictly ahead of `from`, and
/// whether some node on `line` is not ahead of it (behind or at `from`).
fn node_ahead<const N: usize, const D: usize>(
    nodes: &Nodes<N, D>,
    s: usize,
    line: &Line<D>,
    from: f64,
) -> (Option<usize>, bool) {
    let a = line.axis;
    let mut best: Option<(usize, f64)> = None;
    let mut behind = false;
    for m in nodes.of_simplex(s) {
        let x = &nodes.point[m];
        if (0..D).any(|k| k != a && x[k] != line.val[k]) {
            continue;
        }
        let ds = (x[a] as f64 - from) * line.sgn;
        if ds > 0.0 {
            if best.is_none_or(|(_, b)| ds < b) {
                best = Some((m, ds));
            }
        } else {
            behind = true;
        }
    }
    (best.map(|(m, _)| m), behind)
}

/// Traces side `d` of node `n` (module docs).
pub fn trace<const N: usize, const D: usize>(
    local: &LocalMap<N, D>,
    topo: &Topology<N>,
    nodes: &Nodes<N, D>,
    n: usize,
    d: usize,
    max_steps: usize,
) -> Traced<D>
where
    Dim<N, D>: Simplex<N, D>,
{
    let lost = |end, steps| Traced {
        end,
        steps,
        back: false,
    };
    let mut t = nodes.simplex[n] as usize;
    let axis = d >> 1;
    let mut line = Line {
        axis,
        sgn: if d & 1 == 0 { 1.0 } else { -1.0 },
        val: nodes.point[n],
    };
    line.val[axis] = 0;
    let s0 = nodes.point[n][axis] as f64;
    if let (Some(m), _) = node_ahead(nodes, t, &line, s0) {
        // the reverse, from `m`, finds the nearest node behind it
        let rev = Line {
            sgn: -line.sgn,
            ..line
        };
        let sm = nodes.point[m][axis] as f64;
        return Traced {
            end: node_end(m, line.dir() ^ 1, Rot::<D>::IDENTITY),
            steps: 0,
            back: node_ahead(nodes, t, &rev, sm).0 == Some(n),
        };
    }
    let (hits, nh) = Dim::<N, D>::pierced(&local.coords[t], &line);
    let exit = hits[..nh].iter().find(|h| (h.at - s0) * line.sgn > 0.0);
    let Some(&Pierce {
        face: mut e,
        at_corner: false,
        ..
    }) = exit
    else {
        return lost(End::Inconsistent, 0);
    };
    let mut back = first_reversible(nodes, t, &line, n, &hits[..nh], e);
    let mut rho = Rot::<D>::IDENTITY;
    let mut rows = Rows::of(local, topo, t);
    for step in 1..=max_steps {
        if rows.adj[e] == NONE {
            return lost(End::Boundary, step);
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
            return lost(End::Inconsistent, step);
        };
        // the reverse leaves through the entry: not at a corner
        back &= crossed.corners >> e2 & 1 == 0;
        // the walking sense and the crossing points matter only where a
        // node may end the walk (the next axis does not depend on the sense)
        if !nodes.of_simplex(t2).is_empty() {
            let inn_at = Dim::<N, D>::crossing_at(p, &line2, e2);
            let out_at = Dim::<N, D>::crossing_at(p, &line2, out);
            line2.sgn = if out_at > inn_at { 1.0 } else { -1.0 };
            let (ahead, behind) = node_ahead(nodes, t2, &line2, inn_at);
            if let Some(m) = ahead {
                back &= last_reversible(nodes, t2, &line2, m, [(e2, inn_at), (out, out_at)]);
                let end = node_end(m, line2.dir() ^ 1, rho);
                return Traced {
                    end,
                    steps: step,
                    back,
                };
            }
            // the reverse would stop at a node on the line here
            back &= !behind;
        }
        if crossed.corners >> out & 1 == 1 {
            // the walk reaches a vertex on its iso
            return lost(End::Inconsistent, step);
        }
        (t, e, line, rows) = (t2, out, line2, next);
    }
    lost(End::Loop, max_steps)
}

/// Whether the reverse of the walk from node `n` (`line`, in its first
/// simplex `t`, whose pierced facets are `hits`, leaving through `e`) ends
/// at `n` on the walk's side (module docs): it enters `t` through `e`,
/// needs exactly two facets crossed, finds the sense `−line.sgn` from
/// the two crossings and `n` as the nearest node ahead of `e`'s, as the
/// walk's own steps compute them.
fn first_reversible<const N: usize, const D: usize>(
    nodes: &Nodes<N, D>,
    t: usize,
    line: &Line<D>,
    n: usize,
    hits: &[Pierce],
    e: usize,
) -> bool {
    let [a, b] = hits else {
        return false;
    };
    let (inn, out) = if a.face == e { (a, b) } else { (b, a) };
    let sgn = if out.at > inn.at { 1.0 } else { -1.0 };
    let back = Line { sgn, ..*line };
    sgn == -line.sgn && node_ahead(nodes, t, &back, inn.at).0 == Some(n)
}

/// Whether the reverse of a walk that ends at node `m` of its last
/// simplex `t` (`line`, entered through `crossings[0]`, the other facet
/// crossed `crossings[1]`, each with its crossing) leaves `t` through the
/// entry, as the walk's first step computes it: no node ahead of `m` in
/// the reverse sense, and the entry the first facet (in facet order)
/// crossed ahead of `m`.
fn last_reversible<const N: usize, const D: usize>(
    nodes: &Nodes<N, D>,
    t: usize,
    line: &Line<D>,
    m: usize,
    crossings: [(usize, f64); 2],
) -> bool {
    let back = Line {
        sgn: -line.sgn,
        ..*line
    };
    let sm = nodes.point[m][line.axis] as f64;
    let [(entry, entry_ahead), (other, other_ahead)] =
        crossings.map(|(f, at)| (f, (at - sm) * back.sgn > 0.0));
    let first_is_entry = entry_ahead && !(other_ahead && other < entry);
    first_is_entry && node_ahead(nodes, t, &back, sm).0.is_none()
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

#[cfg(test)]
#[path = "trace_paired_tests.rs"]
mod paired_tests;

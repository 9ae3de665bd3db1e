//! Index fairing (2D, DESIGN §4, paper appendix "Index Fairing").
//!
//! Input: an untangled 2D graph. Output: the same graph after saddle lifts
//! that merge each interior vertex of valence 1 (index ¾), then valence 2
//! (index ½), with the nearest interior vertex of valence ≥ 7 (index ≤ −¾)
//! at most `max_path` edges away, and [`FairingStats`].
//!
//! The lift: at an interior vertex v of valence n ≥ 7 with fan
//! X_0 … X_{n-1} (see [`crate::fan`]), crossings i and j = i ± 4 lie on the
//! same iso with the same value in the chart carried around v (360° apart).
//! OP2 reconnects them: a = X_i.out ↔ c = X_{j+1}.in, with ρ_ac the
//! rotations composed along the fan from X_i to X_{j+1}; the former
//! partners b = X_{i+1}.in ↔ e = X_j.out.
//! ```text
//!   before: v has n corners; w_i, w_j the far ends of crossings i, j
//!   after:  v splits into 4 corners (X_{i+1}..X_j) and n−4 (X_{j+1}..X_i);
//!           w_i and w_j merge: valence(w) = valence(w_i) + valence(w_j)
//! ```
//! So the index ≤ −¾ moves from v to w, one edge along the path; the last
//! lift merges it with the target (valence 1 + 4 → 5, i.e. ¾ − 1 = −¼).
//! Every lift is kept only if it brings the pair one edge closer (else it
//! is undone by the inverse OP2), and a path that stalls is undone whole.
//!
//! Tried at v, for each crossing i towards the next vertex of the path:
//! the lifts (i, i + 4) and (i − 4, i), the 4 corners split off on either
//! side of i, each with the chart carried across them. (A fan read the
//! other way round — a chart turned by a quarter — names them (i′ − 4, i′)
//! and (i′, i′ + 4): the set does not depend on the turning sense.)
//!
//! Ties are broken without node or vertex numbers: the candidate among
//! equally near ones, the path among equally short ones and the order of
//! the trials follow [`crate::canon`], the graph seen from the
//! candidate's corner. So a graph numbered otherwise, or with other
//! charts, is faired into the same graph up to that renumbering (or a
//! symmetry): the layer of an extruded map's columns ([`crate::columns`])
//! as the map's own graph, whose nodes follow the tets, not the triangles.

use crate::canon;
use crate::fair_local::LocalVertices;
use crate::fan::{corner_sides, FanStep};
use crate::glue::Glued;
use crate::graph::NodeGraph;
use crate::ids::{axis, Node, Side};
use crate::ops::OpError;
use dualex_map::{Rot, Rot2};
use serde_json::{json, Value};
use std::collections::VecDeque;

/// What index fairing did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FairingStats {
    /// Interior vertices of valence 1 before fairing.
    pub valence1_before: usize,
    /// Interior vertices of valence 2 before fairing.
    pub valence2_before: usize,
    /// Singularities merged (paths completed).
    pub merged: usize,
    /// Saddle lifts kept.
    pub lifts: usize,
    /// Saddle lifts tried and undone.
    pub undone: usize,
    /// Candidates given up (no lift made progress).
    pub abandoned: usize,
    /// Interior vertices of valence 1 after fairing.
    pub valence1_after: usize,
    /// Interior vertices of valence 2 after fairing.
    pub valence2_after: usize,
}

impl FairingStats {
    /// The stats as a JSON object.
    pub fn to_json(&self) -> Value {
        json!({
            "valence1_before": self.valence1_before,
            "valence2_before": self.valence2_before,
            "merged": self.merged,
            "saddle_lifts": self.lifts,
            "undone": self.undone,
            "abandoned": self.abandoned,
            "valence1_after": self.valence1_after,
            "valence2_after": self.valence2_after,
        })
    }
}

/// How to undo a saddle lift: OP2 of `a` and `b` with `rho_ab`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LiftUndo {
    a: Side,
    b: Side,
    rho_ab: Rot2,
}

/// Mesh vertices of a glued 2D graph: corners, interior flag (their
/// adjacency apart: [`Adjacency`]).
struct Vertices {
    glued: Glued<2>,
    first: Vec<(Node, usize)>,
    corners: Vec<usize>,
    interior: Vec<bool>,
}

/// Neighbours of vertex `v`: `adj[adj_at[v]..adj_at[v + 1]]`, ascending
/// (`(adj_at, adj)`; built by [`adjacency`] only where a path is sought,
/// not for the counts).
type Adjacency<'a> = (&'a [u32], &'a [u32]);

/// Mesh-edge neighbours of every vertex as CSR, each list ascending and
/// without repeats (the adjacency of [`Glued::edges`], built per vertex
/// instead of by one global sort).
fn adjacency(glued: &Glued<2>) -> (Vec<u32>, Vec<u32>) {
    let nv = glued.n_vertices;
    // the cell sides: corners differing in one bit
    let sides = || {
        glued.nodes.iter().flat_map(move |n| {
            [(0, 1), (0, 2), (1, 3), (2, 3)]
                .map(|(c, d)| (glued.vertex(*n, c) as usize, glued.vertex(*n, d) as usize))
        })
    };
    let mut at = vec![0u32; nv + 1];
    for (p, q) in sides() {
        at[p + 1] += 1;
        at[q + 1] += 1;
    }
    for v in 0..nv {
        at[v + 1] += at[v];
    }
    let mut fill: Vec<u32> = at[..nv].to_vec();
    let mut adj = vec![0u32; at[nv] as usize];
    for (p, q) in sides() {
        for (from, to) in [(p, q), (q, p)] {
            adj[fill[from] as usize] = to as u32;
            fill[from] += 1;
        }
    }
    // sort and dedup each list in place, compacting
    let mut out_at = vec![0u32; nv + 1];
    let mut len = 0usize;
    for v in 0..nv {
        let (lo, hi) = (at[v] as usize, at[v + 1] as usize);
        adj[lo..hi].sort_unstable();
        let mut last = None;
        for i in lo..hi {
            if last != Some(adj[i]) {
                last = Some(adj[i]);
                adj[len] = adj[i];
                len += 1;
            }
        }
        out_at[v + 1] = len as u32;
    }
    adj.truncate(len);
    (out_at, adj)
}

impl Vertices {
    fn new(g: &NodeGraph<2>) -> Self {
        let glued = g.glue_vertices();
        let nv = glued.n_vertices;
        let mut first = vec![(Node(0), 0); nv];
        let (mut corners, mut interior) = (vec![0usize; nv], vec![true; nv]);
        for n in &glued.nodes {
            // a corner is interior when both its sides are glued
            let paired: [bool; 4] = std::array::from_fn(|d| g.opposite(g.side(*n, d)).is_some());
            let at = n.idx() * 4;
            for (c, &v) in glued.vertex_of[at..at + 4].iter().enumerate() {
                let v = v as usize;
                if corners[v] == 0 {
                    first[v] = (*n, c);
                }
                corners[v] += 1;
                let (du, dv) = corner_sides(c);
                interior[v] &= paired[du] && paired[dv];
            }
        }
        Vertices {
            glued,
            first,
            corners,
            interior,
        }
    }

    fn valence(&self, v: usize) -> Option<usize> {
        self.interior[v].then_some(self.corners[v])
    }

    fn count(&self, valence: usize) -> usize {
        (0..self.corners.len())
            .filter(|&v| self.valence(v) == Some(valence))
            .count()
    }

    /// Edges from p to the nearest interior vertex of valence ≥ 7 through
    /// interior vertices, if at most `max` (breadth-first; the length does
    /// not depend on the visiting order).
    fn distance(&self, (adj_at, adj): Adjacency, p: usize, max: usize) -> Option<usize> {
        let mut seen = vec![false; self.corners.len()];
        let mut queue = VecDeque::from([(p, 0usize)]);
        seen[p] = true;
        while let Some((v, d)) = queue.pop_front() {
            if v != p && self.valence(v).is_some_and(|k| k >= 7) {
                return Some(d);
            }
            if d == max {
                continue;
            }
            for &w in &adj[adj_at[v] as usize..adj_at[v + 1] as usize] {
                let w = w as usize;
                if !seen[w] && self.interior[w] {
                    seen[w] = true;
                    queue.push_back((w, d + 1));
                }
            }
        }
        None
    }
}

impl NodeGraph<2> {
    /// Saddle lift at the vertex of corner `code` of `x`, reconnecting
    /// crossings `i` and `j` of its fan (see the module docs).
    pub fn lift(&mut self, x: Node, code: usize, i: usize, j: usize) -> Result<LiftUndo, OpError> {
        let fan = self.fan(x, code).ok_or(OpError::BadLift(x))?;
        let n = fan.len();
        if i >= n || j >= n || i == j {
            return Err(OpError::BadLift(x));
        }
        let a = self.side(fan[i].node, fan[i].out_dir);
        let next = &fan[(j + 1) % n];
        let c = self.side(next.node, next.in_dir);
        let mut rho = Rot::IDENTITY;
        let mut k = i;
        loop {
            rho = rho.then(&fan[k].rot);
            if k == j {
                break;
            }
            k = (k + 1) % n;
        }
        let b = self.opposite(a).ok_or(OpError::BadLift(x))?;
        let rho_ab = self.rot[a.idx()];
        self.op2(a, c, rho)?;
        Ok(LiftUndo { a, b, rho_ab })
    }

    /// Undoes a lift (the inverse OP2); the graph must not have changed
    /// since around those sides.
    pub fn undo_lift(&mut self, u: LiftUndo) -> Result<(), OpError> {
        self.op2(u.a, u.b, u.rho_ab).map(|_| ())
    }

    /// Index fairing with paths of at most `max_path` edges.
    pub fn fair(&mut self, max_path: usize) -> FairingStats {
        self.fair_glued(max_path).0
    }

    /// [`Self::fair`], also returning the vertices of the graph it leaves as
    /// [`Self::glue_from`] takes them (none when all paths tried were undone).
    pub fn fair_glued(&mut self, max_path: usize) -> (FairingStats, Option<Glued<2>>) {
        let v = Vertices::new(self);
        let mut st = FairingStats {
            valence1_before: v.count(1),
            valence2_before: v.count(2),
            ..Default::default()
        };
        let mut changed = false;
        for target in [1, 2] {
            // nothing to merge: skip the (whole-graph) vertex rebuilds
            let count = if changed {
                Vertices::new(self).count(target)
            } else {
                v.count(target)
            };
            if count == 0 {
                continue;
            }
            let mut given_up: Vec<(Node, usize)> = Vec::new();
            let bound = 2 * count + 1;
            for _ in 0..bound {
                let Some((start, dist)) = self.next_candidate(target, &given_up, max_path) else {
                    break;
                };
                if self.move_along(start, dist, max_path, target, &mut st) {
                    st.merged += 1;
                    changed = true;
                } else {
                    given_up.push(start);
                    st.abandoned += 1;
                }
            }
        }
        if changed {
            let v = Vertices::new(self);
            st.valence1_after = v.count(1);
            st.valence2_after = v.count(2);
            return (st, Some(v.glued));
        }
        // failed paths are undone exactly: the graph is as before
        st.valence1_after = st.valence1_before;
        st.valence2_after = st.valence2_before;
        let untouched = st.abandoned == 0;
        (st, untouched.then_some(v.glued))
    }

    /// The corner to move from and its distance: of the interior vertices
    /// of valence `target` (but those of `given_up`'s corners) with a
    /// vertex of valence ≥ 7 at most `max_path` edges away, the nearest;
    /// among equally near ones, [`Self::start_corner`].
    fn next_candidate(
        &self,
        target: usize,
        given_up: &[(Node, usize)],
        max_path: usize,
    ) -> Option<((Node, usize), usize)> {
        let v = Vertices::new(self);
        let (adj_at, adj) = adjacency(&v.glued);
        let skip: Vec<u32> = given_up
            .iter()
            .map(|&(n, c)| v.glued.vertex(n, c))
            .collect();
        let near: Vec<(usize, usize)> = (0..v.corners.len())
            .filter(|&p| v.valence(p) == Some(target) && !skip.contains(&(p as u32)))
            .filter_map(|p| v.distance((&adj_at, &adj), p, max_path).map(|d| (d, p)))
            .collect();
        let dist = near.iter().map(|&(d, _)| d).min()?;
        let nearest: Vec<(Node, usize)> = near
            .iter()
            .filter(|&&(d, _)| d == dist)
            .map(|&(_, p)| v.first[p])
            .collect();
        Some((self.start_corner(&nearest)?, dist))
    }

    /// Among the vertices of the corners `nearest`, all equally near their
    /// valence ≥ 7 vertex, the corner to move from: the least by
    /// [`canon::compare`] of all their alive corners, so the choice does
    /// not depend on the numbering of nodes or vertices (the searches from
    /// all these corners are compared until they differ).
    fn start_corner(&self, nearest: &[(Node, usize)]) -> Option<(Node, usize)> {
        let mut corners = Vec::new();
        for &pc in nearest {
            let mut v = LocalVertices::new(self, pc);
            let p = v.vertex_of(pc.0, pc.1)?;
            corners.extend(v.corners(p));
        }
        canon::least(self, &corners)
    }

    /// Moves the singularity at distance `dist` from the vertex of corner
    /// `pc` onto it, one lift per edge; undoes everything on a stall.
    fn move_along(
        &mut self,
        pc: (Node, usize),
        dist: usize,
        max_path: usize,
        target: usize,
        st: &mut FairingStats,
    ) -> bool {
        let mut done = Vec::new();
        for left in (1..=dist).rev() {
            match self.lift_towards(pc, left, max_path, target, st) {
                Some(u) => done.push(u),
                None => {
                    for u in done.into_iter().rev() {
                        if let Err(e) = self.undo_lift(u) {
                            panic!("bug: undoing a saddle lift failed: {e}");
                        }
                        st.undone += 1;
                    }
                    return false;
                }
            }
        }
        st.lifts += done.len();
        true
    }

    /// One lift bringing the nearest valence ≥ 7 vertex from distance
    /// `dist` to `dist − 1` of the vertex of `pc` (merging when 1).
    fn lift_towards(
        &mut self,
        pc: (Node, usize),
        dist: usize,
        max_path: usize,
        target: usize,
        st: &mut FairingStats,
    ) -> Option<LiftUndo> {
        // local queries: the same answers as a whole-graph rebuild (see
        // `fair_local`), at the cost of the region they touch
        let mut v = LocalVertices::new(self, pc);
        let p = v.vertex_of(pc.0, pc.1)?;
        let path = v.path(p, max_path).filter(|path| path.len() == dist + 1)?;
        let (s, next) = (path[dist], path[dist - 1]);
        let (sx, scode) = v.first(s)?;
        let fan = self
            .fan(sx, scode)
            .filter(|f| f.len() == v.corner_count(s))?;
        let n = fan.len();
        // the steps whose far corner is `next` (before any lift: a failed
        // lift is undone exactly, so this stays true between trials)
        let towards: Vec<bool> = fan
            .iter()
            .map(|step| {
                let far = step.code() ^ (1 << axis(step.in_dir));
                v.vertex_of(step.node, far) == Some(next)
            })
            .collect();
        // per trial, the nodes whose sides the lift reconnects and their
        // loop sides before it (a lift must not add any)
        let trials: Vec<(usize, usize, [Node; 4], usize)> = trial_order(&mut v, &fan, &towards)
            .into_iter()
            .map(|(i, j)| {
                let touched = [i, (i + 1) % n, j, (j + 1) % n].map(|k| fan[k].node);
                (i, j, touched, loop_sides(&mut v, &touched))
            })
            .collect();
        for (i, j, touched, loops_before) in trials {
            {
                let Ok(u) = self.lift(sx, scode, i, j) else {
                    continue;
                };
                let mut after = LocalVertices::new(self, pc);
                let ok = loop_sides(&mut after, &touched) <= loops_before
                    && match after.vertex_of(pc.0, pc.1) {
                        None => false,
                        Some(np) if dist == 1 => after.valence(np).is_some_and(|k| k > target),
                        Some(np) => after.path(np, max_path).is_some_and(|p| p.len() == dist),
                    };
                if ok {
                    return Some(u);
                }
                if let Err(e) = self.undo_lift(u) {
                    panic!("bug: undoing a saddle lift failed: {e}");
                }
                st.undone += 1;
            }
        }
        None
    }
}

/// The saddle lifts to try at a vertex with fan `fan`, as pairs `(i, j)`
/// of [`NodeGraph::lift`]: for each crossing `i` towards the next vertex
/// (`towards[i]`), the lifts carrying the chart across the 4 steps from
/// `i` to `i + 4` and from `i − 4` to `i` (360° apart, one each way
/// around). They are ordered by what they reconnect — the corner ranks of
/// `v` (seen from the fairing's start) on both crossings, then of the
/// corners walked — so neither the fan's first corner nor the turning
/// sense of the charts (which reverses the fan) changes the order.
fn trial_order(v: &mut LocalVertices, fan: &[FanStep], towards: &[bool]) -> Vec<(usize, usize)> {
    let n = fan.len();
    let ranks: Vec<u64> = fan
        .iter()
        .map(|f| v.corner_rank(f.node, f.code()))
        .collect();
    let crossing = |k: usize| {
        let (a, b) = (ranks[k], ranks[(k + 1) % n]);
        (a.min(b), a.max(b))
    };
    let mut keyed: Vec<_> = (0..n)
        .filter(|&i| towards[i])
        .flat_map(|i| [(i, (i + 4) % n), ((i + n - 4) % n, i)])
        .map(|(i, j)| {
            let (a, b) = (crossing(i), crossing(j));
            let mut walked: Vec<u64> = (0..=(j + n - i) % n + 1)
                .map(|k| ranks[(i + k) % n])
                .collect();
            walked.sort_unstable();
            ((a.min(b), a.max(b), walked), i, j)
        })
        .collect();
    keyed.sort_unstable();
    // a lift reached from both its crossings (both towards the next
    // vertex) is tried once
    keyed.dedup_by(|x, y| x.0 == y.0);
    keyed.into_iter().map(|(_, i, j)| (i, j)).collect()
}

/// Sides of `nodes` whose two corners are one vertex (loop edges). A lift
/// must not add any: on a fan that visits a node twice (the traced graphs
/// of maps with holes at singular vertices), reconnecting its crossings can
/// glue both ends of a side together, a vertex with two fans once glued.
fn loop_sides(v: &mut LocalVertices, nodes: &[Node]) -> usize {
    let mut n = 0;
    for &x in nodes {
        for (c, d) in [(0, 1), (0, 2), (1, 3), (2, 3)] {
            if v.vertex_of(x, c).is_some() && v.vertex_of(x, c) == v.vertex_of(x, d) {
                n += 1;
            }
        }
    }
    n
}

#[cfg(test)]
mod local_tests;

//! Vertices of a 2D graph found around given corners, without gluing the
//! whole graph: what index fairing asks after each trial saddle lift.
//!
//! Input: a [`NodeGraph<2>`] (its opposite relation an involution, as
//! [`NodeGraph::check`] requires) and a start corner. Output, for the
//! vertex of any corner: the same answers as [`crate::glue::Glued`] and
//! the fairing's vertex table built from it — the set of corners glued
//! together (the same union–find links: a pair of sides is processed from
//! its smaller side, when that side's node is alive, and only if all its
//! corners match), the alive corners, the interior flag, the neighbours
//! along cell edges — and a vertex order that does not depend on the
//! numbering of nodes: the least [`Canon`] corner rank of its alive
//! corners, seen from the start corner. Shortest paths are searched in
//! that order, so the path taken among equally short ones is the same
//! however the graph is numbered. A vertex is explored on first use; the
//! cost is proportional to the region the queries touch.

use crate::canon::Canon;
use crate::fan::corner_sides;
use crate::graph::NodeGraph;
use crate::ids::{Node, Side};
use std::collections::{HashMap, VecDeque};

/// One vertex: the least corner rank of its alive corners (its order),
/// its alive corners (by corner rank) and whether it is interior.
struct Vertex {
    rep: u64,
    alive: Vec<usize>,
    interior: bool,
}

/// Vertices explored so far (valid while the graph does not change).
pub(crate) struct LocalVertices<'a> {
    g: &'a NodeGraph<2>,
    order: Canon<'a>,
    of_corner: HashMap<usize, usize>,
    vertices: Vec<Vertex>,
}

impl<'a> LocalVertices<'a> {
    /// Vertices ordered as seen from corner `start` (module docs).
    pub(crate) fn new(g: &'a NodeGraph<2>, start: (Node, usize)) -> Self {
        LocalVertices {
            g,
            order: Canon::new(g, start),
            of_corner: HashMap::new(),
            vertices: Vec::new(),
        }
    }

    /// The corner rank of `corner` (`node·4 + code`) seen from the start;
    /// corners outside the start's component (which no query starting
    /// there reaches: glued corners and cell edges stay in it) last.
    fn rank(&mut self, corner: usize) -> u64 {
        let node = Node((corner / 4) as u32);
        self.order.corner_rank(node, corner % 4).unwrap_or(u64::MAX)
    }

    /// [`Self::rank`] of corner `code` of `node`.
    pub(crate) fn corner_rank(&mut self, node: Node, code: usize) -> u64 {
        self.rank(node.idx() * 4 + code)
    }

    /// The corners glued to `corner` across side `s` of its node.
    fn across(&self, s: Side, corner: usize, out: &mut Vec<usize>) {
        let g = self.g;
        let Some(t) = g.opposite(s) else { return };
        let (lo, hi) = if s < t { (s, t) } else { (t, s) };
        if !g.is_alive(g.node_of(lo)) {
            return;
        }
        // the gluing's own rule, from the smaller side
        let Some((pairs, n)) = g.matched_corners(lo, hi) else {
            return; // a mismatched pair glues nothing
        };
        let (lnode, hnode) = (g.node_of(lo).idx(), g.node_of(hi).idx());
        let code = corner % 4;
        for &(c, ct) in &pairs[..n] {
            if s == lo && c == code {
                out.push(hnode * 4 + ct);
            }
            if s == hi && ct == code {
                out.push(lnode * 4 + c);
            }
        }
    }

    /// The vertex holding `corner` (`node·4 + code`), explored if new.
    pub(crate) fn vertex(&mut self, corner: usize) -> usize {
        if let Some(&v) = self.of_corner.get(&corner) {
            return v;
        }
        let g = self.g;
        let mut all = vec![corner];
        let mut queue = VecDeque::from([corner]);
        let mut next = Vec::new();
        while let Some(k) = queue.pop_front() {
            let (node, code) = (Node((k / 4) as u32), k % 4);
            next.clear();
            let (du, dv) = corner_sides(code);
            for d in [du, dv] {
                self.across(g.side(node, d), k, &mut next);
            }
            for &m in &next {
                if !all.contains(&m) {
                    all.push(m);
                    queue.push_back(m);
                }
            }
        }
        let mut alive: Vec<(u64, usize)> = all
            .iter()
            .copied()
            .filter(|&k| g.is_alive(Node((k / 4) as u32)))
            .map(|k| (self.rank(k), k))
            .collect();
        alive.sort_unstable();
        let rep = alive.first().map_or(u64::MAX, |&(r, _)| r);
        let alive: Vec<usize> = alive.into_iter().map(|(_, k)| k).collect();
        let interior = alive.iter().all(|&k| {
            let (du, dv) = corner_sides(k % 4);
            let node = Node((k / 4) as u32);
            [du, dv]
                .iter()
                .all(|&d| g.opposite(g.side(node, d)).is_some())
        });
        let id = self.vertices.len();
        for &k in &all {
            self.of_corner.insert(k, id);
        }
        self.vertices.push(Vertex {
            rep,
            alive,
            interior,
        });
        id
    }

    /// The vertex of corner `code` of `node`, if `node` is alive (the
    /// glued table has no vertex for dead nodes).
    pub(crate) fn vertex_of(&mut self, node: Node, code: usize) -> Option<usize> {
        (self.g.is_alive(node) && code < 4).then(|| self.vertex(node.idx() * 4 + code))
    }

    /// Valence of an interior vertex (its alive corners), `None` on the
    /// boundary.
    pub(crate) fn valence(&self, v: usize) -> Option<usize> {
        let x = &self.vertices[v];
        x.interior.then_some(x.alive.len())
    }

    /// Number of alive corners.
    pub(crate) fn corner_count(&self, v: usize) -> usize {
        self.vertices[v].alive.len()
    }

    /// The first alive corner (least corner rank) as `(node, code)`.
    pub(crate) fn first(&self, v: usize) -> Option<(Node, usize)> {
        let k = *self.vertices[v].alive.first()?;
        Some((Node((k / 4) as u32), k % 4))
    }

    /// The alive corners, first to last, as `(node, code)`.
    pub(crate) fn corners(&self, v: usize) -> Vec<(Node, usize)> {
        let alive = &self.vertices[v].alive;
        alive
            .iter()
            .map(|&k| (Node((k / 4) as u32), k % 4))
            .collect()
    }

    /// Neighbours along cell edges, by vertex order, without repeats.
    fn neighbours(&mut self, v: usize) -> Vec<usize> {
        let corners = self.vertices[v].alive.clone();
        let mut out: Vec<usize> = Vec::with_capacity(2 * corners.len());
        for k in corners {
            for bit in [1, 2] {
                out.push(self.vertex((k / 4) * 4 + ((k % 4) ^ bit)));
            }
        }
        out.sort_unstable_by_key(|&w| self.vertices[w].rep);
        out.dedup();
        out
    }

    /// Shortest path p → … → s through interior vertices to the nearest
    /// interior vertex of valence ≥ 7, at most `max` edges: breadth-first,
    /// neighbours in vertex order (module docs).
    pub(crate) fn path(&mut self, p: usize, max: usize) -> Option<Vec<usize>> {
        let mut parent: HashMap<usize, usize> = HashMap::from([(p, p)]);
        let mut queue = VecDeque::from([(p, 0usize)]);
        while let Some((v, d)) = queue.pop_front() {
            if v != p && self.valence(v).is_some_and(|k| k >= 7) {
                let mut path = vec![v];
                while let Some(&last) = path.last().filter(|&&x| x != p) {
                    path.push(parent[&last]);
                }
                path.reverse();
                return Some(path);
            }
            if d == max {
                continue;
            }
            for w in self.neighbours(v) {
                if !parent.contains_key(&w) && self.vertices[w].interior {
                    parent.insert(w, v);
                    queue.push_back((w, d + 1));
                }
            }
        }
        None
    }
}

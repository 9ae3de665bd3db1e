//! Collapsed clusters: vertices joined by zero-length map edges, which
//! sanitization moves as one (DESIGN §3.1).
//!
//! Input: map, stars, (local) coordinates per corner. Output: [`Clusters`]:
//! per non-trivial cluster its members with the rotation from the root's
//! reference chart to each member's reference chart (read through a simplex
//! that holds both ends of a collapsed edge); a cluster is stuck (`None`)
//! when its rotations disagree. Singular vertices never join a cluster:
//! they do not move, and a vertex collapsed onto one (exactly, once
//! singular vertices are snapped to their fixed points) must still move
//! away from it. Generic over
//! the dimension: used by both extractions. The collapsed edges are found
//! in parallel and joined in simplex order: the clusters do not depend on
//! the thread count.

use dualex_map::{Rot, SimplexMap, Stars};
use dualex_util::union_find::UnionFind;
use rayon::prelude::*;
use std::collections::HashMap;

/// The collapsed clusters of a map.
pub struct Clusters<const D: usize> {
    /// The clusters as sets (each joined into its second vertex's set:
    /// [`UnionFind::union_into`], whose root gives the reference chart).
    sets: UnionFind,
    /// Per vertex: rotation from its cluster root's reference chart to its
    /// own reference chart; `None` when the cluster cannot move. (With
    /// `sets`, empty when no edge is collapsed: [`Self::lone`].)
    rot_from_root: Vec<Option<Rot<D>>>,
    members: HashMap<u32, Vec<u32>>,
}

impl<const D: usize> Clusters<D> {
    /// Finds the clusters.
    pub fn build<const N: usize>(
        map: &SimplexMap<N, D>,
        stars: &Stars<D>,
        coords: &[[[f64; D]; N]],
    ) -> Self {
        let nv = map.positions.len();
        // a singular vertex never moves: a vertex collapsed onto it moves
        // on its own, away from it
        let singular = |v: u32| stars.singular[v as usize];
        let collapsed = |tet: &[u32; N], c: &[[f64; D]; N], k: usize, l: usize| {
            c[k] == c[l] && !singular(tet[k]) && !singular(tet[l])
        };
        // first whether any edge is collapsed (the common answer: none), by
        // plain loops in tasks of `EDGE_TASK` simplices
        let any = map
            .simplices
            .par_chunks(EDGE_TASK)
            .zip(coords.par_chunks(EDGE_TASK))
            .any(|(ts, cs)| {
                ts.iter()
                    .zip(cs)
                    .any(|(t, c)| (0..N).any(|k| (k + 1..N).any(|l| collapsed(t, c, k, l))))
            });
        if !any {
            return Self::lone();
        }
        // the collapsed edges, found in parallel, in simplex order
        let edges: Vec<(u32, u32, usize)> = map
            .simplices
            .par_iter()
            .zip(coords)
            .enumerate()
            .with_min_len(EDGE_TASK)
            .flat_map_iter(|(s, (tet, c))| {
                (0..N)
                    .flat_map(|k| (k + 1..N).map(move |l| (k, l)))
                    .filter(move |&(k, l)| collapsed(tet, c, k, l))
                    .map(move |(k, l)| (tet[k], tet[l], s))
            })
            .collect();
        let mut sets = UnionFind::new(nv);
        // joined in that order (the roots depend on it)
        for &(a, b, _) in &edges {
            sets.union_into(a as usize, b as usize);
        }
        // only vertices on a collapsed edge can be in a non-trivial cluster
        let mut on_edge: Vec<u32> = edges.iter().flat_map(|&(a, b, _)| [a, b]).collect();
        on_edge.sort_unstable();
        on_edge.dedup();
        let mut members: HashMap<u32, Vec<u32>> = HashMap::new();
        for v in on_edge {
            let r = sets.find(v as usize) as u32;
            members.entry(r).or_default().push(v);
        }
        members.retain(|_, m| m.len() > 1);
        let adj = rotation_edges(stars, &edges);
        let mut rot_from_root: Vec<Option<Rot<D>>> = vec![Some(Rot::IDENTITY); nv];
        for (&root, m) in &members {
            let ok_singular = m.iter().all(|&v| !stars.singular[v as usize]);
            let seen = spread(root, &adj);
            let ok = ok_singular && seen.as_ref().is_some_and(|s| s.len() == m.len());
            for &v in m {
                rot_from_root[v as usize] = if ok {
                    seen.as_ref().and_then(|s| s.get(&v).copied())
                } else {
                    None
                };
            }
        }
        Clusters {
            sets,
            rot_from_root,
            members,
        }
    }

    /// No collapsed edge: every vertex its own root, movable, alone (what
    /// the sets and rotations of [`Self::build`] say then, without their
    /// per-vertex arrays).
    fn lone() -> Self {
        Clusters {
            sets: UnionFind::new(0),
            rot_from_root: Vec::new(),
            members: HashMap::new(),
        }
    }

    /// Number of clusters with more than one vertex.
    pub fn count_nontrivial(&self) -> usize {
        self.members.len()
    }

    /// The cluster root of `v`.
    pub fn root(&self, v: u32) -> u32 {
        if self.sets.is_empty() {
            return v;
        }
        self.sets.root(v as usize) as u32
    }

    /// Whether the cluster of `root` can move consistently (every member
    /// has a rotation from the root's chart: all or none of them have).
    pub fn movable(&self, root: u32) -> bool {
        self.rot_from_root.is_empty() || self.rot_from_root[root as usize].is_some()
    }

    /// Calls `f` with every member of the cluster of `root` (which
    /// [`Self::movable`]) and its rotation from the root's chart; a lone
    /// vertex is its own cluster, without a look-up.
    pub fn for_each_member(&self, root: u32, mut f: impl FnMut(u32, Rot<D>)) {
        let members = if self.members.is_empty() {
            None
        } else {
            self.members.get(&root)
        };
        match members {
            None => f(root, Rot::IDENTITY),
            Some(m) => {
                for &v in m {
                    if let Some(r) = self.rot_from_root[v as usize] {
                        f(v, r);
                    }
                }
            }
        }
    }
}

/// Simplices per parallel task of the collapsed-edge scans.
const EDGE_TASK: usize = 4096;

type Adjacency<const D: usize> = HashMap<u32, Vec<(u32, Rot<D>)>>;

/// Collapsed edges as rotations between the endpoints' reference charts.
fn rotation_edges<const D: usize>(stars: &Stars<D>, edges: &[(u32, u32, usize)]) -> Adjacency<D> {
    let star_rot = |v: u32, s: usize| {
        stars
            .of(v as usize)
            .iter()
            .find(|e| e.simplex as usize == s)
            .map(|e| e.rot)
    };
    let mut adj: Adjacency<D> = HashMap::new();
    for &(a, b, s) in edges {
        if let (Some(ra), Some(rb)) = (star_rot(a, s), star_rot(b, s)) {
            let ab = ra.then(&rb.inverse()); // a_ref → s → b_ref
            adj.entry(a).or_default().push((b, ab));
            adj.entry(b).or_default().push((a, ab.inverse()));
        }
    }
    adj
}

/// Rotations from `root` to every reachable vertex; `None` on disagreement.
fn spread<const D: usize>(root: u32, adj: &Adjacency<D>) -> Option<HashMap<u32, Rot<D>>> {
    let mut seen: HashMap<u32, Rot<D>> = HashMap::new();
    seen.insert(root, Rot::IDENTITY);
    let mut stack = vec![root];
    while let Some(a) = stack.pop() {
        let ra = seen[&a];
        for &(b, ab) in adj.get(&a).map(|x| x.as_slice()).unwrap_or(&[]) {
            let rb = ra.then(&ab);
            match seen.get(&b) {
                Some(old) if *old != rb => return None,
                Some(_) => {}
                None => {
                    seen.insert(b, rb);
                    stack.push(b);
                }
            }
        }
    }
    Some(seen)
}

#[cfg(test)]
mod tests {
    use super::Clusters;
    use crate::local::LocalMap;
    use dualex_map::{Rot, Stars, Topology, Transitions};

    /// Without a collapsed edge, the clusters answer as the sets and
    /// rotations built for every vertex did (no union: each vertex its own
    /// root; every rotation the identity: movable, alone); with collapsed
    /// edges (the collapsed square) the sets are built.
    #[test]
    fn lone_clusters_answer_as_built_ones() {
        let mut lone = 0;
        for name in dualex_gen::names() {
            let Some((map, _)) = dualex_gen::by_name(&name, 1) else {
                continue;
            };
            let Ok(topo) = Topology::build(&map) else {
                continue;
            };
            let Ok((trans, _)) = Transitions::derive(&map, &topo, &Default::default()) else {
                continue;
            };
            let stars = Stars::build(&map, &topo, &trans);
            let mut local = LocalMap::new(&map, &topo, &trans);
            local.snap(&stars);
            let c = Clusters::build(&map, &stars, &local.coords);
            if name == "square_collapsed" {
                assert!(c.count_nontrivial() > 0, "{name}");
            }
            if c.count_nontrivial() > 0 {
                continue;
            }
            lone += 1;
            for v in 0..map.positions.len() as u32 {
                assert_eq!(c.root(v), v, "{name} {v}");
                assert!(c.movable(v), "{name} {v}");
                let mut members = Vec::new();
                c.for_each_member(v, |w, r| members.push((w, r)));
                assert_eq!(members, vec![(v, Rot::IDENTITY)], "{name} {v}");
            }
        }
        assert!(lone >= 10, "{lone}");
    }
}

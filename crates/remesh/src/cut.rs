//! Cutting the surface to a topological disk through every singularity.
//!
//! Input: a [`Surface`] and its singular vertices. Output: a [`Cut`], the
//! set of interior edges to cut along. Cutting along them (and the
//! boundary, already open) leaves one topological disk per connected
//! component, with every singular vertex on the cut or the boundary
//! ([`Cut::check`] verifies both), so the field combs on it
//! ([`Cut::comb`]: quarter turns per face that make every uncut matching
//! 0, what the seamless integration needs).
//!
//! Method (the standard one): a breadth-first spanning tree of the dual
//! graph (faces, across interior edges) from the first face of each
//! component; the interior edges the tree does not cross form the cut
//! graph, which cuts the surface to a disk (a tree of triangles). Then
//! cut edges that dangle are pruned: while a vertex that is neither
//! singular nor on the boundary has exactly one cut edge, that edge is
//! dropped. Boundary vertices are never pruned at (they have two
//! boundary edges), so a cut joining two boundary loops stays. What
//! remains: the loops that generate the topology, the boundary
//! connections, and trees reaching every singularity.
//!
//! The cut is not the shortest possible one (a BFS tree from one face);
//! the seamless integration does not depend on its shape.

use crate::error::RemeshError;
use crate::field::CrossField;
use crate::surface::{Surface, NO_FACE};
use dualex_util::union_find::{find, union};
use std::collections::VecDeque;

/// The edges to cut along.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Cut {
    /// Per edge: cut (always `false` on the boundary).
    pub is_cut: Vec<bool>,
}

/// The cut of `surface` through the vertices `singularities` (the first
/// entry of each pair; indices out of range are an error).
pub fn cut_to_disk(surface: &Surface, singularities: &[(u32, i32)]) -> Result<Cut, RemeshError> {
    let nv = surface.positions.len();
    let mut keep = vec![false; nv];
    for &(v, _) in singularities {
        *keep
            .get_mut(v as usize)
            .ok_or(RemeshError::CutVertexOutOfRange {
                vertex: v,
                vertices: nv,
            })? = true;
    }
    let mut is_cut = dual_tree_complement(surface);
    prune(surface, &keep, &mut is_cut);
    Ok(Cut { is_cut })
}

/// Interior edges not crossed by a BFS spanning tree of the dual graph.
fn dual_tree_complement(surface: &Surface) -> Vec<bool> {
    let nf = surface.triangles.len();
    let mut is_cut: Vec<bool> = surface.edge_faces.iter().map(|f| f[1] != NO_FACE).collect();
    let mut seen = vec![false; nf];
    let mut queue = VecDeque::new();
    for start in 0..nf {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        queue.push_back(start as u32);
        while let Some(f) = queue.pop_front() {
            for &e in &surface.face_edges[f as usize] {
                let [f0, f1] = surface.edge_faces[e as usize];
                let g = if f0 == f { f1 } else { f0 };
                if g != NO_FACE && !seen[g as usize] {
                    seen[g as usize] = true;
                    is_cut[e as usize] = false;
                    queue.push_back(g);
                }
            }
        }
    }
    is_cut
}

/// Drops dangling cut edges ending at a vertex not in `keep` and not on
/// the boundary, until none is left.
fn prune(surface: &Surface, keep: &[bool], is_cut: &mut [bool]) {
    let nv = surface.positions.len();
    // vertex → incident edges (CSR)
    let mut start = vec![0u32; nv + 1];
    for [a, b] in &surface.edges {
        start[*a as usize + 1] += 1;
        start[*b as usize + 1] += 1;
    }
    for v in 0..nv {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut incident = vec![0u32; 2 * surface.edges.len()];
    for (e, [a, b]) in surface.edges.iter().enumerate() {
        for v in [a, b] {
            incident[fill[*v as usize] as usize] = e as u32;
            fill[*v as usize] += 1;
        }
    }
    // degree in the graph cut ∪ boundary
    let mut degree = vec![0u32; nv];
    for (e, [a, b]) in surface.edges.iter().enumerate() {
        if is_cut[e] || surface.is_boundary_edge(e as u32) {
            degree[*a as usize] += 1;
            degree[*b as usize] += 1;
        }
    }
    let prunable =
        |v: usize, degree: &[u32]| degree[v] == 1 && !keep[v] && !surface.boundary_vertex[v];
    let mut stack: Vec<u32> = (0..nv as u32)
        .filter(|&v| prunable(v as usize, &degree))
        .collect();
    while let Some(v) = stack.pop() {
        if !prunable(v as usize, &degree) {
            continue;
        }
        let edges = &incident[start[v as usize] as usize..start[v as usize + 1] as usize];
        let Some(&e) = edges.iter().find(|&&e| is_cut[e as usize]) else {
            continue;
        };
        is_cut[e as usize] = false;
        let [a, b] = surface.edges[e as usize];
        let w = if a == v { b } else { a };
        degree[v as usize] -= 1;
        degree[w as usize] -= 1;
        if prunable(w as usize, &degree) {
            stack.push(w);
        }
    }
}

impl Cut {
    /// Combs the field on the cut-open surface: per face a number `r_f` of
    /// quarter turns such that, rotating each face's direction back by
    /// `r_f·π/2`, every uncut interior edge has matching 0
    /// (`r_f1 = r_f0 + p_e mod 4`). Possible exactly when no singularity
    /// is left inside the cut-open surface; the error names the first
    /// edge where the quarter turns disagree.
    pub fn comb(&self, surface: &Surface, field: &CrossField) -> Result<Vec<u8>, RemeshError> {
        let nf = surface.triangles.len();
        let mut rot = vec![u8::MAX; nf];
        let mut stack = Vec::new();
        for start in 0..nf {
            if rot[start] != u8::MAX {
                continue;
            }
            rot[start] = 0;
            stack.push(start as u32);
            while let Some(f) = stack.pop() {
                for &e in &surface.face_edges[f as usize] {
                    let [f0, f1] = surface.edge_faces[e as usize];
                    if f1 == NO_FACE || self.is_cut[e as usize] {
                        continue;
                    }
                    let p = field.matching[e as usize];
                    let (g, want) = if f == f0 {
                        (f1, (rot[f as usize] + p) % 4)
                    } else {
                        (f0, (rot[f as usize] + 4 - p % 4) % 4)
                    };
                    if rot[g as usize] == u8::MAX {
                        rot[g as usize] = want;
                        stack.push(g);
                    } else if rot[g as usize] != want {
                        let [a, b] = surface.edges[e as usize];
                        return Err(RemeshError::NotCombed {
                            edge: e,
                            ends: [a, b],
                        });
                    }
                }
            }
        }
        Ok(rot)
    }

    /// The vertices of the cut-open surface: per face corner, the id of
    /// its copy of the vertex (corners around a vertex share a copy when
    /// they are joined across uncut interior edges), and the number of
    /// copies.
    pub fn corner_vertices(&self, surface: &Surface) -> (Vec<[u32; 3]>, u32) {
        let nc = 3 * surface.triangles.len();
        let mut parent: Vec<u32> = (0..nc as u32).collect();
        let corner = |f: u32, v: u32| -> u32 {
            let t = surface.triangles[f as usize];
            let i = t.iter().position(|&w| w == v).unwrap_or(0);
            3 * f + i as u32
        };
        for (e, &[f0, f1]) in surface.edge_faces.iter().enumerate() {
            if f1 == NO_FACE || self.is_cut[e] {
                continue;
            }
            for v in surface.edges[e] {
                union(&mut parent, corner(f0, v), corner(f1, v));
            }
        }
        let mut id = vec![u32::MAX; nc];
        let mut count = 0;
        let mut out = vec![[0u32; 3]; surface.triangles.len()];
        for c in 0..nc as u32 {
            let r = find(&mut parent, c) as usize;
            if id[r] == u32::MAX {
                id[r] = count;
                count += 1;
            }
            out[c as usize / 3][c as usize % 3] = id[r];
        }
        (out, count)
    }

    /// Checks that cutting leaves one disk per connected component
    /// (Euler characteristic 1 each) and that every singular vertex is on
    /// the cut or the boundary.
    pub fn check(
        &self,
        surface: &Surface,
        singularities: &[(u32, i32)],
    ) -> Result<(), RemeshError> {
        let mut on_cut = surface.boundary_vertex.clone();
        for (e, [a, b]) in surface.edges.iter().enumerate() {
            if self.is_cut[e] {
                if surface.is_boundary_edge(e as u32) {
                    return Err(RemeshError::BoundaryEdgeCut { edge: e });
                }
                on_cut[*a as usize] = true;
                on_cut[*b as usize] = true;
            }
        }
        for &(v, _) in singularities {
            if !on_cut.get(v as usize).copied().unwrap_or(false) {
                return Err(RemeshError::SingularOffCut { vertex: v });
            }
        }
        let (comp, ncomp) = crate::smooth::face_components(surface);
        let mut chi = vec![0i64; ncomp as usize];
        for (f, &c) in comp.iter().enumerate() {
            chi[c as usize] += 1; // faces
            let _ = f;
        }
        for (e, &[f0, _]) in surface.edge_faces.iter().enumerate() {
            chi[comp[f0 as usize] as usize] -= if self.is_cut[e] { 2 } else { 1 };
        }
        let (corners, count) = self.corner_vertices(surface);
        let mut copy_comp = vec![u32::MAX; count as usize];
        for (f, cs) in corners.iter().enumerate() {
            for &c in cs {
                copy_comp[c as usize] = comp[f];
            }
        }
        for c in copy_comp {
            chi[c as usize] += 1;
        }
        match chi.iter().position(|&x| x != 1) {
            Some(c) => Err(RemeshError::ComponentNotDisk {
                component: c,
                euler: chi[c],
            }),
            None => Ok(()),
        }
    }
}

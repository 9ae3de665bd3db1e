//! The cut-open surface: combed field, wedges (chart vertices) and seams.
//!
//! Input: a [`Surface`], a [`CrossField`] and the cut edges. Output:
//! [`Charts`]:
//! - every face's angle *combed* by quarter turns (a breadth-first walk
//!   over the faces through uncut interior edges), so that every uncut
//!   edge has matching 0 afterwards;
//! - the **wedges**: a wedge is a maximal fan of face corners around one
//!   vertex whose faces are joined by uncut interior edges; it carries one
//!   `(u, v)` pair. A vertex away from the cut has one wedge; a vertex on
//!   the cut has one per side;
//! - the **seams**: cut interior edges, with their combed matching.
//!
//! Invariants checked (an error otherwise): every uncut interior edge has
//! combed matching 0 (the cut passes through every singularity) and every
//! piece of the cut-open surface is a disk (Euler characteristic 1), so
//! that a map exists on it.

use crate::error::RemeshError;
use crate::field::CrossField;
use crate::surface::{Surface, NO_FACE};
use dualex_util::union_find::UnionFind;
use std::collections::VecDeque;
use std::f64::consts::FRAC_PI_2;

/// The cut-open surface (module docs).
#[derive(Clone, Debug)]
pub struct Charts {
    /// Per face: the field's angle after combing, `θ + r·π/2`.
    pub angle: Vec<f64>,
    /// Per corner `3·f + i`: its wedge.
    pub corner_wedge: Vec<u32>,
    /// Number of wedges.
    pub wedges: usize,
    /// Per edge: the combed matching `0..4` of a seam (cut interior edge);
    /// `None` for every other edge.
    pub seam: Vec<Option<u8>>,
    /// Per face: its connected component of the (uncut) surface.
    pub component: Vec<u32>,
    /// Number of components.
    pub components: usize,
}

impl Charts {
    /// The wedge of vertex `v` in face `f` (`v` must be a corner of `f`).
    pub fn wedge(&self, surface: &Surface, f: u32, v: u32) -> u32 {
        let t = surface.triangles[f as usize];
        let i = t.iter().position(|&x| x == v).unwrap_or(0);
        self.corner_wedge[3 * f as usize + i]
    }
}

/// Builds the [`Charts`]; see the module docs for the checks.
pub fn build(
    surface: &Surface,
    field: &CrossField,
    is_cut: &[bool],
) -> Result<Charts, RemeshError> {
    let (nf, ne) = (surface.triangles.len(), surface.edges.len());
    if field.angle.len() != nf || field.matching.len() != ne || is_cut.len() != ne {
        return Err(RemeshError::Sizes {
            angles: field.angle.len(),
            matchings: field.matching.len(),
            cut_flags: is_cut.len(),
            faces: nf,
            edges: ne,
        });
    }
    if let Some(f) = field.angle.iter().position(|a| !a.is_finite()) {
        return Err(RemeshError::FaceAngle {
            face: f,
            angle: field.angle[f],
        });
    }
    let joined = |e: usize| !is_cut[e] && surface.edge_faces[e][1] != NO_FACE;
    let turns = comb(surface, field, &joined)?;
    let angle = (0..nf)
        .map(|f| field.angle[f] + f64::from(turns[f]) * FRAC_PI_2)
        .collect();
    let mut seam = vec![None; ne];
    for e in 0..ne {
        let [f0, f1] = surface.edge_faces[e];
        if f1 == NO_FACE {
            continue;
        }
        let p = (field.matching[e] + turns[f1 as usize] + 4 - turns[f0 as usize]) % 4;
        if is_cut[e] {
            seam[e] = Some(p);
        } else if p != 0 {
            let [a, b] = surface.edges[e];
            return Err(RemeshError::CutMissesSingularity {
                ends: [a, b],
                matching: p,
            });
        }
    }
    let (corner_wedge, wedges) = wedges(surface, &joined);
    let mut faces = UnionFind::new(nf);
    for e in 0..ne {
        let [f0, f1] = surface.edge_faces[e];
        if f1 != NO_FACE {
            faces.union(f0 as usize, f1 as usize);
        }
    }
    let (component, components) = faces.labels();
    check_disks(surface, is_cut, &corner_wedge, wedges)?;
    Ok(Charts {
        angle,
        corner_wedge,
        wedges,
        seam,
        component,
        components,
    })
}

/// Quarter turns per face that make every joined edge's matching 0
/// wherever the walk reaches it first.
fn comb(
    surface: &Surface,
    field: &CrossField,
    joined: &dyn Fn(usize) -> bool,
) -> Result<Vec<u8>, RemeshError> {
    let nf = surface.triangles.len();
    let mut turns: Vec<Option<u8>> = vec![None; nf];
    let mut queue = VecDeque::new();
    for start in 0..nf {
        if turns[start].is_some() {
            continue;
        }
        turns[start] = Some(0);
        queue.push_back(start);
        while let Some(f) = queue.pop_front() {
            let r = turns[f].unwrap_or(0);
            for &e in &surface.face_edges[f] {
                let e = e as usize;
                if !joined(e) {
                    continue;
                }
                let [f0, f1] = surface.edge_faces[e];
                let p = field.matching[e] % 4;
                // combed matching p + r1 − r0 must vanish
                let (g, rg) = if f0 as usize == f {
                    (f1 as usize, (r + 4 - p) % 4)
                } else {
                    (f0 as usize, (r + p) % 4)
                };
                if turns[g].is_none() {
                    turns[g] = Some(rg);
                    queue.push_back(g);
                }
            }
        }
    }
    Ok(turns.into_iter().map(|t| t.unwrap_or(0)).collect())
}

/// Corners joined across uncut interior edges, numbered.
fn wedges(surface: &Surface, joined: &dyn Fn(usize) -> bool) -> (Vec<u32>, usize) {
    let corner = |f: u32, v: u32| {
        let t = surface.triangles[f as usize];
        3 * f as usize + t.iter().position(|&x| x == v).unwrap_or(0)
    };
    let mut uf = UnionFind::new(3 * surface.triangles.len());
    for e in 0..surface.edges.len() {
        if !joined(e) {
            continue;
        }
        let [f0, f1] = surface.edge_faces[e];
        for v in surface.edges[e] {
            uf.union(corner(f0, v), corner(f1, v));
        }
    }
    uf.labels()
}

/// Every piece of the cut-open surface is a disk: wedges − edge sides +
/// faces = 1 per piece (a cut edge counts once per side).
fn check_disks(
    surface: &Surface,
    is_cut: &[bool],
    corner_wedge: &[u32],
    wedges: usize,
) -> Result<(), RemeshError> {
    // pieces: faces joined through uncut interior edges = faces sharing a wedge
    let mut uf = UnionFind::new(wedges);
    for f in 0..surface.triangles.len() {
        uf.union(
            corner_wedge[3 * f] as usize,
            corner_wedge[3 * f + 1] as usize,
        );
        uf.union(
            corner_wedge[3 * f] as usize,
            corner_wedge[3 * f + 2] as usize,
        );
    }
    let (piece, pieces) = uf.labels();
    let mut chi = vec![0i64; pieces];
    for &p in &piece {
        chi[p as usize] += 1;
    }
    let piece_of = |f: u32| piece[corner_wedge[3 * f as usize] as usize] as usize;
    for f in 0..surface.triangles.len() as u32 {
        chi[piece_of(f)] += 1;
    }
    for (e, &[f0, f1]) in surface.edge_faces.iter().enumerate() {
        chi[piece_of(f0)] -= 1;
        if f1 != NO_FACE && is_cut[e] {
            chi[piece_of(f1)] -= 1;
        }
    }
    match chi.iter().position(|&c| c != 1) {
        Some(p) => Err(RemeshError::NotDisks { euler: chi[p] }),
        None => Ok(()),
    }
}

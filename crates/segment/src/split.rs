//! Step 3: splitting faces of a simplex mesh at their barycentre, in any
//! dimension: the operation behind the paper's "if both edge extremities
//! are singularities … we need to split the edge", extended to the tet
//! edges and faces that vertices which cannot move span (issue: singular
//! structure anywhere). Which faces, per dimension: [`ToSplit`]
//! (`dim2.rs`, `dim3.rs`); the passes: `crate::steps::prepare`.
//!
//! Input: a map and a list of faces (2 or more vertex ids each, a face of
//! some simplex). Output: a new map where each applied face `F` has a new
//! vertex `m` at its barycentre (position, and in the chart of every
//! simplex around `F` the mean of `F`'s corners there), and every simplex
//! around `F` is replaced, in place, by one simplex per vertex of `F`, in
//! which that vertex is replaced by `m`.
//!
//! Invariants: orientation is kept (each piece is its simplex with one
//! vertex moved into the relative interior of a face it holds); the map
//! stays exactly as GP as before (a mean of corners related by a
//! transition is related by the same transition); `m` is not singular (its
//! star is that of a point inside `F`, where the charts agree). At most one
//! face is split per simplex per call: a face sharing a simplex with an
//! earlier applied face of the list waits for the next call (the caller
//! repeats until nothing is left).

use crate::local::LocalMap;
pub use crate::simplex::Dim;
use dualex_map::{SimplexMap, Stars, Topology, Transitions};
use std::collections::HashMap;

mod dim2;
mod dim3;

/// What one pass of step 3 reads: the (split) map, its topology, stars
/// and local map (singular vertices snapped), the free axes of its
/// singular vertices ([`ToSplit::free_axes`]).
pub struct Pass<'a, const N: usize, const D: usize> {
    /// The map of this pass.
    pub map: &'a SimplexMap<N, D>,
    /// Its adjacency.
    pub topo: &'a Topology<N>,
    /// Its vertex stars.
    pub stars: &'a Stars<D>,
    /// Its local map.
    pub local: &'a LocalMap<N, D>,
    /// The free axes of its singular vertices.
    pub free: &'a [Option<usize>],
}

/// Step 3's choice of the faces to split, the part that differs per
/// dimension: one `impl` per dimension on [`Dim`] (`dim2.rs`: edges
/// between two singular vertices through a grid point; `dim3.rs`: tet
/// edges and faces that vertices which cannot move span across the grid).
pub trait ToSplit<const N: usize, const D: usize> {
    /// What the choice reads from the model of one pass besides the stars,
    /// before the local map takes the transitions over (D = 3: the
    /// singular edges; D = 2: nothing).
    type Singular;

    /// Reads [`Self::Singular`] from the model of one pass.
    fn singular(
        map: &SimplexMap<N, D>,
        topo: &Topology<N>,
        trans: &Transitions<N, D>,
        stars: &Stars<D>,
    ) -> Self::Singular;

    /// The free axis of every singular vertex that has one
    /// ([`crate::sanitize::free_axes`]; D = 2: none, empty), read by the
    /// choice and by sanitization (step 4).
    fn free_axes(
        topo: &Topology<N>,
        stars: &Stars<D>,
        local: &LocalMap<N, D>,
    ) -> Vec<Option<usize>>;

    /// The faces to split (2 or more vertex ids each), each once, for
    /// [`split_faces_traced`].
    fn faces(pass: &Pass<'_, N, D>, singular: &Self::Singular) -> Vec<Vec<u32>>;

    /// The most faces split over all passes, past which the passes stop
    /// (D = 2: the simplices of the current map, `current`; D = 3: those
    /// of the input, `input`).
    fn max_split(input: usize, current: usize) -> usize;
}

/// Splits `faces` of `map` (see the module docs); returns the new map and
/// the number of faces applied.
pub fn split_faces<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    faces: &[Vec<u32>],
) -> (SimplexMap<N, D>, usize) {
    let (out, applied, _) = split_faces_traced(map, faces);
    (out, applied)
}

/// [`split_faces`], also returning for each simplex of the new map the
/// simplex of `map` it is (a piece of): a non-decreasing list.
pub fn split_faces_traced<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    faces: &[Vec<u32>],
) -> (SimplexMap<N, D>, usize, Vec<u32>) {
    // the simplices around each vertex of a face
    let mut around: HashMap<u32, Vec<usize>> = HashMap::new();
    for f in faces {
        for &v in f {
            around.entry(v).or_default();
        }
    }
    for (s, simplex) in map.simplices.iter().enumerate() {
        for v in simplex {
            if let Some(list) = around.get_mut(v) {
                list.push(s);
            }
        }
    }
    let mut out = map.clone();
    // per simplex: the new vertex and the corners of the face it splits
    let mut cut: Vec<Option<(u32, [bool; N])>> = vec![None; map.len()];
    let mut applied = 0;
    for f in faces {
        let Some(first) = f.first().and_then(|v| around.get(v)) else {
            continue;
        };
        let holders: Vec<usize> = first
            .iter()
            .copied()
            .filter(|&s| f.iter().all(|v| map.simplices[s].contains(v)))
            .collect();
        if holders.is_empty() || holders.iter().any(|&s| cut[s].is_some()) {
            continue;
        }
        let m = out.positions.len() as u32;
        let k = f.len() as f64;
        let mut p = [0.0; 3];
        for &v in f {
            for (pk, x) in p.iter_mut().zip(map.positions[v as usize]) {
                *pk += x / k;
            }
        }
        out.positions.push(p);
        for &s in &holders {
            cut[s] = Some((m, map.simplices[s].map(|v| f.contains(&v))));
        }
        applied += 1;
    }
    if applied == 0 {
        return (out, 0, (0..map.len() as u32).collect());
    }
    out.simplices.clear();
    out.coords.clear();
    let mut parent = Vec::with_capacity(map.len() + N * applied);
    for (s, cut_s) in cut.iter().enumerate() {
        let (simplex, uv) = (map.simplices[s], map.coords[s]);
        let Some((m, in_face)) = *cut_s else {
            out.simplices.push(simplex);
            out.coords.push(uv);
            parent.push(s as u32);
            continue;
        };
        let k = in_face.iter().filter(|&&b| b).count() as f64;
        let mut um = [0.0; D];
        for c in (0..N).filter(|&c| in_face[c]) {
            for (u, x) in um.iter_mut().zip(uv[c]) {
                *u += x / k;
            }
        }
        // pieces in the reverse cyclic order of the face's corners, starting
        // after the first corner outside it
        let outside = in_face.iter().position(|&b| !b).unwrap_or(0);
        for step in (1..N).rev() {
            let c = (outside + step) % N;
            if !in_face[c] {
                continue;
            }
            let mut t = simplex;
            t[c] = m;
            let mut u = uv;
            u[c] = um;
            out.simplices.push(t);
            out.coords.push(u);
            parent.push(s as u32);
        }
    }
    (out, applied, parent)
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_map::test_maps::{grid, tet_cube};

    fn volume<const N: usize, const D: usize>(m: &SimplexMap<N, D>) -> f64 {
        (0..m.len()).map(|s| m.map_det(s)).sum()
    }

    /// An interior edge of a triangle grid: 2 triangles become 4, same
    /// signed area, the new vertex at the midpoint in both charts.
    #[test]
    fn edge_of_a_triangle_mesh() {
        let m = grid(2);
        let t = m.simplices[0];
        let (out, n) = split_faces(&m, &[vec![t[0], t[2]]]);
        assert_eq!(n, 1);
        assert_eq!(out.len(), m.len() + 2);
        assert_eq!(out.positions.len(), m.positions.len() + 1);
        assert!((volume(&out) - volume(&m)).abs() < 1e-12);
        assert!((0..out.len()).all(|s| out.map_det(s) > 0.0));
        out.validate().unwrap_or_else(|e| panic!("{e}"));
    }

    /// Each piece names the simplex it came from; the others keep their
    /// own index shifted by the pieces before them.
    #[test]
    fn pieces_name_their_parent() {
        let m = tet_cube(2);
        let t = m.simplices[3];
        let (out, n, parent) = split_faces_traced(&m, &[vec![t[0], t[1], t[2]]]);
        assert_eq!((n, parent.len()), (1, out.len()));
        assert!(parent.windows(2).all(|w| w[0] <= w[1]));
        for (piece, &p) in out.simplices.iter().zip(&parent) {
            let old = m.simplices[p as usize];
            let same = (0..4).filter(|&c| piece[c] == old[c]).count();
            assert!(same >= 3, "piece {piece:?} of {old:?}");
        }
        assert_eq!(parent.iter().filter(|&&p| p == 3).count(), 3);
        let (_, _, id) = split_faces_traced(&m, &[]);
        assert_eq!(id, (0..m.len() as u32).collect::<Vec<_>>());
    }

    /// A tet edge and a tet face: every tet around the edge in two, both
    /// tets of the face in three; volume and orientation kept; a second
    /// face in a simplex already cut waits.
    #[test]
    fn edge_and_face_of_a_tet_mesh() {
        let m = tet_cube(2);
        let t = m.simplices[0];
        let around = m
            .simplices
            .iter()
            .filter(|s| s.contains(&t[0]) && s.contains(&t[1]))
            .count();
        let (out, n) = split_faces(&m, &[vec![t[0], t[1]], vec![t[0], t[1], t[2]]]);
        assert_eq!(n, 1, "the face shares tet 0 with the edge");
        assert_eq!(out.len(), m.len() + around);
        assert!((volume(&out) - volume(&m)).abs() < 1e-9);
        let face = m
            .simplices
            .iter()
            .filter(|s| [t[0], t[1], t[2]].iter().all(|v| s.contains(v)))
            .count();
        let (out2, n2) = split_faces(&m, &[vec![t[0], t[1], t[2]]]);
        assert_eq!(n2, 1);
        assert_eq!(out2.len(), m.len() + 2 * face);
        assert!((volume(&out2) - volume(&m)).abs() < 1e-9);
        for o in [&out, &out2] {
            assert!((0..o.len()).all(|s| o.map_det(s) > 0.0));
            o.validate().unwrap_or_else(|e| panic!("{e}"));
        }
    }
}

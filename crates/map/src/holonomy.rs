//! Rotation around a **ridge**: a vertex of a triangle mesh or an edge of a
//! tet mesh (a face of dimension `N - 3`), composed from the transitions of
//! the facets that contain it.
//!
//! Input: topology, transitions, one simplex `s` and the corners of `s` that
//! span the ridge (1 corner in 2D, 2 in 3D). Output: the rotation of `s`'s
//! chart after one turn around the ridge, or `None` when the ridge is on the
//! boundary (the walk leaves the mesh).
//!
//! Orientation of the walk, the same in both dimensions: with the simplex's
//! corners ordered `(ridge…, x, y)` as an even permutation of its corner
//! order, the walk leaves through the facet opposite `x`:
//! ```text
//!   2D: triangle (v, x, y) CCW: exit through edge v-y, i.e. counter-
//!       clockwise around v            y
//!                                     |\    next triangle across v-y
//!                                     v--x
//!   3D: tet (a, b, x, y) positive: exit through face a-b-y, i.e. right-
//!       handed around the edge direction a→b.
//! ```
//! With this walk a counter-clockwise quarter turn (`k = 1`) is a cone of
//! index +1/4 (a cube corner, quad valence 3); see the cone tests.

use crate::{Rot, Topology, Transitions};

/// Holonomy around the ridge spanned by `ridge` (corners of `s`, length
/// `N - 2`), or `None` if the ridge is on the boundary.
pub fn ridge_rotation<const N: usize, const D: usize>(
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
    s0: usize,
    ridge: &[usize],
) -> Option<Rot<D>> {
    let mut corners = [0usize; 4];
    corners[..ridge.len()].copy_from_slice(ridge);
    let k = ridge.len();
    let mut s = s0;
    let mut f = exit_facet::<N>(&corners[..k]);
    let mut acc = Rot::<D>::IDENTITY;
    for _ in 0..=topo.adj.len() {
        let (n, g) = topo.neighbour(s, f)?;
        acc = acc.then(&trans.rot[s][f]);
        for c in corners[..k].iter_mut() {
            *c = topo.nbr_corner[s][f][*c] as usize;
        }
        if n == s0 {
            return Some(acc);
        }
        let Some(next) = (0..N).find(|&h| h != g && !corners[..k].contains(&h)) else {
            panic!("bug: no exit facet around a ridge in simplex {n}");
        };
        s = n;
        f = next;
    }
    panic!("bug: walk around a ridge of simplex {s0} does not close")
}

/// The facet through which the walk leaves a simplex whose ridge corners are
/// `ridge` (see the module docs).
pub fn exit_facet<const N: usize>(ridge: &[usize]) -> usize {
    let mut order = [0usize; 4];
    order[..ridge.len()].copy_from_slice(ridge);
    let mut k = ridge.len();
    for c in 0..N {
        if !ridge.contains(&c) {
            order[k] = c;
            k += 1;
        }
    }
    let mut inversions = 0;
    for i in 0..N {
        for j in i + 1..N {
            if order[i] > order[j] {
                inversions += 1;
            }
        }
    }
    // (ridge…, x, y) even: leave opposite x; odd: swap x and y
    if inversions % 2 == 0 {
        order[N - 2]
    } else {
        order[N - 1]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exit_facets() {
        // triangle (v, x, y) = corners (0, 1, 2): leave opposite 1
        assert_eq!(exit_facet::<3>(&[0]), 1);
        assert_eq!(exit_facet::<3>(&[1]), 2);
        assert_eq!(exit_facet::<3>(&[2]), 0);
        // tet: ridge (0,1) → (0,1,2,3) even → leave opposite 2
        assert_eq!(exit_facet::<4>(&[0, 1]), 2);
        assert_eq!(exit_facet::<4>(&[1, 0]), 3);
        assert_eq!(exit_facet::<4>(&[2, 3]), 0);
    }
}

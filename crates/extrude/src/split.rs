//! The built-in fallback when TetGen is absent: every prism split into 3
//! tets by the vertex-index rule (the same walls as the TetGen input, see
//! [`crate::plc`]): with the bottom corners sorted by vertex id `a < b < c`
//! and `x'` the corner above `x`, the tets are `a b c c'`, `a b b' c'`,
//! `a a' b' c'`. No Steiner points.
//!
//! Output: a [`TetgenMesh`] over the slab points with `region = prism + 1`,
//! so that [`crate::chart::tet_map`] treats both paths alike.

use crate::slab::Slab;
use crate::tetgen::TetgenMesh;

/// Splits every prism of `slab` (module docs).
pub fn prism_split(slab: &Slab) -> TetgenMesh {
    let mut out = TetgenMesh {
        nodes: slab.points.clone(),
        oriented: true,
        ..Default::default()
    };
    for prism in 0..slab.prisms() {
        for tet in prism_tets(slab, prism) {
            out.tets.push(tet);
            out.regions.push(prism as u64 + 1);
        }
    }
    out
}

/// The 3 tets of one prism (module docs), as slab point ids.
pub fn prism_tets(slab: &Slab, prism: usize) -> [[u32; 4]; 3] {
    let (t, l) = slab.prism_of(prism);
    let mut tri = slab.tris[t];
    tri.sort_unstable();
    let [a, b, c] = tri;
    let at = |v: u32, up: usize| slab.point(v, l + up);
    let corners = [
        [(a, 0), (b, 0), (c, 0), (c, 1)],
        [(a, 0), (b, 0), (b, 1), (c, 1)],
        [(a, 0), (a, 1), (b, 1), (c, 1)],
    ];
    corners.map(|t| {
        let mut ids = t.map(|(v, up)| at(v, up));
        if canonical_volume(&slab.tris[t_index(slab, prism)], &t) < 0.0 {
            ids.swap(0, 1);
        }
        ids
    })
}

fn t_index(slab: &Slab, prism: usize) -> usize {
    slab.prism_of(prism).0
}

/// Six times the volume of a tet of a prism in the prism's canonical
/// embedding (its triangle's corners, in the triangle's order, at (0,0),
/// (1,0), (0,1); the layer above at height 1): the orientation the tet
/// inherits from its triangle, whatever the real geometry (a slab over a
/// self-intersecting surface has locally inverted prisms, and orienting
/// by real volume would make neighbouring tets disagree).
fn canonical_volume(tri: &[u32; 3], tet: &[(u32, usize); 4]) -> f64 {
    const BASE: [[f64; 2]; 3] = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    let pos = |(v, up): (u32, usize)| {
        let k = tri.iter().position(|&x| x == v).unwrap_or(0);
        [BASE[k][0], BASE[k][1], up as f64]
    };
    let p = tet.map(pos);
    let e = |i: usize| [p[i][0] - p[0][0], p[i][1] - p[0][1], p[i][2] - p[0][2]];
    let (a, b, c) = (e(1), e(2), e(3));
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plc::facets;
    use dualex_map::TriMap;
    use std::collections::{BTreeSet, HashMap};

    fn key(mut k: [u32; 3]) -> [u32; 3] {
        k.sort_unstable();
        k
    }

    /// Every tet face is either an input facet (a wall, a level triangle)
    /// or interior to its prism and shared by exactly 2 of its tets.
    #[test]
    fn split_faces_are_the_plc_facets_or_interior() {
        let m = TriMap {
            positions: vec![
                [0., 0., 0.],
                [1., 0., 0.],
                [1., 1., 0.],
                [0., 1., 0.],
                [2., 0.5, 0.],
            ],
            simplices: vec![[3, 0, 2], [2, 0, 1], [1, 4, 2]],
            coords: vec![[[0.; 2]; 3]; 3],
        };
        let s = Slab::new(&m, 2, Some(1.0)).expect("valid");
        let tg = prism_split(&s);
        assert_eq!(tg.tets.len(), 3 * 3 * 2);
        let plc: BTreeSet<[u32; 3]> = facets(&s).into_iter().map(key).collect();
        let mut count: HashMap<([u32; 3], u64), usize> = HashMap::new();
        for (t, &r) in tg.tets.iter().zip(&tg.regions) {
            for f in 0..4 {
                let mut k = [0; 3];
                for (j, i) in (0..4).filter(|&i| i != f).enumerate() {
                    k[j] = t[i];
                }
                *count.entry((key(k), r)).or_insert(0) += 1;
            }
        }
        for ((k, r), n) in count {
            assert!(plc.contains(&k) || n == 2, "face {k:?} of prism {r}: {n}");
        }
    }
}

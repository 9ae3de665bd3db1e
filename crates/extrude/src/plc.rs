//! The piecewise linear complex given to TetGen: every prism wall is a
//! constraint facet, so every tet TetGen makes lies inside one prism.
//!
//! Input: a [`Slab`]. Output: triangle facets and the `.poly` text
//! (0-based, one region seed per prism at its centroid whose attribute is
//! `prism id + 1`, so `-A` labels every tet with its prism).
//!
//! Facets: the triangle at every level (`T · (L+1)`), and the two
//! triangles of every side quad of every layer, cut by the *vertex-index
//! rule* (the diagonal from the lower-index bottom vertex to the other's
//! top):
//! ```text
//!   a' ─── b'        a < b: triangles (a, b, b') and (a, b', a')
//!   │   ╱  │
//!   │  ╱   │         a prism's three walls then never form a cycle of
//!   a ─── b          diagonals (Schönhardt), so it splits into 3 tets
//! ```

use crate::slab::Slab;
use crate::text::{push_hex_float, push_uint};

/// Triangle facets of the slab (module docs), as point ids.
pub fn facets(slab: &Slab) -> Vec<[u32; 3]> {
    let mut out = Vec::new();
    for level in 0..=slab.layers {
        out.extend(slab.tris.iter().map(|t| t.map(|v| slab.point(v, level))));
    }
    let mut edges: Vec<(u32, u32)> = slab
        .tris
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
        .collect();
    edges.sort_unstable();
    edges.dedup();
    for l in 0..slab.layers {
        for &(a, b) in &edges {
            out.extend(wall(slab, a, b, l));
        }
    }
    out
}

/// The two triangles of the side quad over edge `a < b` in layer `l`.
pub fn wall(slab: &Slab, a: u32, b: u32, l: usize) -> [[u32; 3]; 2] {
    let (a0, b0, a1, b1) = (
        slab.point(a, l),
        slab.point(b, l),
        slab.point(a, l + 1),
        slab.point(b, l + 1),
    );
    [[a0, b0, b1], [a0, b1, a1]]
}

/// The `.poly` file (ASCII text): nodes, facets, no holes, one region per prism.
/// Coordinates are hexadecimal floats ([`crate::text`]): exact, and
/// written without `core::fmt`.
pub fn poly_text(slab: &Slab) -> Vec<u8> {
    let f = facets(slab);
    let mut s = Vec::with_capacity(64 * slab.points.len() + 24 * f.len() + 80 * slab.prisms());
    push_record(&mut s, &[slab.points.len() as u64, 3, 0, 0], &[], &[]);
    for (i, p) in slab.points.iter().enumerate() {
        push_record(&mut s, &[i as u64], p, &[]);
    }
    push_record(&mut s, &[f.len() as u64, 0], &[], &[]);
    for t in &f {
        push_record(&mut s, &[1], &[], &[]);
        push_record(&mut s, &[3], &[], &t.map(u64::from));
    }
    push_record(&mut s, &[0], &[], &[]);
    push_record(&mut s, &[slab.prisms() as u64], &[], &[]);
    for prism in 0..slab.prisms() {
        let c = centroid(slab, prism);
        push_record(&mut s, &[prism as u64], &c, &[prism as u64 + 1, 0]);
    }
    s
}

/// The `.poly` of the base surface alone (level 0's points and triangles,
/// no region), for TetGen's self-intersection check (`-d`, see
/// [`crate::tetgen::intersecting_triangles`]).
pub fn surface_poly_text(slab: &Slab) -> Vec<u8> {
    let mut s = Vec::with_capacity(64 * slab.nv + 24 * slab.tris.len());
    push_record(&mut s, &[slab.nv as u64, 3, 0, 0], &[], &[]);
    for (i, p) in slab.points[..slab.nv].iter().enumerate() {
        push_record(&mut s, &[i as u64], p, &[]);
    }
    push_record(&mut s, &[slab.tris.len() as u64, 0], &[], &[]);
    for t in &slab.tris {
        push_record(&mut s, &[1], &[], &[]);
        push_record(&mut s, &[3], &[], &t.map(u64::from));
    }
    push_record(&mut s, &[0], &[], &[]);
    push_record(&mut s, &[0], &[], &[]);
    s
}

/// Appends one line: the integers `head` (at least one), the floats `x`,
/// the integers `tail`, separated by single spaces.
fn push_record(s: &mut Vec<u8>, head: &[u64], x: &[f64], tail: &[u64]) {
    for (k, &v) in head.iter().enumerate() {
        if k > 0 {
            s.push(b' ');
        }
        push_uint(s, v);
    }
    for &v in x {
        s.push(b' ');
        push_hex_float(s, v);
    }
    for &v in tail {
        s.push(b' ');
        push_uint(s, v);
    }
    s.push(b'\n');
}

/// A point strictly inside the prism's region: the centroid of the first
/// tet of its split (the split's tets fill exactly the region bounded by
/// the prism's facets). The mean of the 6 corners is not safe: on a thin,
/// bent slab it can fall into a neighbouring prism, whose tets would then
/// take this prism's chart.
fn centroid(slab: &Slab, prism: usize) -> [f64; 3] {
    let tet = crate::split::prism_tets(slab, prism)[0];
    let mut c = [0.0; 3];
    for v in tet {
        let p = slab.points[v as usize];
        for k in 0..3 {
            c[k] += p[k] / 4.0;
        }
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_map::TriMap;
    use std::collections::BTreeSet;

    fn slab(layers: usize) -> Slab {
        let m = TriMap {
            positions: vec![[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]],
            simplices: vec![[0, 1, 2], [0, 2, 3]],
            coords: vec![
                [[0., 0.], [2., 0.], [2., 2.]],
                [[0., 0.], [2., 2.], [0., 2.]],
            ],
        };
        Slab::new(&m, layers, Some(1.0)).expect("valid")
    }

    #[test]
    fn facet_counts_and_conformity() {
        for layers in 1..=3 {
            let s = slab(layers);
            let f = facets(&s);
            // 2 triangles × (L+1) levels + 5 edges × L layers × 2
            assert_eq!(f.len(), 2 * (layers + 1) + 10 * layers);
            let keys: BTreeSet<[u32; 3]> = f
                .iter()
                .map(|t| {
                    let mut k = *t;
                    k.sort_unstable();
                    k
                })
                .collect();
            assert_eq!(keys.len(), f.len(), "no facet twice");
        }
    }

    #[test]
    fn poly_has_all_sections() {
        let s = slab(2);
        let text = String::from_utf8(poly_text(&s)).expect("ASCII");
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "12 3 0 0");
        assert_eq!(lines[13], format!("{} 0", facets(&s).len()));
        // the last line is the seed of prism 3 (attribute 4)
        let last: Vec<&str> = lines[lines.len() - 1].split(' ').collect();
        assert_eq!((last[0], last[4]), ("3", "4"));
    }
}

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
use std::collections::BTreeSet;
use std::fmt::Write;

/// Triangle facets of the slab (module docs), as point ids.
pub fn facets(slab: &Slab) -> Vec<[u32; 3]> {
    let mut out = Vec::new();
    for level in 0..=slab.layers {
        out.extend(slab.tris.iter().map(|t| t.map(|v| slab.point(v, level))));
    }
    let edges: BTreeSet<(u32, u32)> = slab
        .tris
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k].min(t[(k + 1) % 3]), t[k].max(t[(k + 1) % 3]))))
        .collect();
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

/// The `.poly` text: nodes, facets, no holes, one region per prism.
pub fn poly_text(slab: &Slab) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{} 3 0 0", slab.points.len());
    for (i, p) in slab.points.iter().enumerate() {
        let _ = writeln!(s, "{i} {:e} {:e} {:e}", p[0], p[1], p[2]);
    }
    let f = facets(slab);
    let _ = writeln!(s, "{} 0", f.len());
    for t in &f {
        let _ = writeln!(s, "1\n3 {} {} {}", t[0], t[1], t[2]);
    }
    let _ = writeln!(s, "0\n{}", slab.prisms());
    for prism in 0..slab.prisms() {
        let c = centroid(slab, prism);
        let _ = writeln!(
            s,
            "{prism} {:e} {:e} {:e} {} 0",
            c[0],
            c[1],
            c[2],
            prism + 1
        );
    }
    s
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
        let text = poly_text(&s);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "12 3 0 0");
        assert_eq!(lines[13], format!("{} 0", facets(&s).len()));
        // the last line is the seed of prism 3 (attribute 4)
        let last: Vec<&str> = lines[lines.len() - 1].split(' ').collect();
        assert_eq!((last[0], last[4]), ("3", "4"));
    }
}

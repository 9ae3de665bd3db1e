//! Long edges split before the field: room for the field and the map on
//! CAD tessellations.
//!
//! Input: a [`Surface`] and a length `max_len` (the pipeline gives
//! [`QUAD_EDGES`] target quad edges, [`crate::pipeline`]). Output: `None` when no edge is
//! longer (the surface is used as it is), else the surface with every
//! edge longer than `max_len` bisected, longest first, each split
//! carried into the one or two triangles of the edge:
//!
//! ```text
//!        c                  c
//!       / \                /|\
//!      /   \              / | \
//!     a─────b     →      a──m──b      (and the same on the other side,
//!      \   /              \ | /        across a–b, with its vertex d)
//!       \ /                \|/
//!        d                  d
//! ```
//!
//! Why: CAD exports tessellate a planar cap as a fan of triangles around
//! one centre vertex, and a cone's side as a fan around the apex; every
//! triangle of such a fan touches the sharp rim. The field is fixed on
//! every face beside a feature ([`crate::smooth`]), so on a fan it is
//! fixed everywhere, and the whole turning of the cap (index +1) lands on
//! the centre: one singularity of index 4/4, a cone of angle 0 that the
//! integration collapses (measured on `surface_cad_cylinder`: map area
//! 4.7e-20, 2576 of 6336 triangles flipped). Split, the cap gets rings
//! of free faces inside the rim, where the field can turn and where the
//! four quarter singularities that replace the +1
//! ([`crate::smooth`], "quarter singularities") have vertices to sit on.
//!
//! Splitting the longest edge first keeps every split edge the longest of
//! its triangles (longest-edge bisection): angles are never worse than
//! half those of the input, and a fan's spokes become rings. An edge no
//! no longer than two target quad edges is left alone, so the surfaces
//! whose triangles are already smaller than the quads (scans, the generated
//! smooth surfaces at the usual sizes) go through unchanged, and their
//! maps with them.
//!
//! Invariants: the output's vertices are the input's (same numbers, same
//! positions) followed by edge midpoints, each on an input edge, so every
//! output triangle lies in an input triangle's plane, inside it: the
//! output is the input surface, exactly (up to the rounding of a
//! midpoint). Topology (components, χ, boundary loops) and orientation
//! are the input's; a sharp edge split is two sharp edges.

use crate::surface::{norm, sub, Surface};
use std::collections::{BinaryHeap, HashMap};

/// The pipeline splits the edges longer than this many target quad
/// edges. Measured (`dualex remesh`, seeds 1–2 at 300, 1000 and 5000
/// quads, `surface_cad_*`): with 1 or 2, every run valid with 8 quarter
/// singularities on the cylinder and the cone; with 1, the maps of the
/// generated smooth surfaces at 2000 quads change too (their diagonals
/// are 1.0–1.4 quad edges), and one torus map among them shows the
/// half-integer seam translation of issue 23 part 1; with 2, of the
/// generated surfaces without fans only `surface_cube` at 2000 quads
/// changes (its triangles are 3.2 quad edges long there).
pub const QUAD_EDGES: f64 = 2.0;

/// At most this many triangles are made (a guard against a `max_len`
/// far below the edges: the split stops there).
pub const MAX_TRIANGLES: usize = 2_000_000;

/// The surface with its edges longer than `max_len` bisected (module
/// docs); `None` when there is none.
pub fn split_long_edges(surface: &Surface, max_len: f64) -> Option<Surface> {
    if !(max_len.is_finite() && max_len > 0.0) {
        return None;
    }
    let mut p = surface.positions.clone();
    let mut t = surface.triangles.clone();
    let length = |p: &[[f64; 3]], a: u32, b: u32| norm(sub(p[b as usize], p[a as usize]));
    // half-edge a → b: (triangle, corner of a)
    let mut half: HashMap<(u32, u32), u32> = HashMap::with_capacity(3 * t.len());
    // (length bits, a, b), a < b: positive floats order as their bits
    let mut heap = BinaryHeap::new();
    for (f, tri) in t.iter().enumerate() {
        for i in 0..3 {
            let (a, b) = (tri[i], tri[(i + 1) % 3]);
            half.insert((a, b), f as u32);
            let l = length(&p, a, b);
            let once = a < b || surface.is_boundary_edge(surface.face_edges[f][i]);
            if once && l > max_len {
                heap.push((l.to_bits(), a.min(b), a.max(b)));
            }
        }
    }
    if heap.is_empty() {
        return None;
    }
    while let Some((_, a, b)) = heap.pop() {
        if t.len() + 2 > MAX_TRIANGLES {
            break;
        }
        let sides: Vec<(u32, u32, u32)> = [(a, b), (b, a)]
            .into_iter()
            .filter_map(|(x, y)| half.get(&(x, y)).map(|&f| (x, y, f)))
            .collect();
        if sides.is_empty() {
            continue; // split already
        }
        let m = p.len() as u32;
        let (pa, pb) = (p[a as usize], p[b as usize]);
        p.push([0, 1, 2].map(|k| 0.5 * (pa[k] + pb[k])));
        let half_len = 0.5 * length(&p, a, b);
        for (x, y, f) in sides {
            // triangle f = [x, y, c] (rotated): [x, m, c] and [m, y, c]
            let tri = t[f as usize];
            let i = (0..3).find(|&i| tri[i] == x).expect("x is a corner");
            let c = tri[(i + 2) % 3];
            let g = t.len() as u32;
            t[f as usize] = [x, m, c];
            t.push([m, y, c]);
            half.remove(&(x, y));
            for (key, face) in [
                ((x, m), f),
                ((m, c), f),
                ((m, y), g),
                ((y, c), g),
                ((c, m), g),
            ] {
                half.insert(key, face);
            }
            let l = length(&p, m, c);
            if l > max_len {
                heap.push((l.to_bits(), m.min(c), m.max(c)));
            }
        }
        if half_len > max_len {
            heap.push((half_len.to_bits(), a.min(m), a.max(m)));
            heap.push((half_len.to_bits(), m.min(b), m.max(b)));
        }
    }
    Some(Surface::new(p, t).expect("a bisected surface is a surface"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes_cad::cad_cylinder;

    /// Every output triangle lies inside an input triangle (its corners
    /// on it: in its plane, barycentric coordinates in [0, 1]).
    fn inside(input: &Surface, out: &Surface) -> bool {
        out.triangles.iter().all(|tri| {
            input.triangles.iter().any(|s| {
                tri.iter().all(|&v| {
                    let q = out.positions[v as usize];
                    let [a, b, c] = s.map(|w| input.positions[w as usize]);
                    let n = crate::surface::cross(sub(b, a), sub(c, a));
                    let n2 = crate::surface::dot(n, n);
                    let bary = |x: [f64; 3], y: [f64; 3]| {
                        crate::surface::dot(crate::surface::cross(sub(y, x), sub(q, x)), n) / n2
                    };
                    let w = [bary(b, c), bary(c, a), bary(a, b)];
                    let off = crate::surface::dot(sub(q, a), n) / n2.sqrt();
                    off.abs() < 1e-12 && w.iter().all(|&w| (-1e-12..=1.0 + 1e-12).contains(&w))
                })
            })
        })
    }

    /// A cylinder of 8 sectors (rim edges 0.77, spokes 1, strips 1.08
    /// long): split to edges ≤ 0.4, closed, χ = 2, the input's vertices
    /// first and unmoved, every triangle inside an input one, the area
    /// kept; nothing to split at a length above every edge.
    #[test]
    fn bisection_keeps_the_surface() {
        let s = cad_cylinder(8, 1, 0.5);
        let r = split_long_edges(&s, 0.4).expect("edges above 0.4");
        assert_eq!(r.euler_characteristic(), 2);
        assert!(r.boundary_vertex.iter().all(|&b| !b));
        assert_eq!(r.positions[..s.positions.len()], s.positions[..]);
        for e in &r.edges {
            let l = norm(sub(r.positions[e[1] as usize], r.positions[e[0] as usize]));
            assert!(l <= 0.4, "edge {e:?} of length {l}");
        }
        let area = |s: &Surface| s.areas.iter().sum::<f64>();
        assert!((area(&r) - area(&s)).abs() < 1e-12 * area(&s));
        assert!(inside(&s, &r));
        assert!(r.triangles.len() > 4 * s.triangles.len());
        assert!(split_long_edges(&s, 1.2).is_none());
    }

    /// An open strip: boundary edges split too, the boundary stays one
    /// loop (χ = 1).
    #[test]
    fn boundary_edges_split() {
        let p = vec![
            [0.0, 0.0, 0.0],
            [3.0, 0.0, 0.0],
            [3.0, 0.1, 0.0],
            [0.0, 0.1, 0.0],
        ];
        let s = Surface::new(p, vec![[0, 1, 2], [0, 2, 3]]).expect("a strip");
        let r = split_long_edges(&s, 1.0).expect("long edges");
        assert_eq!(r.euler_characteristic(), 1);
        assert!(inside(&s, &r));
        let boundary = r.edges.iter().enumerate();
        let n = boundary
            .filter(|&(e, _)| r.is_boundary_edge(e as u32))
            .count();
        assert_eq!(n, 2 * 4 + 2, "each long side in 4, the short ones whole");
    }
}

//! Long edges split before the field: room for the field and the map on
//! CAD tessellations.
//!
//! Input: a [`Surface`] and a length `max_len` (the pipeline gives
//! [`QUAD_EDGES`] target quad edges, [`crate::pipeline`]). Output: `None`
//! when no edge is longer (the surface is used as it is), else the surface
//! with every edge longer than `max_len` cut into `⌈length / max_len⌉`
//! equal pieces and every triangle filled again from the points on its
//! sides ([`fill`]):
//!
//! ```text
//!   one side whole (a–b), a zipper       no side whole: the longest side
//!   of rungs between the other two       cut at its middle point m, m–c
//!                                        cut like an edge, each half
//!          c                             filled again
//!         / \                                   c
//!        r2──q2                                /|\
//!       / ╲   \                               / | \
//!      r1───q1 \                             a──m──b
//!     / ╲      \\
//!    a───────────b
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
//! Why equal pieces and a fill per triangle (not longest-edge bisection,
//! as before): bisection carries every split into the neighbouring
//! triangle and halves lengths, so a needle (a strip of a cylinder's side,
//! aspect 1000) is cut to a power of two pieces, up to twice as many as
//! needed, and its zigzags are split again: `surface_cad_needles` (4000
//! triangles) became 1.5 million at 5000 quads. Here an input edge is cut
//! once, by its own length, so both of its triangles agree on its points
//! and a needle becomes one ladder of `k₁ + k₂ − 1` triangles
//! (docs/messy-cases.md, "needles").
//!
//! An edge no longer than two target quad edges is left alone, so the
//! surfaces whose triangles are already smaller than the quads (scans, the
//! generated smooth surfaces at the usual sizes) go through unchanged, and
//! their maps with them.
//!
//! Invariants: the output's vertices are the input's (same numbers, same
//! positions) followed by points on input edges and inside input
//! triangles, and every output triangle lies in one input triangle: the
//! output is the input surface, exactly (up to the rounding of a point).
//! Topology (components, χ, boundary loops) and orientation are the
//! input's; a sharp edge split is sharp edges. Every edge made is at most
//! `max_len` long except a zipper's rungs and diagonals, at most about
//! twice that.

use crate::surface::{norm, sub, Surface};

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

/// At most about this many triangles are made (a guard against a
/// `max_len` far below the edges: the length is raised until the
/// estimate, [`estimate`], is below it).
pub const MAX_TRIANGLES: usize = 2_000_000;

/// The surface with its edges longer than `max_len` split (module
/// docs); `None` when there is none, or when a piece is too small for a
/// [`Surface`] (zero area in floating point: the input is used as it is).
pub fn split_long_edges(surface: &Surface, max_len: f64) -> Option<Surface> {
    if !(max_len.is_finite() && max_len > 0.0) {
        return None;
    }
    let p = &surface.positions;
    let length = |&[a, b]: &[u32; 2]| norm(sub(p[b as usize], p[a as usize]));
    if !surface.edges.iter().any(|e| length(e) > max_len) {
        return None;
    }
    let mut max_len = max_len;
    while estimate(surface, max_len) > MAX_TRIANGLES as f64 {
        max_len *= 1.25;
    }
    let mut fill = Fill {
        positions: surface.positions.clone(),
        triangles: Vec::with_capacity(estimate(surface, max_len) as usize),
        max_len,
    };
    // every input edge's points, from edges[e][0] to edges[e][1]
    let chains: Vec<Vec<u32>> = surface
        .edges
        .iter()
        .map(|&[a, b]| fill.chain(a, b))
        .collect();
    for (tri, edges) in surface.triangles.iter().zip(&surface.face_edges) {
        let sides = [0, 1, 2].map(|i| {
            let e = edges[i] as usize;
            let mut side = chains[e].clone();
            if surface.edges[e][0] != tri[i] {
                side.reverse();
            }
            side
        });
        fill.triangle(sides);
    }
    Surface::new(fill.positions, fill.triangles).ok()
}

/// About the number of triangles [`split_long_edges`] makes at
/// `max_len`: per triangle, its sides' pieces and four per `max_len²` of
/// its area.
fn estimate(surface: &Surface, max_len: f64) -> f64 {
    let p = &surface.positions;
    let pieces = |&[a, b]: &[u32; 2]| (norm(sub(p[b as usize], p[a as usize])) / max_len).ceil();
    let sides: f64 = surface.edges.iter().map(pieces).sum();
    let area: f64 = surface.areas.iter().sum();
    2.0 * sides + 4.0 * area / (max_len * max_len)
}

/// The output being built: the input's positions followed by the points
/// made, and the triangles filled so far.
struct Fill {
    positions: Vec<[f64; 3]>,
    triangles: Vec<[u32; 3]>,
    max_len: f64,
}

/// A triangle to fill: per side `i`, its points from corner `i` to corner
/// `i + 1` (both included), counter-clockwise.
type Sides = [Vec<u32>; 3];

impl Fill {
    /// `a`, the points cutting `a`–`b` into `⌈length / max_len⌉` equal
    /// pieces (made here), then `b`.
    fn chain(&mut self, a: u32, b: u32) -> Vec<u32> {
        let (pa, pb) = (self.positions[a as usize], self.positions[b as usize]);
        let pieces = (norm(sub(pb, pa)) / self.max_len).ceil().max(1.0);
        // the guard of split_long_edges keeps this far below u32::MAX
        let k = pieces as u32;
        let mut chain = Vec::with_capacity(k as usize + 1);
        chain.push(a);
        for i in 1..k {
            let s = f64::from(i) / f64::from(k);
            chain.push(self.positions.len() as u32);
            self.positions
                .push([0, 1, 2].map(|j| pa[j] + s * (pb[j] - pa[j])));
        }
        chain.push(b);
        chain
    }

    fn distance(&self, a: u32, b: u32) -> f64 {
        norm(sub(self.positions[b as usize], self.positions[a as usize]))
    }

    /// Fills one triangle given its sides' points (module docs): a zipper
    /// on its shortest whole side, else halves at the longest side's
    /// middle point, until every piece has a whole side.
    fn triangle(&mut self, sides: Sides) {
        let mut stack = vec![sides];
        while let Some(s) = stack.pop() {
            let whole = (0..3).filter(|&i| s[i].len() == 2);
            let side_len = |i: usize| self.distance(s[i][0], s[(i + 1) % 3][0]);
            if let Some(i) = whole.min_by(|&i, &j| side_len(i).total_cmp(&side_len(j))) {
                self.zipper(&s, i);
                continue;
            }
            let i = (0..3)
                .max_by(|&i, &j| side_len(i).total_cmp(&side_len(j)))
                .unwrap_or(0);
            let [cut, next, prev] = [0, 1, 2].map(|k| &s[(i + k) % 3]);
            // cut: a → b with ≥ 3 points, next: b → c, prev: c → a
            let mid = cut.len() / 2;
            let m = cut[mid];
            let mc = self.chain(m, prev[0]);
            let cm: Vec<u32> = mc.iter().rev().copied().collect();
            stack.push([cut[..=mid].to_vec(), mc, prev.clone()]);
            stack.push([cut[mid..].to_vec(), next.clone(), cm]);
        }
    }

    /// The ladder between the two sides after the whole side `i` (`a`–`b`,
    /// corner `c` opposite), each step to the shorter diagonal:
    /// `k₁ + k₂ − 1` triangles for sides of `k₁` and `k₂` pieces.
    ///
    /// ```text
    ///        c
    ///       r2─q2        r: a → c (side i + 2 reversed)
    ///      / ╲  \        q: b → c (side i + 1)
    ///     r1──q1 \       triangles [r_x, q_y, r_x+1] or [r_x, q_y, q_y+1]
    ///    a────────b
    /// ```
    fn zipper(&mut self, s: &Sides, i: usize) {
        let q = &s[(i + 1) % 3];
        let r: Vec<u32> = s[(i + 2) % 3].iter().rev().copied().collect();
        let (m, n) = (r.len() - 1, q.len() - 1);
        let (mut x, mut y) = (0, 0);
        while x + y < m + n - 2 {
            let up_r = if x == m - 1 {
                false
            } else if y == n - 1 {
                true
            } else {
                self.distance(r[x + 1], q[y]) <= self.distance(r[x], q[y + 1])
            };
            if up_r {
                self.triangles.push([r[x], q[y], r[x + 1]]);
                x += 1;
            } else {
                self.triangles.push([r[x], q[y], q[y + 1]]);
                y += 1;
            }
        }
        self.triangles.push([r[m - 1], q[n - 1], q[n]]);
    }
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
    /// long): split to edges ≤ 0.8 (a zipper's rungs and diagonals; the
    /// pieces of input edges ≤ 0.4), closed, χ = 2, the input's vertices
    /// first and unmoved, every triangle inside an input one, the area
    /// kept; nothing to split at a length above every edge.
    #[test]
    fn split_keeps_the_surface() {
        let s = cad_cylinder(8, 1, 0.5);
        let r = split_long_edges(&s, 0.4).expect("edges above 0.4");
        assert_eq!(r.euler_characteristic(), 2);
        assert!(r.boundary_vertex.iter().all(|&b| !b));
        assert_eq!(r.positions[..s.positions.len()], s.positions[..]);
        for e in &r.edges {
            let l = norm(sub(r.positions[e[1] as usize], r.positions[e[0] as usize]));
            assert!(l <= 0.8, "edge {e:?} of length {l}");
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
        assert_eq!(n, 2 * 3 + 2, "each long side in 3, the short ones whole");
    }

    /// A needle (aspect 1000, sides of 100 pieces) becomes one ladder of
    /// 199 triangles; with a second needle on its long side, the shared
    /// side's points are the same for both.
    #[test]
    fn needles_become_ladders() {
        let p = vec![[0.0, 0.0, 0.0], [0.1, 0.0, 0.0], [0.05, 99.5, 0.0]];
        let s = Surface::new(p.clone(), vec![[0, 1, 2]]).expect("a needle");
        let r = split_long_edges(&s, 1.0).expect("long edges");
        assert_eq!(r.triangles.len(), 199);
        assert_eq!(r.positions.len(), 3 + 2 * 99);
        assert!(inside(&s, &r));
        let mut p2 = p;
        p2.push([0.15, 99.5, 0.0]);
        let s2 = Surface::new(p2, vec![[0, 1, 2], [1, 3, 2]]).expect("two needles");
        let r2 = split_long_edges(&s2, 1.0).expect("long edges");
        assert_eq!(r2.triangles.len(), 2 * 199);
        assert_eq!(r2.euler_characteristic(), 1);
        assert!(inside(&s2, &r2));
    }
}

//! Connectivity and per-face frames of a plain triangle surface.
//!
//! Input: positions and consistently oriented triangles. Output: a
//! [`Surface`] with its edges, the faces on each side of every edge, and an
//! orthonormal frame per face, in which the cross field's angles and the
//! map's gradients are written.
//!
//! Invariants checked by [`Surface::new`]: every index in range, no
//! triangle with a repeated vertex or (numerically) zero area, every edge
//! in at most two triangles that use it in opposite directions.

use std::fmt;

/// "No face here": the missing side of a boundary edge.
pub const NO_FACE: u32 = u32::MAX;

/// Why a triangle soup is not a surface the remesher can work on. The
/// message names the element.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SurfaceError(pub String);

impl fmt::Display for SurfaceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SurfaceError {}

/// An oriented triangle surface with edges and face frames.
#[derive(Clone, Debug)]
pub struct Surface {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Triangles, counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
    /// Edges as `[a, b]` with `a < b`.
    pub edges: Vec<[u32; 2]>,
    /// `edge_faces[e] = [f0, f1]`: `f0` holds the half-edge `a → b` when
    /// such a face exists, else `b → a`; `f1` is the other side or
    /// [`NO_FACE`] on the boundary. `f0` is never [`NO_FACE`].
    pub edge_faces: Vec<[u32; 2]>,
    /// `face_edges[f][i]` is the edge from corner `i` to corner `i + 1`.
    pub face_edges: Vec<[u32; 3]>,
    /// Per face: `[e1, e2, n]`, orthonormal, `e1` along corner 0 → 1,
    /// `n` the unit normal.
    pub frames: Vec<[[f64; 3]; 3]>,
    /// Per face: area.
    pub areas: Vec<f64>,
    /// Per vertex: on the boundary.
    pub boundary_vertex: Vec<bool>,
}

impl Surface {
    /// Builds the connectivity; see the module docs for what is checked.
    pub fn new(positions: Vec<[f64; 3]>, triangles: Vec<[u32; 3]>) -> Result<Self, SurfaceError> {
        let n = positions.len();
        let mut frames = Vec::with_capacity(triangles.len());
        let mut areas = Vec::with_capacity(triangles.len());
        for (f, t) in triangles.iter().enumerate() {
            if let Some(&v) = t.iter().find(|&&v| v as usize >= n) {
                return Err(SurfaceError(format!(
                    "triangle {f}: vertex {v} out of range ({n} vertices)"
                )));
            }
            if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
                return Err(SurfaceError(format!("triangle {f}: repeated vertex {t:?}")));
            }
            let [p0, p1, p2] = t.map(|v| positions[v as usize]);
            let a = sub(p1, p0);
            let c = cross(a, sub(p2, p0));
            let (la, lc) = (norm(a), norm(c));
            let scale = norm(a).max(norm(sub(p2, p0))).max(norm(sub(p2, p1)));
            if lc.is_nan() || lc <= 1e-14 * scale * scale || !lc.is_finite() {
                return Err(SurfaceError(format!("triangle {f}: zero area")));
            }
            let e1 = mul(a, 1.0 / la);
            let nn = mul(c, 1.0 / lc);
            frames.push([e1, cross(nn, e1), nn]);
            areas.push(0.5 * lc);
        }
        // half-edges sorted by their undirected edge
        let mut half: Vec<(u32, u32, u32, u8)> = Vec::with_capacity(3 * triangles.len());
        for (f, t) in triangles.iter().enumerate() {
            for i in 0..3 {
                let (a, b) = (t[i], t[(i + 1) % 3]);
                half.push((a.min(b), a.max(b), f as u32, i as u8));
            }
        }
        half.sort_unstable();
        let mut edges = Vec::new();
        let mut edge_faces = Vec::new();
        let mut face_edges = vec![[0u32; 3]; triangles.len()];
        let mut i = 0;
        while i < half.len() {
            let mut j = i + 1;
            while j < half.len() && half[j].0 == half[i].0 && half[j].1 == half[i].1 {
                j += 1;
            }
            let (a, b) = (half[i].0, half[i].1);
            if j - i > 2 {
                return Err(SurfaceError(format!(
                    "edge {a}–{b}: in {} triangles (non-manifold)",
                    j - i
                )));
            }
            let forward = |h: &(u32, u32, u32, u8)| triangles[h.2 as usize][h.3 as usize] == a;
            let e = edges.len() as u32;
            let pair = if j - i == 2 {
                let (h0, h1) = (&half[i], &half[i + 1]);
                if forward(h0) == forward(h1) {
                    return Err(SurfaceError(format!(
                        "edge {a}–{b}: triangles {} and {} are oriented inconsistently",
                        h0.2, h1.2
                    )));
                }
                if forward(h0) {
                    [h0.2, h1.2]
                } else {
                    [h1.2, h0.2]
                }
            } else {
                [half[i].2, NO_FACE]
            };
            for h in &half[i..j] {
                face_edges[h.2 as usize][h.3 as usize] = e;
            }
            edges.push([a, b]);
            edge_faces.push(pair);
            i = j;
        }
        let mut boundary_vertex = vec![false; n];
        for (e, f) in edges.iter().zip(&edge_faces) {
            if f[1] == NO_FACE {
                boundary_vertex[e[0] as usize] = true;
                boundary_vertex[e[1] as usize] = true;
            }
        }
        Ok(Surface {
            positions,
            triangles,
            edges,
            edge_faces,
            face_edges,
            frames,
            areas,
            boundary_vertex,
        })
    }

    /// Whether edge `e` is on the boundary.
    pub fn is_boundary_edge(&self, e: u32) -> bool {
        self.edge_faces[e as usize][1] == NO_FACE
    }

    /// A 3D vector written in face `f`'s frame (its normal part dropped).
    pub fn in_frame(&self, f: u32, v: [f64; 3]) -> [f64; 2] {
        let [e1, e2, _] = self.frames[f as usize];
        [dot(v, e1), dot(v, e2)]
    }

    /// Angle, in face `f`'s frame, of edge `e` taken from its smaller
    /// vertex to its larger one. The transport of a direction across `e`
    /// keeps its angle to this edge.
    pub fn edge_angle(&self, e: u32, f: u32) -> f64 {
        let [a, b] = self.edges[e as usize];
        let d = sub(self.positions[b as usize], self.positions[a as usize]);
        let [x, y] = self.in_frame(f, d);
        y.atan2(x)
    }

    /// Euler characteristic V − E + F (vertices used by no triangle count).
    pub fn euler_characteristic(&self) -> i64 {
        self.positions.len() as i64 - self.edges.len() as i64 + self.triangles.len() as i64
    }
}

pub(crate) fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub(crate) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub(crate) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub(crate) fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}
pub(crate) fn mul(a: [f64; 3], s: f64) -> [f64; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Surface {
        let p = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        Surface::new(p, vec![[0, 1, 2], [0, 2, 3]]).unwrap()
    }

    #[test]
    fn square_connectivity() {
        let s = square();
        assert_eq!(s.edges.len(), 5);
        assert_eq!(s.euler_characteristic(), 1);
        let diag = s.edges.iter().position(|&e| e == [0, 2]).unwrap();
        assert_eq!(s.edge_faces[diag], [1, 0]);
        assert_eq!(
            s.edges
                .iter()
                .enumerate()
                .filter(|(e, _)| s.is_boundary_edge(*e as u32))
                .count(),
            4
        );
        assert!(s.boundary_vertex.iter().all(|&b| b));
        for (f, fe) in s.face_edges.iter().enumerate() {
            for i in 0..3 {
                let t = s.triangles[f];
                let mut ab = [t[i], t[(i + 1) % 3]];
                ab.sort();
                assert_eq!(s.edges[fe[i] as usize], ab);
            }
        }
        // the diagonal (0 → 2) is at 45° in both faces (same plane, e1 = x)
        let d0 = s.edge_angle(diag as u32, 0);
        assert!((d0 - std::f64::consts::FRAC_PI_4).abs() < 1e-12);
        assert_eq!(s.areas, vec![0.5, 0.5]);
    }

    #[test]
    fn bad_surfaces_name_the_element() {
        let p = vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let e = Surface::new(p.clone(), vec![[0, 1, 9]]).unwrap_err();
        assert_eq!(e.0, "triangle 0: vertex 9 out of range (4 vertices)");
        let e = Surface::new(p.clone(), vec![[0, 1, 2], [0, 1, 3]]).unwrap_err();
        assert!(e.0.contains("inconsistently"), "{e}");
        let e = Surface::new(p.clone(), vec![[0, 1, 1]]).unwrap_err();
        assert!(e.0.contains("repeated"), "{e}");
        let flat = vec![[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
        let e = Surface::new(flat, vec![[0, 1, 2]]).unwrap_err();
        assert!(e.0.contains("zero area"), "{e}");
        let e = Surface::new(p, vec![[0, 1, 2], [1, 0, 3], [0, 1, 3]]).unwrap_err();
        assert!(e.0.contains("non-manifold"), "{e}");
    }
}

//! How each output vertex may move: freely (3D interior), on the
//! reference surface, along its curves (boundary, features) or not at all
//! (corners).
//!
//! Input: the output vertices, which of them are on the output's boundary,
//! a normal hint per vertex (the side of the surface it faces) and the
//! [`Reference`]. Output: a [`Kind`] per vertex, a linear tangent basis
//! at its current position, and the projection back onto its set.
//! Invariants: a vertex's basis spans exactly its [`Kind::dof`]
//! directions, orthonormal, but for a [`Kind::Surface`] vertex on a
//! feature curve (a sharp edge), whose basis is all of space (its
//! projection decides which face it lands on); projecting a point of the
//! set leaves it there.

use crate::quality::{cross, dot, norm, sub, unit};
use crate::reference::Reference;
use std::sync::atomic::AtomicU32;

/// A point of the surface within this fraction of the bounding box's
/// diagonal of a feature curve is on it (a foot found on a triangle's
/// edge is on it up to rounding).
pub const ON_FEATURE: f64 = 1e-9;

/// The set a vertex stays on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Anywhere (interior vertices of a volume mesh).
    Free,
    /// On the reference surface.
    Surface,
    /// On the reference's curves (only its boundary curves when `boundary`).
    Curve {
        /// Only boundary segments.
        boundary: bool,
    },
    /// Not moved (corners of the curves).
    Fixed,
}

impl Kind {
    /// Degrees of freedom.
    pub fn dof(self) -> usize {
        match self {
            Kind::Free => 3,
            Kind::Surface => 2,
            Kind::Curve { .. } => 1,
            Kind::Fixed => 0,
        }
    }
}

/// The kinds of a mesh's vertices.
#[derive(Debug)]
pub struct Constraints {
    /// Per vertex.
    pub kind: Vec<Kind>,
    /// Per vertex, a normal the surface under it must agree with.
    pub hint: Vec<[f64; 3]>,
    /// Per vertex, the triangle of its last closest-point query
    /// (`u32::MAX`: none), where the next one starts: it changes the work
    /// of a query, never its answer.
    feet: Vec<AtomicU32>,
    /// Per vertex on the boundary curves, the arc it stays on
    /// (`u32::MAX`: the nearest of any): the arc between the input corners
    /// that hold the mesh's corners around it (`stage::corners`).
    pub arc: Vec<u32>,
}

/// Whether the mesh is a surface (D = 2: every vertex on the reference)
/// or a volume (D = 3: only boundary vertices on it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// Quads on the reference surface.
    Surface,
    /// Hexes whose boundary lies on the reference.
    Volume,
}

impl Constraints {
    /// Classifies every vertex (see the module docs); `tol`: the distance
    /// under which a vertex is on a curve or a corner.
    pub fn classify(
        r: &Reference,
        positions: &[[f64; 3]],
        on_boundary: &[bool],
        hint: Vec<[f64; 3]>,
        role: Role,
        tol: f64,
    ) -> Self {
        use rayon::prelude::*;
        let has_boundary = r.has_boundary();
        // per vertex on its own (a closest-point search each), in parallel
        let kind = positions
            .par_iter()
            .zip(on_boundary)
            .with_min_len(256)
            .map(|(&p, &b)| {
                let on_ref = role == Role::Surface || b;
                if !on_ref {
                    return Kind::Free;
                }
                // a 2D boundary vertex goes onto the boundary curves
                let boundary_only = role == Role::Surface && b && has_boundary;
                match r.closest_on_curves(p, boundary_only) {
                    Some((s, _, d)) if d <= tol || boundary_only => {
                        let seg = r.segments[s as usize];
                        let at_corner = seg.ends.iter().any(|&e| {
                            r.corner[e as usize] && norm(sub(r.positions[e as usize], p)) <= tol
                        });
                        if at_corner {
                            Kind::Fixed
                        } else {
                            Kind::Curve {
                                boundary: boundary_only,
                            }
                        }
                    }
                    _ => Kind::Surface,
                }
            })
            .collect();
        let feet = (0..positions.len())
            .map(|_| AtomicU32::new(u32::MAX))
            .collect();
        let arc = vec![u32::MAX; positions.len()];
        Constraints {
            kind,
            hint,
            feet,
            arc,
        }
    }

    /// The point of vertex `v`'s set nearest `p`.
    pub fn project(&self, r: &Reference, v: usize, p: [f64; 3]) -> [f64; 3] {
        match self.kind[v] {
            Kind::Free | Kind::Fixed => p,
            Kind::Surface => r
                .closest_cached(p, Some(self.hint[v]), self.feet.get(v))
                .map_or(p, |f| f.point),
            Kind::Curve { boundary } => self.curve_foot(r, v, p, boundary).map_or(p, |c| c.1),
        }
    }

    /// The nearest point to `p` on vertex `v`'s curves: its arc when it
    /// has one, else any curve (boundary ones only when `boundary`).
    fn curve_foot(
        &self,
        r: &Reference,
        v: usize,
        p: [f64; 3],
        boundary: bool,
    ) -> Option<(u32, [f64; 3], f64)> {
        match self.arc[v] {
            u32::MAX => r.closest_on_curves(p, boundary),
            a => r.closest_on_arc(p, a),
        }
    }

    /// An orthonormal basis of the directions vertex `v` may move in at
    /// `p` (on its set), and their count: for a vertex on the surface,
    /// its foot triangle's tangent plane, or all of space where the foot
    /// is on a feature curve. (With one face's plane a vertex on a sharp
    /// edge could only slide along it or back onto that face, never cross
    /// onto the other: the noisy cube's round trips kept inverted quads
    /// bent across the edge, issue 21.)
    pub fn basis(&self, r: Option<&Reference>, v: usize, p: [f64; 3]) -> Basis {
        self.project_basis(r, v, p).1
    }

    /// The point of vertex `v`'s set nearest `p`, and the [`basis`](Self::basis)
    /// there (one closest-point query for both).
    pub fn project_basis(&self, r: Option<&Reference>, v: usize, p: [f64; 3]) -> ([f64; 3], Basis) {
        let id = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        match (self.kind[v], r) {
            (Kind::Free, _) => (p, (3, id)),
            (Kind::Surface, Some(r)) => {
                let foot = r.closest_cached(p, Some(self.hint[v]), self.feet.get(v));
                let n = foot
                    .map(|f| r.normals[f.triangle as usize])
                    .filter(|n| norm(*n) > 0.0)
                    .unwrap_or_else(|| unit(self.hint[v]));
                let q = foot.map_or(p, |f| f.point);
                if norm(n) == 0.0 {
                    return (q, (0, id));
                }
                // on a sharp edge: free to leave it onto either face (the
                // projection puts it back on the surface); one face's
                // tangent plane would keep it on that face's side
                if r.on_feature(q, ON_FEATURE * r.diagonal) {
                    return (q, (3, id));
                }
                let t1 = unit(perpendicular(n));
                (q, (2, [t1, cross(n, t1), [0.0; 3]]))
            }
            (Kind::Curve { boundary }, Some(r)) => match self.curve_foot(r, v, p, boundary) {
                Some((s, q, _)) if norm(r.direction(s)) > 0.0 => {
                    (q, (1, [r.direction(s), [0.0; 3], [0.0; 3]]))
                }
                Some((_, q, _)) => (q, (0, id)),
                None => (p, (0, id)),
            },
            _ => (p, (0, id)),
        }
    }
}

/// Directions a vertex may move in: their count and an orthonormal basis
/// (the first `count` rows).
pub type Basis = (usize, [[f64; 3]; 3]);

/// A vector perpendicular to `n` (not unit).
pub(crate) fn perpendicular(n: [f64; 3]) -> [f64; 3] {
    let axis = if n[0].abs() < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let t = cross(n, axis);
    debug_assert!(dot(t, n).abs() < 1e-9 * norm(n).max(1.0));
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A surface vertex moves in its face's plane, on a sharp edge in
    /// space, and a step off the edge lands on the face it went towards.
    #[test]
    fn a_surface_vertex_on_a_sharp_edge_may_cross_it() {
        let r = crate::tests::unit_cube_surface(60.0);
        let top = [0.5, 0.5, 1.0];
        let c = Constraints::classify(
            &r,
            &[top],
            &[true],
            vec![[0.0, 1.0, 1.0]],
            Role::Volume,
            1e-6,
        );
        assert_eq!(c.kind[0], Kind::Surface);
        assert_eq!(c.basis(Some(&r), 0, top).0, 2);
        // on the edge y = 1, z = 1 (a corner of the cube too)
        for on_edge in [[0.5, 1.0, 1.0], [1.0, 1.0, 1.0]] {
            let (q, b) = c.project_basis(Some(&r), 0, on_edge);
            assert_eq!((q, b.0), (on_edge, 3));
        }
        // down the face y = 1, and back onto the top face
        let q = c.project(&r, 0, [0.5, 1.01, 0.8]);
        assert!((q[1] - 1.0).abs() < 1e-15 && (q[2] - 0.8).abs() < 1e-15);
        let q = c.project(&r, 0, [0.5, 0.8, 1.01]);
        assert!((q[1] - 0.8).abs() < 1e-15 && (q[2] - 1.0).abs() < 1e-15);
    }
}

//! The reference an output mesh lives on: a triangle surface (the input
//! surface of a quad mesh, the boundary of the input volume of a hex
//! mesh), its curves (boundary edges, and feature edges whose dihedral
//! angle exceeds a threshold) and its corners.
//!
//! Input: positions and triangles (or tets, whose boundary is taken,
//! oriented outward). Output: closest points on the surface (with a normal
//! filter, so that a point never jumps to the far side of a thin part) and
//! on the curves. Invariants: triangle normals are unit or zero
//! (degenerate triangles); a curve segment is a boundary edge or a feature
//! edge, never both; a corner is a curve vertex with other than 2 curve
//! edges, or where its 2 curve edges turn by more than the threshold.

use crate::bvh::{Aabb, Bvh};
use crate::quality::{cross, dot, norm, sub};
pub use curves::MIN_FEATURE_SEGMENTS;
use curves::{corners, curve_segments, drop_short_features, label_arcs};
use std::sync::atomic::{AtomicU32, Ordering};

mod curves;
#[cfg(test)]
mod tests;

/// A curve segment of the reference.
#[derive(Clone, Copy, Debug)]
pub struct Segment {
    /// Its end vertices.
    pub ends: [u32; 2],
    /// A boundary edge (one triangle); otherwise a feature edge.
    pub boundary: bool,
    /// Its arc: the chain of segments between corners it lies on
    /// (segments meeting at a vertex that is no corner share it; a closed
    /// curve without a corner is one arc).
    pub arc: u32,
}

/// A point of the reference surface nearest a query.
#[derive(Clone, Copy, Debug)]
pub struct Foot {
    /// The triangle it lies on.
    pub triangle: u32,
    /// The point.
    pub point: [f64; 3],
    /// Its distance to the query.
    pub distance: f64,
}

/// How much farther than the nearest triangle a triangle agreeing with a
/// normal hint may be ([`Reference::closest`]).
pub const HINT_REACH: f64 = 10.0;

/// The reference surface (see the module docs).
#[derive(Clone, Debug)]
pub struct Reference {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Triangles.
    pub triangles: Vec<[u32; 3]>,
    /// Unit normal of each triangle (zero when degenerate).
    pub normals: Vec<[f64; 3]>,
    /// Curve segments.
    pub segments: Vec<Segment>,
    /// Per vertex: a corner of the curves.
    pub corner: Vec<bool>,
    /// Per corner of the curves: the sum of its triangles' angles there
    /// (radians; at a boundary vertex of a surface, the surface's interior
    /// angle); 0 at other vertices.
    pub angle: Vec<f64>,
    /// Bounding-box diagonal.
    pub diagonal: f64,
    triangle_bvh: Bvh,
    segment_bvh: Bvh,
}

impl Reference {
    /// The reference of a triangle surface; `feature_deg`: edges whose
    /// normals differ by more than this angle are features (180: none).
    pub fn surface(positions: &[[f64; 3]], triangles: &[[u32; 3]], feature_deg: f64) -> Self {
        use rayon::prelude::*;
        let normals: Vec<[f64; 3]> = triangles
            .par_iter()
            .map(|t| {
                let n = cross(
                    sub(positions[t[1] as usize], positions[t[0] as usize]),
                    sub(positions[t[2] as usize], positions[t[0] as usize]),
                );
                let l = norm(n);
                if l > 0.0 {
                    n.map(|x| x / l)
                } else {
                    [0.0; 3]
                }
            })
            .collect();
        let cos = feature_deg.to_radians().cos();
        let mut segments = curve_segments(positions.len(), triangles, &normals, cos);
        drop_short_features(&mut segments, positions.len());
        let corner = corners(positions, &segments, cos);
        label_arcs(&mut segments, &corner);
        let mut angle = vec![0.0; positions.len()];
        for t in triangles
            .iter()
            .filter(|t| t.iter().any(|&v| corner[v as usize]))
        {
            let p = t.map(|v| positions[v as usize]);
            for k in (0..3).filter(|&k| corner[t[k] as usize]) {
                let (a, b) = (sub(p[(k + 1) % 3], p[k]), sub(p[(k + 2) % 3], p[k]));
                let l = norm(a) * norm(b);
                if l > 0.0 {
                    angle[t[k] as usize] += (dot(a, b) / l).clamp(-1.0, 1.0).acos();
                }
            }
        }
        let bbox = Aabb::of_par(positions);
        let triangle_bvh = Bvh::new(
            &triangles
                .par_iter()
                .map(|t| Aabb::of(&t.map(|v| positions[v as usize])))
                .collect::<Vec<_>>(),
        );
        let segment_bvh = Bvh::new(
            &segments
                .iter()
                .map(|s| Aabb::of(&s.ends.map(|v| positions[v as usize])))
                .collect::<Vec<_>>(),
        );
        Reference {
            positions: positions.to_vec(),
            triangles: triangles.to_vec(),
            normals,
            segments,
            corner,
            angle,
            diagonal: bbox.diagonal(),
            triangle_bvh,
            segment_bvh,
        }
    }

    /// The reference of a tet mesh: its boundary triangles, outward.
    pub fn volume_boundary(positions: &[[f64; 3]], tets: &[[u32; 4]], feature_deg: f64) -> Self {
        let lone = dualex_check::topology::lone_tet_faces(tets);
        Self::volume_boundary_of(positions, tets, &lone, feature_deg)
    }

    /// [`Reference::volume_boundary`] with the boundary faces given:
    /// `lone`, the places `4·tet + f` of the faces of one tet
    /// (`dualex_check::topology::lone_tet_faces`, in any order).
    pub fn volume_boundary_of(
        positions: &[[f64; 3]],
        tets: &[[u32; 4]],
        lone: &[usize],
        feature_deg: f64,
    ) -> Self {
        use rayon::prelude::*;
        // the face opposite corner f, outward for a positive tet
        const FACE: [[usize; 3]; 4] = [[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]];
        // a face of one tet is boundary, turned outward by its tet's volume
        let mut tris: Vec<[u32; 3]> = lone
            .par_iter()
            .map(|&place| {
                let t = &tets[place / 4];
                let p = t.map(|v| positions[v as usize]);
                let vol = dot(cross(sub(p[1], p[0]), sub(p[2], p[0])), sub(p[3], p[0]));
                let mut tri = FACE[place % 4].map(|k| t[k]);
                if vol < 0.0 {
                    tri.swap(1, 2);
                }
                tri
            })
            .collect();
        // fully ordered keys: the order of the serial sort
        tris.par_sort_unstable();
        Self::surface(positions, &tris, feature_deg)
    }

    /// The nearest point of the surface to `p` on a triangle whose normal
    /// agrees with `hint` (positive dot product) within [`HINT_REACH`]
    /// times the distance to the nearest triangle (plus 1e-3 of the
    /// bounding box); the nearest triangle without a hint, or when none
    /// agrees there. (An unbounded search for an agreeing triangle visits
    /// the whole hierarchy for a point over a flipped region.)
    pub fn closest(&self, p: [f64; 3], hint: Option<[f64; 3]>) -> Option<Foot> {
        self.closest_seeded(p, hint, None)
    }

    /// [`Reference::closest`], the search started from triangle `seed`
    /// (the answer for a nearby point): the same answer, less work.
    pub fn closest_seeded(
        &self,
        p: [f64; 3],
        hint: Option<[f64; 3]>,
        seed: Option<u32>,
    ) -> Option<Foot> {
        let d2 = |t: u32| {
            let q = self.closest_on_triangle(t, p);
            let d = sub(q, p);
            dot(d, d)
        };
        let bvh = &self.triangle_bvh;
        let nearest = bvh.nearest_seeded(p, f64::INFINITY, seed, |t| Some(d2(t)))?;
        let found = match hint {
            Some(h) if dot(self.normals[nearest.0 as usize], h) <= 0.0 => {
                let reach = HINT_REACH * nearest.1.sqrt() + 1e-3 * self.diagonal;
                let agrees = |t: u32| dot(self.normals[t as usize], h) > 0.0;
                bvh.nearest_seeded(p, reach * reach, seed, |t| agrees(t).then(|| d2(t)))
                    .unwrap_or(nearest)
            }
            _ => nearest,
        };
        let point = self.closest_on_triangle(found.0, p);
        Some(Foot {
            triangle: found.0,
            point,
            distance: found.1.sqrt(),
        })
    }

    /// The nearest point to `p` on the curves (only boundary segments when
    /// `boundary_only`): the segment, the point, the distance.
    pub fn closest_on_curves(
        &self,
        p: [f64; 3],
        boundary_only: bool,
    ) -> Option<(u32, [f64; 3], f64)> {
        self.closest_on(p, |seg| !boundary_only || seg.boundary)
    }

    fn closest_on(
        &self,
        p: [f64; 3],
        keep: impl Fn(&Segment) -> bool,
    ) -> Option<(u32, [f64; 3], f64)> {
        self.closest_on_within(p, f64::INFINITY, keep)
    }

    /// [`Self::closest_on`] among the segments within squared distance
    /// `max_d2` of `p` (the search prunes every box farther).
    fn closest_on_within(
        &self,
        p: [f64; 3],
        max_d2: f64,
        keep: impl Fn(&Segment) -> bool,
    ) -> Option<(u32, [f64; 3], f64)> {
        let (s, d2) = self.segment_bvh.nearest_within(p, max_d2, |s| {
            let seg = self.segments[s as usize];
            keep(&seg).then(|| {
                let q = self.closest_on_segment(s, p);
                let d = sub(q, p);
                dot(d, d)
            })
        })?;
        Some((s, self.closest_on_segment(s, p), d2.sqrt()))
    }

    /// The nearest point to `p` on the boundary segments of `arc`: the
    /// segment, the point, the distance.
    pub fn closest_on_arc(&self, p: [f64; 3], arc: u32) -> Option<(u32, [f64; 3], f64)> {
        self.closest_on(p, |seg| seg.boundary && seg.arc == arc)
    }

    /// Whether `p` lies on a feature curve (within `tol`): a sharp edge
    /// of the surface, where a vertex on it may cross onto either side.
    /// It runs for every surface vertex at every step of the untangler:
    /// the search stops at `tol` instead of finding the nearest curve.
    pub fn on_feature(&self, p: [f64; 3], tol: f64) -> bool {
        self.closest_on_within(p, tol * tol, |seg| !seg.boundary)
            .is_some()
    }

    /// The arcs of the curve segments at vertex `v`.
    pub fn arcs_at(&self, v: u32) -> Vec<u32> {
        let mut out: Vec<u32> = self
            .segments
            .iter()
            .filter(|s| s.ends.contains(&v))
            .map(|s| s.arc)
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }

    /// The corner of the curves at `p` (within `tol`), if any.
    pub fn corner_at(&self, p: [f64; 3], tol: f64) -> Option<u32> {
        let (s, _, d) = self.closest_on_curves(p, false)?;
        if d > tol {
            return None;
        }
        self.segments[s as usize]
            .ends
            .into_iter()
            .find(|&e| self.corner[e as usize] && norm(sub(self.positions[e as usize], p)) <= tol)
    }

    /// The corner of the curves nearest `p` within `radius` whose
    /// [`angle`](Self::angle) is at most `max_angle`.
    pub fn nearest_corner(&self, p: [f64; 3], radius: f64, max_angle: f64) -> Option<[f64; 3]> {
        let (s, _, d) = self.closest_on_curves(p, false)?;
        if d > radius {
            return None;
        }
        // the corners of the nearest segment, else of the segments sharing
        // its ends (a corner is where curves turn, so it ends a segment
        // near p)
        let ends = self.segments[s as usize].ends;
        ends.iter()
            .map(|&e| (e, norm(sub(self.positions[e as usize], p))))
            .filter(|&(e, d)| {
                self.corner[e as usize] && d <= radius && self.angle[e as usize] <= max_angle
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(e, _)| self.positions[e as usize])
    }

    /// The normal under a quad with corners `p`: that of the triangle
    /// nearest its centre (the quad's Newell normal as the hint, so that a
    /// thin part's far side is not taken), or the unit Newell normal when
    /// that triangle is degenerate or there is none. The quad measure's
    /// normal for a quad without a source triangle (the stage) and for a
    /// mesh file measured against a surface (`dualex inspect --surface`).
    pub fn quad_normal(&self, p: &[[f64; 3]; 4]) -> [f64; 3] {
        self.quad_normal_cached(p, None)
    }

    /// [`Reference::quad_normal`], its search started from (and the
    /// triangle found kept in) `cache`: the same answer, less work.
    pub fn quad_normal_cached(&self, p: &[[f64; 3]; 4], cache: Option<&AtomicU32>) -> [f64; 3] {
        let centre = [0, 1, 2].map(|k| p.iter().map(|x| x[k]).sum::<f64>() / 4.0);
        let newell = cross(sub(p[2], p[0]), sub(p[3], p[1]));
        self.closest_cached(centre, Some(newell), cache)
            .map(|f| self.normals[f.triangle as usize])
            .filter(|n| norm(*n) > 0.0)
            .unwrap_or_else(|| crate::quality::unit(newell))
    }

    /// [`Reference::closest_seeded`] from the triangle in `cache`
    /// (`u32::MAX`: none), which then holds the triangle found.
    pub fn closest_cached(
        &self,
        p: [f64; 3],
        hint: Option<[f64; 3]>,
        cache: Option<&AtomicU32>,
    ) -> Option<Foot> {
        let seed = cache
            .map(|c| c.load(Ordering::Relaxed))
            .filter(|&t| t != u32::MAX);
        let foot = self.closest_seeded(p, hint, seed);
        if let (Some(c), Some(f)) = (cache, &foot) {
            c.store(f.triangle, Ordering::Relaxed);
        }
        foot
    }

    /// Whether the reference has boundary segments.
    pub fn has_boundary(&self) -> bool {
        self.segments.iter().any(|s| s.boundary)
    }

    /// The unit direction of segment `s` (zero when degenerate).
    pub fn direction(&self, s: u32) -> [f64; 3] {
        let [a, b] = self.segments[s as usize].ends;
        let d = sub(self.positions[b as usize], self.positions[a as usize]);
        let l = norm(d);
        if l > 0.0 {
            d.map(|x| x / l)
        } else {
            [0.0; 3]
        }
    }

    fn closest_on_segment(&self, s: u32, p: [f64; 3]) -> [f64; 3] {
        let [a, b] = self.segments[s as usize]
            .ends
            .map(|v| self.positions[v as usize]);
        let d = sub(b, a);
        let l2 = dot(d, d);
        let t = if l2 > 0.0 {
            (dot(sub(p, a), d) / l2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        [0, 1, 2].map(|k| a[k] + t * d[k])
    }

    /// The point of triangle `t` nearest `p` (Ericson, *Real-Time
    /// Collision Detection*, 5.1.5: by the Voronoi regions of its
    /// features).
    pub fn closest_on_triangle(&self, t: u32, p: [f64; 3]) -> [f64; 3] {
        let [a, b, c] = self.triangles[t as usize].map(|v| self.positions[v as usize]);
        let lerp = |x: [f64; 3], y: [f64; 3], s: f64| [0, 1, 2].map(|k| x[k] + s * (y[k] - x[k]));
        let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
        let (d1, d2) = (dot(ab, ap), dot(ac, ap));
        if d1 <= 0.0 && d2 <= 0.0 {
            return a;
        }
        let bp = sub(p, b);
        let (d3, d4) = (dot(ab, bp), dot(ac, bp));
        if d3 >= 0.0 && d4 <= d3 {
            return b;
        }
        let vc = d1 * d4 - d3 * d2;
        if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
            return lerp(a, b, d1 / (d1 - d3));
        }
        let cp = sub(p, c);
        let (d5, d6) = (dot(ab, cp), dot(ac, cp));
        if d6 >= 0.0 && d5 <= d6 {
            return c;
        }
        let vb = d5 * d2 - d1 * d6;
        if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
            return lerp(a, c, d2 / (d2 - d6));
        }
        let va = d3 * d6 - d5 * d4;
        if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
            return lerp(b, c, (d4 - d3) / ((d4 - d3) + (d5 - d6)));
        }
        let denom = va + vb + vc;
        if denom.abs() < f64::MIN_POSITIVE {
            return a; // a degenerate triangle whose edges all failed above
        }
        let (v, w) = (vb / denom, vc / denom);
        [0, 1, 2].map(|k| a[k] + ab[k] * v + ac[k] * w)
    }
}

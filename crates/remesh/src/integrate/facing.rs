//! Boundary walls that face each other across a strip of the surface.
//!
//! Input: the [`Surface`], the [`Charts`], the aligned boundary edges of
//! the [`Constraints`] and a continuous map `x` (unknown `2·w + c` is
//! coordinate `c` of wedge `w`). Output: [`Facing`]:
//! - the **walls**: a wall is a maximal run of aligned boundary edges on
//!   one iso-line of one chart (their integer unknowns are equal through
//!   the rows `A_c = B_c`); one per boundary integer unknown;
//! - the **pairs** of walls facing each other: from a point of an aligned
//!   boundary edge a ray in the map, perpendicular to the edge (along its
//!   coordinate) into its face, crossing uncut faces only, ends on an
//!   aligned boundary edge of the same coordinate within `reach` map
//!   units. A ray that meets a seam, an unaligned boundary edge or no
//!   exit ends without a pair: a wall has many edges and the cut crosses
//!   a strip along a thin line, so other rays of the wall find its
//!   partner.
//!
//! Invariants: in each pair `(low, high)` the two walls differ, the strip
//! lies between them and `low`'s value is below `high`'s in `x`; pairs
//! are unique, sorted by their gap in `x` (narrowest first).

use super::charts::Charts;
use super::constraints::Constraints;
use crate::surface::Surface;
use dualex_util::union_find::UnionFind;
use std::collections::HashMap;

/// Walls and facing pairs (module docs).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Facing {
    /// Per boundary integer unknown (entry of [`Constraints::boundary`]):
    /// its wall.
    pub wall: Vec<u32>,
    /// `(low, high, gap)`: walls facing each other, `gap` their distance
    /// in `x` (module docs).
    pub pairs: Vec<(u32, u32, f64)>,
}

/// Most faces a ray crosses.
const MAX_STEPS: usize = 4096;

/// Where on its edge a ray starts (a fraction away from the midpoint, so
/// that rays of a regular triangulation miss its vertices).
const START: f64 = 0.414_213_562;

/// The walls and facing pairs (module docs) of `cons` in the map `x`,
/// gaps up to `reach`.
pub fn find(
    surface: &Surface,
    charts: &Charts,
    cons: &Constraints,
    x: &[f64],
    reach: f64,
) -> Facing {
    let wall = walls(cons);
    let mut aligned: HashMap<u32, usize> = HashMap::new();
    for (k, a) in cons.boundary_edges.iter().enumerate() {
        aligned.insert(a.edge, k);
    }
    let ray = Ray {
        surface,
        charts,
        x,
        reach,
    };
    let mut pairs: Vec<(u32, u32, f64)> = Vec::new();
    for (k, a) in cons.boundary_edges.iter().enumerate() {
        let Some((e, gap, up)) = ray.cast(a.edge, a.face, a.coordinate) else {
            continue;
        };
        let Some(&k2) = aligned.get(&e) else { continue };
        if cons.boundary_edges[k2].coordinate != a.coordinate || wall[k] == wall[k2] {
            continue;
        }
        let (lo, hi) = if up {
            (wall[k], wall[k2])
        } else {
            (wall[k2], wall[k])
        };
        pairs.push((lo, hi, gap));
    }
    pairs.sort_by(|a, b| {
        (a.0, a.1, a.2)
            .partial_cmp(&(b.0, b.1, b.2))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    pairs.dedup_by(|b, a| (a.0, a.1) == (b.0, b.1));
    pairs.sort_by(|a, b| a.2.total_cmp(&b.2));
    Facing { wall, pairs }
}

/// One wall per boundary integer unknown: runs of aligned edges joined
/// where they share a coordinate unknown (module docs).
fn walls(cons: &Constraints) -> Vec<u32> {
    let mut key: HashMap<u32, usize> = HashMap::new();
    let mut uf = UnionFind::new(cons.boundary.len());
    for (k, q) in cons.boundary.iter().enumerate() {
        // the row `A_c − B_c` of this edge names both of its unknowns
        for &(var, _) in &q.terms {
            match key.get(&var) {
                Some(&j) => {
                    uf.union(j, k);
                }
                None => {
                    key.insert(var, k);
                }
            }
        }
    }
    // the other end of each edge: the row pushed with it
    for r in &cons.rows {
        if let [(a, _), (b, _)] = r.terms[..] {
            if let (Some(&i), Some(&j)) = (key.get(&a), key.get(&b)) {
                uf.union(i, j);
            }
        }
    }
    uf.labels().0
}

/// A ray walk in the continuous map (module docs).
struct Ray<'a> {
    surface: &'a Surface,
    charts: &'a Charts,
    x: &'a [f64],
    reach: f64,
}

impl Ray<'_> {
    /// Corner `i` of face `f` in the map.
    fn uv(&self, f: usize, i: usize) -> [f64; 2] {
        let w = self.charts.corner_wedge[3 * f + i] as usize;
        [self.x[2 * w], self.x[2 * w + 1]]
    }

    /// From boundary edge `e` of face `f`, along coordinate `c` into `f`:
    /// the boundary edge reached, the distance, and whether the ray went
    /// up (towards larger `c`).
    fn cast(&self, e: u32, f: u32, c: u32) -> Option<(u32, f64, bool)> {
        let (s, c) = (self.surface, c as usize);
        let (fu, eu) = (f as usize, e as usize);
        let [a, b] = s.edges[eu];
        let tri = s.triangles[fu];
        let ia = tri.iter().position(|&v| v == a)?;
        let ib = tri.iter().position(|&v| v == b)?;
        let io = 3 - ia - ib;
        let (pa, pb, po) = (self.uv(fu, ia), self.uv(fu, ib), self.uv(fu, io));
        let start = [0, 1].map(|d| pa[d] + START * (pb[d] - pa[d]));
        let up = po[c] > start[c];
        let sign = if up { 1.0 } else { -1.0 };
        if (po[c] - start[c]).abs() < 1e-12 {
            return None;
        }
        let lane = start[1 - c];
        let (mut face, mut entry, mut at) = (fu, eu, start[c]);
        for _ in 0..MAX_STEPS {
            let (exit, cross) = self.exit(face, entry, c, lane, sign, at)?;
            let gap = sign * (cross - start[c]);
            if gap > self.reach {
                return None;
            }
            let [f0, f1] = s.edge_faces[exit];
            if s.is_boundary_edge(exit as u32) {
                return Some((exit as u32, gap, up));
            }
            if self.charts.seam[exit].is_some() {
                return None;
            }
            face = if f0 as usize == face { f1 } else { f0 } as usize;
            (entry, at) = (exit, cross);
        }
        None
    }

    /// The edge of `face` other than `entry` where the line of constant
    /// `1 − c` coordinate `lane` leaves it going `sign`, and its `c`
    /// there (at least `at`, up to rounding).
    fn exit(
        &self,
        face: usize,
        entry: usize,
        c: usize,
        lane: f64,
        sign: f64,
        at: f64,
    ) -> Option<(usize, f64)> {
        let s = self.surface;
        let mut best: Option<(usize, f64)> = None;
        for &edge in &s.face_edges[face] {
            let edge = edge as usize;
            if edge == entry {
                continue;
            }
            let [a, b] = s.edges[edge];
            let tri = s.triangles[face];
            let ia = tri.iter().position(|&v| v == a)?;
            let ib = tri.iter().position(|&v| v == b)?;
            let (pa, pb) = (self.uv(face, ia), self.uv(face, ib));
            let (la, lb) = (pa[1 - c], pb[1 - c]);
            if (lane - la) * (lane - lb) > 0.0 || la == lb {
                continue;
            }
            let t = (lane - la) / (lb - la);
            let cross = pa[c] + t * (pb[c] - pa[c]);
            if sign * (cross - at) < -1e-9 {
                continue;
            }
            if best.is_none_or(|(_, m)| sign * cross > sign * m) {
                best = Some((edge, cross));
            }
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::{charts, constraints};
    use crate::shapes_sweep::square_with_holes;

    /// The map `x` of a surface that is its own chart: `(u, v) = (x, y)`
    /// scaled, every edge uncut.
    fn planar_map(surface: &Surface, charts: &Charts, scale: f64) -> Vec<f64> {
        let mut x = vec![0.0; 2 * charts.wedges];
        for (corner, &w) in charts.corner_wedge.iter().enumerate() {
            let p = surface.positions[surface.triangles[corner / 3][corner % 3] as usize];
            x[2 * w as usize] = scale * p[0];
            x[2 * w as usize + 1] = scale * p[1];
        }
        x
    }

    /// Two holes in a row: the walls between them face each other, each
    /// hole faces the outer boundary on all four sides, and a wide reach
    /// finds more pairs than a short one.
    #[test]
    fn two_holes_face_each_other_and_the_outer_boundary() {
        let s = square_with_holes(2);
        // the field along x in every face
        let angle = (0..s.triangles.len() as u32)
            .map(|f| {
                let [a, b] = s.in_frame(f, [1.0, 0.0, 0.0]);
                b.atan2(a)
            })
            .collect();
        let field = crate::field::CrossField::from_angles(&s, angle);
        // a cut is needed for the charts' check only: the map is planar
        let cut = crate::cut::cut_to_disk(&s, &[]).expect("cut");
        let ch = charts::build(&s, &field, &cut.is_cut).expect("charts");
        let cons = constraints::build(&s, &ch, &[], Some(0.3), &[]).expect("constraints");
        assert_eq!(cons.boundary.len(), cons.boundary_edges.len());
        // one cell = 1 map unit
        let x = planar_map(&s, &ch, 104.0);
        let near = find(&s, &ch, &cons, &x, 1.5);
        let far = find(&s, &ch, &cons, &x, 40.0);
        assert!(!near.pairs.is_empty(), "the 1-cell gap is found");
        assert!(far.pairs.len() > near.pairs.len());
        for &(lo, hi, gap) in &far.pairs {
            assert_ne!(lo, hi);
            assert!(gap > 0.0 && gap <= 40.0, "{gap}");
        }
        let walls = *near.wall.iter().max().expect("walls") as usize + 1;
        assert!(
            walls >= 12,
            "4 outer walls and 4 per hole at least: {walls}"
        );
    }
}

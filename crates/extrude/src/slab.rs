//! The layered slab over a triangle map: points, prisms, offsets.
//!
//! Input: a [`TriMap`] (planar or a surface), `layers ≥ 1`, a total
//! thickness. Output: a [`Slab`] whose points are the map's *referenced*
//! vertices (compacted) repeated at `layers + 1` levels, level-major:
//! ```text
//!   point id = level · nv + v          (v: compacted vertex, level 0..=L)
//!   prism id = layer · T + t           (t: triangle, layer 0..L)
//!   prism (t, l): bottom tri[t] at level l, top tri[t] at level l + 1
//! ```
//! Offsets: planar maps (every z equal) move along ±z, surfaces along the
//! area-weighted vertex normals (turned where those point nearly along or
//! below an incident triangle, [`crate::offset`]); the sign follows the triangles' orientation
//! so that every prism has positive geometric volume. `w` is the level
//! (`w = level`, integer at every layer interface), reversed (`w = L −
//! level`) when the map's total signed area is negative, so that prisms of
//! non-reverted triangles have a positive map determinant. The dual nodes of
//! a layer `[k, k+1]` are at `w = k + ½`: exactly `L` layers of hexes.

use crate::offset::{surface_offsets, Offsets};
use dualex_map::error::Extrusion;
use dualex_map::{InputError, TriMap};

/// Default total thickness as a fraction of the mean triangle edge length.
/// Thin, because a surface offset along its vertex normals self-intersects
/// where the offset exceeds the local feature size (sharp concave creases):
/// at 0.5 TetGen aborts on QEx's fandisk and ducks; at 0.05 it does not,
/// and the map (hence the hex mesh) does not depend on the thickness.
pub const DEFAULT_THICKNESS_FRACTION: f64 = 0.05;

/// Default total thickness of a planar map's slab, as a fraction of the mean
/// edge length: a plane offset cannot self-intersect, and a thicker slab
/// keeps TetGen's quality refinement (`--quality`) from exploding (a thin
/// slab makes `-q` add points by the hundred thousand).
pub const PLANAR_THICKNESS_FRACTION: f64 = 0.5;

/// The slab of prisms over a triangle map (see the module docs).
#[derive(Clone, Debug)]
pub struct Slab {
    /// Points, level-major (`level · nv + v`).
    pub points: Vec<[f64; 3]>,
    /// Referenced vertices per level.
    pub nv: usize,
    /// Number of layers `L`.
    pub layers: usize,
    /// Triangles over compacted vertex ids.
    pub tris: Vec<[u32; 3]>,
    /// Map `(u, v)` per triangle corner (copied from the input).
    pub coords: Vec<[[f64; 2]; 3]>,
    /// `+1`: `w = level`; `-1`: `w = L − level`.
    pub w_sign: f64,
    /// The total thickness used.
    pub thickness: f64,
    /// Whether the map was planar (offset along ±z).
    pub planar: bool,
    /// Vertices whose offset direction was turned from the area-weighted
    /// normal ([`crate::offset`]).
    pub turned: usize,
    /// Vertices where no offset direction sees every incident triangle from
    /// above (the surface folds back there; [`crate::offset`]).
    pub folded: usize,
}

impl Slab {
    /// Builds the slab; `thickness = None` uses
    /// [`DEFAULT_THICKNESS_FRACTION`] × the mean edge length.
    pub fn new(map: &TriMap, layers: usize, thickness: Option<f64>) -> Result<Slab, InputError> {
        map.validate()?;
        if layers == 0 {
            return Err(Extrusion::NoLayers.into());
        }
        let (base, tris) = compact(map);
        let planar = base.iter().all(|p| p[2] == base[0][2]);
        let thickness = match thickness {
            Some(t) if t.is_finite() && t > 0.0 => t,
            Some(t) => return Err(Extrusion::Thickness(t).into()),
            None if planar => PLANAR_THICKNESS_FRACTION * mean_edge_length(&base, &tris),
            None => DEFAULT_THICKNESS_FRACTION * mean_edge_length(&base, &tris),
        };
        let offsets = if planar {
            planar_offsets(&base, &tris)
        } else {
            surface_offsets(&base, &tris)?
        };
        let dirs = &offsets.dirs;
        let nv = base.len();
        let step = thickness / layers as f64;
        let mut points = Vec::with_capacity(nv * (layers + 1));
        for level in 0..=layers {
            let h = step * level as f64;
            points.extend(
                base.iter()
                    .zip(dirs)
                    .map(|(p, d)| [p[0] + h * d[0], p[1] + h * d[1], p[2] + h * d[2]]),
            );
        }
        let area: f64 = (0..map.len()).map(|s| map.map_det(s)).sum();
        Ok(Slab {
            points,
            nv,
            layers,
            tris,
            coords: map.coords.clone(),
            w_sign: if area < 0.0 { -1.0 } else { 1.0 },
            thickness,
            planar,
            turned: offsets.turned,
            folded: offsets.folded,
        })
    }

    /// Number of prisms.
    pub fn prisms(&self) -> usize {
        self.tris.len() * self.layers
    }

    /// `(triangle, layer)` of a prism.
    pub fn prism_of(&self, prism: usize) -> (usize, usize) {
        (prism % self.tris.len(), prism / self.tris.len())
    }

    /// Point id of compacted vertex `v` at `level`.
    pub fn point(&self, v: u32, level: usize) -> u32 {
        (level * self.nv) as u32 + v
    }

    /// `w` at a level.
    pub fn w(&self, level: usize) -> f64 {
        if self.w_sign > 0.0 {
            level as f64
        } else {
            (self.layers - level) as f64
        }
    }

    /// The 6 point ids of a prism: bottom `[0..3]`, top `[3..6]`, in the
    /// triangle's corner order.
    pub fn prism_points(&self, prism: usize) -> [u32; 6] {
        let (t, l) = self.prism_of(prism);
        let tri = self.tris[t];
        std::array::from_fn(|k| self.point(tri[k % 3], l + k / 3))
    }

    /// Map value of a point of prism `prism` given as (corner, level).
    pub fn corner_map(&self, t: usize, corner: usize, level: usize) -> [f64; 3] {
        let c = self.coords[t][corner];
        [c[0], c[1], self.w(level)]
    }
}

/// Keeps the referenced vertices only (renumbered in first-use order by
/// increasing old id) so that every point of the slab lies on a prism.
fn compact(map: &TriMap) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let mut new_id = vec![u32::MAX; map.positions.len()];
    for t in &map.simplices {
        for &v in t {
            new_id[v as usize] = 0;
        }
    }
    let mut base = Vec::new();
    for (old, id) in new_id.iter_mut().enumerate() {
        if *id == 0 {
            *id = base.len() as u32;
            base.push(map.positions[old]);
        }
    }
    let tris = map
        .simplices
        .iter()
        .map(|t| t.map(|v| new_id[v as usize]))
        .collect();
    (base, tris)
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(a: [f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// Mean length of the triangles' sides (each side once per triangle).
fn mean_edge_length(p: &[[f64; 3]], tris: &[[u32; 3]]) -> f64 {
    let sum: f64 = tris
        .iter()
        .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
        .map(|(a, b)| norm(sub(p[a as usize], p[b as usize])))
        .sum();
    sum / (3 * tris.len()) as f64
}

/// ±z for every vertex of a planar map: the side its triangles face.
fn planar_offsets(p: &[[f64; 3]], tris: &[[u32; 3]]) -> Offsets {
    let z: f64 = tris
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| p[v as usize]);
            cross(sub(b, a), sub(c, a))[2]
        })
        .sum();
    let s = if z < 0.0 { -1.0 } else { 1.0 };
    Offsets {
        dirs: vec![[0.0, 0.0, s]; p.len()],
        ..Default::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two triangles of the unit square, CCW seen from +z.
    pub(crate) fn square(flip: bool, z: f64) -> TriMap {
        let mut m = TriMap {
            positions: vec![
                [0., 0., z],
                [1., 0., z],
                [1., 1., z],
                [0., 1., z],
                [9., 9., 9.],
            ],
            simplices: vec![[0, 1, 2], [0, 2, 3]],
            coords: vec![
                [[0., 0.], [2., 0.], [2., 2.]],
                [[0., 0.], [2., 2.], [0., 2.]],
            ],
        };
        if flip {
            for (t, c) in m.simplices.iter_mut().zip(&mut m.coords) {
                t.swap(1, 2);
                c.swap(1, 2);
            }
        }
        m
    }

    #[test]
    fn planar_slab_levels_and_directions() {
        for flip in [false, true] {
            let s = Slab::new(&square(flip, 0.5), 3, Some(0.6)).expect("valid");
            assert!(s.planar);
            // the unreferenced vertex 4 is dropped
            assert_eq!((s.nv, s.points.len(), s.prisms()), (4, 16, 6));
            let dz = if flip { -0.2 } else { 0.2 };
            for level in 0..=3 {
                let p = s.points[s.point(2, level) as usize];
                assert!((p[2] - (0.5 + dz * level as f64)).abs() < 1e-12, "{p:?}");
            }
            // flipping the corners flips the offset and the map's sign: w
            // runs down, so the prisms' map stays positive
            assert_eq!(s.w_sign, if flip { -1.0 } else { 1.0 });
            let want = if flip {
                [8, 10, 9, 12, 14, 13]
            } else {
                [8, 9, 10, 12, 13, 14]
            };
            assert_eq!(s.prism_points(4), want);
        }
    }

    #[test]
    fn default_thickness_and_reversed_w() {
        let mut m = square(false, 0.0);
        for c in &mut m.coords {
            for x in c.iter_mut() {
                x[0] = -x[0];
            }
        }
        let s = Slab::new(&m, 2, None).expect("valid");
        let mean = (4.0 + 2.0 * 2f64.sqrt()) / 6.0;
        assert!((s.thickness - PLANAR_THICKNESS_FRACTION * mean).abs() < 1e-12);
        assert_eq!((s.w_sign, s.w(0), s.w(2)), (-1.0, 2.0, 0.0));
    }

    #[test]
    fn surface_normals_and_errors() {
        let mut m = square(false, 0.0);
        m.positions[2][2] = 1.0; // a bent square: not planar
        let s = Slab::new(&m, 1, Some(1.0)).expect("valid");
        assert!(!s.planar);
        let d = sub(s.points[s.point(1, 1) as usize], s.points[1]);
        assert!((norm(d) - 1.0).abs() < 1e-12 && d[2] > 0.0);
        assert!(Slab::new(&m, 0, None).is_err());
        assert!(Slab::new(&m, 1, Some(-1.0)).is_err());
    }
}

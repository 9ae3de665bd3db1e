//! 3D maps extruded from 2D ones: a triangle map × `layers` prisms, each
//! prism split into 3 tets, the map `(u, v)` of the triangle's chart and
//! `w` affine in the height.
//!
//! Prism split (conforming between neighbours): with the bottom vertices
//! sorted by index `a < b < c` and `x'` the vertex above `x`, the tets are
//! `a b c c'`, `a b b' c'`, `a a' b' c'`; every side quad is cut by the
//! diagonal from its lower-index bottom vertex to the other's top. Tets are
//! then reordered to positive volume.

use crate::block::ExpectedHex;
use crate::disk::{disk_map, IDENTITY};
use crate::expected::cells_between;
use dualex_map::{TetMap, TriMap};

/// Extrudes `map` (planar positions) into `layers` layers of height
/// `1/layers`, with `w` affine from `w_lo` (bottom) to `w_hi` (top).
pub fn extrude(map: &TriMap, layers: usize, w_lo: f64, w_hi: f64) -> TetMap {
    let layers = layers.max(1);
    let nv = map.positions.len();
    let mut out = TetMap::default();
    for l in 0..=layers {
        let z = l as f64 / layers as f64;
        out.positions
            .extend(map.positions.iter().map(|p| [p[0], p[1], z]));
    }
    let w = |l: usize| w_lo + (w_hi - w_lo) * l as f64 / layers as f64;
    for l in 0..layers {
        for (t, c) in map.simplices.iter().zip(&map.coords) {
            let mut order = [0usize, 1, 2];
            order.sort_by_key(|&i| t[i]);
            let [a, b, c2] = order;
            // (corner of the triangle, layer offset)
            let tets = [
                [(a, 0), (b, 0), (c2, 0), (c2, 1)],
                [(a, 0), (b, 0), (b, 1), (c2, 1)],
                [(a, 0), (a, 1), (b, 1), (c2, 1)],
            ];
            for tet in tets {
                let mut ids = tet.map(|(i, dl)| (t[i] as usize + (l + dl) * nv) as u32);
                let mut coords = tet.map(|(i, dl)| [c[i][0], c[i][1], w(l + dl)]);
                if volume(&out.positions, &ids) < 0.0 {
                    ids.swap(0, 1);
                    coords.swap(0, 1);
                }
                out.simplices.push(ids);
                out.coords.push(coords);
            }
        }
    }
    out
}

/// Six times the signed volume of a tet.
fn volume(p: &[[f64; 3]], t: &[u32; 4]) -> f64 {
    let q = t.map(|v| p[v as usize]);
    let e = |i: usize| [q[i][0] - q[0][0], q[i][1] - q[0][1], q[i][2] - q[0][2]];
    let (a, b, c) = (e(1), e(2), e(3));
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

/// A singular edge: the disk of `singular_disk(index_quarters, false,
/// rings, sectors, scale)` extruded into `layers` layers with `w` from
/// 0.2 to 3.2, so the transitions across the seam are quarter turns about
/// the `w` axis and the centre's vertical edges form one singular edge
/// (valence `4 − k` in the hex mesh). Expected: the disk's quads × 3
/// layers of hexes. `None` as for `singular_disk`.
pub fn wedge_singular_edge(
    index_quarters: i32,
    rings: usize,
    sectors: usize,
    scale: f64,
    layers: usize,
) -> Option<(TetMap, ExpectedHex)> {
    let (_, e) = crate::disk::singular_disk(index_quarters, false, rings, sectors, scale)?;
    let quarters = (4 - index_quarters) as u32;
    let disk = disk_map(quarters, &IDENTITY, rings, sectors, scale, false);
    let map = extrude(&disk, layers, 0.2, 3.2);
    let expected = ExpectedHex {
        hexes: e.quads.map(|q| q * cells_between(0.2, 3.2)),
        boundary_components: Some(1),
        boundary_euler: Some(2),
    };
    Some((map, expected))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::square::square_identity;
    use crate::Diagonal;

    #[test]
    fn extruded_square_is_positive_and_conforming() {
        let (m, _) = square_identity(3, 0.2, 3.2, Diagonal::Alternating);
        let t = extrude(&m, 2, 0.2, 2.2);
        assert!(t.validate().is_ok());
        assert_eq!((t.positions.len(), t.len()), (16 * 3, 18 * 3 * 2));
        assert!((0..t.len()).all(|s| volume(&t.positions, &t.simplices[s]) > 0.0));
        assert!((0..t.len()).all(|s| t.map_det(s) > 0.0));
        // conforming: every triangle face is shared by at most 2 tets, and
        // the boundary faces cover the box: 2·(2·9) + 4·(3·2·2) triangles
        let mut faces = std::collections::HashMap::new();
        for tet in &t.simplices {
            for f in 0..4 {
                let mut k: Vec<u32> = (0..4).filter(|&i| i != f).map(|i| tet[i]).collect();
                k.sort_unstable();
                *faces.entry(k).or_insert(0) += 1;
            }
        }
        assert!(faces.values().all(|&n| n <= 2));
        assert_eq!(faces.values().filter(|&&n| n == 1).count(), 36 + 48);
    }

    #[test]
    fn wedge_has_the_disk_expectation_times_layers() {
        for k in [1, -1] {
            let (m, e) = wedge_singular_edge(k, 6, 16, 3.3, 3).expect("valid");
            assert!(m.validate().is_ok());
            assert!((0..m.len()).all(|s| m.map_det(s) > 0.0));
            let (_, d) = crate::disk::singular_disk(k, false, 6, 16, 3.3).expect("valid");
            assert_eq!(e.hexes, d.quads.map(|q| 3 * q));
            // the seam rotation about w appears in the charts: corners of
            // one vertex differ by a quarter turn that keeps w
            let v = 1u32; // ring 1, θ = 0: on the seam
            let ws: Vec<[f64; 3]> = m
                .simplices
                .iter()
                .zip(&m.coords)
                .flat_map(|(t, c)| t.iter().zip(c).filter(|(x, _)| **x == v).map(|(_, c)| *c))
                .collect();
            assert!(ws.iter().all(|c| c[2] == 0.2));
            assert!(ws.iter().any(|c| c[0] != ws[0][0] || c[1] != ws[0][1]));
            // dualex-map sees one singular edge per layer, exact transitions
            let opts = dualex_map::InspectOptions {
                weld: false,
                ..Default::default()
            };
            let r = dualex_map::inspect(&m, &opts).expect("valid map");
            assert_eq!(r.max_transition_residual, 0.0);
            assert_eq!(r.singular_edges.values().sum::<usize>(), 3, "{r:?}");
        }
    }
}

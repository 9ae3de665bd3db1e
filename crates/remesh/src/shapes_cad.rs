//! CAD-style tessellations: surfaces tessellated the way CAD exports are,
//! the inputs a remesher meets most in engineering and the ones the
//! smooth generators of [`crate::shapes`] do not have.
//!
//! - the side of a cylinder in long strips (one row of needle triangles
//!   from rim to rim by default);
//! - each planar cap a fan of triangles around one centre vertex (a vertex
//!   of valence `sectors`);
//! - the rims sharp (90° on the cylinder), closed feature loops around the
//!   caps.
//!
//! Output: a closed [`Surface`] with outward normals (Euler characteristic
//! 2). Vertex numbering, rings of `sectors` vertices counter-clockwise
//! seen from +z:
//!
//! ```text
//!   cylinder: ring k (z = k·height/rows) = k·sectors .. (k+1)·sectors,
//!             then the bottom centre, then the top centre
//!   cone:     the base ring 0 .. sectors, the base centre, the apex
//! ```

use crate::surface::Surface;
use std::f64::consts::TAU;

/// The ring of `sectors` points of radius `radius` at height `z`.
fn ring(sectors: u32, radius: f64, z: f64) -> impl Iterator<Item = [f64; 3]> {
    (0..sectors).map(move |i| {
        let a = TAU * f64::from(i) / f64::from(sectors);
        [radius * a.cos(), radius * a.sin(), z]
    })
}

/// The fan of a planar cap around `centre` over the ring starting at
/// vertex `first`: facing +z when `up`, else −z.
fn fan(centre: u32, first: u32, sectors: u32, up: bool) -> impl Iterator<Item = [u32; 3]> {
    (0..sectors).map(move |i| {
        let (a, b) = (first + i, first + (i + 1) % sectors);
        if up {
            [centre, a, b]
        } else {
            [centre, b, a]
        }
    })
}

/// A closed cylinder of radius 1 and height `height`: the side in `rows`
/// strips of `2·sectors` triangles, each cap a fan of `sectors` triangles
/// around its centre (`4·sectors` triangles with one row).
pub fn cad_cylinder(sectors: u32, rows: u32, height: f64) -> Surface {
    let mut p: Vec<[f64; 3]> = (0..=rows)
        .flat_map(|k| ring(sectors, 1.0, height * f64::from(k) / f64::from(rows)))
        .collect();
    let mut t = Vec::new();
    for k in 0..rows {
        for i in 0..sectors {
            let j = (i + 1) % sectors;
            let (a, b) = (k * sectors + i, k * sectors + j);
            let (c, d) = (b + sectors, a + sectors);
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    let bottom = p.len() as u32;
    p.push([0.0, 0.0, 0.0]);
    p.push([0.0, 0.0, height]);
    t.extend(fan(bottom, 0, sectors, false));
    t.extend(fan(bottom + 1, rows * sectors, sectors, true));
    Surface::new(p, t).expect("a fan-capped cylinder is a surface")
}

/// A closed cone of base radius 1 and height `height`: the side a fan of
/// `sectors` triangles around the apex, the base a fan around its centre.
pub fn cad_cone(sectors: u32, height: f64) -> Surface {
    let mut p: Vec<[f64; 3]> = ring(sectors, 1.0, 0.0).collect();
    let centre = sectors;
    p.push([0.0, 0.0, 0.0]);
    p.push([0.0, 0.0, height]);
    let mut t: Vec<[u32; 3]> = fan(centre, 0, sectors, false).collect();
    // the apex fan faces outward (and up): counter-clockwise from outside
    t.extend(fan(centre + 1, 0, sectors, true).map(|[c, a, b]| [a, b, c]));
    Surface::new(p, t).expect("a fan-capped cone is a surface")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact counts: vertices, triangles, closed (χ = 2), every edge with
    /// two faces, the fan centres of valence `sectors`, outward normals.
    #[test]
    fn counts_valences_and_orientation() {
        for (s, n, tris, centres) in [
            (cad_cylinder(24, 1, 2.0), 2 * 24 + 2, 4 * 24, [48u32, 49]),
            (
                cad_cylinder(16, 3, 1.0),
                4 * 16 + 2,
                2 * 3 * 16 + 2 * 16,
                [64, 65],
            ),
            (cad_cone(24, 1.5), 24 + 2, 2 * 24, [24, 25]),
        ] {
            assert_eq!(s.positions.len(), n);
            assert_eq!(s.triangles.len(), tris);
            assert_eq!(s.euler_characteristic(), 2);
            assert!(s.boundary_vertex.iter().all(|&b| !b), "closed");
            for c in centres {
                let valence = s.triangles.iter().filter(|t| t.contains(&c)).count();
                assert_eq!(valence as u32, if n == 66 { 16 } else { 24 });
            }
            let vol = crate::shapes::signed_volume(&s);
            assert!(vol > 0.0, "volume {vol}: normals point inward");
        }
    }
}

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

/// The top (`up`) or bottom face of a square cell around a round hole,
/// as CAD exports it: each corner a fan to its quarter of the hole's
/// `4·m` vertices (from `first`, counter-clockwise from angle 0), one
/// triangle between two corners. `corners` are at 45°, 135°, 225°, 315°
/// from the hole's centre.
fn cell_around_hole(corners: [u32; 4], first: u32, m: u32, up: bool) -> Vec<[u32; 3]> {
    let hole = |j: u32| first + j % (4 * m);
    let mut t = Vec::new();
    for k in 0..4 {
        let c = corners[k as usize];
        for j in k * m..(k + 1) * m {
            t.push([c, hole(j + 1), hole(j)]);
        }
        t.push([c, corners[((k + 1) % 4) as usize], hole((k + 1) * m)]);
    }
    if !up {
        for tri in &mut t {
            tri.swap(1, 2);
        }
    }
    t
}

/// The side between two loops of equal length (`lower[i]` under
/// `upper[i]`), counter-clockwise seen from +z: two triangles per
/// segment, facing away from the loops' inside (`outward`) or into it (a
/// hole's wall).
fn wall(lower: &[u32], upper: &[u32], outward: bool) -> Vec<[u32; 3]> {
    let n = lower.len();
    let mut t = Vec::with_capacity(2 * n);
    for i in 0..n {
        let j = (i + 1) % n;
        let (a, b, c, d) = (lower[i], lower[j], upper[j], upper[i]);
        if outward {
            t.push([a, b, c]);
            t.push([a, c, d]);
        } else {
            t.push([a, c, b]);
            t.push([a, d, c]);
        }
    }
    t
}

/// A plate `2·holes × 2 × thickness` with `holes` round through-holes of
/// radius 0.5 in a row, as CAD exports it: each face around a hole a set
/// of corner fans ([`cell_around_hole`], `4·m` vertices per hole rim),
/// the hole walls and the outer walls one strip (genus `holes`).
pub fn cad_plate_with_holes(holes: u32, m: u32, thickness: f64) -> Surface {
    let n = 4 * m;
    let mut p: Vec<[f64; 3]> = Vec::new();
    // corners: level z (0 bottom, 1 top), column i, row y ∈ {-1, 1}
    let corner = |z: u32, i: u32, y: u32| z * 2 * (holes + 1) + 2 * i + y;
    for z in [0.0, thickness] {
        for i in 0..=holes {
            for y in [-1.0, 1.0] {
                p.push([2.0 * f64::from(i), y, z]);
            }
        }
    }
    let mut t = Vec::new();
    for h in 0..holes {
        let cx = 2.0 * f64::from(h) + 1.0;
        let rims: Vec<u32> = [0.0, thickness]
            .into_iter()
            .map(|z| {
                let first = p.len() as u32;
                p.extend(ring(n, 0.5, z).map(|[x, y, z]| [x + cx, y, z]));
                first
            })
            .collect();
        for (z, &first) in rims.iter().enumerate() {
            let z = z as u32;
            let c = [
                corner(z, h + 1, 1),
                corner(z, h, 1),
                corner(z, h, 0),
                corner(z, h + 1, 0),
            ];
            t.extend(cell_around_hole(c, first, m, z == 1));
        }
        let rim = |first: u32| (0..n).map(|j| first + j).collect::<Vec<_>>();
        t.extend(wall(&rim(rims[0]), &rim(rims[1]), false));
    }
    // the outer loop, counter-clockwise from +z
    let outer = |z: u32| -> Vec<u32> {
        let front = (0..=holes).map(|i| corner(z, i, 0));
        let back = (0..=holes).rev().map(|i| corner(z, i, 1));
        front.chain(back).collect()
    };
    t.extend(wall(&outer(0), &outer(1), true));
    Surface::new(p, t).expect("a CAD plate with holes is a surface")
}

/// A box `2 × 2 × 1` with a round boss of radius 0.5 and height `boss` on
/// its top, as CAD exports it: the box's five other faces two triangles
/// each, its top corner fans around the boss's foot ([`cell_around_hole`],
/// `4·m` vertices), the boss's wall one strip, its top a fan.
pub fn cad_box_with_boss(m: u32, boss: f64) -> Surface {
    let n = 4 * m;
    let mut p: Vec<[f64; 3]> = Vec::new();
    for z in [0.0, 1.0] {
        for [x, y] in [[1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]] {
            p.push([x, y, z]);
        }
    }
    let (foot, top) = (8, 8 + n);
    p.extend(ring(n, 0.5, 1.0));
    p.extend(ring(n, 0.5, 1.0 + boss));
    let centre = p.len() as u32;
    p.push([0.0, 0.0, 1.0 + boss]);
    let mut t = vec![[0, 2, 1], [0, 3, 2]]; // the bottom, facing −z
    t.extend(cell_around_hole([4, 5, 6, 7], foot, m, true));
    // the box's sides: loop counter-clockwise from +z (corners 2, 3, 0, 1)
    t.extend(wall(&[2, 3, 0, 1], &[6, 7, 4, 5], true));
    let rim = |first: u32| (0..n).map(|j| first + j).collect::<Vec<_>>();
    t.extend(wall(&rim(foot), &rim(top), true));
    t.extend(fan(centre, top, n, true));
    Surface::new(p, t).expect("a CAD box with a boss is a surface")
}

/// A slab `2a × 2b × thickness` whose four vertical edges are filleted
/// with radius `radius` (`segments` strips each, tangent to the flat
/// sides: not sharp), as CAD exports it: the side one strip of long
/// triangles, each cap a fan around its centre.
pub fn cad_filleted_slab(a: f64, b: f64, radius: f64, segments: u32, thickness: f64) -> Surface {
    let mut outline = Vec::new();
    for (k, [cx, cy]) in [[a, b], [-a, b], [-a, -b], [a, -b]].into_iter().enumerate() {
        let (cx, cy) = (cx - radius * cx.signum(), cy - radius * cy.signum());
        for i in 0..=segments {
            let phi = TAU / 4.0 * (k as f64 + f64::from(i) / f64::from(segments));
            outline.push([cx + radius * phi.cos(), cy + radius * phi.sin()]);
        }
    }
    let n = outline.len() as u32;
    let mut p: Vec<[f64; 3]> = [0.0, thickness]
        .into_iter()
        .flat_map(|z| outline.iter().map(move |&[x, y]| [x, y, z]))
        .collect();
    let centre = p.len() as u32;
    p.push([0.0, 0.0, 0.0]);
    p.push([0.0, 0.0, thickness]);
    let rim = |first: u32| (0..n).map(|j| first + j).collect::<Vec<_>>();
    let mut t = wall(&rim(0), &rim(n), true);
    t.extend(fan(centre, 0, n, false));
    t.extend(fan(centre + 1, n, n, true));
    Surface::new(p, t).expect("a CAD filleted slab is a surface")
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

    /// The plate, the box with a boss and the filleted slab: exact
    /// counts, closed, χ = 2 − 2·genus, outward normals, the volume.
    #[test]
    fn plate_box_and_slab() {
        let pi = std::f64::consts::PI;
        let slab_volume = (4.0 * 3.0 - (4.0 - pi) * 0.25) * 0.5;
        let hole_plate = (6.0 * 2.0 - 3.0 * pi * 0.25) * 0.5;
        let boss_box = 4.0 + pi * 0.25 * 0.5;
        for (s, vertices, triangles, chi, volume) in [
            // 3 holes of 8 rim vertices: corners 2·8, rims 2·3·8
            (
                cad_plate_with_holes(3, 2, 0.5),
                16 + 48,
                3 * (2 * 12 + 16) + 16,
                -4,
                hole_plate,
            ),
            // 8 corners, two rims of 12, the boss's centre
            (
                cad_box_with_boss(3, 0.5),
                8 + 24 + 1,
                2 + 16 + 8 + 24 + 12,
                2,
                boss_box,
            ),
            // 4 fillets of 3 segments: 16 outline vertices
            (
                cad_filleted_slab(2.0, 1.5, 0.5, 3, 0.5),
                32 + 2,
                32 + 32,
                2,
                slab_volume,
            ),
        ] {
            assert_eq!(s.positions.len(), vertices);
            assert_eq!(s.triangles.len(), triangles);
            assert_eq!(s.euler_characteristic(), chi);
            assert!(s.boundary_vertex.iter().all(|&b| !b), "closed");
            let vol = crate::shapes::signed_volume(&s);
            assert!(vol > 0.0, "volume {vol}: normals point inward");
            // the holes and the boss are polygons: within 5 % of the round
            assert!(
                (vol - volume).abs() < 0.05 * volume,
                "volume {vol} for {volume}"
            );
        }
    }
}

//! Tests of the reference: the curves, corners and closest points of a
//! unit square and of the unit cube's boundary (outward normals, the
//! thin-part hint and its reach, seeded searches).

use super::*;

/// The unit square [0,1]² as 2 triangles, and a unit cube of 6 tets.
#[test]
fn square_curves_corners_and_closest_points() {
    let p = [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]];
    let r = Reference::surface(&p, &[[0, 1, 2], [0, 2, 3]], 35.0);
    assert_eq!(r.segments.len(), 4);
    assert!(r.segments.iter().all(|s| s.boundary));
    assert_eq!(r.corner, vec![true; 4]);
    let f = r.closest([0.3, 0.6, 2.0], Some([0., 0., 1.])).unwrap();
    assert!((f.distance - 2.0).abs() < 1e-12);
    assert!((0..3).all(|k| (f.point[k] - [0.3, 0.6, 0.0][k]).abs() < 1e-12));
    let (_, q, d) = r.closest_on_curves([0.5, 0.2, 0.0], true).unwrap();
    assert_eq!(q, [0.5, 0.0, 0.0]);
    assert!((d - 0.2).abs() < 1e-15);
    // outside the square: the nearest point on its border
    let f = r.closest([2.0, 0.5, 0.0], None).unwrap();
    assert!((f.point[0] - 1.0).abs() < 1e-15 && (f.point[1] - 0.5).abs() < 1e-15);
}

#[test]
fn cube_boundary_has_12_feature_edges() {
    let r = crate::tests::unit_cube_surface(35.0);
    assert_eq!(r.triangles.len(), 12);
    assert_eq!(r.segments.len(), 12);
    assert!(r.segments.iter().all(|s| !s.boundary));
    assert_eq!(r.corner, vec![true; 8]);
    // outward normals: the face z = 1 points up
    let f = r.closest([0.5, 0.5, 1.5], Some([0., 0., 1.])).unwrap();
    assert!(r.normals[f.triangle as usize][2] > 0.99);
    // a thin-part hint: from inside near the top, asking for a face
    // that looks down finds the bottom (within HINT_REACH times the
    // distance to the top)
    let f = r.closest([0.5, 0.5, 0.9], Some([0., 0., -1.])).unwrap();
    assert!(f.point[2].abs() < 1e-15);
    // beyond that reach, the nearest face, whatever it looks at
    let f = r.closest([0.5, 0.5, 0.99], Some([0., 0., -1.])).unwrap();
    assert!((f.point[2] - 1.0).abs() < 1e-15);
    // a seeded search gives the same answers
    for t in 0..12 {
        let g = r
            .closest_seeded([0.5, 0.5, 0.9], Some([0., 0., -1.]), Some(t))
            .unwrap();
        assert_eq!(
            g.triangle,
            r.closest([0.5, 0.5, 0.9], Some([0., 0., -1.]))
                .unwrap()
                .triangle
        );
    }
}

/// The corners' former form: a list of curve neighbours per vertex.
fn corners_by_lists(positions: &[[f64; 3]], segments: &[Segment], cos: f64) -> Vec<bool> {
    let mut around: Vec<Vec<u32>> = vec![Vec::new(); positions.len()];
    for s in segments {
        around[s.ends[0] as usize].push(s.ends[1]);
        around[s.ends[1] as usize].push(s.ends[0]);
    }
    around
        .iter()
        .enumerate()
        .map(|(v, n)| match n.len() {
            0 | 1 => false,
            2 => {
                let p = positions[v];
                let a = sub(p, positions[n[0] as usize]);
                let b = sub(positions[n[1] as usize], p);
                let l = norm(a) * norm(b);
                l > 0.0 && dot(a, b) < cos * l
            }
            _ => true,
        })
        .collect()
}

/// Corners from the sorted segment ends as from per-vertex lists: random
/// curves over few vertices (many of degree 0 to 4), points on a coarse
/// grid (repeated positions, straight and turning pairs), any threshold.
#[test]
fn corners_as_by_lists() {
    let mut rng = dualex_util::rng::SplitMix::new(25);
    for round in 0..400 {
        let n = 2 + rng.below(40);
        let positions: Vec<[f64; 3]> = (0..n)
            .map(|_| [0; 3].map(|_| (rng.below(3) as f64) - 1.0))
            .collect();
        let mut ends: Vec<[u32; 2]> = (0..rng.below(3 * n))
            .filter_map(|_| {
                let (a, b) = (rng.below(n) as u32, rng.below(n) as u32);
                (a != b).then_some([a.min(b), a.max(b)])
            })
            .collect();
        ends.sort_unstable();
        ends.dedup();
        if round % 2 == 1 {
            rng.shuffle(&mut ends);
        }
        let segments: Vec<Segment> = ends
            .into_iter()
            .map(|ends| Segment {
                ends,
                boundary: rng.below(2) == 0,
                arc: u32::MAX,
            })
            .collect();
        let cos = [1.0, 0.9, 0.0, -0.5, -1.0][rng.below(5)];
        assert_eq!(
            super::curves::corners(&positions, &segments, cos),
            corners_by_lists(&positions, &segments, cos),
            "round {round}"
        );
    }
}

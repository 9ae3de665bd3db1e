//! End-to-end tests of the quad pipeline on small maps built here.
use super::*;

/// res×res cells on [0,1]², map affine onto [lo,hi]², alternating diagonals.
fn square(res: usize, lo: f64, hi: f64) -> TriMap {
    let mut m = TriMap::default();
    let id = |i: usize, j: usize| (j * (res + 1) + i) as u32;
    for j in 0..=res {
        for i in 0..=res {
            m.positions
                .push([i as f64 / res as f64, j as f64 / res as f64, 0.0]);
        }
    }
    let uv = |v: u32| {
        let p = [
            (v as usize % (res + 1)) as f64 / res as f64,
            (v as usize / (res + 1)) as f64 / res as f64,
        ];
        [lo + (hi - lo) * p[0], lo + (hi - lo) * p[1]]
    };
    for j in 0..res {
        for i in 0..res {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            let tris = if (i + j) % 2 == 0 {
                [[a, b, c], [a, c, d]]
            } else {
                [[a, b, d], [b, c, d]]
            };
            for t in tris {
                m.simplices.push(t);
                m.coords.push(t.map(uv));
            }
        }
    }
    m
}

#[test]
fn square_free_boundary_gives_7x7() {
    let m = square(10, 0.2, 7.2);
    let (mesh, st) = extract(&m, &QuadOptions::default()).expect("extract");
    assert_eq!(mesh.cells.len(), 49, "{}", st.to_json());
    assert_eq!(st.boundary_loops, 1);
    assert_eq!(st.components, 1);
    assert_eq!(st.valence_interior.get(&4), Some(&36));
    assert_eq!(st.euler, 1);
}

#[test]
fn square_exact_grid_points_is_sanitized() {
    // every vertex on a half-integer: all on dual isos before sanitization
    let m = square(8, -0.5, 7.5);
    let (mesh, st) = extract(&m, &QuadOptions::default()).expect("extract");
    assert!(st.sanitize.perturbed_vertices > 0);
    assert_eq!(mesh.cells.len(), 64, "{}", st.to_json());
}

#[test]
fn square_far_from_origin() {
    for off in [1e6, (1u64 << 40) as f64] {
        let m = square(10, off + 0.2, off + 7.2);
        let (mesh, st) = extract(&m, &QuadOptions::default()).expect("extract");
        assert_eq!(mesh.cells.len(), 49, "offset {off}: {}", st.to_json());
    }
}

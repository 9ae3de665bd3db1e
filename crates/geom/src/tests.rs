//! Tests of the stage on tangled meshes made here: planar and curved quad
//! grids, hex grids; untangled, boundary vertices put on the boundary,
//! untouched when clean, smoothed.

use crate::quality::norm;
use crate::{hexes, quads, Mode, Options};

/// A small deterministic generator in [-1, 1).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
}

/// Positions, cells of `K` corners, and simplices of `S` corners.
type Grid<const K: usize, const S: usize> = (Vec<[f64; 3]>, Vec<[u32; K]>, Vec<[u32; S]>);

/// An n×n quad grid on [0, n]², and its triangles (2 per quad, quad q's
/// first is 2q).
fn quad_grid(n: usize) -> Grid<4, 3> {
    let id = |i: usize, j: usize| (j * (n + 1) + i) as u32;
    let mut p = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            p.push([i as f64, j as f64, 0.0]);
        }
    }
    let (q, t) = quads_of(n, id);
    (p, q, t)
}

/// The n×n quads of a grid whose vertex `(i, j)` is `id(i, j)`, and
/// their two triangles each.
fn quads_of(n: usize, id: impl Fn(usize, usize) -> u32) -> (Vec<[u32; 4]>, Vec<[u32; 3]>) {
    let (mut q, mut t) = (Vec::new(), Vec::new());
    for j in 0..n {
        for i in 0..n {
            let c = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            q.push(c);
            t.push([c[0], c[1], c[2]]);
            t.push([c[0], c[2], c[3]]);
        }
    }
    (q, t)
}

/// The unit cube's surface (the boundary of its 6 Kuhn tets, as the
/// generator's one-cell block: 12 triangles, 12 feature edges), edges of
/// more than `feature_deg` being features.
pub(crate) fn unit_cube_surface(feature_deg: f64) -> crate::Reference {
    let (cube, _) = dualex_gen::block::block(1, 1, 1, 0.0, 1.0);
    crate::Reference::volume_boundary(&cube.positions, &cube.simplices, feature_deg)
}

/// An n³ hex grid on [0, n]³ and its 6 tets per hex.
fn hex_grid(n: usize) -> Grid<8, 4> {
    let id = |i: usize, j: usize, k: usize| ((k * (n + 1) + j) * (n + 1) + i) as u32;
    let mut p = Vec::new();
    for k in 0..=n {
        for j in 0..=n {
            for i in 0..=n {
                p.push([i as f64, j as f64, k as f64]);
            }
        }
    }
    let (mut h, mut t) = (Vec::new(), Vec::new());
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                let c = [
                    id(i, j, k),
                    id(i + 1, j, k),
                    id(i + 1, j + 1, k),
                    id(i, j + 1, k),
                    id(i, j, k + 1),
                    id(i + 1, j, k + 1),
                    id(i + 1, j + 1, k + 1),
                    id(i, j + 1, k + 1),
                ];
                h.push(c);
                for [a, b] in [[1, 2], [2, 3], [3, 7], [7, 4], [4, 5], [5, 1]] {
                    let s = [c[0], c[a], c[b], c[6]];
                    t.push(s);
                }
            }
        }
    }
    (p, h, t)
}

fn boundary_2d(p: [f64; 3], n: f64) -> bool {
    p[0] == 0.0 || p[1] == 0.0 || p[0] == n || p[1] == n
}

#[test]
fn tangled_planar_grid_is_untangled_in_the_plane() {
    let n = 8;
    let (p, q, t) = quad_grid(n);
    let mut x = p.clone();
    let mut rng = Rng(3);
    for v in x.iter_mut() {
        if !boundary_2d(*v, n as f64) {
            v[0] += 0.9 * rng.next();
            v[1] += 0.9 * rng.next();
        }
    }
    let sources: Vec<u32> = (0..q.len() as u32).map(|i| 2 * i).collect();
    let r = quads(&mut x, &q, &p, &t, &sources, false, &Options::default());
    assert!(
        r.before.inverted > 3,
        "the test must tangle: {:?}",
        r.before
    );
    assert_eq!(r.after.inverted, 0, "{r:?}");
    assert!(r.moved());
    for (a, b) in x.iter().zip(&p) {
        assert_eq!(a[2], 0.0, "left the plane");
        if boundary_2d(*b, n as f64) {
            // boundary vertices stay on the boundary (corners in place)
            assert!(
                boundary_2d(*a, n as f64) || (a[0] - b[0]).abs() < 1e-9,
                "{a:?} from {b:?}"
            );
        }
    }
}

#[test]
fn clean_meshes_are_left_bit_for_bit() {
    let (p, q, t) = quad_grid(4);
    let mut x = p.clone();
    let sources: Vec<u32> = (0..q.len() as u32).map(|i| 2 * i).collect();
    let r = quads(&mut x, &q, &p, &t, &sources, false, &Options::default());
    assert_eq!(
        (r.moved_vertices, r.before.inverted, r.boundary_off),
        (0, 0, 0)
    );
    assert_eq!(x, p);
    let (p, h, t) = hex_grid(3);
    let mut x = p.clone();
    let lone = dualex_check::topology::lone_tet_faces(&t);
    let r = hexes(&mut x, &h, &p, &t, &lone, &Options::default());
    assert_eq!(
        (r.moved_vertices, r.before.inverted, r.boundary_off),
        (0, 0, 0)
    );
    assert!((r.before.min - 1.0).abs() < 1e-12);
    assert_eq!(x, p);
}

#[test]
fn boundary_vertices_go_onto_the_boundary_without_inverting() {
    let n = 6;
    let (p, q, t) = quad_grid(n);
    let mut x = p.clone();
    let mut rng = Rng(11);
    // boundary vertices pulled inwards by up to 0.6 of an edge (as a
    // free-boundary map leaves them), corners kept
    for v in x.iter_mut() {
        let corner = (v[0] == 0.0 || v[0] == n as f64) && (v[1] == 0.0 || v[1] == n as f64);
        if boundary_2d(*v, n as f64) && !corner {
            let inward = [
                (n as f64 / 2.0 - v[0]).signum(),
                (n as f64 / 2.0 - v[1]).signum(),
            ];
            let a = 0.6 * (rng.next() + 1.0) / 2.0;
            if v[0] == 0.0 || v[0] == n as f64 {
                v[0] += a * inward[0];
            } else {
                v[1] += a * inward[1];
            }
            v[0] += 0.2 * rng.next();
        }
    }
    let sources: Vec<u32> = (0..q.len() as u32).map(|i| 2 * i).collect();
    let r = quads(&mut x, &q, &p, &t, &sources, false, &Options::default());
    assert!(r.boundary_off > 10, "{r:?}");
    assert!(
        r.boundary_distance[0] > 0.1 && r.boundary_distance[1] <= 1e-9 * 8.5,
        "{r:?}"
    );
    assert_eq!(r.after.inverted, 0, "{r:?}");
    for (a, b) in x.iter().zip(&p) {
        if boundary_2d(*b, n as f64) {
            assert!(boundary_2d(*a, n as f64), "{a:?} off the boundary");
        }
    }
}

#[test]
fn tangled_hex_grid_is_untangled_with_its_boundary_on_the_cube() {
    let n = 5;
    let (p, h, t) = hex_grid(n);
    let mut x = p.clone();
    let mut rng = Rng(5);
    let on = |v: [f64; 3]| v.iter().any(|&c| c == 0.0 || c == n as f64);
    for v in x.iter_mut() {
        if !on(*v) {
            for c in v.iter_mut() {
                *c += 0.8 * rng.next();
            }
        }
    }
    let lone = dualex_check::topology::lone_tet_faces(&t);
    let r = hexes(&mut x, &h, &p, &t, &lone, &Options::default());
    assert!(r.before.inverted > 10, "{:?}", r.before);
    assert_eq!(r.after.inverted, 0, "{r:?}");
    for (a, b) in x.iter().zip(&p) {
        if on(*b) {
            // on the cube's boundary still (boundary vertices are on it)
            assert!(
                a.iter()
                    .any(|&c| c.abs() < 1e-9 || (c - n as f64).abs() < 1e-9),
                "{a:?}"
            );
        }
    }
}

#[test]
fn curved_surface_untangled_on_the_surface() {
    // a cylinder of radius 3 (open at both ends): a 24 × 6 quad grid
    // wrapped around, tangled by moves along the surface
    let (m, rows) = (24usize, 6usize);
    let id = |i: usize, j: usize| (j * m + i % m) as u32;
    let mut p = Vec::new();
    for j in 0..=rows {
        for i in 0..m {
            let a = std::f64::consts::TAU * i as f64 / m as f64;
            p.push([3.0 * a.cos(), 3.0 * a.sin(), j as f64 * 0.8]);
        }
    }
    let mut q = Vec::new();
    let mut t = Vec::new();
    for j in 0..rows {
        for i in 0..m {
            let c = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
            q.push(c);
            t.push([c[0], c[1], c[2]]);
            t.push([c[0], c[2], c[3]]);
        }
    }
    let mut x = p.clone();
    let mut rng = Rng(9);
    for (v, pv) in x.iter_mut().zip(&p) {
        if pv[2] > 0.0 && pv[2] < rows as f64 * 0.8 - 1e-9 {
            let a = pv[1].atan2(pv[0]) + 0.7 * 0.26 * rng.next();
            *v = [3.0 * a.cos(), 3.0 * a.sin(), pv[2] + 0.7 * 0.8 * rng.next()];
        }
    }
    let sources: Vec<u32> = (0..q.len() as u32).map(|i| 2 * i).collect();
    let r = quads(&mut x, &q, &p, &t, &sources, false, &Options::default());
    assert!(r.before.inverted > 3, "{:?}", r.before);
    assert_eq!(r.after.inverted, 0, "{r:?}");
    // on the polygonal cylinder: radius between the inscribed one and 3
    let inner = 3.0 * (std::f64::consts::PI / m as f64).cos();
    for v in &x {
        let rad = norm([v[0], v[1], 0.0]);
        assert!(
            rad <= 3.0 + 1e-9 && rad >= inner - 1e-9,
            "{v:?} off the surface"
        );
    }
}

#[test]
fn smoothing_raises_the_5th_percentile_and_keeps_the_boundary() {
    let n = 8;
    let (p, q, t) = quad_grid(n);
    let mut x = p.clone();
    let mut rng = Rng(21);
    for v in x.iter_mut() {
        if !boundary_2d(*v, n as f64) {
            v[0] += 0.35 * rng.next();
            v[1] += 0.35 * rng.next();
        }
    }
    let sources: Vec<u32> = (0..q.len() as u32).map(|i| 2 * i).collect();
    let o = Options {
        mode: Mode::Smooth(10),
        ..Options::default()
    };
    let r = quads(&mut x, &q, &p, &t, &sources, false, &o);
    assert_eq!(r.after.inverted, 0);
    assert!(r.after.p5 > r.before.p5 + 0.1 && r.after.p5 > 0.9, "{r:?}");
    let o = Options {
        mode: Mode::Off,
        ..Options::default()
    };
    let mut y = p.clone();
    y[10][0] += 2.0;
    let r = quads(&mut y, &q, &p, &t, &sources, false, &o);
    assert!(r.before.inverted > 0 && r.after.inverted == r.before.inverted && !r.moved());
}

/// A boundary vertex the map put past a corner of the input (on the
/// other side's edge) goes back to its own side: it is bound to the arc
/// between the corners of the mesh around it, not to the nearest curve.
#[test]
fn a_boundary_vertex_past_a_corner_goes_back_to_its_arc() {
    let n = 4;
    let (p, q, t) = quad_grid(n);
    let mut x = p.clone();
    // vertex (1, 0), on the bottom edge, put on the left edge past the
    // corner (0, 0): the corner quad is flat
    x[1] = [0.0, 0.3, 0.0];
    let sources: Vec<u32> = (0..q.len() as u32).map(|i| 2 * i).collect();
    let r = quads(&mut x, &q, &p, &t, &sources, false, &Options::default());
    assert!(r.before.inverted > 0, "{r:?}");
    assert_eq!(r.after.inverted, 0, "{r:?}");
    assert_eq!(x[0], [0.0, 0.0, 0.0], "the mesh corner stays on the corner");
    assert!(x[1][1].abs() <= 1e-9 && x[1][0] > 0.0, "{:?}", x[1]);
}

/// A closed n×n quad torus (a grid whose last row and column wrap) and
/// its two triangles per quad.
fn quad_torus(n: usize) -> Grid<4, 3> {
    let id = |i: usize, j: usize| ((j % n) * n + i % n) as u32;
    let mut p = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (u, v) = (i as f64 / n as f64, j as f64 / n as f64);
            let (cu, su) = (std::f64::consts::TAU * u).sin_cos();
            let (cv, sv) = (std::f64::consts::TAU * v).sin_cos();
            let r = 3.0 + cv;
            p.push([r * cu, r * su, sv]);
        }
    }
    let (q, t) = quads_of(n, id);
    (p, q, t)
}

#[test]
fn a_closed_mesh_said_closed_is_staged_as_found_closed() {
    let (p, q, t) = quad_torus(12);
    let sources: Vec<u32> = (0..q.len() as u32).map(|i| 2 * i).collect();
    let mut rng = Rng(5);
    // clean, then tangled (the optimisation runs)
    for jitter in [0.0, 0.4] {
        let mut x = p.clone();
        for v in x.iter_mut() {
            for c in v.iter_mut() {
                *c += jitter * rng.next();
            }
        }
        let mut y = x.clone();
        let o = Options::default();
        let mut a = quads(&mut x, &q, &p, &t, &sources, false, &o);
        let mut b = quads(&mut y, &q, &p, &t, &sources, true, &o);
        (a.time_ms, b.time_ms) = (0.0, 0.0);
        assert_eq!(format!("{a:?}"), format!("{b:?}"), "jitter {jitter}");
        assert_eq!(x, y, "jitter {jitter}");
        assert_eq!(a.boundary_vertices, 0);
        if jitter > 0.0 {
            assert!(a.before.inverted > 0, "the test must tangle: {a:?}");
        }
    }
}

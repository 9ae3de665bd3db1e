//! The facade end to end on small maps built from slices: welding by
//! default, the counts, errors, files.

use crate::*;

/// An `n × n` grid of unit squares (two triangles each) with the identity
/// map scaled by `k`, cut along `x = n/2` when `cut`: the seam's vertices
/// are duplicated, as in a cut-mesh file.
fn square(n: u32, k: f64, cut: bool) -> TriMap {
    let half = n / 2;
    let mut positions = Vec::new();
    let mut id = std::collections::HashMap::new();
    let mut vertex = |i: u32, j: u32, side: u32| {
        let key = if cut && i == half {
            (i, j, side)
        } else {
            (i, j, 0)
        };
        *id.entry(key).or_insert_with(|| {
            positions.push([i as f64, j as f64, 0.0]);
            positions.len() as u32 - 1
        })
    };
    let mut triangles = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let side = u32::from(i >= half);
            let v =
                [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)].map(|(a, b)| vertex(a, b, side));
            triangles.push([v[0], v[1], v[2]]);
            triangles.push([v[0], v[2], v[3]]);
        }
    }
    let uv: Vec<[[f64; 2]; 3]> = triangles
        .iter()
        .map(|t| {
            t.map(|v| {
                let p = positions[v as usize];
                [k * p[0], k * p[1]]
            })
        })
        .collect();
    tri_map_from_slices(&positions, &triangles, &uv).expect("valid map")
}

#[test]
fn cut_meshes_are_welded_by_default() {
    let map = square(4, 1.0, true);
    let out = quad(&map, &Options::default()).unwrap();
    assert_eq!(out.stats.welded_vertices, 5);
    assert_eq!(out.stats.cells, 16);
    assert_eq!(out.stats.components, 1);
    assert!(out.stats.topology.matches());
    let apart = Options {
        weld: false,
        ..Default::default()
    };
    let out = quad(&map, &apart).unwrap();
    assert_eq!(out.stats.welded_vertices, 0);
    assert_eq!(out.stats.components, 2);
    assert_eq!(out.stats.topology.input.components, 2);
}

#[test]
fn counts_are_the_meshes() {
    let out = quad(&square(2, 2.0, false), &Options::default()).unwrap();
    let s = &out.stats;
    assert_eq!(
        (s.cells, s.vertices, s.euler, s.boundary_components),
        (16, 25, 1, 1)
    );
    assert_eq!(s.cells, out.mesh.cells.len());
    assert_eq!(s.vertices, out.mesh.positions.len());
    assert_eq!(s.valence_interior.get(&4), Some(&9));
    assert_eq!(s.input_simplices, 8);
    assert_eq!(s.grid_offset, GridOffset::Half);
}

#[test]
fn bad_maps_are_errors_not_panics() {
    // all corners of one triangle on the same map point: no node
    let p = [[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let flat = [[[0.5, 0.5]; 3]];
    let map = tri_map_from_slices(&p, &[[0, 1, 2]], &flat).unwrap();
    let r = quad(&map, &Options::default());
    if let Ok(out) = &r {
        assert!(out.mesh.cells.is_empty());
    }
    let e = read_tri_map("no/such/map.obj").unwrap_err();
    assert!(matches!(e, Error::Input(_)));
    assert!(
        e.to_string().starts_with("no/such/map.obj: cannot read"),
        "{e}"
    );
}

#[test]
fn meshes_are_written_and_read_back() {
    let dir = std::env::temp_dir().join(format!("dualex-facade-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = quad(&square(2, 1.0, false), &Options::default()).unwrap();
    let p = dir.join("q.obj");
    let written = write_quad_mesh(&p, &out.mesh);
    let back = dualex_io::read_polygon_mesh(&p);
    let bad = write_quad_mesh(dir.join("q.stl"), &out.mesh);
    let uv = dir.join("uv.obj");
    let written_uv = write_quad_mesh_uv(&uv, &out.mesh, &out.corners);
    let back_uv = dualex_io::read_polygon_mesh(&uv);
    let text_uv = std::fs::read_to_string(&uv).unwrap_or_default();
    let bad_uv = write_quad_mesh_uv(dir.join("q.vtk"), &out.mesh, &out.corners);
    let _ = std::fs::remove_dir_all(&dir);
    written.unwrap();
    assert_eq!(back.unwrap().faces.len(), 4);
    assert!(matches!(bad, Err(Error::Output(_))));
    written_uv.unwrap();
    assert_eq!(back_uv.unwrap().faces.len(), 4);
    assert_eq!(text_uv.lines().filter(|l| l.starts_with("vt ")).count(), 16);
    assert!(matches!(bad_uv, Err(Error::Output(_))));
}

/// Whether `p` lies in triangle `t` of a flat map (z = 0), with a margin
/// (nodes on an edge are moved off it by a tiny perturbation).
fn in_triangle(map: &TriMap, t: u32, p: [f64; 2]) -> bool {
    let c = map.simplices[t as usize].map(|v| map.positions[v as usize]);
    (0..3).all(|i| {
        let (a, b) = (c[i], c[(i + 1) % 3]);
        (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= -1e-4
    })
}

/// Every cell of `out` has its corners' map coordinates, exact integers,
/// `scale` × its vertices' positions (an identity map scaled).
fn assert_corners_scale<const K: usize, const D: usize>(out: &Output<K, D>, scale: f64) {
    for (cell, corners) in out.mesh.cells.iter().zip(&out.corners) {
        let corners = corners.expect("corners");
        for (&v, t) in cell.iter().zip(corners) {
            let p = out.mesh.positions[v as usize];
            assert!(t.iter().all(|x| x.fract() == 0.0), "{t:?}");
            assert!(
                (0..D).all(|k| (t[k] - scale * p[k]).abs() < 1e-4),
                "{t:?} at {p:?}"
            );
        }
    }
}

#[test]
fn each_quad_names_the_triangle_holding_its_node() {
    // identity map scaled by 3: the node of a quad is its centre
    for cut in [false, true] {
        let map = square(4, 3.0, cut);
        let out = quad(&map, &Options::default()).unwrap();
        assert_eq!(out.sources.len(), out.mesh.cells.len());
        for (q, s) in out.mesh.cells.iter().zip(&out.sources) {
            let c = q.map(|v| out.mesh.positions[v as usize]);
            let centre = [0, 1].map(|k| c.iter().map(|p| p[k]).sum::<f64>() / 4.0);
            let t = s.expect("a source");
            assert!(
                in_triangle(&map, t, centre),
                "quad {q:?} centre {centre:?} not in triangle {t}"
            );
        }
        // the map is 3 × the position (up to sanitization's moves of map
        // vertices on the grid's diagonals), the corners exact integers
        assert_eq!(out.corners.len(), out.mesh.cells.len());
        assert_corners_scale(&out, 3.0);
    }
}

#[test]
fn each_hex_names_the_tet_holding_its_node() {
    // 6 tets per unit cube (around its diagonal), identity map scaled by 2
    let n = 2u32;
    let id = |i: u32, j: u32, k: u32| (k * (n + 1) + j) * (n + 1) + i;
    let mut positions = Vec::new();
    for k in 0..=n {
        for j in 0..=n {
            for i in 0..=n {
                positions.push([i as f64, j as f64, k as f64]);
            }
        }
    }
    let mut tets = Vec::new();
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                let c = |b: u32| id(i + (b & 1), j + (b >> 1 & 1), k + (b >> 2 & 1));
                for [a, b, d] in [
                    [1, 3, 7],
                    [3, 2, 7],
                    [2, 6, 7],
                    [6, 4, 7],
                    [4, 5, 7],
                    [5, 1, 7],
                ] {
                    tets.push([c(0), c(a), c(b), c(d)]);
                }
            }
        }
    }
    let uvw: Vec<[[f64; 3]; 4]> = tets
        .iter()
        .map(|t| t.map(|v| positions[v as usize].map(|x| 2.0 * x)))
        .collect();
    let map = tet_map_from_slices(&positions, &tets, &uvw).unwrap();
    let out = hex(&map, &Options::default()).unwrap();
    assert_eq!(out.stats.cells, 64);
    assert_eq!(out.sources.len(), 64);
    let det = |a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]| {
        let (u, v, w) = (
            [0, 1, 2].map(|i| b[i] - a[i]),
            [0, 1, 2].map(|i| c[i] - a[i]),
            [0, 1, 2].map(|i| d[i] - a[i]),
        );
        u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0])
    };
    for (h, &s) in out.mesh.cells.iter().zip(&out.sources) {
        let s = s.expect("every hex has a source tet");
        let p = [0, 1, 2].map(|k| {
            h.iter()
                .map(|&v| out.mesh.positions[v as usize][k])
                .sum::<f64>()
                / 8.0
        });
        let c = map.simplices[s as usize].map(|v| map.positions[v as usize]);
        let whole = det(c[0], c[1], c[2], c[3]);
        let inside = (0..4).all(|i| {
            let mut q = c;
            q[i] = p;
            det(q[0], q[1], q[2], q[3]) * whole >= -1e-4 * whole.abs()
        });
        assert!(inside, "hex {h:?} centre {p:?} not in tet {s}");
    }
    // the map is 2 × the position (up to sanitization's moves): each
    // corner's uvw, an exact integer
    assert_eq!(out.corners.len(), 64);
    assert_corners_scale(&out, 2.0);
}

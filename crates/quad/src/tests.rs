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
    assert!(st.segment.sanitize.perturbed_vertices > 0);
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

fn check_valid(mesh: &QuadMesh, what: &str) -> dualex_check::QuadReport {
    let rep = dualex_check::check_quad_mesh(mesh.positions.len(), &mesh.cells);
    assert!(rep.is_valid(), "{what}: {:?}", rep.errors());
    rep
}

#[test]
fn edges_between_singular_vertices_through_grid_points_are_split() {
    // one segment per cube edge: each face diagonal joins two singular
    // corners and passes exactly through grid points of the shifted map
    let (m, _) =
        dualex_gen::cube_surface(3, 1, dualex_gen::Perturb::None, dualex_gen::Diagonal::Fixed);
    let (mesh, st) = extract(&m, &QuadOptions::default()).expect("extract");
    assert!(st.segment.split > 0, "{}", st.to_json());
    let rep = check_valid(&mesh, "cube res 1");
    assert_eq!(mesh.cells.len(), 54, "{}", st.to_json());
    assert_eq!(rep.interior_valence.get(&3), Some(&8));
    assert_eq!(rep.euler, 2);
}

/// The map of `name` translated by (½, ½) in every chart: still exactly GP
/// (`h − R·h` is integral), and its singularity now sits on a dual node.
fn on_node(name: &str) -> TriMap {
    let (mut m, _) = dualex_gen::by_name(name, 1).expect("generator");
    for c in m.coords.iter_mut().flatten() {
        c[0] += 0.5;
        c[1] += 0.5;
    }
    m
}

#[test]
fn singularity_of_90_degrees_on_a_node_gives_a_valid_mesh() {
    for name in ["disk_p1", "disk_m1", "cube"] {
        let m = on_node(name);
        let (mesh, st) = extract(&m, &QuadOptions::default()).expect("extract");
        let rep = check_valid(&mesh, name);
        let closed = name == "cube";
        assert_eq!(
            rep.boundary_loops,
            usize::from(!closed),
            "{name}: {}",
            st.to_json()
        );
        assert_eq!(
            st.boundary_loops,
            usize::from(!closed),
            "{name}: graph boundary"
        );
        assert_eq!(rep.components, 1);
        assert_eq!(rep.euler, if closed { 2 } else { 1 }, "{name}");
        eprintln!("{name} on a node: {}", st.to_json());
    }
}

#[test]
fn singularity_on_an_iso_but_not_a_node() {
    // translated by (½, 0): the centre lies on a dual iso-line only
    for name in ["disk_p1", "disk_m2"] {
        let (mut m, _) = dualex_gen::by_name(name, 1).expect("generator");
        let rot_ok = m.coords.iter().flatten().all(|c| c[0].is_finite());
        assert!(rot_ok);
        for c in m.coords.iter_mut().flatten() {
            c[0] += 0.5;
        }
        // a 90° seam maps (½, 0) to a non-integer translation: only the
        // 180° disk stays GP under this shift
        match extract(&m, &QuadOptions::default()) {
            Ok((mesh, st)) => {
                check_valid(&mesh, name);
                eprintln!("{name} on an iso: {}", st.to_json());
            }
            Err(e) => assert!(
                name == "disk_p1" && e.to_string().contains("residual"),
                "{name}: {e}"
            ),
        }
    }
}

/// The maps of the 3×3 grid whose centre is split by a valence-2 vertex
/// (`grid_with_doublet`) and of that centre's two quads alone: fairing
/// finds no partner, the graph merges the two nodes, and the merged quad's
/// corners are the centre square's vertices — the corner at the doublet
/// traced from the deleted node (a trace from the kept node's own corner
/// lands on the doublet's vertex, (1.5, 1.5); in the grid the far corner's
/// other quads place it anyway, alone nothing else does).
#[test]
fn a_doublet_is_merged_in_the_graph_with_its_vertices_in_place() {
    use dualex_gen::from_mesh::{from_quads, meshes::grid_with_doublet, FromMeshOptions};
    let grid = grid_with_doublet();
    let pair = QuadMesh {
        positions: [16, 5, 6, 10, 9].map(|v| grid.positions[v]).to_vec(),
        cells: vec![[0, 1, 2, 3], [0, 3, 4, 1]],
    };
    for (input, quads, interior4) in [(&grid, 9, Some(&4)), (&pair, 1, None)] {
        let fq = from_quads(input, &FromMeshOptions::default()).expect("map");
        let (mesh, st) = extract(&fq.map, &QuadOptions::default()).expect("extract");
        let rep = check_valid(&mesh, "doublet");
        let (nq, nv) = (mesh.cells.len(), mesh.positions.len());
        assert_eq!(
            (nq, nv),
            (quads, input.positions.len() - 1),
            "{}",
            st.to_json()
        );
        let d = st.doublets;
        assert_eq!((d.dissolved, d.in_graph, d.left), (1, 1, 0));
        assert_eq!(rep.interior_valence.get(&4), interior4);
        // (sanitization moves vertices by ~1e-5; the doublet's is 0.7 away
        // from any other)
        for p in &mesh.positions {
            let near = input.positions.iter().any(|q| {
                let doublet = (q[0] - 1.5).abs() < 1e-9 && (q[1] - 1.5).abs() < 1e-9;
                !doublet && (0..3).all(|k| (p[k] - q[k]).abs() < 1e-3)
            });
            assert!(near, "vertex {p:?} is not a grid point");
        }
    }
}

/// `extract` refuses an absurd map (see `dualex_segment::nodes::check_size`)
/// before any work.
#[test]
fn an_absurd_map_is_refused_before_any_work() {
    let mut m = TriMap {
        positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        simplices: vec![[0, 1, 2]; 2],
        coords: vec![[[0.0, 0.0], [1e9, 0.0], [0.0, 1e9]]],
    };
    m.coords.insert(0, [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    let e = extract(&m, &Default::default()).err();
    assert!(e.is_some_and(|e| matches!(
        e.cause(),
        dualex_map::InputErrorKind::Map(dualex_map::error::MapError::TooLarge { .. })
    )));
}

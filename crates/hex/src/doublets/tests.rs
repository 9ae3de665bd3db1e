use super::*;
use dualex_cells::QuadMesh;
use dualex_gen::from_mesh::meshes::{extrude, grid_with_doublet};

/// The check's report: valid but for doublets (interior edges in 2
/// hexes, which it reports as errors exactly when there are some).
fn check(m: &HexMesh) -> dualex_check::HexReport {
    let r = dualex_check::check_hex_mesh(m.positions.len(), &m.cells, None);
    let (doublets, other): (Vec<String>, Vec<String>) =
        r.errors().into_iter().partition(|e| e.contains("doublets"));
    assert!(other.is_empty(), "{other:?}");
    let thin = r.interior_edge_valence.range(..3).count() > 0;
    assert_eq!(doublets.is_empty(), !thin, "{doublets:?}");
    r
}

/// The extruded doublet is a chain of valence-2 edges from the bottom to
/// the top boundary: dissolving it gives the extruded 3×3 grid, layer by
/// layer (9·L hexes, 16·(L+1) vertices), valid, Euler kept.
#[test]
fn an_extruded_doublet_column_is_dissolved() {
    for layers in [1, 3] {
        let m = extrude(&grid_with_doublet(), layers);
        let before = check(&m);
        let (out, rep) = dissolve(&m);
        assert_eq!(
            rep,
            Chains {
                dissolved: 1,
                edges: layers,
                left: 0,
                rounds: 0,
                in_graph: 0,
            },
            "L = {layers}"
        );
        assert_eq!(out.cells.len(), 9 * layers);
        assert_eq!(out.positions.len(), 16 * (layers + 1));
        let after = check(&out);
        assert_eq!(after.euler, before.euler);
        assert_eq!(after.boundary_faces, 2 * 9 + 4 * 3 * layers);
    }
}

/// A mesh without valence-2 edges is returned as it is.
#[test]
fn nothing_to_do_on_a_block() {
    let mut g = grid_with_doublet();
    g.cells.truncate(8);
    g.positions.truncate(16);
    g.cells.push([5, 6, 10, 9]);
    let m = extrude(&g, 2);
    let (out, rep) = dissolve(&m);
    assert_eq!(rep, Chains::default());
    assert_eq!(out.cells, m.cells);
}

/// A strip of two quads with a folded quad glued between them along the
/// edge 1–4 (`[v, 1, 4, 1]`, `v` held by it alone), extruded: the folded
/// hexes of every layer are collapsed and the strip's extrusion is left,
/// valid.
#[test]
fn an_extruded_folded_quad_is_collapsed() {
    let mut m = QuadMesh::default();
    for j in 0..2 {
        for i in 0..3 {
            m.positions.push([i as f64, j as f64, 0.0]);
        }
    }
    m.positions.push([1.2, 0.5, 0.0]); // v = 6
    m.cells = vec![[0, 1, 4, 3], [1, 2, 5, 4], [6, 1, 4, 1]];
    for layers in [1, 3] {
        let h = extrude(&m, layers);
        assert!(h.cells.iter().all(|c| {
            let mut s = c.to_vec();
            s.sort_unstable();
            s.dedup();
            s.len() == 8 || folded(c).is_some()
        }));
        let (out, n) = collapse_folded(&h);
        assert_eq!(n, layers, "L = {layers}");
        assert_eq!(out.cells.len(), 2 * layers);
        assert_eq!(out.positions.len(), 6 * (layers + 1));
        check(&out);
    }
}

/// `quads` stacked into `layers` layers of hexes, corners in the quads'
/// order (no reorientation): vertex `v` of level `l` is `v + l·nv`.
fn stack(nv: u32, quads: &[[u32; 4]], layers: u32) -> HexMesh {
    let positions = vec![[0.0; 3]; (nv * (layers + 1)) as usize];
    let mut cells = Vec::new();
    for l in 0..layers {
        for q in quads {
            cells.push(std::array::from_fn(|i| q[i % 4] + (l + i as u32 / 4) * nv));
        }
    }
    HexMesh { positions, cells }
}

/// Two nested doublets: `v` between `[v, a, x, b]` and `[v, b, y, a]`,
/// and `a` (valence 3 with `[a, y, z, x]`) becomes one when `v` goes. One
/// round leaves a valence-2 edge column; the rounds dissolve it too, as
/// the 2D removal's queue does.
#[test]
fn a_doublet_made_by_dissolving_one_is_dissolved_in_a_second_round() {
    let (v, a, b, x, y, z) = (0, 1, 2, 3, 4, 5);
    let quads = [[v, a, x, b], [v, b, y, a], [a, y, z, x]];
    for layers in [1, 2] {
        let m = stack(6, &quads, layers);
        check(&m);
        let (once, rep) = dissolve(&m);
        assert_eq!(
            (rep.edges, once.cells.len()),
            (layers as usize, 2 * layers as usize)
        );
        let r = check(&once);
        assert_eq!(r.interior_edge_valence.get(&2), Some(&(layers as usize)));
        let (out, rep, kept) = dissolve_all_traced(&m);
        assert_eq!(
            rep,
            Chains {
                dissolved: 2,
                edges: 2 * layers as usize,
                left: 0,
                rounds: 1,
                in_graph: 0,
            }
        );
        assert_eq!(out.cells.len(), layers as usize);
        assert_eq!(kept.len(), out.cells.len());
        let r = check(&out);
        assert_eq!(r.interior_edge_valence.get(&2), None);
    }
}

/// Two doublets of one quad: the centre cell of the 3×3 grid split by
/// `v1` and `v2` into `[5, 6, 10, v1]`, `[5, v1, 10, v2]`, `[5, v2, 10, 9]`
/// (both of valence 2, sharing the middle quad). The 2D removal takes one
/// after the other; extruded, both columns are chains of the first pass,
/// so the second (whose middle hex the first changed) waits for the next
/// round: the extruded 3×3 grid is left, valid.
#[test]
fn two_doublets_of_one_quad_are_dissolved_one_after_the_other() {
    let mut g = grid_with_doublet();
    g.cells.truncate(8);
    g.positions.truncate(16);
    g.positions.extend([[1.7, 1.4, 0.0], [1.3, 1.6, 0.0]]);
    let (v1, v2) = (16, 17);
    g.cells
        .extend([[5, 6, 10, v1], [5, v1, 10, v2], [5, v2, 10, 9]]);
    for layers in [1, 3] {
        let m = extrude(&g, layers);
        check(&m);
        let (once, rep) = dissolve(&m);
        check(&once);
        assert_eq!((rep.dissolved, rep.edges, rep.left), (1, layers, layers));
        let (out, rep, kept) = dissolve_all_traced(&m);
        assert_eq!(
            rep,
            Chains {
                dissolved: 2,
                edges: 2 * layers,
                left: 0,
                rounds: 1,
                in_graph: 0,
            },
            "L = {layers}"
        );
        assert_eq!((out.cells.len(), kept.len()), (9 * layers, 9 * layers));
        assert_eq!(out.positions.len(), 16 * (layers + 1));
        let r = check(&out);
        assert_eq!(r.interior_edge_valence.get(&2), None);
        assert_eq!(r.boundary_faces, 2 * 9 + 4 * 3 * layers);
    }
}

//! Step 8d: one output component per input component — bubbles deleted.
//!
//! On maps with many folds (`dualex remesh` on coarse grids), untangling can
//! close part of a fold into a small closed surface beside the real one (a
//! sphere of a few quads), and where many walks are lost at singular
//! vertices (singularities left on the isos) a few nodes can be cut off
//! the rest (a strip of two quads): the output has more components than
//! the input, a wrong mesh (the holes they leave in the surface are closed
//! by step 10 like any other). Walks never leave an input component, so
//! every component of the node graph lies in one input component (that of
//! its nodes' triangles). Per *closed* input component the largest graph
//! component is the surface (an input with boundary can be cut into pieces
//! legitimately: a cut map not welded has one piece per chart, so nothing
//! is deleted there but a lone node, none of whose sides is glued, beside
//! a piece of more than half of the nodes: a sliver of the surface
//! narrower than a grid cell); the strictly smaller others are bubbles and are
//! deleted when open (their sides are holes of the surface, closed by step
//! 8) or spheres (a closed piece with a handle is kept, and the mesh
//! refused, rather than a handle silently lost). A graph shattered into
//! pieces none of which holds half of the nodes is left as it is (refused
//! by the last check: there is no surface to keep). Deletion is by
//! `NodeGraph::delete_components`, which leaves the rest of the graph
//! untouched.
//!
//! Input: the graph after untangling and fairing, the (split) map's
//! topology, the triangle of each node. Output: the number of bubbles
//! deleted. Maps whose graph is connected cost one labelling pass.

use dualex_graph::{Node, NodeGraph};
use dualex_map::Topology;

/// Deletes the bubbles (see the module docs); returns how many.
pub fn drop_bubbles(graph: &mut NodeGraph<2>, topo: &Topology<3>, tri_of_node: &[u32]) -> usize {
    let (labels, k) = graph.component_labels();
    if k <= 1 {
        return 0;
    }
    let (tri_comp, open) = triangle_components(topo, topo.adj.len());
    // per graph component: nodes, input component
    let mut members: Vec<Vec<Node>> = vec![Vec::new(); k];
    let mut input = vec![u32::MAX; k];
    for x in graph.alive_nodes() {
        let c = labels[x.idx()] as usize;
        members[c].push(x);
        if let Some(&t) = tri_of_node.get(x.idx()) {
            input[c] = tri_comp.get(t as usize).copied().unwrap_or(u32::MAX);
        }
    }
    // per input component: (largest piece, all nodes)
    let mut largest: std::collections::HashMap<u32, (usize, usize)> = Default::default();
    for c in 0..k {
        let e = largest.entry(input[c]).or_insert((0, 0));
        *e = (e.0.max(members[c].len()), e.1 + members[c].len());
    }
    let (euler, open_piece) = component_shapes(graph, &labels, k);
    let mut deleted = 0;
    for c in 0..k {
        let (biggest, all) = largest.get(&input[c]).copied().unwrap_or((0, 0));
        let closed_input = open.get(input[c] as usize) == Some(&false);
        // on an input with boundary, only a lone node (no side glued: a
        // sliver of the surface narrower than a grid cell) beside a surface
        // of more than half of the nodes
        let lone = match members[c][..] {
            [x] => (0..4).all(|d| graph.opposite(graph.side(x, d)).is_none()),
            _ => false,
        } && 2 * biggest > all
            && biggest > 1;
        let bubble = closed_input
            && 2 * biggest >= all
            && members[c].len() < biggest
            && (open_piece[c] || euler[c] == 2);
        if (bubble || lone && !closed_input) && graph.delete_components(&members[c]).is_ok() {
            deleted += 1;
        }
    }
    deleted
}

/// Per graph component its Euler characteristic V − E + F (glued
/// vertices; a glued pair of sides is one edge, an unmatched side one) and
/// whether it has an unmatched side.
fn component_shapes(graph: &NodeGraph<2>, labels: &[u32], k: usize) -> (Vec<i64>, Vec<bool>) {
    let glued = graph.glue();
    // per component: vertices + faces, and twice the edges
    let (mut vf, mut e2) = (vec![0i64; k], vec![0i64; k]);
    let mut open = vec![false; k];
    let mut seen = vec![false; glued.n_vertices];
    for x in graph.alive_nodes() {
        let c = labels[x.idx()] as usize;
        vf[c] += 1;
        for d in 0..4 {
            if graph.opposite(graph.side(x, d)).is_some() {
                e2[c] += 1;
            } else {
                e2[c] += 2;
                open[c] = true;
            }
        }
        for code in 0..4 {
            let v = glued.vertex(x, code) as usize;
            if v < seen.len() && !seen[v] {
                seen[v] = true;
                vf[c] += 1;
            }
        }
    }
    let euler = vf.iter().zip(&e2).map(|(a, b)| a - b / 2).collect();
    (euler, open)
}

/// Per triangle its connected component (across shared edges), and per
/// component whether it has a boundary edge.
fn triangle_components(topo: &Topology<3>, n: usize) -> (Vec<u32>, Vec<bool>) {
    let mut label = vec![u32::MAX; n];
    let mut open = Vec::new();
    let mut stack = Vec::new();
    let mut k = 0u32;
    for start in 0..n {
        if label[start] != u32::MAX {
            continue;
        }
        label[start] = k;
        stack.push(start);
        open.push(false);
        while let Some(s) = stack.pop() {
            for f in 0..3 {
                match topo.neighbour(s, f) {
                    Some((t, _)) if label[t] == u32::MAX => {
                        label[t] = k;
                        stack.push(t);
                    }
                    Some(_) => {}
                    None => open[k as usize] = true,
                }
            }
        }
        k += 1;
    }
    (label, open)
}

/// The bubbles of a repaired *mesh* (after `crate::pinched` split a
/// pinch point, a pocket of a fold can come apart from the surface): the
/// same rule as [`drop_bubbles`] on the mesh's components — per closed
/// input component (that of the cells' `sources`), the strictly smaller
/// closed spheres beside a piece holding at least half of the cells.
/// Returns the cells kept (indices) and how many components were deleted;
/// `None` when nothing is deleted.
pub fn drop_mesh_bubbles(
    mesh: &dualex_cells::QuadMesh,
    topo: &Topology<3>,
    sources: &[u32],
) -> Option<(Vec<u32>, usize)> {
    let n = mesh.cells.len();
    let mut uf = dualex_util::union_find::UnionFind::new(mesh.positions.len());
    for q in &mesh.cells {
        for k in 1..4 {
            uf.union(q[0] as usize, q[k] as usize);
        }
    }
    let label: Vec<usize> = mesh.cells.iter().map(|q| uf.find(q[0] as usize)).collect();
    let mut comps: std::collections::HashMap<usize, Vec<u32>> = Default::default();
    for (c, &l) in label.iter().enumerate() {
        comps.entry(l).or_default().push(c as u32);
    }
    if comps.len() <= 1 {
        return None;
    }
    let (tri_comp, open) = triangle_components(topo, topo.adj.len());
    let input_of = |cells: &[u32]| {
        cells
            .iter()
            .find_map(|&c| tri_comp.get(*sources.get(c as usize)? as usize).copied())
            .unwrap_or(u32::MAX)
    };
    let mut largest: std::collections::HashMap<u32, (usize, usize)> = Default::default();
    for cells in comps.values() {
        let e = largest.entry(input_of(cells)).or_insert((0, 0));
        *e = (e.0.max(cells.len()), e.1 + cells.len());
    }
    let mut drop = vec![false; n];
    let mut deleted = 0;
    for cells in comps.values() {
        let input = input_of(cells);
        let (biggest, all) = largest.get(&input).copied().unwrap_or((0, 0));
        let closed_input = open.get(input as usize) == Some(&false);
        let piece: Vec<[u32; 4]> = cells.iter().map(|&c| mesh.cells[c as usize]).collect();
        let shape = dualex_check::check_quad_mesh(mesh.positions.len(), &piece);
        let sphere = shape.boundary_edges == 0 && shape.euler == 2;
        if closed_input && 2 * biggest >= all && cells.len() < biggest && sphere {
            cells.iter().for_each(|&c| drop[c as usize] = true);
            deleted += 1;
        }
    }
    (deleted > 0).then(|| {
        (
            (0..n as u32).filter(|&c| !drop[c as usize]).collect(),
            deleted,
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_graph::testgrid::GridSpec;
    use dualex_map::{Rot2, TriMap};

    /// A closed input: the octahedron (map coordinates do not matter here).
    fn octahedron() -> Topology<3> {
        let m = TriMap {
            positions: vec![
                [1.0, 0.0, 0.0],
                [-1.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                [0.0, -1.0, 0.0],
                [0.0, 0.0, 1.0],
                [0.0, 0.0, -1.0],
            ],
            simplices: vec![
                [0, 2, 4],
                [2, 1, 4],
                [1, 3, 4],
                [3, 0, 4],
                [2, 0, 5],
                [1, 2, 5],
                [3, 1, 5],
                [0, 3, 5],
            ],
            coords: vec![[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]; 8],
        };
        Topology::build(&m).unwrap_or_else(|e| panic!("{e}"))
    }

    /// A 3×3 grid (nodes 0..9), two nodes glued on all sides (9, 10: a
    /// closed piece of two quads, a torus) and a strip of two (11, 12).
    fn pieces() -> NodeGraph<2> {
        let grid = GridSpec::regular([3, 3]).build();
        let mut g = NodeGraph::<2>::new(vec![false; 13]);
        for x in 0..9 {
            for d in 0..4 {
                let s = grid.side(Node(x), d);
                if let (Some(t), Some(r)) = (grid.opposite(s), grid.rotation(s)) {
                    if s.0 < t.0 {
                        g.link(s, t, r).unwrap_or_else(|e| panic!("{e}"));
                    }
                }
            }
        }
        for d in 0..4 {
            g.link(g.side(Node(9), d), g.side(Node(10), d ^ 1), Rot2::IDENTITY)
                .unwrap_or_else(|e| panic!("{e}"));
        }
        g.link(g.side(Node(11), 0), g.side(Node(12), 1), Rot2::IDENTITY)
            .unwrap_or_else(|e| panic!("{e}"));
        g
    }

    #[test]
    fn open_pieces_go_and_the_surface_and_handles_stay() {
        let topo = octahedron();
        let mut g = pieces();
        let (labels, k) = g.component_labels();
        assert_eq!(k, 3);
        let (euler, open) = component_shapes(&g, &labels, k);
        assert_eq!((euler[1], open[1]), (0, false), "the pair is a torus");
        assert!(open[2]);
        assert_eq!(drop_bubbles(&mut g, &topo, &[0; 13]), 1);
        g.check_structure().unwrap_or_else(|e| panic!("{e}"));
        assert!(!g.is_alive(Node(11)) && !g.is_alive(Node(12)));
        assert!((0..11).all(|x| g.is_alive(Node(x))));
    }

    #[test]
    fn inputs_with_boundary_keep_their_pieces() {
        let m = TriMap {
            positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            simplices: vec![[0, 1, 2]],
            coords: vec![[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]],
        };
        let topo = Topology::build(&m).unwrap_or_else(|e| panic!("{e}"));
        let mut g = pieces();
        assert_eq!(drop_bubbles(&mut g, &topo, &[0; 13]), 0);
        assert_eq!(g.n_alive(), 13);
        // a lone node (no side glued) beside them is a sliver: deleted
        let mut g = pieces();
        let mut lone = NodeGraph::<2>::new(vec![false; 14]);
        for s in (0..g.n_sides() as u32).map(dualex_graph::Side) {
            if let (Some(t), Some(r)) = (g.opposite(s), g.rotation(s)) {
                if s.0 < t.0 {
                    lone.link(s, t, r).unwrap_or_else(|e| panic!("{e}"));
                }
            }
        }
        g = lone;
        assert_eq!(drop_bubbles(&mut g, &topo, &[0; 14]), 1);
        g.check_structure().unwrap_or_else(|e| panic!("{e}"));
        assert!(!g.is_alive(Node(13)));
        assert_eq!(g.n_alive(), 13);
    }
}

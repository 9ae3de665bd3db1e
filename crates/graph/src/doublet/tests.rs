//! Doublet merges on small graphs built from cells, in both dimensions;
//! `check()` after every operation, the graph untouched on every refusal.

use super::Takeover;
use crate::glue::{cell_code, corner_across, corners_on, rotate_corner};
use crate::ids::Node;
use crate::testgrid::{random_rotations, rotate_charts};
use crate::tests::support::{assert_same_partition, counts};
use crate::{Glued, NodeGraph, OpError};
use dualex_map::Rot;
use std::collections::{BTreeMap, HashMap};

/// The vertex of corner `code` of a cell given in output order.
fn at<const D: usize>(cell: &[u32], code: usize) -> u32 {
    let k = (0..1 << D).find(|&k| cell_code::<D>(k, false) == code);
    cell[k.expect("bug: no such corner")]
}

/// The sorted vertices of side `dir` of a cell.
fn side_set<const D: usize>(cell: &[u32], dir: usize) -> Vec<u32> {
    let mut v: Vec<u32> = corners_on::<D>(dir).map(|c| at::<D>(cell, c)).collect();
    v.sort_unstable();
    v
}

/// Glues the sides of cells `i` and `j` made of `verts`, with the rotation
/// that matches their corners.
fn link_cells<const D: usize>(
    g: &mut NodeGraph<D>,
    cells: &[Vec<u32>],
    i: usize,
    j: usize,
    verts: &[u32],
) {
    let mut want = verts.to_vec();
    want.sort_unstable();
    let find = |c: usize, not: Option<usize>| {
        (0..2 * D)
            .find(|&d| side_set::<D>(&cells[c], d) == want && Some(d) != not)
            .expect("bug: no such side")
    };
    let di = find(i, None);
    let dj = find(j, (i == j).then_some(di));
    let (x, y) = (Node(i as u32), Node(j as u32));
    let rho = Rot::<D>::all().into_iter().find(|r| {
        g.label_dir(x, y, di, r) == dj
            && corners_on::<D>(di).all(|c| {
                corner_across(di, dj, r, c)
                    .is_some_and(|cj| at::<D>(&cells[j], cj) == at::<D>(&cells[i], c))
            })
    });
    let rho = rho.expect("bug: the cells do not match");
    g.link(g.side(x, di), g.side(y, dj), rho).expect("link");
}

/// The graph of consistently oriented cells (output order), sides glued
/// wherever exactly two sides have the same vertices.
fn graph_of<const D: usize>(cells: &[Vec<u32>]) -> NodeGraph<D> {
    let mut g = NodeGraph::<D>::new(vec![false; cells.len()]);
    let mut by_set: BTreeMap<Vec<u32>, Vec<usize>> = BTreeMap::new();
    for (i, c) in cells.iter().enumerate() {
        for d in 0..2 * D {
            by_set.entry(side_set::<D>(c, d)).or_default().push(i);
        }
    }
    for (set, owners) in by_set {
        if let [i, j] = owners[..] {
            link_cells(&mut g, cells, i, j, &set);
        }
    }
    g.check().expect("valid input graph");
    g
}

/// A 3×3 grid of quads whose centre is split by the valence-2 vertex 16
/// into X = cell 8 and Y = cell 9 (the smallest doublet).
fn grid_with_doublet() -> (Vec<[f64; 2]>, Vec<Vec<u32>>) {
    let mut pos: Vec<[f64; 2]> = (0..16).map(|v| [(v % 4) as f64, (v / 4) as f64]).collect();
    pos.push([1.5, 1.5]);
    let mut cells = Vec::new();
    for j in 0..3 {
        for i in 0..3 {
            if (i, j) != (1, 1) {
                let id = |a: u32, b: u32| b * 4 + a;
                cells.push(vec![id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
    }
    cells.push(vec![16, 5, 6, 10]);
    cells.push(vec![16, 10, 9, 5]);
    (pos, cells)
}

/// `quads` stacked into `layers` layers of hexes (VTK order); with
/// `closed`, the top level is the bottom one (a ring).
fn extrude(quads: &[Vec<u32>], nv: u32, layers: u32, closed: bool) -> Vec<Vec<u32>> {
    let level = |l: u32| if closed { l % layers } else { l };
    (0..layers)
        .flat_map(|l| {
            quads.iter().map(move |q| {
                (0..8)
                    .map(|i| q[i % 4] + level(l + i as u32 / 4) * nv)
                    .collect()
            })
        })
        .collect()
}

/// Per glued vertex, the input vertex that its corners name through the
/// takeovers (asserting they agree), and the cells' input vertices.
fn vertices_through<const D: usize>(
    gl: &Glued<D>,
    cells: &[Vec<u32>],
    tk: &Takeover<D>,
) -> Vec<Vec<u32>> {
    vertices_charted(gl, cells, tk, |_, c| c)
}

/// [`vertices_through`] on a graph whose charts were rotated: `cell_code`
/// maps a (node, corner code) to the code in the cell's own order.
fn vertices_charted<const D: usize>(
    gl: &Glued<D>,
    cells: &[Vec<u32>],
    tk: &Takeover<D>,
    cell_code: impl Fn(Node, usize) -> usize,
) -> Vec<Vec<u32>> {
    let mut name: HashMap<u32, u32> = HashMap::new();
    let mut out = Vec::new();
    for &n in &gl.nodes {
        let mut cell = Vec::new();
        for code in 0..1 << D {
            let v = gl.vertex(n, code);
            for (m, c) in tk.origins(n, code) {
                let input = at::<D>(&cells[m.idx()], cell_code(m, c));
                assert_eq!(*name.entry(v).or_insert(input), input, "vertex {v}");
            }
            cell.push(name[&v]);
        }
        cell.sort_unstable();
        out.push(cell);
    }
    out
}

/// Cells per edge → edges.
fn histogram<const D: usize>(gl: &Glued<D>) -> BTreeMap<usize, usize> {
    let mut h = BTreeMap::new();
    for c in edge_valence(gl).into_values() {
        *h.entry(c).or_insert(0) += 1;
    }
    h
}

/// Edges (vertex pairs of corners one bit apart) → cells around them.
fn edge_valence<const D: usize>(gl: &Glued<D>) -> HashMap<(u32, u32), usize> {
    let mut out = HashMap::new();
    for &n in &gl.nodes {
        for c in 0..1usize << D {
            for b in (0..D).map(|a| 1 << a).filter(|b| c & b == 0) {
                let (p, q) = (gl.vertex(n, c), gl.vertex(n, c | b));
                *out.entry((p.min(q), p.max(q))).or_insert(0) += 1;
            }
        }
    }
    out
}

#[test]
fn a_doublet_in_a_grid_is_merged() {
    let (pos, cells) = grid_with_doublet();
    let mut g = graph_of::<2>(&cells);
    let before = g.glue();
    assert_eq!((before.n_cells(), before.n_vertices), (10, 17));
    let mut tk = Takeover::default();
    let st = g.dissolve_doublets(&mut tk);
    g.check().expect("valid after");
    assert_eq!((st.merged, st.pairs, st.rounds, st.refused), (1, 1, 0, 0));
    assert!(tk.is_merged(Node(8)) && !g.is_alive(Node(9)));
    let gl = g.glue();
    assert_eq!((gl.n_cells(), gl.n_vertices, gl.boundary_loops), (9, 16, 1));
    // edges per vertex: the 3×3 grid back (4 corners, 8 sides, 4 inside)
    let deg = counts(&gl).valence;
    assert_eq!(deg, BTreeMap::from([(2, 4), (3, 8), (4, 4)]));
    // the merged cell's corners are the centre square's, at their places:
    // the corner at 16 is taken over from Y's far corner (9)
    let named = vertices_through(&gl, &cells, &tk);
    assert_eq!(named[8], [5, 6, 9, 10]);
    assert_eq!(tk.origins(Node(8), 0), [(Node(9), 3)]);
    // X's corners at 5 and 10 may be traced from Y's too
    assert_eq!(tk.origins(Node(8), 1), [(Node(8), 1), (Node(9), 2)]);
    assert_eq!(pos[at::<2>(&cells[9], 3) as usize], [1.0, 2.0]);
    // nothing left: a second pass does nothing
    assert_eq!(g.dissolve_doublets(&mut tk), Default::default());
}

#[test]
fn a_merge_keeps_every_chart_rotation() {
    let (_, cells) = grid_with_doublet();
    let g = graph_of::<2>(&cells);
    let mut plain = g.clone();
    plain.merge_doublet(Node(8), 1, 3).expect("merge");
    let want = plain.glue();
    for seed in 0..64 {
        let rots = random_rotations::<2>(g.n_nodes(), seed);
        let mut r = rotate_charts(&g, &rots);
        r.check().expect("rotated");
        let mut tk = Takeover::default();
        let st = r.dissolve_doublets(&mut tk);
        r.check().expect("valid after");
        assert_eq!(st.merged, 1, "seed {seed}");
        let gl = r.glue();
        assert_same_partition(&want, &gl, |n, c| (n, rotate_corner(&rots[n.idx()], c)));
        let back = |n: Node, c| rotate_corner(&rots[n.idx()].inverse(), c);
        let named = vertices_charted(&gl, &cells, &tk, back);
        assert_eq!(named[8], [5, 6, 9, 10], "seed {seed}");
    }
}

#[test]
fn two_quads_alone_sharing_two_edges_become_one() {
    // X = [v, a, x, b], Y = [v, b, y, a]: a disk of two quads
    let cells = vec![vec![0, 1, 2, 3], vec![0, 3, 4, 1]];
    let mut g = graph_of::<2>(&cells);
    let m = g.merge_doublet(Node(0), 1, 3).expect("merge");
    g.check().expect("valid");
    assert_eq!(m.pairs, [(Node(0), Node(1))]);
    let gl = g.glue();
    assert_eq!((gl.n_cells(), gl.n_vertices, gl.unmatched_sides), (1, 4, 4));
    let mut tk = Takeover::default();
    tk.record(&m);
    assert_eq!(vertices_through(&gl, &cells, &tk)[0], [1, 2, 3, 4]);
}

#[test]
fn degenerate_doublets_are_refused_untouched() {
    // a closed pillow: Y's outer sides are glued to X
    let mut g = graph_of::<2>(&[vec![0, 1, 2, 3], vec![0, 3, 2, 1]]);
    let before = g.clone();
    assert_eq!(
        g.merge_doublet(Node(0), 1, 3),
        Err(OpError::DoubletPartner(Node(0)))
    );
    assert_eq!(g, before);
    // the two faces share their four vertices, x = y through a digon
    // filled by P1, P2: the merged quad would be [a, x, b, x]
    let (v, a, x, b, c, d) = (0, 1, 2, 3, 4, 5);
    let cells = vec![
        vec![v, a, x, b],
        vec![v, b, x, a],
        vec![x, d, c, b],
        vec![x, b, c, d],
    ];
    let mut g = NodeGraph::<2>::new(vec![false; 4]);
    for (i, j, e) in [
        (0, 1, [v, a]),
        (0, 1, [v, b]),
        (0, 2, [x, b]),
        (3, 1, [b, x]),
    ] {
        link_cells(&mut g, &cells, i, j, &e);
    }
    for e in [[x, d], [d, c], [c, b]] {
        link_cells(&mut g, &cells, 2, 3, &e);
    }
    g.check().expect("valid");
    let before = g.clone();
    assert_eq!(
        g.merge_doublet(Node(0), 1, 3),
        Err(OpError::RepeatedCorner(Node(0)))
    );
    assert_eq!(g, before);
    // not a doublet: X's corner at a is not glued to one node on both sides
    assert_eq!(
        g.merge_doublet(Node(0), 0, 3),
        Err(OpError::Unmatched(g.side(Node(0), 0)))
    );
    assert_eq!(
        g.merge_doublet(Node(0), 1, 1),
        Err(OpError::NotDoublet(Node(0)))
    );
    assert_eq!(
        g.merge_doublet(Node(0), 1, 7),
        Err(OpError::NotDoublet(Node(0)))
    );
    let mut tk = Takeover::default();
    let st = g.dissolve_doublets(&mut tk);
    assert_eq!((st.merged, tk.is_empty()), (0, true));
    assert!(st.refused > 0);
    assert_eq!(g, before);
    // a folded outer corner of Y (y of valence 1): its sides are glued
    // to each other, i.e. to Y itself
    let (_, cells) = grid_with_doublet();
    let mut g = graph_of::<2>(&cells[8..]);
    let y = Node(1);
    let (s, t) = (g.side(y, 0), g.side(y, 2));
    let r = Rot::all()
        .into_iter()
        .find(|r| g.label_dir(y, y, 0, r) == 2);
    g.link(s, t, r.expect("a fold")).expect("fold");
    g.check().expect("valid");
    let before = g.clone();
    assert_eq!(
        g.merge_doublet(Node(0), 1, 3),
        Err(OpError::DoubletPartner(Node(0)))
    );
    assert_eq!(g, before);
}

/// The 3D doublet: the grid with a doublet extruded, open or closed.
fn column(layers: u32, closed: bool) -> (Vec<Vec<u32>>, NodeGraph<3>) {
    let (_, quads) = grid_with_doublet();
    let cells = extrude(&quads, 17, layers, closed);
    let g = graph_of::<3>(&cells);
    (cells, g)
}

#[test]
fn a_chain_of_valence_two_edges_is_merged_whole() {
    for (layers, closed) in [(1, false), (3, false), (3, true), (4, true)] {
        let (cells, mut g) = column(layers, closed);
        let n = layers as usize;
        let before = histogram(&g.glue());
        assert!(before.get(&2).copied().unwrap_or(0) >= n);
        let mut tk = Takeover::default();
        let st = g.dissolve_doublets(&mut tk);
        g.check().expect("valid after");
        assert_eq!((st.merged, st.pairs, st.refused), (1, n, 0), "L = {layers}");
        let gl = g.glue();
        let levels = if closed { n } else { n + 1 };
        assert_eq!((gl.n_cells(), gl.n_vertices), (9 * n, 16 * levels));
        // the edge valences of the regular 3×3 block (ring)
        let (_, quads) = grid_with_doublet();
        let mut regular = quads[..8].to_vec();
        regular.push(vec![5, 6, 10, 9]);
        let block = graph_of::<3>(&extrude(&regular, 17, layers, closed));
        assert_eq!(histogram(&gl), histogram(&block.glue()), "L = {layers}");
        // the merged hexes are the centre columns of the grid
        let named = vertices_through(&gl, &cells, &tk);
        for l in 0..layers {
            let lv = |v: u32, k: u32| v + ((l + k) % if closed { layers } else { layers + 1 }) * 17;
            let mut want = vec![
                lv(5, 0),
                lv(6, 0),
                lv(9, 0),
                lv(10, 0),
                lv(5, 1),
                lv(6, 1),
                lv(9, 1),
                lv(10, 1),
            ];
            want.sort_unstable();
            assert!(named.contains(&want), "L = {layers}, layer {l}");
        }
    }
}

#[test]
fn a_chain_is_merged_all_or_nothing() {
    let (_, mut g) = column(3, false);
    // unglue X's column between layers 1 and 2 (cells 18 and 28), not Y's
    let (x1, x2) = (Node(18), Node(28));
    let s = (0..6)
        .map(|d| g.side(x1, d))
        .find(|&s| g.opposite(s).is_some_and(|t| g.node_of(t) == x2));
    g.unlink(s.expect("glued")).expect("unlink");
    g.check().expect("valid");
    let before = g.clone();
    let mut tk = Takeover::default();
    let st = g.dissolve_doublets(&mut tk);
    assert_eq!((st.merged, st.pairs), (0, 0));
    assert!(st.refused >= 3);
    assert_eq!(g, before);
}

#[test]
fn edges_of_a_regular_block_are_no_doublets() {
    let (_, quads) = grid_with_doublet();
    let cells = extrude(&quads[..8], 17, 2, false);
    let mut g = graph_of::<3>(&cells);
    let before = g.clone();
    assert_eq!(
        g.dissolve_doublets(&mut Takeover::default()),
        Default::default()
    );
    assert_eq!(g, before);
}

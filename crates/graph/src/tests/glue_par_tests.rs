//! The gluing's parallel numbering and component count against a serial
//! union–find over the same pairs: grids with folds, charts turned, random
//! unlinks, pieces deleted and nodes renumbered, in both dimensions; and
//! dead nodes still linked (the serial fallback).

use crate::glue::NO_VERTEX;
use crate::ids::{Node, Side};
use crate::testgrid::{random_permutation, random_rotations, renumber, rotate_charts, GridSpec};
use crate::NodeGraph;
use dualex_util::rng::SplitMix;
use dualex_util::union_find::UnionFind;

/// Per corner its vertex (numbered by first corner in node order, none for
/// dead nodes) and the vertex count, by a serial union–find over the
/// pairs the gluing unites.
fn serial_vertices<const D: usize>(g: &NodeGraph<D>) -> (Vec<u32>, usize) {
    let k = 1usize << D;
    let mut uf = UnionFind::new(g.n_nodes() * k);
    for s in (0..g.n_sides() as u32).map(Side) {
        let Some(t) = g.opposite(s) else { continue };
        if t > s && g.is_alive(g.node_of(s)) {
            if let Some((pairs, n)) = g.matched_corners(s, t) {
                let (x, y) = (g.node_of(s).idx(), g.node_of(t).idx());
                for &(c, ct) in &pairs[..n] {
                    uf.union(x * k + c, y * k + ct);
                }
            }
        }
    }
    let (mut vertex_of, mut id) = (
        vec![NO_VERTEX; g.n_nodes() * k],
        vec![NO_VERTEX; g.n_nodes() * k],
    );
    let mut n = 0u32;
    for x in g.alive_nodes() {
        for c in 0..k {
            let r = uf.find(x.idx() * k + c);
            if id[r] == NO_VERTEX {
                (id[r], n) = (n, n + 1);
            }
            vertex_of[x.idx() * k + c] = id[r];
        }
    }
    (vertex_of, n as usize)
}

/// A folded grid, turned, cut by `cuts` random unlinks, every third piece
/// deleted, renumbered.
fn scrambled<const D: usize>(dims: [usize; D], cuts: usize, seed: u64) -> NodeGraph<D> {
    let mut rng = SplitMix::new(seed);
    let spec = GridSpec::regular(dims).fold(1 + rng.below(dims[0] - 1));
    let g = spec.build();
    let mut g = rotate_charts(&g, &random_rotations(g.n_nodes(), seed));
    for _ in 0..cuts {
        let s = Side(rng.below(g.n_sides()) as u32);
        if g.opposite(s).is_some() {
            g.unlink(s).expect("unlink");
        }
    }
    let mut g = renumber(&g, &random_permutation(g.n_nodes(), seed + 1));
    let (labels, k) = g.component_labels();
    for c in (0..k as u32).filter(|c| c % 3 == 1) {
        let piece: Vec<Node> = g.alive_nodes().filter(|x| labels[x.idx()] == c).collect();
        g.delete_components(&piece).expect("a piece");
    }
    g
}

fn same_as_serial<const D: usize>(g: &NodeGraph<D>, what: &str) -> usize {
    let glued = g.glue();
    let (vertex_of, n) = serial_vertices(g);
    assert_eq!(
        (&glued.vertex_of, glued.n_vertices),
        (&vertex_of, n),
        "{what}"
    );
    assert_eq!(glued.components, g.component_labels_serial().1, "{what}");
    glued.components
}

#[test]
fn parallel_numbering_and_components_are_the_serial_ones() {
    let mut pieces = 0;
    for seed in 0..30 {
        let g = scrambled([7, 6], 10 + 4 * seed as usize, seed);
        pieces += same_as_serial(&g, &format!("2D seed {seed}"));
        let g = scrambled([4, 3, 5], 20 + 6 * seed as usize, 50 + seed);
        pieces += same_as_serial(&g, &format!("3D seed {seed}"));
    }
    assert!(pieces > 150, "too few pieces: {pieces}");
    // several blocks of the prefix count
    let g = scrambled([120, 90], 16000, 7);
    assert!(same_as_serial(&g, "large 2D") > 5);
    let g = scrambled([30, 20, 16], 24000, 8);
    assert!(same_as_serial(&g, "large 3D") > 5);
}

/// Nodes marked dead with their links kept: a set's smallest corner may
/// be a dead node's, and the serial fallback numbers the corners.
#[test]
fn dead_nodes_still_linked_fall_back_to_the_serial_numbering() {
    for seed in 0..20 {
        let mut g = scrambled([9, 8], 6, 200 + seed);
        let mut rng = SplitMix::new(seed);
        for _ in 0..5 {
            let x = rng.below(g.n_nodes());
            g.alive[x] = false;
        }
        same_as_serial(&g, &format!("2D dead, seed {seed}"));
        let mut g = scrambled([5, 4, 4], 6, 300 + seed);
        for _ in 0..5 {
            let x = rng.below(g.n_nodes());
            g.alive[x] = false;
        }
        same_as_serial(&g, &format!("3D dead, seed {seed}"));
    }
}

/// The borrowed cell array is the cells' iterator, cell by cell.
#[test]
fn cell_array_is_the_cells() {
    for seed in 0..10 {
        let g = scrambled([7, 6], 10 + 4 * seed as usize, seed).glue();
        let cells: Vec<[u32; 4]> = g.cells().map(|(_, q)| q).collect();
        assert_eq!(g.cell_array::<4>(), &cells[..], "2D seed {seed}");
        assert_eq!(g.cell_array::<4>().len(), g.n_cells());
        let g = scrambled([4, 3, 5], 20 + 6 * seed as usize, 50 + seed).glue();
        let cells: Vec<[u32; 8]> = g.cells().map(|(_, h)| h).collect();
        assert_eq!(g.cell_array::<8>(), &cells[..], "3D seed {seed}");
    }
}

//! The search order from a corner: a breadth-first order in the start's
//! frame, blind to node numbers and charts, and a comparison that ties
//! exactly the starts a symmetry exchanges.

use super::*;
use crate::testgrid::{
    random_permutation, random_rotations, renumber, rotate_charts, rotate_corner, singular_disk,
    GridSpec,
};

/// The singular disks of 3 … 8 sectors, each also split by a saddle lift
/// at its centre (a valence-1 or -2 vertex next to a valence ≥ 7 one),
/// and an untangled folded grid.
fn graphs() -> Vec<NodeGraph<2>> {
    let mut out = Vec::new();
    for sectors in 3..=8 {
        let g = singular_disk(sectors, 3);
        let mut split = g.clone();
        let (a, c) = (split.side(Node(0), 1), split.side(Node(9), 3));
        if split.op2(a, c, Rot2::quarter_turns(3)).is_ok() && split.check().is_ok() {
            out.push(split);
        }
        out.push(g);
    }
    let mut folded = GridSpec::regular([5, 4]).fold(2).build();
    folded.untangle();
    out.push(folded);
    out
}

/// `g` with its charts turned and its nodes renumbered (seeded), and the
/// image of each corner `(node, code)`.
fn shuffled(
    g: &NodeGraph<2>,
    seed: u64,
) -> (NodeGraph<2>, impl Fn((Node, usize)) -> (Node, usize)) {
    let rots = random_rotations::<2>(g.n_nodes(), seed);
    let perm = random_permutation(g.n_nodes(), seed + 1);
    let h = renumber(&rotate_charts(g, &rots), &perm);
    let map = move |(x, c): (Node, usize)| (Node(perm[x.idx()]), rotate_corner(&rots[x.idx()], c));
    (h, map)
}

fn alive_corners(g: &NodeGraph<2>) -> Vec<(Node, usize)> {
    g.alive_nodes()
        .flat_map(|x| (0..4).map(move |c| (x, c)))
        .collect()
}

#[test]
fn ranks_follow_the_start_frame_breadth_first() {
    // 2 × 2 nodes, node = 2u + v: from corner 0 of node 0 (−u, −v) the
    // frame is the chart: +u → node 2, +v → node 1, then node 3
    let g = GridSpec::regular([2, 2]).build();
    let ranks = |start: (Node, usize)| {
        let mut c = Canon::new(&g, start);
        (0..4)
            .map(|x| c.corner_rank(Node(x), 0).map(|r| r / 4))
            .collect::<Vec<_>>()
    };
    assert_eq!(ranks((Node(0), 0)), [Some(0), Some(2), Some(1), Some(3)]);
    // from corner 3 of node 3 (+u, +v) the frame is a half turn
    assert_eq!(ranks((Node(3), 3)), [Some(3), Some(1), Some(2), Some(0)]);
    // the start corner reads as code 0 in its frame
    for code in 0..4 {
        let mut c = Canon::new(&g, (Node(1), code));
        assert_eq!(c.corner_rank(Node(1), code), Some(0), "code {code}");
    }
    // dead or out of range: nothing ranked
    let mut c = Canon::new(&g, (Node(0), 4));
    assert_eq!(c.corner_rank(Node(0), 0), None);
}

#[test]
fn ranks_and_comparisons_ignore_numbering_and_charts() {
    for (i, g) in graphs().iter().enumerate() {
        let corners = alive_corners(g);
        let starts: Vec<(Node, usize)> = corners.iter().copied().step_by(7).collect();
        for seed in [1, 2, 3] {
            let (h, map) = shuffled(g, 100 * i as u64 + seed);
            h.check().expect("shuffled graph valid");
            for &a in &starts {
                let (mut cg, mut ch) = (Canon::new(g, a), Canon::new(&h, map(a)));
                for &(x, c) in &corners {
                    let (y, d) = map((x, c));
                    assert_eq!(cg.corner_rank(x, c), ch.corner_rank(y, d), "graph {i}");
                }
                for &b in &starts {
                    assert_eq!(compare(g, a, b), compare(&h, map(a), map(b)), "graph {i}");
                }
            }
        }
    }
}

#[test]
fn only_starts_a_symmetry_exchanges_compare_equal() {
    for sectors in 3..=8 {
        let g = singular_disk(sectors, 3);
        // the centre's corners, one per sector: the disk's rotations
        let centre: Vec<(Node, usize)> = (0..sectors).map(|s| (Node(9 * s as u32), 0)).collect();
        for &a in &centre {
            assert_eq!(compare(&g, centre[0], a), Ordering::Equal, "{sectors}");
        }
        // a corner on the boundary, one beside the centre: no symmetry
        for b in [(Node(8), 3), (Node(0), 3)] {
            let o = compare(&g, centre[0], b);
            assert_ne!(o, Ordering::Equal, "{sectors}: {b:?}");
            assert_eq!(compare(&g, b, centre[0]), o.reverse());
        }
        // the least is not greater than any
        let all = [(Node(8), 3), centre[1], (Node(0), 3), (Node(4), 2)];
        let l = least(&g, &all).unwrap_or_else(|| panic!("no least"));
        assert!(all.iter().all(|&x| compare(&g, l, x) != Ordering::Greater));
    }
    // a lone node: its four corners are exchanged by its turns
    let g = NodeGraph::<2>::new(vec![false]);
    for code in 1..4 {
        assert_eq!(compare(&g, (Node(0), 0), (Node(0), code)), Ordering::Equal);
    }
}

#[test]
fn the_least_start_is_the_same_whatever_the_numbering() {
    for (i, g) in graphs().iter().enumerate() {
        let corners = alive_corners(g);
        let least_g = least(g, &corners).expect("corners");
        for seed in [5, 6] {
            let (h, map) = shuffled(g, 100 * i as u64 + seed);
            let mapped: Vec<_> = corners.iter().map(|&c| map(c)).collect();
            let least_h = least(&h, &mapped).expect("corners");
            // the same corner, or one a symmetry of h maps onto it
            assert_eq!(compare(&h, least_h, map(least_g)), Ordering::Equal, "{i}");
        }
    }
}

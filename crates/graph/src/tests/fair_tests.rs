//! Index fairing on singular disks split by a saddle lift.

use crate::ids::{Node, Side};
use crate::testgrid::{singular_disk, GridSpec};
use crate::NodeGraph;
use dualex_map::Rot2;
use std::collections::BTreeMap;

/// Interior valences (closed fans), one entry per vertex.
fn interior_valences(g: &NodeGraph<2>) -> BTreeMap<usize, usize> {
    let gl = g.glue();
    let mut seen = vec![false; gl.n_vertices];
    let mut h = BTreeMap::new();
    for n in g.alive_nodes() {
        for c in 0..4 {
            let v = gl.vertex(n, c) as usize;
            if !std::mem::replace(&mut seen[v], true) {
                if let Some(f) = g.fan(n, c) {
                    *h.entry(f.len()).or_insert(0) += 1;
                }
            }
        }
    }
    h
}

fn hist(pairs: &[(usize, usize)]) -> BTreeMap<usize, usize> {
    pairs.iter().copied().collect()
}

const K: usize = 3;

/// Sector s's node (0, 0), whose corner 0 is the singular vertex.
fn centre(s: usize) -> Node {
    Node((s * K * K) as u32)
}

/// Splits the centre (valence n) by a saddle lift into a vertex with
/// `corners` ∈ {1, 2} corners (sectors 0.. glued around it) and one of
/// n − corners; the far ends of the two edges merge into valence 8.
fn split(g: &mut NodeGraph<2>, corners: usize) {
    let a: Side = g.side(centre(0), 1);
    let c = g.side(centre(corners - 1), 3);
    g.op2(a, c, Rot2::quarter_turns(3)).unwrap();
    g.check().unwrap();
}

#[test]
fn singular_disks_have_one_singular_vertex() {
    for n in 3..=8 {
        let g = singular_disk(n, K);
        g.check().unwrap();
        assert_eq!(g.fan(centre(0), 0).map(|f| f.len()), Some(n));
        let interior = n * (K - 1) * (K - 1) + n * (K - 1);
        let mut want = hist(&[(4, interior)]);
        *want.entry(n).or_insert(0) += 1;
        assert_eq!(interior_valences(&g), want, "{n} sectors");
        let gl = g.glue();
        assert_eq!((gl.boundary_loops, gl.components), (1, 1));
    }
}

#[test]
fn fairing_undoes_a_split_of_valence_5_to_8() {
    for (n, corners) in [(5, 1), (6, 1), (6, 2), (7, 2), (8, 1), (8, 2)] {
        let g0 = singular_disk(n, K);
        let before = interior_valences(&g0);
        let mut g = g0.clone();
        split(&mut g, corners);
        let h = interior_valences(&g);
        assert_eq!(h.get(&corners), Some(&1), "{n}/{corners}: {h:?}");
        assert_eq!(
            h.get(&8).copied().unwrap_or(0),
            1 + usize::from(n - corners == 8),
            "{h:?}"
        );
        let st = g.fair(10);
        g.check().unwrap();
        assert_eq!(
            (st.merged, st.lifts, st.abandoned),
            (1, 1, 0),
            "{n}/{corners}: {st:?}"
        );
        assert_eq!((st.valence1_after, st.valence2_after), (0, 0));
        assert_eq!(interior_valences(&g), before);
        assert_eq!(g, g0, "{n}/{corners}: not the original graph");
    }
}

#[test]
fn fairing_moves_a_singularity_along_a_path() {
    let g0 = singular_disk(5, K);
    let mut g = g0.clone();
    split(&mut g, 1);
    // the valence-8 vertex: corner 1 of the centre node (the far end of -v)
    let fan = g.fan(centre(0), 1).unwrap();
    assert_eq!(fan.len(), 8);
    // move it one edge away from the valence-1 vertex with another lift
    let p = g.glue().vertex(centre(0), 0);
    let gl = g.glue();
    let away = (0..8)
        .find(|&i| {
            let s = fan[i];
            let far = s.code() ^ (1 << (s.in_dir >> 1));
            let w = gl.vertex(s.node, far);
            let w4 = {
                let t = fan[(i + 4) % 8];
                gl.vertex(t.node, t.code() ^ (1 << (t.in_dir >> 1)))
            };
            w != p && w4 != p && g.clone().lift(centre(0), 1, i, (i + 4) % 8).is_ok()
        })
        .unwrap();
    g.lift(centre(0), 1, away, (away + 4) % 8).unwrap();
    g.check().unwrap();
    let h = interior_valences(&g);
    assert_eq!((h.get(&1), h.get(&8)), (Some(&1), Some(&1)), "{h:?}");
    // too short a path: nothing happens
    let mut short = g.clone();
    let st = short.fair(1);
    assert_eq!((st.merged, st.lifts, st.valence1_after), (0, 0, 1));
    assert_eq!(short, g);
    let st = g.fair(10);
    g.check().unwrap();
    assert_eq!(
        (st.merged, st.lifts, st.valence1_after),
        (1, 2, 0),
        "{st:?}"
    );
    assert_eq!(interior_valences(&g), interior_valences(&g0));
}

#[test]
fn fairing_leaves_regular_meshes_alone() {
    let mut g = GridSpec::regular([5, 4]).fold(2).build();
    g.untangle();
    let g0 = g.clone();
    let st = g.fair(10);
    assert_eq!(st, Default::default());
    assert_eq!(g, g0);
    let mut g = singular_disk(3, K);
    let st = g.fair(10);
    assert_eq!((st.lifts, st.valence1_before), (0, 0));
}

#[test]
fn lift_preconditions() {
    let mut g = singular_disk(5, K);
    let g0 = g.clone();
    // boundary corner: no closed fan
    assert!(g.lift(Node(K as u32 - 1), 1, 0, 4).is_err());
    // same crossing, out of range
    assert!(g.lift(centre(0), 0, 1, 1).is_err());
    assert!(g.lift(centre(0), 0, 0, 9).is_err());
    // 180° apart on a valence-5 vertex: not on the same iso (label rule)
    assert!(g.lift(centre(0), 0, 0, 2).is_err());
    assert_eq!(g, g0);
}

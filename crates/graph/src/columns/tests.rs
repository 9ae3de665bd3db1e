use super::*;
use crate::testgrid::{random_rotations, rotate_charts, singular_disk, GridSpec};

const K: usize = 3;

/// The 2D graph `g` extruded into `layers` layers: node `i` of layer `k`
/// is `i·L + k`, the `u, v` links copied in every layer, `w` glued up.
fn extrude(g: &NodeGraph<2>, layers: usize) -> NodeGraph<3> {
    let n = g.n_nodes();
    let reverted = (0..n * layers)
        .map(|x| g.is_reverted(Node((x / layers) as u32)))
        .collect();
    let mut h = NodeGraph::<3>::new(reverted);
    let at = |i: usize, k: usize| Node((i * layers + k) as u32);
    for i in 0..n {
        if !g.is_alive(Node(i as u32)) {
            for k in 0..layers {
                h.alive[at(i, k).idx()] = false;
            }
            continue;
        }
        for k in 0..layers {
            if k + 1 < layers {
                let (a, b) = (h.side(at(i, k), UP), h.side(at(i, k + 1), DOWN));
                h.link(a, b, Rot3::IDENTITY).expect("w link");
            }
            for d in 0..4 {
                let a = g.side(Node(i as u32), d);
                let Some(b) = g.opposite(a) else { continue };
                if b.0 < a.0 {
                    continue;
                }
                let (j, e) = (g.node_of(b).idx(), g.dir_of(b));
                let r = to_3d(g.rotation(a).expect("rotation")).expect("3D");
                h.link(h.side(at(i, k), d), h.side(at(j, k), e), r)
                    .expect("u, v link");
            }
        }
    }
    h
}

/// A valence-7 disk split by a saddle lift into a valence-2 vertex and a
/// valence-8 one (as `fair_tests::split`).
fn split_disk() -> NodeGraph<2> {
    let mut g = singular_disk(7, K);
    let a = g.side(Node(0), 1);
    let c = g.side(Node(K as u32 * K as u32), 3);
    g.op2(a, c, Rot2::quarter_turns(3)).expect("lift");
    g.check().expect("valid");
    g
}

/// Fairing the columns of an extruded graph gives the extrusion of the
/// faired 2D graph, in every layer; the 3D cells are L × the 2D ones.
#[test]
fn fairing_columns_is_the_extrusion_of_2d_fairing() {
    for layers in [1, 3] {
        let g2 = split_disk();
        let mut want = g2.clone();
        let st2 = want.fair(10);
        let collapsed = want.collapse_folded_corners();
        assert_eq!((st2.merged, st2.lifts), (1, 1), "{st2:?}");
        let mut g3 = extrude(&g2, layers);
        g3.check().expect("valid before");
        let rep = g3.fair_columns(10).expect("columns");
        g3.check().expect("valid after");
        assert_eq!(rep.fairing, st2);
        assert_eq!((rep.collapsed, rep.layers), (collapsed, layers));
        assert_eq!(g3, extrude(&want, layers), "L = {layers}");
        assert_eq!(g3.glue().n_cells(), layers * want.glue().n_cells());
    }
}

/// A folded corner (valence-1 vertex) with no partner is collapsed: its
/// whole column goes.
#[test]
fn a_folded_column_is_removed() {
    let g2 = singular_disk(1, K);
    let mut want = g2.clone();
    want.fair(10);
    assert_eq!(want.collapse_folded_corners(), 1);
    let mut g3 = extrude(&g2, 2);
    let rep = g3.fair_columns(10).expect("columns");
    assert_eq!(rep.collapsed, 1);
    g3.check().expect("valid");
    assert_eq!(g3, extrude(&want, 2));
    assert_eq!(g3.n_alive(), 2 * want.n_alive());
}

/// Not columns: charts rotated so that `w` links are not the identity;
/// nothing is written.
#[test]
fn rotated_charts_are_not_columns() {
    let g = GridSpec::<3>::regular([2, 2, 3]).build();
    assert!(g.columns().is_some());
    let mut r = rotate_charts(&g, &random_rotations(g.n_nodes(), 7));
    let before = r.clone();
    assert!(r.fair_columns(10).is_none());
    assert_eq!(r, before);
}

/// Charts turned about `w` above the bottom layer (a column's nodes in
/// different triangles' charts): the frames carry them back, and the
/// result is the turned extrusion of the faired 2D graph.
#[test]
fn turned_charts_up_a_column_are_carried_by_frames() {
    let layers = 3;
    let g2 = split_disk();
    let mut want = g2.clone();
    want.fair(10);
    want.collapse_folded_corners();
    let turns: Vec<Rot3> = (0..g2.n_nodes() * layers)
        .map(|x| {
            let k = (x % layers) as i64 * (x as i64 + 1);
            to_3d(Rot2::quarter_turns(if x % layers == 0 { 0 } else { k })).expect("3D")
        })
        .collect();
    let mut g3 = rotate_charts(&extrude(&g2, layers), &turns);
    g3.check().expect("valid before");
    let rep = g3.fair_columns(10).expect("columns");
    assert_eq!((rep.fairing.merged, rep.fairing.lifts), (1, 1));
    g3.check().expect("valid after");
    assert_eq!(g3, rotate_charts(&extrude(&want, layers), &turns));
}

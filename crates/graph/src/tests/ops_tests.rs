//! OP2, OP1 and pleat removal on hand-built graphs; check() after each.

use crate::ids::{Node, Side};
use crate::{NodeGraph, OpError};
use dualex_map::{Rot, Rot2, Rot3};

const PU: usize = 0; // +u
const MU: usize = 1; // -u
const PV: usize = 2; // +v
const MV: usize = 3; // -v

fn s2(n: u32, d: usize) -> Side {
    Node(n).side::<2>(d)
}

#[test]
fn op2_composes_rotations() {
    // b=Z.+u ↔ a=X.-u, c=Y.-u ↔ e=W.+u; X normal, Y reverted, a ↔ c pleat
    for kz in 0..4 {
        for kw in 0..4 {
            let mut g = NodeGraph::<2>::new(vec![false, true, false, true]);
            let (x, y, z, w) = (0, 1, 2, 3);
            // Z → X: rotation rz; Z's side so that X.-u = rz(Z.side ^ 1)
            let rz = Rot2::quarter_turns(kz);
            let zd = rz.inverse().apply_dir(MU) ^ 1;
            g.link(s2(z, zd), s2(x, MU), rz).unwrap();
            // Y → W pleat-free (both reverted): W's side = rw(-u ^ 1)
            let rw = Rot2::quarter_turns(kw);
            g.link(s2(y, MU), s2(w, rw.apply_dir(PU)), rw).unwrap();
            g.check().unwrap();
            let out = g.op2(s2(x, MU), s2(y, MU), Rot::IDENTITY).unwrap();
            g.check().unwrap();
            let e = s2(w, rw.apply_dir(PU));
            assert_eq!(out.new_pair, Some((s2(z, zd), e)));
            assert_eq!(out.unmatched_partners, 0);
            assert_eq!(g.rotation(s2(z, zd)), Some(rz.then(&rw)));
            assert_eq!(g.opposite(s2(x, MU)), Some(s2(y, MU)));
            assert!(g.is_pleat(s2(z, zd)));
        }
    }
}

#[test]
fn op2_preconditions_write_nothing() {
    let mut g = NodeGraph::<2>::new(vec![false, true, false]);
    g.link(s2(0, PU), s2(1, PU), Rot::IDENTITY).unwrap();
    let before = g.clone();
    let q = Rot2::quarter_turns(1);
    assert_eq!(
        g.op2(s2(0, PU), s2(1, PU), q),
        Err(OpError::AlreadyGlued(s2(0, PU)))
    );
    assert_eq!(
        g.op2(s2(0, MU), s2(0, MU), q),
        Err(OpError::SameSide(s2(0, MU)))
    );
    // same flags need t = ρ(s ^ 1): +u ↔ +u with identity breaks it
    assert_eq!(
        g.op2(s2(0, MV), s2(2, MV), Rot::IDENTITY),
        Err(OpError::LabelRule(s2(0, MV)))
    );
    assert_eq!(
        g.op2(s2(0, MV), Side(400), q),
        Err(OpError::OutOfRange(Side(400)))
    );
    assert_eq!(g, before);
    g.alive[2] = false;
    assert_eq!(
        g.op2(s2(0, MV), s2(2, PV), q),
        Err(OpError::Dead(s2(2, PV)))
    );
}

#[test]
fn op2_with_unmatched_partners() {
    // one partner: b = Z.+u ↔ X.-u, Y.-u free → Z.+u becomes unmatched
    let mut g = NodeGraph::<2>::new(vec![false, true, false]);
    g.link(s2(2, PU), s2(0, MU), Rot::IDENTITY).unwrap();
    let out = g.op2(s2(0, MU), s2(1, MU), Rot::IDENTITY).unwrap();
    g.check().unwrap();
    assert_eq!((out.new_pair, out.unmatched_partners), (None, 1));
    assert_eq!(g.opposite(s2(2, PU)), None);
    // both free
    let out = g.op2(s2(0, PV), s2(1, PV), Rot::IDENTITY).unwrap();
    g.check().unwrap();
    assert_eq!(out.unmatched_partners, 2);
}

#[test]
fn op1_needs_an_isolated_pair() {
    let mut g = NodeGraph::<2>::new(vec![false, true, false]);
    for d in 0..3 {
        g.link(s2(0, d), s2(1, d), Rot::IDENTITY).unwrap();
    }
    let before = g.clone();
    assert_eq!(
        g.op1(Node(0), Node(1)),
        Err(OpError::NotIsolated(Node(0), Node(1)))
    );
    assert_eq!(
        g.op1(Node(0), Node(0)),
        Err(OpError::NotIsolated(Node(0), Node(0)))
    );
    assert_eq!(g, before);
    g.link(s2(0, MV), s2(1, MV), Rot::IDENTITY).unwrap();
    g.op1(Node(0), Node(1)).unwrap();
    g.check().unwrap();
    assert_eq!((g.n_alive(), g.unmatched_sides()), (1, 4));
    assert_eq!(g.op1(Node(0), Node(2)), Err(OpError::Dead(s2(0, 0))));
}

#[test]
fn remove_pleat_preconditions() {
    let mut g = NodeGraph::<2>::new(vec![false, true, false]);
    g.link(s2(0, PU), s2(2, MU), Rot::IDENTITY).unwrap();
    assert_eq!(g.remove_pleat(s2(0, PU)), Err(OpError::NotPleat(s2(0, PU))));
    assert_eq!(
        g.remove_pleat(s2(0, PV)),
        Err(OpError::Unmatched(s2(0, PV)))
    );
    // a pleat breaking the label rule: X.+v ↔ Y.-v (needs Y.+v)
    g.link(s2(0, PV), s2(1, MV), Rot::IDENTITY).unwrap();
    let before = g.clone();
    assert_eq!(
        g.remove_pleat(s2(0, PV)),
        Err(OpError::LabelRule(s2(0, PV)))
    );
    assert_eq!(g, before);
}

#[test]
fn remove_pleat_self_loop_and_partner_in_pleat() {
    // X normal, Y reverted, pleat X.+u ↔ Y.+u; Z normal with
    // Z.+u ↔ X.-u and Z.-u ↔ Y.-u (a pleat too): removal closes Z on itself
    let mut g = NodeGraph::<2>::new(vec![false, true, false]);
    g.link(s2(0, PU), s2(1, PU), Rot::IDENTITY).unwrap();
    g.link(s2(2, PU), s2(0, MU), Rot::IDENTITY).unwrap();
    g.link(s2(2, MU), s2(1, MU), Rot::IDENTITY).unwrap();
    // and X glued to itself along v: X.+v ↔ X.-v
    g.link(s2(0, PV), s2(0, MV), Rot::IDENTITY).unwrap();
    g.check().unwrap();
    let out = g.remove_pleat(s2(0, PU)).unwrap();
    g.check().unwrap();
    assert_eq!(out.new_pairs, vec![s2(2, PU)]);
    assert_eq!(g.opposite(s2(2, PU)), Some(s2(2, MU)));
    assert_eq!((out.self_loops, out.partner_in_pleat, out.op2), (1, 1, 3));
    assert_eq!((out.one_boundary, out.both_boundary), (1, 1));
    assert_eq!(g.n_alive(), 1);
}

#[test]
fn remove_pleat_bigon() {
    // X and Y face each other on +u and +v (two pleat pairs, ρ = identity)
    let mut g = NodeGraph::<2>::new(vec![false, true]);
    g.link(s2(0, PU), s2(1, PU), Rot::IDENTITY).unwrap();
    g.link(s2(0, PV), s2(1, PV), Rot::IDENTITY).unwrap();
    let out = g.remove_pleat(s2(0, PU)).unwrap();
    g.check().unwrap();
    assert_eq!((out.bigon_sides, out.op2, out.both_boundary), (1, 2, 2));
    assert_eq!(g.n_alive(), 0);
}

#[test]
fn remove_pleat_3d_every_rotation() {
    // X normal, Y reverted glued on X.+w ↔ Y.ρ(+w); neighbours A (of X
    // along -w) and B (of Y on the side matching -w) become glued
    for rho in Rot3::all() {
        let mut g = NodeGraph::<3>::new(vec![false, true, false, true]);
        let (x, y, a, b) = (Node(0), Node(1), Node(2), Node(3));
        g.link(x.side::<3>(4), y.side::<3>(rho.apply_dir(4)), rho)
            .unwrap();
        g.link(a.side::<3>(4), x.side::<3>(5), Rot::IDENTITY)
            .unwrap();
        let yd = rho.apply_dir(5);
        g.link(y.side::<3>(yd), b.side::<3>(yd ^ 1), Rot::IDENTITY)
            .unwrap();
        g.check().unwrap();
        let out = g.remove_pleat(x.side::<3>(4)).unwrap();
        g.check().unwrap();
        let ab = g.opposite(a.side::<3>(4));
        assert_eq!(ab, Some(b.side::<3>(yd ^ 1)), "{rho:?}");
        assert_eq!(g.rotation(a.side::<3>(4)), Some(rho), "{rho:?}");
        assert!(g.is_pleat(a.side::<3>(4)));
        assert_eq!((out.op2, out.both_boundary, out.new_pairs.len()), (5, 4, 1));
    }
}

//! [`Mover::round`] against the planned form kept as its oracle
//! ([`Mover::round_planned`]): on every generated map of both dimensions
//! (collapsed squares: clusters; disks: singular vertices and stuck
//! clusters; wedges: free axes; folds and noise: vertices on isos in
//! several charts), through every round of the amplitude schedule, with
//! the scan's bad lists and random subsets of the vertices, two movers
//! side by side must move the same vertices by the same bits and leave
//! their generators at the same place.

use super::mover::Mover;
use super::{free_axes, Dim, Predicates, Scan};
use crate::cluster::Clusters;
use crate::local::LocalMap;
use crate::sanitize_report::amplitude;
use crate::sanitize_report::ROUNDS;
use dualex_map::{SimplexMap, Stars, Topology, Transitions};
use dualex_util::rng::SplitMix;

/// Whether two movers are in the same state after a round.
fn assert_same<const D: usize>(a: &Mover<'_, D>, b: &Mover<'_, D>, what: &str) {
    assert_eq!(a.touched, b.touched, "{what}: touched");
    let bits = |m: &Mover<'_, D>| -> Vec<[u64; D]> {
        m.deltas.iter().map(|d| d.map(f64::to_bits)).collect()
    };
    assert_eq!(bits(a), bits(b), "{what}: deltas");
    assert_eq!(
        a.rng.clone().next_u64(),
        b.rng.clone().next_u64(),
        "{what}: rng"
    );
    assert_eq!(a.moved, b.moved, "{what}: moved");
    assert_eq!(a.moved_singular, b.moved_singular, "{what}: moved singular");
    assert_eq!(a.stuck, b.stuck, "{what}: stuck");
    assert_eq!(a.apart, b.apart, "{what}: apart");
    assert_eq!(a.epoch, b.epoch, "{what}: epoch");
}

/// Every round of the schedule on `map`: the scan's bad list first, then
/// random sorted subsets of the vertices (empty, one, all, a fifth).
/// Returns whether the map had no non-trivial cluster (the lone path).
fn rounds_agree<const N: usize, const D: usize>(map: &SimplexMap<N, D>, name: &str) -> bool
where
    Dim<N, D>: Predicates<N, D>,
{
    let Ok(topo) = Topology::build(map) else {
        return false;
    };
    let Ok((trans, _)) = Transitions::derive(map, &topo, &Default::default()) else {
        return false;
    };
    let stars = Stars::build(map, &topo, &trans);
    let mut local = LocalMap::new(map, &topo, &trans);
    let free = if D == 3 {
        free_axes(&topo, &stars, &local)
    } else {
        Vec::new()
    };
    local.snap(&stars);
    let clusters = Clusters::build(map, &stars, &local.coords);
    let nv = map.positions.len() as u32;
    let mut a = Mover::new(&stars, &clusters, &free, 11);
    let mut b = Mover::new(&stars, &clusters, &free, 11);
    let mut pick = SplitMix::new(3);
    let bad = Scan::new(map, &local.coords).list();
    for round in 0.. {
        let Some(amp) = amplitude(round) else {
            break;
        };
        let last_resort = round >= ROUNDS;
        let from: Vec<u32> = match round % 5 {
            0 => bad.clone(),
            1 => Vec::new(),
            2 => vec![round as u32 % nv.max(1)],
            3 => (0..nv).collect(),
            _ => (0..nv).filter(|_| pick.unit() < 0.2).collect(),
        };
        let todo = a.movable(&from, last_resort);
        assert_eq!(todo, b.movable(&from, last_resort), "{name} round {round}");
        for m in [&mut a, &mut b] {
            m.touched.clear();
            m.deltas.clear();
        }
        a.round::<N>(&todo, amp, last_resort);
        b.round_planned::<N>(&todo, amp, last_resort);
        assert_same(&a, &b, &format!("{name} round {round}"));
    }
    clusters.count_nontrivial() == 0
}

#[test]
fn rounds_equal_planned_rounds_on_every_generated_map() {
    let mut lone = 0;
    for name in dualex_gen::names() {
        for seed in [1, 2] {
            let Some((map, _)) = dualex_gen::by_name(&name, seed) else {
                continue;
            };
            lone += usize::from(rounds_agree(&map, &name));
        }
    }
    for name in dualex_gen::names_3d() {
        let Some((map, _)) = dualex_gen::by_name_3d(&name, 1) else {
            continue;
        };
        lone += usize::from(rounds_agree(&map, &name));
    }
    // the lone path was taken (and compared) on most maps
    assert!(lone >= 20, "{lone} maps without clusters");
}

/// A vertex with a free axis in a round keeps the round planned: the
/// wedge's singular edge vertices move along their axis only.
#[test]
fn free_axes_keep_the_planned_round() {
    let Some((map, _)) = dualex_gen::by_name_3d("wedge_p1", 1) else {
        panic!("wedge_p1");
    };
    let topo = Topology::build(&map).unwrap_or_else(|e| panic!("{e}"));
    let (trans, _) =
        Transitions::derive(&map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
    let stars = Stars::build(&map, &topo, &trans);
    let local = LocalMap::new(&map, &topo, &trans);
    let free = free_axes(&topo, &stars, &local);
    let with_axis: Vec<u32> = (0..free.len() as u32)
        .filter(|&v| free[v as usize].is_some())
        .collect();
    assert!(!with_axis.is_empty());
    let clusters = Clusters::build(&map, &stars, &local.coords);
    let mut a = Mover::new(&stars, &clusters, &free, 5);
    let mut b = Mover::new(&stars, &clusters, &free, 5);
    let todo: Vec<u32> = (0..map.positions.len() as u32).collect();
    a.round::<4>(&todo, 1e-5, false);
    b.round_planned::<4>(&todo, 1e-5, false);
    assert_same(&a, &b, "wedge");
    assert_eq!(a.moved_singular.len(), with_axis.len());
}

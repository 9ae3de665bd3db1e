//! The parallel linking of a fresh graph against the serial loop, on
//! random ends: mutual pairs with matching and mismatching rotations,
//! sides reaching themselves, walks to a side that walked elsewhere or
//! out of range, and the other ends.

use super::*;
use dualex_map::Rot2;
use dualex_util::rng::SplitMix;

/// Random ends for `n` nodes of dimension `D`: about half of the sides
/// in mutual pairs, the rest anything.
fn random_ends<const D: usize>(rng: &mut SplitMix, n: usize) -> Vec<End<D>> {
    let sides = n * 2 * D;
    let rots = Rot::<D>::all();
    let rot = |rng: &mut SplitMix| rots[rng.below(rots.len())];
    let mut ends = vec![End::Boundary; sides];
    let mut order: Vec<usize> = (0..sides).collect();
    rng.shuffle(&mut order);
    for pair in order.chunks(2) {
        let a = pair[0];
        let b = *pair.get(1).unwrap_or(&a);
        match rng.below(8) {
            0..=3 => {
                let rho = rot(rng);
                // a quarter of the pairs with rotations that disagree
                let back = if rng.below(4) == 0 {
                    rot(rng)
                } else {
                    rho.inverse()
                };
                ends[a] = End::Node {
                    side: b as u32,
                    rho,
                };
                ends[b] = End::Node {
                    side: a as u32,
                    rho: back,
                };
            }
            4 => {
                ends[a] = End::Node {
                    side: a as u32,
                    rho: rot(rng),
                }
            }
            5 => {
                ends[a] = End::Node {
                    side: b as u32,
                    rho: rot(rng),
                };
                ends[b] = End::Node {
                    side: rng.below(sides + 3) as u32,
                    rho: rot(rng),
                };
            }
            6 => {
                ends[a] = End::Node {
                    side: (sides + rng.below(3)) as u32,
                    rho: rot(rng),
                }
            }
            _ => {
                ends[a] = [End::Boundary, End::Inconsistent, End::Loop][rng.below(3)];
                ends[b] = End::Loop;
            }
        }
    }
    ends
}

/// The opposite and rotation of every side.
fn glued<const D: usize>(g: &NodeGraph<D>) -> Vec<(Option<Side>, Option<Rot<D>>)> {
    (0..g.n_sides() as u32)
        .map(|s| (g.opposite(Side(s)), g.rotation(Side(s))))
        .collect()
}

fn same_as_serial<const D: usize>(seed: u64) {
    let mut rng = SplitMix::new(seed);
    for n in [0, 1, 2, 3, 17, 1000, 5000] {
        let ends = random_ends::<D>(&mut rng, n);
        let mut fresh = NodeGraph::<D>::new(vec![false; n]);
        let mut serial = NodeGraph::<D>::new(vec![false; n]);
        assert!(n == 0 || fresh.is_fresh());
        let got = fresh.link_mutual(&ends);
        let want = serial.link_mutual_serial(&ends);
        assert_eq!(got, want, "D {D}, {n} nodes");
        assert_eq!(glued(&fresh), glued(&serial), "D {D}, {n} nodes");
        assert!(got.non_mutual + got.rotation_mismatches > 0 || n < 17);
        // glued both ways, with inverse rotations (random pairs break the
        // label rule, which linking does not check)
        for s in 0..fresh.n_sides() as u32 {
            if let Some(o) = fresh.opposite(Side(s)) {
                assert_eq!(fresh.opposite(o), Some(Side(s)));
                let (r, q) = (fresh.rotation(Side(s)), fresh.rotation(o));
                assert_eq!(r.map(|r| r.inverse()), q);
            }
        }
    }
}

#[test]
fn fresh_links_as_the_serial_loop() {
    for seed in 1..6 {
        same_as_serial::<2>(seed);
        same_as_serial::<3>(seed);
    }
}

/// A graph that is not fresh (a dead node, a side glued before) goes the
/// serial way, with its errors counted.
#[test]
fn a_used_graph_links_one_pair_after_the_other() {
    let id = Rot2::IDENTITY;
    let mut ends = vec![End::Boundary; 12];
    ends[0] = End::Node { side: 5, rho: id };
    ends[5] = End::Node { side: 0, rho: id };
    ends[2] = End::Node { side: 9, rho: id };
    ends[9] = End::Node { side: 2, rho: id };
    let mut g = NodeGraph::<2>::new(vec![false; 3]);
    g.link(Side(1), Side(4), id).expect("link");
    assert!(!g.is_fresh());
    g.unlink(Side(1)).expect("unlink");
    assert!(g.is_fresh());
    g.alive[2] = false;
    assert!(!g.is_fresh());
    let rep = g.link_mutual(&ends);
    // 0 ↔ 5 linked; 2 ↔ 9 not (node 2 is dead)
    assert_eq!((rep.non_mutual, rep.rotation_mismatches), (1, 0));
    assert_eq!(g.opposite(Side(0)), Some(Side(5)));
    assert_eq!(g.opposite(Side(2)), None);
}

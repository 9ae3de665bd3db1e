//! [`walk_all_paired`] against [`walk_all`] on made-up walks: random
//! sides reaching each other in mutual pairs (rotations inverse), walks
//! that are not answered, ends off the nodes; `back` said exactly where
//! the reached side's walk is the reverse.

use super::*;
use dualex_map::Rot3;
use dualex_util::rng::SplitMix;

/// Random walks of `n` nodes (3D sides): `(end, steps)` per side.
fn made_up(n: usize, seed: u64) -> Vec<(End<3>, usize)> {
    let mut rng = SplitMix::new(seed);
    let rots = Rot3::all();
    let sides = n * 6;
    let mut walks: Vec<(End<3>, usize)> = (0..sides)
        .map(|_| match rng.below(4) {
            0 => (End::Boundary, rng.below(9)),
            1 => (End::Inconsistent, rng.below(9)),
            _ => (End::Loop, 40),
        })
        .collect();
    let mut order: Vec<usize> = (0..sides).collect();
    rng.shuffle(&mut order);
    for pair in order.chunks(2) {
        let [a, b] = pair else { continue };
        let rho = rots[rng.below(24)];
        let steps = rng.below(30);
        walks[*a] = (
            End::Node {
                side: *b as u32,
                rho,
            },
            steps,
        );
        match rng.below(4) {
            // not answered, or answered with another rotation
            0 => {}
            1 => {
                let rho = rho.then(&rots[1 + rng.below(23)]);
                walks[*b] = (
                    End::Node {
                        side: *a as u32,
                        rho,
                    },
                    steps,
                );
            }
            _ => {
                let rho = rho.inverse();
                walks[*b] = (
                    End::Node {
                        side: *a as u32,
                        rho,
                    },
                    steps,
                );
            }
        }
    }
    walks
}

/// Whether the walk from the side `walks[s]` reached is `walks[s]`
/// reversed.
fn comes_back(walks: &[(End<3>, usize)], s: usize) -> bool {
    let (End::Node { side, rho }, steps) = walks[s] else {
        return false;
    };
    let back = End::Node {
        side: s as u32,
        rho: rho.inverse(),
    };
    walks[side as usize] == (back, steps)
}

#[test]
fn paired_walks_equal_every_side_walked() {
    for (n, seed) in [(1, 1), (2, 2), (7, 3), (500, 4), (3000, 5)] {
        let walks = made_up(n, seed);
        let want = walk_all::<3>(n, |m, d| walks[m * 6 + d]);
        let got = walk_all_paired::<3>(n, |m, d| {
            let (end, steps) = walks[m * 6 + d];
            (end, steps, comes_back(&walks, m * 6 + d))
        });
        assert_eq!(got, want, "{n} nodes");
        // `back` said of every walk to a node: the unanswered walks'
        // targets take the reverse's end
        let lied = walk_all_paired::<3>(n, |m, d| {
            let (end, steps) = walks[m * 6 + d];
            (end, steps, matches!(end, End::Node { .. }))
        });
        if n >= 7 {
            assert_ne!(lied, want, "{n} nodes");
        }
    }
}

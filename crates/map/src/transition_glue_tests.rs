//! Tests of `transition_glue` against its reference, `glue_with` then
//! `derive` (the two passes it replaces): the same topology, the same
//! transitions and report, the same errors, on generated maps re-charted
//! at random (every facet a seam), with noise of every size (rounded,
//! refused, non-grid rotations), collapsed corners (ambiguous facets),
//! far and overflowing coordinates, flipped and duplicated simplices,
//! the simplices shuffled (the glue's bucket order far from facet order),
//! with and without `round`.

use super::*;
use crate::test_maps::{cone, cube_surface, flat_torus, grid, rechart, tet_cube, Lcg};

/// The reference's result as comparable values: the glue's error, or
/// the topology and the transitions and report, or their error.
type Outcome<const N: usize, const D: usize> = Result<
    (
        (Vec<[u32; N]>, Vec<[u8; N]>, Vec<[[u8; N]; N]>, usize),
        Result<(Vec<[Rot<D>; N]>, Vec<[[i64; D]; N]>, String), String>,
    ),
    String,
>;

fn outcome<const N: usize, const D: usize>(
    glued: Result<(Topology<N>, Derived<N, D>), InputError>,
) -> Outcome<N, D> {
    let (topo, derived) = glued.map_err(|e| e.to_string())?;
    let t = (
        topo.adj,
        topo.adj_facet,
        topo.nbr_corner,
        topo.boundary_facets,
    );
    let d = derived
        .map(|(tr, rep)| (tr.rot, tr.trans, format!("{rep:?}")))
        .map_err(|e| e.to_string());
    Ok((t, d))
}

/// `glue_derive` against `glue_with` then `derive`.
fn same<const N: usize, const D: usize>(map: &SimplexMap<N, D>, opts: &TransitionOptions) {
    let corners = VertexCorners::build(&map.simplices, map.positions.len(), false);
    let reference = Topology::glue_with(map, &corners).map(|topo| {
        let derived = Transitions::derive(map, &topo, opts);
        (topo, derived)
    });
    let want = outcome(reference);
    let got = outcome(glue_derive(map, &corners, opts));
    assert_eq!(got, want);
}

/// The map with its simplices (and their charts) in a random order.
fn shuffled<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    rng: &mut Lcg,
) -> SimplexMap<N, D> {
    let mut order: Vec<usize> = (0..map.len()).collect();
    for i in (1..order.len()).rev() {
        order.swap(i, rng.below(i as u64 + 1) as usize);
    }
    SimplexMap {
        positions: map.positions.clone(),
        simplices: order.iter().map(|&s| map.simplices[s]).collect(),
        coords: order.iter().map(|&s| map.coords[s]).collect(),
    }
}

/// Damage of one kind at a random simplex: noise of a random size on one
/// corner, a corner collapsed onto another, a huge coordinate, the
/// simplex flipped, or duplicated, or its whole chart moved.
fn damage<const N: usize, const D: usize>(map: &mut SimplexMap<N, D>, rng: &mut Lcg) {
    let s = rng.below(map.len() as u64) as usize;
    let c = rng.below(N as u64) as usize;
    let k = rng.below(D as u64) as usize;
    const NOISE: [f64; 8] = [1e-9, 1e-4, 2e-3, 0.05, 0.2, 0.3, 0.5, 1.0];
    match rng.below(12) {
        0..=5 => {
            let x = NOISE[rng.below(NOISE.len() as u64) as usize];
            map.coords[s][c][k] += if rng.below(2) == 0 { x } else { -x };
        }
        6 | 7 => {
            // the vertex collapsed onto another of the simplex, in every
            // simplex around it (the same offset in each chart)
            let v = map.simplices[s][c];
            let (to, from) = (map.coords[s][(c + 1) % N], map.coords[s][c]);
            for (simplex, coords) in map.simplices.iter().zip(map.coords.iter_mut()) {
                for (&w, p) in simplex.iter().zip(coords.iter_mut()) {
                    if w == v && *p == from {
                        *p = to;
                    }
                }
            }
        }
        8 => map.coords[s][c][k] = if rng.below(2) == 0 { 1.5e308 } else { -1.5e308 },
        9 => {
            map.simplices[s].swap(0, 1);
            map.coords[s].swap(0, 1);
        }
        10 => {
            map.simplices.push(map.simplices[s]);
            map.coords.push(map.coords[s]);
        }
        _ => {
            // the whole chart moved: a residual (refused, rounded) or a
            // far integral translation
            let x = [0.3, 0.05, 0.45, 1e12][rng.below(4) as usize];
            for p in map.coords[s].iter_mut() {
                p[k] += x;
            }
        }
    }
}

/// Many random variants of `base`: re-charted or not, damaged 0–3
/// times, shuffled, with the default options and with `round`.
fn many<const N: usize, const D: usize>(base: &SimplexMap<N, D>, seeds: u64) {
    let round = TransitionOptions {
        round: true,
        ..Default::default()
    };
    for seed in 0..seeds {
        let mut rng = Lcg(seed * 7919 + 1);
        let mut map = base.clone();
        if seed % 3 != 0 {
            rechart(&mut map, seed);
        }
        for _ in 0..rng.below(4) {
            damage(&mut map, &mut rng);
        }
        let map = if seed % 2 == 0 {
            shuffled(&map, &mut rng)
        } else {
            map
        };
        same(&map, &TransitionOptions::default());
        same(&map, &round);
    }
}

#[test]
fn triangles_as_derive() {
    many(&grid(7), 300);
    many(&flat_torus(6), 120);
    many(&cube_surface(3), 120);
    many(&cone(5), 60);
}

#[test]
fn tets_as_derive() {
    many(&tet_cube(2), 200);
}

/// Several refused facets in one map (non-grid rotations; or equal
/// residuals): the least facet is named, whatever the order the glue
/// meets them in.
#[test]
fn the_least_facets_error_is_named() {
    for seed in 0..60 {
        let mut rng = Lcg(seed + 100);
        let mut map = grid(8);
        rechart(&mut map, seed);
        let x = [0.3, 0.4, 0.2, 1.0][seed as usize % 4];
        for _ in 0..3 + rng.below(4) {
            let s = rng.below(map.len() as u64) as usize;
            let k = rng.below(2) as usize;
            if seed % 2 == 0 {
                // a non-grid rotation
                map.coords[s][rng.below(3) as usize][k] += x;
            } else {
                // the whole chart moved: equal residuals, the least named
                for p in map.coords[s].iter_mut() {
                    p[k] += x;
                }
            }
        }
        same(&shuffled(&map, &mut rng), &TransitionOptions::default());
    }
}

/// The merge of two tallies is commutative: a block's fits come before
/// or after another's by the blocks' order, not the facets'.
#[test]
fn the_merge_is_commutative() {
    let opts = TransitionOptions::default();
    let fit = |residual: f64, tol: f64| {
        Ok(crate::transition_fit::Fit::<2> {
            rot: Rot::IDENTITY,
            trans: [0.0; 2],
            rounded: [0; 2],
            residual,
            tol,
            ambiguous: None,
        })
    };
    let mut rng = Lcg(5);
    for _ in 0..200 {
        let facets: Vec<(u32, f64)> = (0..6)
            .map(|_| {
                (
                    rng.below(20) as u32,
                    [0.0, 0.05, 0.3, 0.3][rng.below(4) as usize],
                )
            })
            .collect();
        let tally = |part: &[(u32, f64)]| {
            let mut t = Unordered::<2>::default();
            for &(h, r) in part {
                t.add(h, fit(r, 1e-3), &opts);
            }
            t
        };
        let cut = rng.below(7) as usize;
        let (a, b) = (tally(&facets[..cut]), tally(&facets[cut..]));
        let (c, d) = (tally(&facets[..cut]), tally(&facets[cut..]));
        let (ab, ba) = (a.merge(b), d.merge(c));
        assert_eq!(
            (ab.worst, ab.failed, ab.snapped),
            (ba.worst, ba.failed, ba.snapped)
        );
    }
}

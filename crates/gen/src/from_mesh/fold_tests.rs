//! Tests of the folds at singular vertices: exact GP, the centres and
//! every vertex away from them still, simplices flipped near the centres,
//! at every k; `magnify` scales the coordinates only.

use super::meshes::*;
use super::refine::Refined;
use super::tests::gp_residual_3d;
use super::*;
use crate::testing::gp_residual;
use dualex_map::SimplexMap;

fn with_folds(k: usize, seed: u64) -> FromMeshOptions {
    FromMeshOptions {
        scale: k,
        singular_folds: 8,
        seed,
        ..Default::default()
    }
}

/// Checks `folded` against `clean` (same options, no folds): centres and
/// vertices of no element holding a centre keep their coordinates;
/// returns the number of flipped simplices.
fn compare<const N: usize, const D: usize>(
    what: &str,
    folded: &SimplexMap<N, D>,
    clean: &SimplexMap<N, D>,
    r: &Refined<D>,
    centres: &[u32],
) -> usize {
    assert!(!centres.is_empty(), "{what}: no centre");
    let mut near = vec![false; folded.positions.len()];
    for e in 0..r.elements {
        let corner = |b: usize| r.id(e, std::array::from_fn(|a| r.k * (b >> a & 1)));
        if (0..1usize << D).any(|b| centres.contains(&corner(b))) {
            let side = r.k + 1;
            for i in 0..side.pow(D as u32) {
                let lat: [usize; D] = std::array::from_fn(|a| i / side.pow(a as u32) % side);
                near[r.id(e, lat) as usize] = true;
            }
        }
    }
    for (s, t) in folded.simplices.iter().enumerate() {
        for (c, &v) in t.iter().enumerate() {
            let still = centres.contains(&v) || !near[v as usize];
            if still && v < near.len() as u32 {
                assert_eq!(
                    folded.coords[s][c], clean.coords[s][c],
                    "{what}: vertex {v}"
                );
            }
        }
    }
    (0..folded.len())
        .filter(|&s| folded.map_det(s) < 0.0)
        .count()
}

#[test]
fn hex_folds_stay_exact_and_move_only_around_the_centres() {
    for name in ["cubed_ball_sub", "ball_cutout5", "polycube_notch"] {
        let m = hex_mesh_by_name(name).unwrap_or_else(|| panic!("{name}"));
        for k in 1..=3 {
            for seed in 1..=2 {
                let o = with_folds(k, seed);
                let what = format!("{name} k {k} seed {seed}");
                let g = from_hexes(&m, &o).unwrap_or_else(|e| panic!("{what}: {e}"));
                let clean = from_hexes(&m, &opts_clean(k)).unwrap();
                assert_eq!(gp_residual_3d(&g.map), 0.0, "{what}");
                let r = Refined::<3>::new(&m.positions, &m.cells, k).unwrap();
                let centres = fold::centres(&r, &g.classes, 8, seed);
                let flipped = compare(&what, &g.map, &clean.map, &r, &centres);
                assert!(flipped > 0, "{what}: nothing flipped");
            }
        }
    }
}

fn opts_clean(k: usize) -> FromMeshOptions {
    FromMeshOptions {
        scale: k,
        ..Default::default()
    }
}

#[test]
fn quad_folds_stay_exact_and_move_only_around_the_centres() {
    for name in ["ngon5", "ngon8", "prism5_poles", "cube6"] {
        let m = quad_mesh_by_name(name).unwrap_or_else(|| panic!("{name}"));
        for k in 2..=3 {
            for seed in 1..=2 {
                let o = with_folds(k, seed);
                let what = format!("{name} k {k} seed {seed}");
                let g = from_quads(&m, &o).unwrap_or_else(|e| panic!("{what}: {e}"));
                let clean = from_quads(&m, &opts_clean(k)).unwrap();
                assert_eq!(gp_residual(&g.map), 0.0, "{what}");
                let r = Refined::<2>::new(&m.positions, &m.cells, k).unwrap();
                let centres = fold::centres(&r, &g.classes, 8, seed);
                let flipped = compare(&what, &g.map, &clean.map, &r, &centres);
                assert!(flipped > 0, "{what}: nothing flipped");
            }
        }
    }
}

#[test]
fn magnify_multiplies_the_coordinates_and_refines_the_expectation() {
    let m = hex_mesh_by_name("polycube_notch").unwrap();
    let one = from_hexes(&m, &with_folds(1, 3)).unwrap();
    let o = FromMeshOptions {
        magnify: 3,
        ..with_folds(1, 3)
    };
    let three = from_hexes(&m, &o).unwrap();
    assert_eq!(three.map.simplices, one.map.simplices);
    for (a, b) in three
        .map
        .coords
        .iter()
        .flatten()
        .zip(one.map.coords.iter().flatten())
    {
        assert_eq!(*a, b.map(|x| 3.0 * x));
    }
    let res = gp_residual_3d(&three.map);
    assert_eq!(res, 0.0, "{res}");
    let k3 = from_hexes(&m, &opts_clean(3)).unwrap();
    assert_eq!(three.refined.cells.len(), k3.refined.cells.len());
    assert_eq!(three.expected, k3.expected);
}

/// Percentage of flipped simplices among those of the elements holding a
/// centre (the folds' support).
fn flipped_near_centres(name: &str, k: usize, seed: u64) -> f64 {
    let m = hex_mesh_by_name(name).unwrap_or_else(|| panic!("{name}"));
    let g = from_hexes(&m, &with_folds(k, seed)).unwrap_or_else(|e| panic!("{name}: {e}"));
    let r = Refined::<3>::new(&m.positions, &m.cells, k).unwrap();
    let centres = fold::centres(&r, &g.classes, 8, seed);
    let per_element = g.map.len() / r.elements;
    let holds = |e: usize| {
        (0..8).any(|b| centres.contains(&r.id(e, std::array::from_fn(|a| k * (b >> a & 1)))))
    };
    let near: Vec<usize> = (0..g.map.len())
        .filter(|&s| holds(s / per_element))
        .collect();
    let flipped = near.iter().filter(|&&s| g.map.map_det(s) < 0.0).count();
    100.0 * flipped as f64 / near.len() as f64
}

/// The folds are the same in element units at every k, but the refined
/// map (`scale` k) resolves them on k³ times more simplices: many more of
/// those around a centre flip than at k = 1 (the 7–22 % is the
/// k = 1 figure; `magnify` is what keeps the k = 1 map). Figures in
/// docs/messy-cases.md, "Folds centred on singular vertices".
#[test]
fn refined_folds_flip_more_simplices_near_the_centres_than_at_k1() {
    for name in [
        "ball_cutout4",
        "ball_cutout5",
        "ball_hole69",
        "polycube_notch",
    ] {
        for seed in 1..=2 {
            let f: Vec<f64> = (1..=3)
                .map(|k| flipped_near_centres(name, k, seed))
                .collect();
            eprintln!("{name} seed {seed}: flipped near the centres, k = 1, 2, 3: {f:.1?} %");
            assert!(f[1] > f[0] && f[2] > f[0], "{name} seed {seed}: {f:?}");
        }
    }
}

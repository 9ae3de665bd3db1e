//! [`crate::glued`] against [`crate::topology`] on random pieces of a
//! triangle grid and of a tet block (holes, several components, boundary
//! loops and surfaces), each kept only when it is a map the extraction
//! accepts (no facet of three simplices, vertex stars connected across
//! facets: the module's preconditions).

use crate::glued::{self, NONE};
use crate::topology;
use dualex_util::rng::SplitMix;
use std::collections::HashMap;

/// The facet adjacency of `simplices` by equal vertex sets (`None`: a
/// facet of more than two simplices).
fn adjacency<const N: usize>(simplices: &[[u32; N]]) -> Option<Vec<[u32; N]>> {
    let mut first: HashMap<Vec<u32>, usize> = HashMap::new();
    let mut adj = vec![[NONE; N]; simplices.len()];
    for (s, simplex) in simplices.iter().enumerate() {
        for f in 0..N {
            let mut key: Vec<u32> = (1..N).map(|i| simplex[(f + i) % N]).collect();
            key.sort_unstable();
            match first.get(&key) {
                None => {
                    first.insert(key, N * s + f);
                }
                Some(&p) if adj[p / N][p % N] == NONE => {
                    adj[p / N][p % N] = s as u32;
                    adj[s][f] = (p / N) as u32;
                }
                Some(_) => return None,
            }
        }
    }
    Some(adj)
}

/// Whether the simplices around every vertex are connected through the
/// facets that hold it.
fn stars_connected<const N: usize>(n: usize, simplices: &[[u32; N]], adj: &[[u32; N]]) -> bool {
    let mut star: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (s, simplex) in simplices.iter().enumerate() {
        for &v in simplex {
            star[v as usize].push(s);
        }
    }
    star.iter().enumerate().all(|(v, around)| {
        let Some(&first) = around.first() else {
            return true;
        };
        let (mut seen, mut stack) = (vec![first], vec![first]);
        while let Some(s) = stack.pop() {
            for f in (0..N).filter(|&f| simplices[s][f] != v as u32) {
                let t = adj[s][f];
                if t != NONE && !seen.contains(&(t as usize)) {
                    seen.push(t as usize);
                    stack.push(t as usize);
                }
            }
        }
        seen.len() == around.len()
    })
}

/// The grid piece of test case `case`: sizes 2–6, kept eighths 3–8,
/// 1–3 copies, cycling with the case.
fn grid_case(case: usize, rng: &mut SplitMix) -> (usize, Vec<[u32; 3]>) {
    grid_piece(
        2 + (case % 5) as u32,
        3 + case % 6,
        1 + (case % 3) as u32,
        rng,
    )
}

/// Two triangles per cell of a `k × k` grid, each cell kept with
/// probability `keep` in 1/8, the grid repeated `copies` times apart.
fn grid_piece(k: u32, keep: usize, copies: u32, rng: &mut SplitMix) -> (usize, Vec<[u32; 3]>) {
    let n = (k + 1) * (k + 1);
    let at = |i: u32, j: u32, c: u32| c * n + j * (k + 1) + i;
    let mut tris = Vec::new();
    for c in 0..copies {
        for (i, j) in (0..k).flat_map(|i| (0..k).map(move |j| (i, j))) {
            if rng.below(8) < keep {
                let [a, b, d, e] = [
                    at(i, j, c),
                    at(i + 1, j, c),
                    at(i + 1, j + 1, c),
                    at(i, j + 1, c),
                ];
                tris.extend([[a, b, d], [a, d, e]]);
            }
        }
    }
    ((n * copies) as usize, tris)
}

/// Six tets per cube of a `k³` block, each cube kept with probability
/// `keep` in 1/8, the block repeated `copies` times apart.
fn block_piece(k: u32, keep: usize, copies: u32, rng: &mut SplitMix) -> (usize, Vec<[u32; 4]>) {
    let m = k + 1;
    let n = m * m * m;
    let at = |x: u32, y: u32, z: u32, c: u32| c * n + (z * m + y) * m + x;
    let mut tets = Vec::new();
    for c in 0..copies {
        for z in 0..k {
            for (x, y) in (0..k).flat_map(|x| (0..k).map(move |y| (x, y))) {
                if rng.below(8) >= keep {
                    continue;
                }
                let v = |b: u32| at(x + (b & 1), y + (b >> 1 & 1), z + (b >> 2), c);
                // the six tets around the diagonal 0–7 of the cube
                for p in [[1, 3], [3, 2], [2, 6], [6, 4], [4, 5], [5, 1]] {
                    tets.push([v(0), v(p[0]), v(p[1]), v(7)]);
                }
            }
        }
    }
    ((n * copies) as usize, tets)
}

#[test]
fn surface_shape_equals_the_checkers() {
    let (mut rng, mut compared, mut most) = (SplitMix::new(1), 0, (0, 0));
    for case in 0..400usize {
        let (n, tris) = grid_case(case, &mut rng);
        let Some(adj) = adjacency(&tris) else {
            continue;
        };
        if tris.is_empty() || !stars_connected(n, &tris, &adj) {
            continue;
        }
        compared += 1;
        let want = topology::surface_shape(n, &tris);
        assert_eq!(
            glued::surface_shape(n, &tris, &adj),
            want,
            "case {case}: {tris:?}"
        );
        most = (
            most.0.max(want.components),
            most.1.max(want.boundary_components),
        );
    }
    assert!(compared > 100, "only {compared} cases compared");
    assert!(most.0 > 2 && most.1 > 2, "no case of several: {most:?}");
}

#[test]
fn tet_shape_equals_the_checkers() {
    let (mut rng, mut compared, mut most) = (SplitMix::new(2), 0, (0, 0));
    for case in 0..300usize {
        let (n, tets) = block_piece(
            1 + (case % 3) as u32,
            3 + case % 6,
            1 + (case % 2) as u32,
            &mut rng,
        );
        let Some(adj) = adjacency(&tets) else {
            continue;
        };
        if tets.is_empty() || !stars_connected(n, &tets, &adj) {
            continue;
        }
        compared += 1;
        let (want, mut want_lone) = topology::tet_shape_and_boundary(n, &tets);
        let g = glued::tet_glued(&adj);
        let (shape, lone) = (glued::tet_shape(n, &tets, &g), g.lone);
        want_lone.sort_unstable();
        assert_eq!((shape, lone), (want, want_lone), "case {case}: {tets:?}");
        most = (
            most.0.max(want.components),
            most.1.max(want.boundary_components),
        );
    }
    assert!(compared > 100, "only {compared} cases compared");
    assert!(most.0 > 1 && most.1 > 1, "no case of several: {most:?}");
}

#[test]
fn a_closed_surface_and_a_pillow() {
    // an octahedron (closed, Euler 2) and two triangles glued along all
    // three sides (a pillow: closed, Euler 2), apart
    let mut tris = vec![
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    tris.extend([[6, 7, 8], [7, 6, 8]]);
    let adj = adjacency(&tris).expect("manifold");
    assert!(stars_connected(9, &tris, &adj));
    let shape = glued::surface_shape(9, &tris, &adj);
    assert_eq!(shape, topology::surface_shape(9, &tris));
    assert_eq!(
        (shape.components, shape.euler, shape.boundary_components),
        (2, 4, 0)
    );
}

#[test]
fn components_by_blocks_equal_the_flood_fill() {
    let (mut rng, mut most) = (SplitMix::new(3), 0);
    for case in 0..200usize {
        let (_, tris) = grid_case(case, &mut rng);
        let (_, tets) = block_piece(1 + (case % 3) as u32, 3 + case % 6, 1, &mut rng);
        let (Some(a2), Some(a3)) = (adjacency(&tris), adjacency(&tets)) else {
            continue;
        };
        let want = (glued::facet_components(&a2), glued::facet_components(&a3));
        most = most.max(want.0);
        for block in [1, 2, 3, 7, 64, 1 << 14] {
            let got = (
                glued::components_by_blocks(&a2, block),
                glued::components_by_blocks(&a3, block),
            );
            assert_eq!(got, want, "case {case}, block {block}");
        }
        assert_eq!(glued::facet_components_par(&a2), want.0);
        assert_eq!(glued::facet_components_par(&a3), want.1);
    }
    assert!(most > 2, "no case of several components: {most}");
}

/// Blocks of more than 127 components (isolated simplices) fall back to
/// the flood fill, alone or beside blocks that do not.
#[test]
fn components_by_blocks_past_a_byte_of_labels() {
    let mut adj = vec![[NONE; 3]; 600];
    // a strip of 100 glued triangles after 500 lone ones
    for s in 500..599 {
        adj[s][0] = s as u32 + 1;
        adj[s + 1][1] = s as u32;
    }
    assert_eq!(glued::facet_components(&adj), 501);
    for block in [100, 127, 128, 300, 600, 1 << 14] {
        assert_eq!(
            glued::components_by_blocks(&adj, block),
            501,
            "block {block}"
        );
    }
}

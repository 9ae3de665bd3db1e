//! The shapes of small meshes against hand counts and hash maps.

use super::*;

#[test]
fn square_annulus_and_tet_shapes() {
    // a 3×3 grid of quads, then without its centre quad (an annulus)
    let q = |i: u32, j: u32| {
        let v = |a: u32, b: u32| a + 4 * b;
        [v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)]
    };
    let full: Vec<[u32; 4]> = (0..3).flat_map(|j| (0..3).map(move |i| q(i, j))).collect();
    let disk = surface_shape(16, &full);
    assert_eq!(
        disk,
        Shape {
            components: 1,
            euler: 1,
            boundary_components: 1
        }
    );
    let ring: Vec<[u32; 4]> = full.iter().copied().filter(|f| *f != q(1, 1)).collect();
    let annulus = surface_shape(16, &ring);
    assert_eq!(
        annulus,
        Shape {
            components: 1,
            euler: 0,
            boundary_components: 2
        }
    );
    let c = Comparison {
        input: annulus,
        output: disk,
    };
    assert!(!c.matches());
    assert_eq!(
        c.mismatch().as_deref(),
        Some("Euler characteristic 1 (input 0), boundary components 1 (input 2)")
    );
    assert_eq!(c.to_json()["matches_input"], false);
    // two disjoint tets: 2 components, two spheres
    let tets = [[0, 1, 2, 3], [4, 5, 6, 7]];
    assert_eq!(tet_boundary(&tets).len(), 8);
    let s = tet_shape(8, &tets);
    assert_eq!(
        s,
        Shape {
            components: 2,
            euler: 4,
            boundary_components: 2
        }
    );
    let same = Comparison {
        input: s,
        output: s,
    };
    assert!(same.matches() && same.mismatch().is_none());
}

/// A test mesh's size: the variable `name`, else `default` (larger
/// sizes for measuring under callgrind).
fn size_from_env(name: &str, default: u32) -> u32 {
    let value = std::env::var(name).ok();
    value.and_then(|s| s.parse().ok()).unwrap_or(default)
}

/// A block of `n³` cubes of 6 tets each (`DUALEX_BLOCK_N`, default 8:
/// `valgrind --tool=callgrind --toggle-collect='*lone_tet_faces*'` on
/// this test with a larger `n` measures the bucketing): `12·n²`
/// boundary triangles, a ball.
#[test]
fn block_boundary() {
    let n = size_from_env("DUALEX_BLOCK_N", 8);
    let v = |x: u32, y: u32, z: u32| x + (n + 1) * (y + (n + 1) * z);
    // a cube's 6 tets: the paths 0 → one axis → two axes → 7 (corner
    // bits x = 1, y = 2, z = 4)
    let axes = [[0, 1], [1, 0], [1, 2], [2, 1], [2, 0], [0, 2]];
    let kuhn = axes.map(|[i, j]| [0, 1 << i, 1 << i | 1 << j, 7]);
    let mut tets = Vec::new();
    for (x, y, z) in (0..n).flat_map(|z| (0..n).flat_map(move |y| (0..n).map(move |x| (x, y, z)))) {
        let corner = |c: u32| v(x + (c & 1), y + (c >> 1 & 1), z + (c >> 2));
        tets.extend(kuhn.iter().map(|t: &[u32; 4]| t.map(corner)));
    }
    let lone = lone_tet_faces(&tets);
    assert_eq!(lone.len(), 12 * (n * n) as usize);
    let nv = ((n + 1) * (n + 1) * (n + 1)) as usize;
    let shape = tet_shape_of(nv, &tets, &lone);
    assert_eq!(
        (shape.components, shape.euler, shape.boundary_components),
        (1, 2, 1)
    );
    assert_eq!(tet_shape_and_boundary(nv, &tets), (shape, lone));
}

/// A torus of `m × (m − 1)` squares cut in two triangles each
/// (`DUALEX_TORUS_M`, default 12; 380 is the size of torus537:
/// `valgrind --tool=callgrind --toggle-collect='*surface_shape*'` on
/// this test measures [`surface_shape`]): one component, Euler
/// characteristic 0, no boundary; cut open along a row, two loops.
#[test]
fn torus_shape() {
    let m = size_from_env("DUALEX_TORUS_M", 12);
    let n = m - 1;
    let v = |i: u32, j: u32| (i % m) + m * (j % n);
    let tris: Vec<[u32; 3]> = (0..n)
        .flat_map(|j| (0..m).map(move |i| (i, j)))
        .flat_map(|(i, j)| {
            let a = [v(i, j), v(i + 1, j), v(i + 1, j + 1)];
            [a, [v(i, j), v(i + 1, j + 1), v(i, j + 1)]]
        })
        .collect();
    let shape = surface_shape((m * n) as usize, &tris);
    assert_eq!(
        (shape.components, shape.euler, shape.boundary_components),
        (1, 0, 0)
    );
    // the last row of squares dropped: an annulus
    let open = &tris[..tris.len() - 2 * m as usize];
    let shape = surface_shape((m * n) as usize, open);
    assert_eq!(
        (shape.components, shape.euler, shape.boundary_components),
        (1, 0, 2)
    );
}

/// The bucketed counts equal those of hash maps (the former code) on
/// random small meshes: repeated faces, degenerate and out-of-range
/// cells, isolated vertices.
#[test]
fn bucketed_counts_equal_hash_maps() {
    use std::collections::HashMap;
    fn reference_boundary(tets: &[[u32; 4]]) -> Vec<[u32; 3]> {
        let mut count: HashMap<[u32; 3], (usize, [u32; 3])> = HashMap::new();
        for t in tets {
            for f in 0..4 {
                let tri = [t[(f + 1) % 4], t[(f + 2) % 4], t[(f + 3) % 4]];
                let mut key = tri;
                key.sort_unstable();
                count.entry(key).or_insert((0, tri)).0 += 1;
            }
        }
        let mut out: Vec<[u32; 3]> = count
            .into_values()
            .filter(|(n, _)| *n == 1)
            .map(|(_, t)| t)
            .collect();
        out.sort_unstable();
        out
    }
    fn reference_edges(n: usize, faces: &[[u32; 3]]) -> (i64, usize) {
        let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
        let good = faces.iter().filter(|f| f.iter().all(|&v| (v as usize) < n));
        for f in good {
            for k in 0..3 {
                let (a, b) = (f[k], f[(k + 1) % 3]);
                *edges.entry((a.min(b), a.max(b))).or_default() += 1;
            }
        }
        let once = edges.values().filter(|&&c| c == 1).count();
        (edges.len() as i64, once)
    }
    fn reference_components(n: usize, tets: &[[u32; 4]]) -> usize {
        let mut uf = UnionFind::new(n);
        let good = tets.iter().filter(|t| t.iter().all(|&v| (v as usize) < n));
        let used: Vec<usize> = good.flatten().map(|&v| v as usize).collect();
        for (a, b) in used
            .chunks(4)
            .flat_map(|t| t[1..].iter().map(|&b| (t[0], b)))
        {
            uf.union(a, b);
        }
        uf.count_sets(used.into_iter())
    }
    let mut z = 5u64;
    let mut next = |m: u64| {
        z = z
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((z >> 33) % m) as u32
    };
    for case in 0..300 {
        let n = 3 + case % 17;
        let tets: Vec<[u32; 4]> = (0..case % 40)
            .map(|_| [0; 4].map(|_| next(n as u64 + 1)))
            .collect();
        assert_eq!(tet_boundary(&tets), reference_boundary(&tets), "{tets:?}");
        let components = reference_components(n, &tets);
        assert_eq!(cell_components(n, &tets), components, "{tets:?}");
        let tris = reference_boundary(&tets);
        let shape = surface_shape(n, &tris);
        let (e, once) = reference_edges(n, &tris);
        let good: Vec<[u32; 3]> = tris
            .iter()
            .copied()
            .filter(|f| f.iter().all(|&v| (v as usize) < n))
            .collect();
        let mut used: Vec<u32> = good.iter().flatten().copied().collect();
        used.sort_unstable();
        used.dedup();
        let euler = used.len() as i64 - e + good.len() as i64;
        assert_eq!(shape.euler, euler, "{tris:?}");
        assert_eq!(shape.boundary_components == 0, once == 0, "{tris:?}");
    }
    // more buckets than one parallel block holds, and vertices beyond
    // the bucket count (folded buckets)
    for (count, n) in [
        (9000, 40u64),
        (3 * LONE_FACE_BLOCK, 20_000),
        (50, 1000),
        (2000, 8),
        (40_000, 4000),
    ] {
        let tets: Vec<[u32; 4]> = (0..count).map(|_| [0; 4].map(|_| next(n))).collect();
        assert_eq!(
            tet_boundary(&tets),
            reference_boundary(&tets),
            "{count} {n}"
        );
    }
}

/// A surface's shape does not depend on the order of its faces (the
/// boundary of a tet map is handed over unsorted): grids, tori and cube
/// surfaces, of quads and of triangles, whole and with faces dropped
/// (boundary loops, several components), against the same faces shuffled.
#[test]
fn the_shape_does_not_depend_on_the_faces_order() {
    use crate::test_meshes::{cube, grid, torus};
    use dualex_util::rng::SplitMix;
    let mut rng = SplitMix::new(11);
    let meshes = [grid(5, 4), torus(6, 5), {
        let (p, q) = cube(3);
        (p.len(), q)
    }];
    let mut seen = std::collections::BTreeSet::new();
    for (n, quads) in meshes {
        for keep in [4, 3, 2] {
            let part: Vec<[u32; 4]> = quads
                .iter()
                .copied()
                .filter(|_| rng.below(4) < keep)
                .collect();
            let tris: Vec<[u32; 3]> = part
                .iter()
                .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
                .collect();
            let (mut part2, mut tris2) = (part.clone(), tris.clone());
            rng.shuffle(&mut part2);
            rng.shuffle(&mut tris2);
            let shape = surface_shape(n, &part);
            assert_eq!(surface_shape(n, &part2), shape);
            assert_eq!(surface_shape(n, &tris2), surface_shape(n, &tris));
            seen.insert((shape.components, shape.boundary_components));
        }
    }
    // the cases hold several components and boundary loops
    assert!(seen.iter().any(|&(c, _)| c > 1) && seen.iter().any(|&(_, b)| b > 1));
}

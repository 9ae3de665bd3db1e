use super::*;
use crate::test_meshes::{cube, grid, torus};
use std::borrow::Cow;

/// A xorshift generator from `seed`: draws below `m`.
fn xorshift(seed: u64) -> impl FnMut(u64) -> u32 {
    let mut s = seed;
    move |m| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s % m) as u32
    }
}

fn hist(pairs: &[(u32, usize)]) -> BTreeMap<u32, usize> {
    pairs.iter().copied().collect()
}

#[test]
fn grid_counts() {
    let (n, q) = grid(3, 4);
    let r = check_quad_mesh(n, &q);
    assert!(r.is_valid(), "{:?}", r.errors());
    assert_eq!((r.faces, r.vertices_used, r.unused_vertices), (12, 20, 0));
    assert_eq!((r.edges, r.boundary_edges, r.boundary_loops), (31, 14, 1));
    assert_eq!((r.components, r.euler), (1, 1));
    assert_eq!(r.interior_valence, hist(&[(4, 6)]));
    assert_eq!(r.boundary_valence, hist(&[(2, 4), (3, 10)]));
}

#[test]
fn torus_counts() {
    let (n, q) = torus(5, 3);
    let r = check_quad_mesh(n, &q);
    assert!(r.is_valid(), "{:?}", r.errors());
    assert_eq!((r.faces, r.vertices_used, r.edges), (15, 15, 30));
    assert_eq!((r.boundary_edges, r.boundary_loops, r.euler), (0, 0, 0));
    assert_eq!(r.interior_valence, hist(&[(4, 15)]));
    assert!(r.boundary_valence.is_empty());
}

#[test]
fn cube_counts() {
    let (p, q) = cube(3);
    let r = check_quad_mesh(p.len(), &q);
    assert!(r.is_valid(), "{:?}", r.errors());
    assert_eq!((r.faces, r.vertices_used, r.edges), (54, 56, 108));
    assert_eq!((r.euler, r.components, r.boundary_loops), (2, 1, 0));
    assert_eq!(r.interior_valence, hist(&[(3, 8), (4, 48)]));
}

#[test]
fn flipped_quad_is_misoriented() {
    let (n, mut q) = grid(3, 3);
    q[4].reverse(); // the centre quad
    let r = check_quad_mesh(n, &q);
    assert_eq!(r.misoriented_edges.len(), 4);
    assert!(!r.is_valid());
    assert_eq!(r.errors().len(), 1);
}

#[test]
fn hole_adds_a_boundary_loop() {
    let (n, mut q) = grid(3, 3);
    q.remove(4);
    let r = check_quad_mesh(n, &q);
    assert!(r.is_valid(), "a hole is a valid mesh: {:?}", r.errors());
    assert_eq!((r.boundary_loops, r.euler, r.boundary_edges), (2, 0, 16));
    assert!(r.interior_valence.is_empty());
}

#[test]
fn third_face_on_an_edge_is_non_manifold() {
    let (n, mut q) = grid(2, 1);
    // a fin on the edge 1-4 (the middle edge), using a new vertex pair
    q.push([1, 4, n as u32, n as u32 + 1]);
    let r = check_quad_mesh(n + 2, &q);
    assert_eq!(r.non_manifold_edges, vec![[1, 4]]);
    assert!(!r.is_valid());
}

#[test]
fn bowtie_vertex_is_non_manifold() {
    // two quads touching at vertex 2 only
    let q = [[0, 1, 2, 3], [2, 4, 5, 6]];
    let r = check_quad_mesh(7, &q);
    assert_eq!(r.non_manifold_vertices, vec![2]);
    assert_eq!((r.components, r.boundary_loops), (1, 1));
    assert!(!r.is_valid());
}

#[test]
fn degenerate_and_out_of_range_faces() {
    let (n, mut q) = grid(2, 2);
    q.push([0, 1, 1, 4]);
    q.push([0, 1, 99, 4]);
    let r = check_quad_mesh(n, &q);
    assert_eq!(r.degenerate_faces, vec![4]);
    assert_eq!(r.out_of_range_faces, vec![5]);
    assert_eq!(r.errors().len(), 2);
    // the good faces are still counted
    assert_eq!((r.euler, r.boundary_loops), (1, 1));
}

#[test]
fn empty_and_unused() {
    let r = check_quad_mesh(3, &[]);
    assert!(r.is_valid());
    assert_eq!((r.unused_vertices, r.components, r.euler), (3, 0, 0));
}

#[test]
fn small_fans_count_as_the_general_rule() {
    // random corner groups at one vertex: (vertex, prev, next) with
    // neighbours drawn from a few ids, so that some share edges
    let mut next = xorshift(0x2545_f491_4f6c_dd1d);
    for _ in 0..2000 {
        let k = 1 + next(12) as usize;
        let ids = 2 + u64::from(next(20));
        let group: Vec<(u32, u32, u32)> =
            (0..k).map(|_| (0, 1 + next(ids), 1 + next(ids))).collect();
        assert_eq!(super::fans(&group), super::fans_large(&group), "{group:?}");
    }
}

/// The former classification (always a copy), the oracle of
/// [`classify`] with the quad check's [`class_of`].
fn sort_faces(n: usize, quads: &[[u32; 4]]) -> (Vec<[u32; 4]>, Vec<usize>, Vec<usize>) {
    let (mut good, mut out, mut degenerate) = (Vec::new(), Vec::new(), Vec::new());
    for (f, q) in quads.iter().enumerate() {
        if q.iter().any(|&v| v as usize >= n) {
            out.push(f);
        } else if (0..4).any(|i| q[..i].contains(&q[i])) {
            degenerate.push(f);
        } else {
            good.push(*q);
        }
    }
    (good, out, degenerate)
}

#[test]
fn good_faces_borrowed_are_the_sorted_ones() {
    // the former classification as oracle: all good (borrowed), one face
    // out of range, one repeated corner at each pair of places, random
    // faces over few ids; across task boundaries (10 000 faces)
    let mut next = xorshift(0x9e37_79b9_7f4a_7c15);
    let mut cases: Vec<(usize, Vec<[u32; 4]>)> =
        vec![(0, vec![]), torus(5, 3), grid(3, 4), torus(100, 100)];
    let (n, q) = torus(4, 4);
    for f in [0, 7, 15] {
        for i in 0..4 {
            let mut out = q.clone();
            out[f][i] = n as u32 + next(3);
            cases.push((n, out));
            for j in 0..4 {
                let mut rep = q.clone();
                rep[f][j] = rep[f][i];
                cases.push((n, rep));
            }
        }
    }
    let (n, mut big) = torus(100, 100);
    big[9_000][2] = big[9_000][0];
    big[4_100][1] = n as u32;
    cases.push((n, big));
    for _ in 0..300 {
        let n = 1 + next(9) as usize;
        let faces = (0..next(12)).map(|_| std::array::from_fn(|_| next(n as u64 + 1)));
        cases.push((n, faces.collect()));
    }
    for (n, q) in &cases {
        let got = classify(q, |f| class_of(*n, f));
        let (good, out, degenerate) = sort_faces(*n, q);
        assert_eq!(*got.good, good[..], "{n} {q:?}");
        assert_eq!(
            (got.out_of_range, got.degenerate),
            (out, degenerate),
            "{n} {q:?}"
        );
        assert_eq!(matches!(got.good, Cow::Borrowed(_)), good.len() == q.len());
    }
}

/// The former edge list (every face side bucketed by its lower vertex and
/// sorted there), the oracle of [`edge_uses`] from the corners.
fn sides_edge_uses(n: usize, faces: &[[u32; 4]]) -> Vec<((u32, u32), (u32, u32))> {
    let (_, sides) = bucket::sorted(n, |emit| {
        for q in faces {
            for i in 0..4 {
                let (a, b) = (q[i], q[(i + 1) % 4]);
                emit(a.min(b) as usize, (a.min(b), a.max(b), a > b));
            }
        }
    });
    sides
        .chunk_by(|x, y| (x.0, x.1) == (y.0, y.1))
        .map(|run| {
            let backward = run.iter().filter(|s| s.2).count() as u32;
            (
                (run[0].0, run[0].1),
                (run.len() as u32 - backward, backward),
            )
        })
        .collect()
}

#[test]
fn edges_from_the_corners_are_the_sides_ones() {
    // good faces (distinct vertices) over few ids: shared, repeated,
    // misoriented and non-manifold edges; grids, tori, a cube, faces
    // repeated and reversed
    let mut next = xorshift(0x2545_f491_4f6c_dd1d);
    let mut cases: Vec<(usize, Vec<[u32; 4]>)> = vec![(0, vec![]), grid(3, 4), torus(5, 3)];
    let (p, c) = cube(3);
    cases.push((p.len(), c));
    let (n, mut q) = torus(4, 4);
    q.extend(q.clone().iter().map(|f| [f[3], f[2], f[1], f[0]]));
    q.push(q[0]);
    cases.push((n, q));
    for _ in 0..400 {
        let n = 4 + next(40) as usize;
        let mut faces = Vec::new();
        while faces.len() < next(30) as usize {
            let f: [u32; 4] = std::array::from_fn(|_| next(n as u64));
            if (1..4).all(|i| !f[..i].contains(&f[i])) {
                faces.push(f);
            }
        }
        cases.push((n, faces));
    }
    for (n, q) in &cases {
        let got: Vec<_> = edge_uses(&corner_groups(*n, q))
            .into_iter()
            .map(|(e, u)| (e, (u.forward, u.backward)))
            .collect();
        assert_eq!(got, sides_edge_uses(*n, q), "{n} {q:?}");
    }
}

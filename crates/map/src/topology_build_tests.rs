//! Tests of [`super`]: adjacency, errors in key order, helpers.

use super::*;
use crate::TriMap;

fn tri(simplices: Vec<[u32; 3]>, nv: usize) -> TriMap {
    TriMap {
        positions: vec![[0.0; 3]; nv],
        coords: vec![[[0.0; 2]; 3]; simplices.len()],
        simplices,
    }
}

fn tets(simplices: Vec<[u32; 4]>, nv: usize) -> crate::TetMap {
    crate::TetMap {
        positions: vec![[0.0; 3]; nv],
        coords: vec![[[0.0; 3]; 4]; simplices.len()],
        simplices,
    }
}

#[test]
fn two_triangles() {
    let m = tri(vec![[0, 1, 2], [2, 1, 3]], 4);
    let t = Topology::build(&m).expect("valid");
    assert_eq!(t.boundary_facets, 4);
    // edge 1-2 is facet 0 of triangle 0 and facet 2 of triangle 1
    assert_eq!(t.neighbour(0, 0), Some((1, 2)));
    assert_eq!(t.neighbour(1, 2), Some((0, 0)));
    assert_eq!(t.nbr_corner[0][0], [2, 1, 0]);
    assert_eq!(t.neighbour(0, 1), None);
}

#[test]
fn tets_share_face() {
    let m = tets(vec![[0, 1, 2, 3], [1, 2, 3, 4]], 5);
    // (1,2,3,4) vs (0,1,2,3): s's apex 0 in place of 4 gives (1,2,3,0): odd
    let t = Topology::build(&m).expect("valid");
    assert_eq!(t.neighbour(0, 0), Some((1, 3)));
    assert_eq!(t.nbr_corner[0][0], [3, 0, 1, 2]);
    assert_eq!(t.boundary_facets, 6);
    let bad = crate::TetMap {
        simplices: vec![[0, 1, 2, 3], [2, 1, 3, 4]],
        ..m
    };
    let e = Topology::build(&bad).expect_err("misoriented");
    assert_eq!(
        e.to_string(),
        "tets 0 and 1 have opposite orientations across face 1-2-3"
    );
}

#[test]
fn errors() {
    let e = Topology::build(&tri(vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]], 5)).expect_err("nm");
    assert_eq!(
        e.to_string(),
        "edge 0-1 is shared by 3 triangles (0, 1, 2): non-manifold"
    );
    let e = Topology::build(&tri(vec![[0, 1, 2], [1, 2, 3]], 4)).expect_err("orient");
    assert_eq!(
        e.to_string(),
        "triangles 0 and 1 have opposite orientations across edge 1-2"
    );
    // bow tie: two fans at vertex 0
    let e = Topology::build(&tri(vec![[0, 1, 2], [0, 3, 4]], 5)).expect_err("bow tie");
    assert_eq!(
        e.to_string(),
        "vertex 0 is non-manifold: its triangles form more than one fan"
    );
}

/// Bow ties pinched at vertices 9000 and 5000 (in two blocks of 4096
/// vertices checked in parallel).
fn pinched_twice() -> TriMap {
    let mut simplices = Vec::new();
    for v in [9000u32, 5000] {
        let o = 10000 + 4 * v;
        simplices.extend([[v, o, o + 1], [v, o + 2, o + 3]]);
    }
    tri(simplices, 50000)
}

#[test]
fn the_first_pinched_vertex_is_named() {
    // the least is reported
    let e = Topology::build(&pinched_twice()).expect_err("pinched");
    assert_eq!(
        e.to_string(),
        "vertex 5000 is non-manifold: its triangles form more than one fan"
    );
}

/// The adjacency against one global sort of the half-facets.
fn same_as_sorted<const N: usize, const D: usize>(m: &SimplexMap<N, D>) {
    let topo = Topology::build(m).expect("valid");
    let mut boundary = 0;
    for group in sorted_facets(&m.simplices).chunk_by(|a, b| a.0 == b.0) {
        match group {
            [(_, h)] => {
                boundary += 1;
                let (s, f) = split::<N>(*h);
                assert_eq!(topo.adj[s][f], NONE);
            }
            [(_, a), (_, b)] => {
                let ((s, f), (n, g)) = (split::<N>(*a), split::<N>(*b));
                assert_eq!(topo.neighbour(s, f), Some((n, g)));
                assert_eq!(topo.neighbour(n, g), Some((s, f)));
                assert_eq!(topo.nbr_corner[s][f][f], g as u8);
                for c in (0..N).filter(|&c| c != f) {
                    let cn = topo.nbr_corner[s][f][c] as usize;
                    assert_eq!(m.simplices[n][cn], m.simplices[s][c]);
                    assert_eq!(topo.nbr_corner[n][g][cn] as usize, c);
                }
            }
            _ => panic!("non-manifold test map"),
        }
    }
    assert_eq!(topo.boundary_facets, boundary);
}

#[test]
fn same_adjacency_as_one_global_sort() {
    same_as_sorted(&crate::test_maps::grid(90));
    same_as_sorted(&crate::test_maps::tet_cube(6));
    // buckets above SMALL_BUCKET: the apex's 300 triangles, the axis'
    // 40 tets
    same_as_sorted(&crate::test_maps::cone(300));
    same_as_sorted(&crate::test_maps::edge_fan(40));
}

#[test]
fn the_first_error_in_key_order_is_named() {
    // a misoriented pair at vertex 9000, a non-manifold edge at vertex
    // 5000 (blocks of 4096 vertices glued in parallel): the least key
    let e = Topology::build(&tri(
        vec![
            [9000, 9001, 9002],
            [9001, 9002, 9003],
            [5000, 5001, 5002],
            [5001, 5000, 5003],
            [5000, 5001, 5004],
        ],
        10000,
    ))
    .expect_err("two errors");
    assert_eq!(
        e.to_string(),
        "edge 5000-5001 is shared by 3 triangles (2, 3, 4): non-manifold"
    );
}

#[test]
fn tets_touching_at_a_vertex() {
    let m = tets(vec![[0, 1, 2, 3], [0, 4, 5, 6]], 7);
    let e = Topology::build(&m).expect_err("pinched");
    assert_eq!(
        e.to_string(),
        "vertex 0 is non-manifold: its tets are not connected through the faces around it"
    );
}

#[test]
fn rest_without_the_key_is_the_keys_rest() {
    for t in [[4u32, 9, 2, 7], [1, 2, 3, 4], [8, 3, 5, 0]] {
        for f in 0..4 {
            let key = facet_key(&t, f);
            let c = (0..4).find(|&c| c != f && t[c] == key[0]).expect("least");
            let (rest, order) = rest_without(&t, f, c);
            assert_eq!(rest, rest_of(&key), "{t:?} facet {f}");
            same_order(&t, f, &key, order);
        }
        let tri = [t[0], t[1], t[2]];
        for f in 0..3 {
            let key = facet_key(&tri, f);
            let c = (0..3).find(|&c| c != f && tri[c] == key[0]).expect("least");
            let (rest, order) = rest_without(&tri, f, c);
            assert_eq!(rest, rest_of(&key), "{tri:?} facet {f}");
            same_order(&tri, f, &key, order);
        }
    }
}

/// `order` lists the corners of facet `f` of `simplex` holding the key's
/// vertices in key order, with the parity of that list then `f`.
fn same_order<const N: usize>(simplex: &[u32; N], f: usize, key: &[u32; N], order: u8) {
    let mut perm = [f as u8; N];
    for i in 0..N - 1 {
        let j = order >> (2 * i) & 3;
        assert_eq!(simplex[j as usize], key[i], "{simplex:?} facet {f}");
        perm[i] = j;
    }
    let odd = u32::from(order & ODD != 0);
    assert_eq!(odd, permutation_parity(&perm), "{simplex:?} facet {f}");
}

#[test]
fn parity() {
    assert_eq!(permutation_parity(&[0u8, 1, 2]), 0);
    assert_eq!(permutation_parity(&[1u8, 0, 2]), 1);
    assert_eq!(permutation_parity(&[1u8, 2, 0]), 0);
    assert_eq!(permutation_parity(&[3u8, 0, 1, 2]), 1);
}

/// Without its vertex check ([`glue_with`]), the topology leaves it to
/// the stars' walk, which names the same first vertex.
#[test]
fn the_stars_walk_names_the_same_pinched_vertex() {
    let pinched = pinched_twice();
    let touching = tets(vec![[0, 1, 2, 3], [0, 4, 5, 6]], 7);
    fn same<const N: usize, const D: usize>(m: &SimplexMap<N, D>) {
        let want = Topology::build(m).expect_err("pinched").to_string();
        let corners = VertexCorners::build(&m.simplices, m.positions.len(), true);
        let topo = Topology::glue_with(m, &corners).expect("glued");
        let e = topo.check_vertices(m, &corners).expect_err("pinched");
        assert_eq!(e.to_string(), want);
        let opts = crate::TransitionOptions::default();
        let (tr, _) = crate::Transitions::derive(m, &topo, &opts).expect("no interior facet");
        let e = crate::Stars::build_checked(m, &topo, &tr, &corners).expect_err("pinched");
        assert_eq!(e.to_string(), want);
    }
    same(&pinched);
    same(&touching);
}

#[test]
fn the_first_error_in_key_order_within_a_bucket() {
    // at vertex 0: a misoriented pair across edge 0-5 (triangles 0, 1,
    // met first), then edge 0-2 in three triangles (the least key)
    let e = Topology::build(&tri(
        vec![[0, 5, 6], [0, 5, 7], [0, 2, 8], [2, 0, 9], [0, 2, 10]],
        11,
    ))
    .expect_err("two errors");
    assert_eq!(
        e.to_string(),
        "edge 0-2 is shared by 3 triangles (2, 3, 4): non-manifold"
    );
    // four tets on one face (two pairs, each consistently oriented)
    let e = Topology::build(&tets(
        vec![[0, 1, 2, 3], [1, 0, 2, 4], [0, 1, 2, 5], [1, 0, 2, 6]],
        7,
    ))
    .expect_err("non-manifold face");
    assert_eq!(
        e.to_string(),
        "face 0-1-2 is shared by 4 tets (0, 1, 2, 3): non-manifold"
    );
}

/// Every order of `N` corners ([`rest_without`] of a facet of every
/// permutation of `N` vertices), with its apex.
fn all_orders<const N: usize>() -> Vec<(u8, usize)> {
    let mut out = Vec::new();
    for code in 0..N.pow(N as u32) {
        let t: [u32; N] = std::array::from_fn(|k| (code / N.pow(k as u32) % N) as u32 * 10);
        if (1..N).any(|k| t[..k].contains(&t[k])) {
            continue;
        }
        for f in 0..N {
            let key = facet_key(&t, f);
            let c = (0..N).find(|&c| c != f && t[c] == key[0]).expect("least");
            out.push((rest_without(&t, f, c).1, f));
        }
    }
    out
}

/// [`CornerMaps`] holds, per pair of orders, the corner map the key's
/// positions give, apexes included.
fn corner_maps_agree<const N: usize>() {
    let orders = all_orders::<N>();
    assert_eq!(orders.len(), (1..=N).product::<usize>() * N);
    for &(o1, f) in &orders {
        for &(o2, g) in &orders {
            let mut want = u32::from(g as u8) << (8 * f);
            for i in 0..N - 1 {
                let (a, b) = (o1 >> (2 * i) & 3, o2 >> (2 * i) & 3);
                want |= u32::from(b) << (8 * a);
            }
            let got = CornerMaps::<N>::TABLE[usize::from(o1 & 63)][usize::from(o2 & 63)];
            assert_eq!(got, want, "{o1:#b} {o2:#b}");
        }
    }
}

#[test]
fn corner_maps_agree_3_4() {
    corner_maps_agree::<3>();
    corner_maps_agree::<4>();
}

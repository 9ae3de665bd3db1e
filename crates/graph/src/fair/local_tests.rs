//! The local vertex queries against the glued table.

use super::*;
use crate::testgrid::singular_disk;

/// Seen from `start`, every alive corner's local vertex has the glued
/// vertex's corners and valence, its first corner is its least ranked,
/// and its fairing path is a shortest one: as long as the glued table's
/// distance, along cell edges, through interior vertices.
fn local_matches_global(g: &NodeGraph<2>, start: (Node, usize)) {
    let global = Vertices::new(g);
    let (adj_at, adj) = adjacency(&global.glued);
    let mut corners_of = vec![Vec::new(); global.corners.len()];
    for n in g.alive_nodes() {
        for c in 0..4 {
            corners_of[global.glued.vertex(n, c) as usize].push((n, c));
        }
    }
    let mut local = LocalVertices::new(g, start);
    let to_global = |l: &LocalVertices, v: usize| {
        let (fx, fc) = l.first(v).unwrap_or_else(|| panic!("no first corner"));
        global.glued.vertex(fx, fc) as usize
    };
    for n in g.alive_nodes() {
        for c in 0..4 {
            let gv = global.glued.vertex(n, c) as usize;
            let Some(lv) = local.vertex_of(n, c) else {
                panic!("alive corner without a local vertex")
            };
            let mut corners = local.corners(lv);
            let ranks: Vec<u64> = corners
                .iter()
                .map(|&(x, k)| local.corner_rank(x, k))
                .collect();
            assert!(ranks.windows(2).all(|w| w[0] < w[1]), "{ranks:?}");
            assert_eq!(local.first(lv), corners.first().copied());
            corners.sort_unstable();
            assert_eq!(corners, corners_of[gv], "corners of {n:?}/{c}");
            assert_eq!(local.valence(lv), global.valence(gv));
            for max in [1, 3, 10] {
                let lp = local.path(lv, max);
                let lp = lp.map(|p| p.iter().map(|&v| to_global(&local, v)).collect::<Vec<_>>());
                let want = global.distance((&adj_at, &adj), gv, max);
                assert_eq!(lp.as_ref().map(|p| p.len() - 1), want, "from {n:?}/{c}");
                let Some(lp) = lp else { continue };
                assert_eq!(lp[0], gv);
                let adjacent = |a: usize, b: usize| {
                    let at = adj_at[a] as usize..adj_at[a + 1] as usize;
                    adj[at].contains(&(b as u32))
                };
                assert!(lp.windows(2).all(|w| adjacent(w[0], w[1])), "{lp:?}");
                assert!(lp[1..].iter().all(|&w| global.interior[w]));
                let end = lp[lp.len() - 1];
                assert!(global.valence(end).is_some_and(|k| k >= 7));
            }
        }
    }
}

#[test]
fn local_vertices_answer_as_the_glued_table() {
    for sectors in 3..=8 {
        let mut g = singular_disk(sectors, 3);
        let centre = |s: usize| Node((s * 9) as u32);
        let starts = [(centre(0), 0), (centre(0), 3), (Node(4), 1)];
        for start in starts {
            local_matches_global(&g, start);
        }
        // split the centre by a saddle lift (valence 1 and n − 1 + …)
        let a = g.side(centre(0), 1);
        let c = g.side(centre(0), 3);
        if g.op2(a, c, Rot2::quarter_turns(3)).is_ok() {
            for start in starts {
                local_matches_global(&g, start);
            }
        }
    }
}

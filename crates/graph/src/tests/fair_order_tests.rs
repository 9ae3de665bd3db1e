//! Index fairing does not depend on how the graph is numbered: the same
//! graph with its nodes renumbered and its charts turned is faired into
//! the same graph (up to that renumbering, or a symmetry of the graph).

use crate::canon::graph_code;
use crate::ids::Node;
use crate::rng::SplitMix;
use crate::testgrid::{
    random_permutation, random_rotations, renumber, rotate_charts, singular_disk,
};
use crate::NodeGraph;
use dualex_map::Rot2;

/// A disk of `sectors` sectors of `k × k` nodes whose centre is split by
/// a saddle lift into a vertex of `corners` corners and one of the others
/// (the far ends merge into valence 8), then `moves` random saddle lifts
/// at vertices of valence ≥ 7 (seeded): a few singularities of both
/// signs, some equally near.
fn scrambled_disk(sectors: usize, corners: usize, moves: usize, seed: u64) -> NodeGraph<2> {
    let k = 5;
    let mut g = singular_disk(sectors, k);
    let centre = |s: usize| Node((s * k * k) as u32);
    let (a, c) = (g.side(centre(0), 1), g.side(centre(corners - 1), 3));
    g.op2(a, c, Rot2::quarter_turns(3)).expect("split");
    let mut rng = SplitMix::new(seed);
    for _ in 0..moves {
        let singular: Vec<(Node, usize, usize)> = g
            .alive_nodes()
            .flat_map(|x| (0..4).map(move |c| (x, c)))
            .filter_map(|(x, c)| g.fan(x, c).map(|f| (x, c, f.len())))
            .filter(|&(_, _, n)| n >= 7)
            .collect();
        if singular.is_empty() {
            break;
        }
        let (x, c, n) = singular[rng.below(singular.len())];
        let i = rng.below(n);
        let j = [(i + 4) % n, (i + n - 4) % n][rng.below(2)];
        let before = g.clone();
        let ok = g.lift(x, c, i, j).is_ok()
            && g.check().is_ok()
            && g.glue().corner_mismatches == 0
            && g.glue().components == 1;
        if !ok {
            g = before;
        }
    }
    g
}

/// Faired (and folded corners collapsed, as both extractions do).
fn faired(g: &NodeGraph<2>) -> (NodeGraph<2>, crate::FairingStats) {
    let mut g = g.clone();
    let st = g.fair(10);
    g.collapse_folded_corners();
    (g, st)
}

/// The cases: every split of the centre of 5 … 9 sectors into 1 … 3 and
/// the rest, moved 0 … 3 times.
fn cases() -> Vec<(String, NodeGraph<2>)> {
    let mut out = Vec::new();
    for sectors in 5..=9 {
        for corners in 1..=3 {
            for moves in 0..=3 {
                let seed = (100 * sectors + 10 * corners + moves) as u64;
                let g = scrambled_disk(sectors, corners, moves, seed);
                out.push((format!("{sectors} sectors, {corners}, {moves} moves"), g));
            }
        }
    }
    out
}

#[test]
fn fairing_ignores_node_numbers_and_charts() {
    let (mut faired_cases, mut differ) = (0, Vec::new());
    for (name, g) in cases() {
        let (want, st) = faired(&g);
        if st.lifts == 0 {
            continue;
        }
        faired_cases += 1;
        let code = graph_code(&want);
        for shuffle in 1..=6u64 {
            let rots = random_rotations::<2>(g.n_nodes(), shuffle);
            let perm = random_permutation(g.n_nodes(), shuffle);
            let h = renumber(&rotate_charts(&g, &rots), &perm);
            let (got, st_h) = faired(&h);
            got.check().expect("valid");
            if st_h != st || graph_code(&got) != code {
                differ.push(format!("{name}, shuffle {shuffle}"));
            }
        }
    }
    // the disks do get faired
    assert!(faired_cases >= 30, "only {faired_cases} disks with lifts");
    assert!(differ.is_empty(), "faired into other graphs: {differ:?}");
}

/// `fair_glued`'s vertices are those of the graph it leaves: gluing from
/// them is gluing afresh, on the disks it changes (lifts kept) and those
/// it leaves alone, with paths of 1 and 10 edges (none where it undid
/// every path tried).
#[test]
fn fairings_vertices_are_the_graphs() {
    let (mut after_lifts, mut untouched) = (0, 0);
    for (name, g) in cases() {
        for max_path in [1, 10] {
            let mut h = g.clone();
            let (st, vertices) = h.fair_glued(max_path);
            assert_eq!(st, g.clone().fair(max_path), "{name}: same fairing");
            let Some(v) = vertices else {
                assert!(st.merged == 0 && st.abandoned > 0, "{name}: none");
                continue;
            };
            assert!(h.glue_from(Some(v)) == h.glue(), "{name}, {max_path}");
            if st.merged > 0 {
                after_lifts += 1;
            } else {
                untouched += 1;
            }
        }
    }
    assert!(
        after_lifts >= 30 && untouched > 0,
        "{after_lifts} {untouched}"
    );
}

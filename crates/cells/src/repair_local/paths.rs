//! Which odd faces the local repair pairs, and along which quads: the
//! choice is made on the costs alone, not on the order of the faces, so
//! that the same mesh numbered differently (a layer of an extruded hex
//! mesh, `dualex_hex::columns`) is repaired into the same counts.
//!
//! Cost of a path: the quads it adds — a crossed quad left through the
//! edge opposite its entry becomes 2 quads (+1), one left through an
//! adjacent edge becomes 3 (+2); the end faces add the same whatever the
//! path. Cheapest paths are found by Dijkstra over (face, entry edge)
//! states; the odd faces are then paired (or sent to the boundary) by a
//! minimum-cost matching, exact by dynamic programming over subsets up to
//! [`EXACT_MATCHING`] odd faces, greedy (first odd face to its cheapest
//! end) beyond; an end on the boundary only where an odd face cannot be
//! paired ([`BOUNDARY_END`]). The pair (or boundary end) of least cost is repaired
//! first; the caller asks again after each repair.
//!
//! Invariants: only quads are crossed; a path never enters a face twice
//! (it would cost more than leaving that face directly).

use super::fast_hash::FastMap as HashMap;
use super::{edges, key, Path};
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// Odd faces up to which the matching is exact (2^k subsets).
pub const EXACT_MATCHING: usize = 16;

/// Added to the cost of a path to the boundary: a boundary end moves the
/// boundary, so odd faces are paired with each other wherever they can be
/// (the fewest boundary ends first, then the least cost).
const BOUNDARY_END: u32 = 1 << 20;

type Edge = (u32, u32);
type State = (usize, Option<Edge>);

/// The cheapest paths from one odd face: to each other odd face, and to
/// the boundary.
struct Reach {
    to_face: HashMap<usize, (u32, Path)>,
    boundary: Option<(u32, Path)>,
}

/// The faces and shared edges of the path ending in state `end`.
fn unwind(end: State, prev: &HashMap<State, State>) -> Path {
    let (mut faces, mut shared) = (vec![end.0], Vec::new());
    let mut st = end;
    while let Some(&p) = prev.get(&st) {
        shared.extend(st.1);
        faces.push(p.0);
        st = p;
    }
    faces.reverse();
    shared.reverse();
    (faces, shared)
}

/// Cost of leaving quad `q` (entered through `ein`) through `eout`.
fn step(q: &[u32], ein: Option<Edge>, eout: Edge) -> u32 {
    let Some(ein) = ein else { return 0 };
    let at = |e: Edge| (0..q.len()).find(|&i| key(q[i], q[(i + 1) % q.len()]) == e);
    match (at(ein), at(eout)) {
        (Some(i), Some(j)) if (i + 2) % 4 == j => 1,
        _ => 2,
    }
}

/// Dijkstra from odd face `s` (module docs); with `nearest`, it stops
/// once every state as cheap as the nearest odd face is settled (all the
/// odd faces at that least cost are found; the boundary then is not).
fn reach(
    s: usize,
    polys: &[Vec<u32>],
    by_edge: &HashMap<Edge, Vec<usize>>,
    nearest: bool,
) -> Reach {
    let mut out = Reach {
        to_face: HashMap::default(),
        boundary: None,
    };
    let mut dist: HashMap<State, u32> = HashMap::default();
    let mut prev: HashMap<State, State> = HashMap::default();
    let mut heap = BinaryHeap::new();
    let mut seq = 0u64;
    dist.insert((s, None), 0);
    heap.push(Reverse((0u32, seq, s, None::<Edge>)));
    let mut found: Option<u32> = None;
    while let Some(Reverse((cost, _, f, ein))) = heap.pop() {
        if nearest && found.is_some_and(|c| cost > c) {
            break;
        }
        if dist.get(&(f, ein)).is_some_and(|&d| d < cost) {
            continue;
        }
        if f != s && polys[f].len() % 2 == 1 {
            out.to_face
                .entry(f)
                .or_insert_with(|| (cost, unwind((f, ein), &prev)));
            found.get_or_insert(cost);
            continue;
        }
        if f != s && polys[f].len() != 4 {
            continue; // only quads are crossed
        }
        for (a, b) in edges(&polys[f]) {
            let e = key(a, b);
            if Some(e) == ein {
                continue;
            }
            let c = cost + step(&polys[f], ein, e);
            match by_edge.get(&e).map(Vec::as_slice) {
                Some([_]) if out.boundary.as_ref().is_none_or(|(b, _)| c < *b) => {
                    let (faces, mut shared) = unwind((f, ein), &prev);
                    shared.push(e);
                    out.boundary = Some((c, (faces, shared)));
                }
                Some(&[g0, g1]) => {
                    let g = if g0 == f { g1 } else { g0 };
                    if dist.get(&(g, Some(e))).is_none_or(|&d| c < d) {
                        dist.insert((g, Some(e)), c);
                        prev.insert((g, Some(e)), (f, ein));
                        seq += 1;
                        heap.push(Reverse((c, seq, g, Some(e))));
                    }
                }
                _ => {}
            }
        }
    }
    out
}

/// The next path to repair (module docs), `None` when an odd face can
/// reach neither another odd face nor the boundary.
pub fn next(polys: &[Vec<u32>], by_edge: &HashMap<Edge, Vec<usize>>) -> Option<Path> {
    let odd: Vec<usize> = (0..polys.len())
        .filter(|&f| polys[f].len() % 2 == 1)
        .collect();
    let first = *odd.first()?;
    if odd.len() > EXACT_MATCHING {
        // the nearest odd face (the least cost, then the least faces);
        // the boundary only when no odd face is in reach (then the search
        // went everywhere)
        let r = reach(first, polys, by_edge, true);
        let best = r
            .to_face
            .into_values()
            .min_by_key(|(c, p)| (*c, p.0.clone()));
        return best.or(r.boundary).map(|(_, p)| p);
    }
    let reaches: Vec<Reach> = odd
        .iter()
        .map(|&s| reach(s, polys, by_edge, false))
        .collect();
    let k = odd.len();
    const INF: u32 = u32::MAX / 4;
    let pair = |i: usize, j: usize| reaches[i].to_face.get(&odd[j]).map_or(INF, |(c, _)| *c);
    let alone = |i: usize| {
        reaches[i]
            .boundary
            .as_ref()
            .map_or(INF, |(c, _)| c.saturating_add(BOUNDARY_END))
    };
    // best[mask]: least cost of ending every odd face in `mask`
    let full = (1usize << k) - 1;
    let mut best = vec![INF; full + 1];
    let mut choice: Vec<(usize, Option<usize>)> = vec![(0, None); full + 1];
    best[0] = 0;
    for mask in 1..=full {
        let i = mask.trailing_zeros() as usize;
        let rest = mask & !(1 << i);
        let mut b = (alone(i).saturating_add(best[rest]), (i, None));
        for j in (i + 1..k).filter(|&j| rest >> j & 1 == 1) {
            let c = pair(i, j).saturating_add(best[rest & !(1 << j)]);
            if c < b.0 {
                b = (c, (i, Some(j)));
            }
        }
        best[mask] = b.0.min(INF);
        choice[mask] = b.1;
    }
    if best[full] >= INF {
        return None;
    }
    // the matching's cheapest member first
    let mut mask = full;
    let mut cheapest: Option<(u32, usize, Option<usize>)> = None;
    while mask != 0 {
        let (i, j) = choice[mask];
        let c = j.map_or_else(|| alone(i), |j| pair(i, j));
        if cheapest.is_none_or(|(b, _, _)| c < b) {
            cheapest = Some((c, i, j));
        }
        mask &= !(1 << i);
        if let Some(j) = j {
            mask &= !(1 << j);
        }
    }
    let (_, i, j) = cheapest?;
    match j {
        Some(j) => reaches[i].to_face.get(&odd[j]).map(|(_, p)| p.clone()),
        None => reaches[i].boundary.as_ref().map(|(_, p)| p.clone()),
    }
}

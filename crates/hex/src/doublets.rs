//! Step 11: doublet chains on the mesh — the fallback of the graph's merge
//! (`dualex_graph::doublet`, step 8e) for the chains it did not merge: those
//! made by collapsing folded hexes here, and those whose vertices the
//! gluing identified beyond the graph's corners. The 3D analogue of the 2D
//! doublet removal (`dualex_quad::doublets`), and its extrusion.
//!
//! An interior edge `e = p–q` in exactly two hexes `H1`, `H2` (valence 2)
//! means the two hexes share both faces that contain `e`. Dissolving `e`
//! keeps `H1`, replaces in it `p` and `q` by the corners `y_p`, `y_q` of
//! `H2` diagonally opposite them in `H2`'s faces across `e`, and deletes
//! `H2`: in every layer across `e` it is the 2D merge
//! `[p, a, x, b] + [p, b, y, a] → [y, a, x, b]`. No face is created.
//!
//! One edge alone would leave `p` and `q` in the hexes of the next layer,
//! so edges are dissolved by **chains**: connected sets of valence-2
//! interior edges whose every vertex lies only in the hexes of the chain's
//! pairs (an inner vertex of a chain in 4 hexes, an end on the boundary in
//! 2), each hex in at most one pair. A chain runs between boundary faces
//! or closes on itself; then every vertex of the chain disappears and the
//! replacements agree across layers (two kept hexes meeting at `p` share
//! the face at `p`'s level, whose diagonal corner is the same vertex).
//! A chain that breaks a precondition, or where `y_p` would be a corner of
//! `H1` already (a pillow), is left whole and counted. So is a chain with
//! a hex that a chain dissolved before it in the same pass changed (two
//! doublets of one quad in 2D, which the 2D removal takes one after the
//! other): [`dissolve_all_traced`] dissolves it in the next round.
//!
//! Input: a valid hex mesh (VTK corner order). Output: the mesh without
//! the dissolved chains' vertices and hexes, vertices renumbered in order.

use dualex_cells::HexMesh;
use dualex_segment::place::Placed;
use std::collections::{HashMap, HashSet};

/// What [`dissolve`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Chains {
    /// Chains dissolved.
    pub dissolved: usize,
    /// Hex pairs merged (valence-2 edges dissolved).
    pub edges: usize,
    /// Valence-2 interior edges left (their chain broke a precondition).
    pub left: usize,
    /// Rounds after the first that dissolved chains made by earlier ones
    /// ([`dissolve_all_traced`]; the graph's passes, step 8e, included).
    pub rounds: usize,
    /// Of `dissolved`, the chains merged in the graph (step 8e,
    /// `NodeGraph::dissolve_doublets`).
    pub in_graph: usize,
}

/// Step 11 on the placed hexes: folded hexes collapsed, then doublet
/// chains dissolved (the extrusions of the 2D collapse of folded quads and
/// of doublet removal), the counts added to `st`, the sources and corners
/// carried; only when the checker's counts show a repeated corner or an
/// interior edge of valence 2 (both passes hash every edge).
pub fn collapse_and_dissolve(out: &mut Placed<3, 8>, st: &mut crate::HexStats) {
    let repeated = out
        .mesh
        .cells
        .iter()
        .any(|h| (0..8).any(|i| (i + 1..8).any(|j| h[i] == h[j])));
    if !repeated && !st.edge_valence_interior.contains_key(&2) {
        return;
    }
    let (collapsed, folded, kept_folded) = collapse_folded_traced(&out.mesh);
    let (dissolved, chains, kept_chains) = dissolve_all_traced(&collapsed);
    st.folded_collapsed = folded;
    st.doublets.dissolved += chains.dissolved;
    st.doublets.edges += chains.edges;
    st.doublets.rounds += chains.rounds;
    st.doublets.left = chains.left;
    if folded + chains.edges > 0 {
        out.remake(collapsed, &kept_folded);
        out.remake(dissolved, &kept_chains);
        st.finish_mesh(&out.mesh);
    }
}

/// Cube corner code (bit 0: u, bit 1: v, bit 2: w) of each VTK corner.
const CODE: [usize; 8] = [0, 1, 3, 2, 4, 5, 7, 6];
/// VTK corner of each cube corner code.
const VTK: [usize; 8] = [0, 1, 3, 2, 4, 5, 7, 6];
use dualex_cells::cells::HEX_FACES as FACES;

fn key2(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// The 12 edges of hex `h`.
fn edges(h: &[u32; 8]) -> impl Iterator<Item = (u32, u32)> + '_ {
    (0..8).flat_map(move |c| {
        (0..3)
            .map(move |k| CODE[c] ^ (1 << k))
            .filter(move |&d| d > CODE[c])
            .map(move |d| key2(h[c], h[VTK[d]]))
    })
}

/// `y_p`: the corner of `h` diagonally opposite `p` in `h`'s face through
/// `p` perpendicular to edge `p–q`.
fn across(h: &[u32; 8], p: u32, q: u32) -> Option<u32> {
    let cp = CODE[h.iter().position(|&v| v == p)?];
    let cq = CODE[h.iter().position(|&v| v == q)?];
    let axis = cp ^ cq;
    (axis.count_ones() == 1).then(|| h[VTK[cp ^ (7 ^ axis)]])
}

/// Dissolves the doublet chains of `mesh` (module docs).
pub fn dissolve(mesh: &HexMesh) -> (HexMesh, Chains) {
    let (out, rep, _) = dissolve_traced(mesh);
    (out, rep)
}

/// [`dissolve_traced`] repeated until no chain is left to dissolve:
/// dissolving a chain takes a hex from each of its neighbours' edges, so
/// an edge of valence 3 next to it may become a new doublet (the 2D
/// removal queues the neighbours for the same reason). Returns the mesh,
/// the summed counts (`left`: of the last round) and, for each output hex,
/// the input hex it is.
pub fn dissolve_all_traced(mesh: &HexMesh) -> (HexMesh, Chains, Vec<u32>) {
    let (mut out, mut rep, mut kept) = dissolve_traced(mesh);
    let mut last = rep.edges;
    // each round deletes at least one hex
    while last > 0 {
        let (next, r, k) = dissolve_traced(&out);
        if r.edges == 0 {
            rep.left = r.left;
            break;
        }
        kept = k.iter().map(|&i| kept[i as usize]).collect();
        rep.dissolved += r.dissolved;
        rep.edges += r.edges;
        rep.left = r.left;
        rep.rounds += 1;
        last = r.edges;
        out = next;
    }
    (out, rep, kept)
}

/// The input cell index of each live cell.
fn kept(cells: &[Option<[u32; 8]>]) -> Vec<u32> {
    (0..cells.len() as u32)
        .filter(|&i| cells[i as usize].is_some())
        .collect()
}

/// [`dissolve`], also returning for each output hex the input hex it is
/// (a merged hex takes the place of the first of its pair).
pub fn dissolve_traced(mesh: &HexMesh) -> (HexMesh, Chains, Vec<u32>) {
    let cells = &mesh.cells;
    let mut rep = Chains::default();
    // edges → hexes, faces → count (boundary faces have one hex)
    let mut by_edge: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    let mut by_face: HashMap<[u32; 4], usize> = HashMap::new();
    let mut by_vertex: HashMap<u32, Vec<usize>> = HashMap::new();
    for (i, h) in cells.iter().enumerate() {
        for e in edges(h) {
            by_edge.entry(e).or_default().push(i);
        }
        for f in FACES {
            let mut k = f.map(|c| h[c]);
            k.sort_unstable();
            *by_face.entry(k).or_default() += 1;
        }
        for &v in h {
            by_vertex.entry(v).or_default().push(i);
        }
    }
    let mut boundary_edges: HashSet<(u32, u32)> = HashSet::new();
    for h in cells {
        for f in FACES {
            let mut k = f.map(|c| h[c]);
            k.sort_unstable();
            if by_face.get(&k) == Some(&1) {
                for j in 0..4 {
                    boundary_edges.insert(key2(h[f[j]], h[f[(j + 1) % 4]]));
                }
            }
        }
    }
    let mut doublets: Vec<(u32, u32)> = by_edge
        .iter()
        .filter(|(e, hs)| hs.len() == 2 && !boundary_edges.contains(e))
        .map(|(&e, _)| e)
        .collect();
    doublets.sort_unstable();
    if doublets.is_empty() {
        return (mesh.clone(), rep, (0..cells.len() as u32).collect());
    }
    // chains: connected components of doublet edges through shared vertices
    let mut at_vertex: HashMap<u32, Vec<usize>> = HashMap::new();
    for (i, &(a, b)) in doublets.iter().enumerate() {
        at_vertex.entry(a).or_default().push(i);
        at_vertex.entry(b).or_default().push(i);
    }
    let mut seen = vec![false; doublets.len()];
    let mut new_cells: Vec<Option<[u32; 8]>> = cells.iter().map(|&h| Some(h)).collect();
    for start in 0..doublets.len() {
        if seen[start] {
            continue;
        }
        let mut chain = vec![start];
        seen[start] = true;
        let mut k = 0;
        while k < chain.len() {
            let (a, b) = doublets[chain[k]];
            for v in [a, b] {
                for &j in &at_vertex[&v] {
                    if !seen[j] {
                        seen[j] = true;
                        chain.push(j);
                    }
                }
            }
            k += 1;
        }
        match plan(&chain, &doublets, &by_edge, &by_vertex, cells) {
            // a hex another chain of this round changed: the planned corners
            // are stale, the chain is left for the next round
            Some(changes)
                if changes.iter().any(|&(keep, _, dead)| {
                    [keep, dead].iter().any(|&i| new_cells[i] != Some(cells[i]))
                }) =>
            {
                rep.left += chain.len();
            }
            Some(changes) => {
                for (keep, h, dead) in changes {
                    new_cells[keep] = Some(h);
                    new_cells[dead] = None;
                }
                rep.dissolved += 1;
                rep.edges += chain.len();
            }
            None => rep.left += chain.len(),
        }
    }
    (compact(mesh, &new_cells), rep, kept(&new_cells))
}

/// The merges of one chain (kept hex, its new corners, deleted hex), or
/// `None` when a precondition fails (module docs).
fn plan(
    chain: &[usize],
    doublets: &[(u32, u32)],
    by_edge: &HashMap<(u32, u32), Vec<usize>>,
    by_vertex: &HashMap<u32, Vec<usize>>,
    cells: &[[u32; 8]],
) -> Option<Vec<(usize, [u32; 8], usize)>> {
    let mut in_pairs: HashSet<usize> = HashSet::new();
    let mut verts: HashSet<u32> = HashSet::new();
    let mut out = Vec::with_capacity(chain.len());
    for &i in chain {
        let (p, q) = doublets[i];
        let pair = by_edge.get(&(p, q))?;
        let (keep, dead) = (pair[0].min(pair[1]), pair[0].max(pair[1]));
        if !in_pairs.insert(keep) || !in_pairs.insert(dead) {
            return None; // a hex in two pairs
        }
        verts.extend([p, q]);
        let (yp, yq) = (across(&cells[dead], p, q)?, across(&cells[dead], q, p)?);
        let mut h = cells[keep];
        if h.contains(&yp) || h.contains(&yq) {
            return None; // a pillow: the merged hex would repeat a corner
        }
        for v in h.iter_mut() {
            if *v == p {
                *v = yp;
            } else if *v == q {
                *v = yq;
            }
        }
        out.push((keep, h, dead));
    }
    // every hex at a chain vertex is in one of the chain's pairs
    let closed = verts.iter().all(|v| {
        by_vertex
            .get(v)
            .is_some_and(|hs| hs.iter().all(|h| in_pairs.contains(h)))
    });
    closed.then_some(out)
}

/// Whether hex `h` is folded along one axis: in each of its two faces
/// across that axis (one per layer) a pair of diagonal corners is one
/// vertex (`[v, a, x, a]`), and its other corners are distinct. Returns,
/// per layer, the two corners `v`, `x` next to the pair: one of them is
/// the apex of the fold, which no unfolded hex holds.
pub fn folded(h: &[u32; 8]) -> Option<[[u32; 2]; 2]> {
    let mut distinct = h.to_vec();
    distinct.sort_unstable();
    distinct.dedup();
    if distinct.len() != 6 {
        return None;
    }
    // the two pairs of equal corners, by cube code
    let mut pairs = Vec::new();
    for c in 0..8 {
        for d in c + 1..8 {
            if h[VTK[c]] == h[VTK[d]] {
                pairs.push((c, d));
            }
        }
    }
    let [(c1, d1), (c2, d2)] = pairs[..] else {
        return None;
    };
    let (m1, m2) = (c1 ^ d1, c2 ^ d2);
    let across = 7 ^ m1;
    if m1 != m2 || m1.count_ones() != 2 || c1 ^ c2 != across {
        return None;
    }
    // the other two corners of each pair's face: c with one bit of the
    // pair's mask flipped
    let bits: Vec<usize> = (0..3).map(|k| 1 << k).filter(|b| m1 & b != 0).collect();
    let others = |c: usize| [h[VTK[c ^ bits[0]]], h[VTK[c ^ bits[1]]]];
    Some([others(c1), others(c2)])
}

/// Collapses the folded hexes of `mesh` (see [`folded`]) whose apex
/// vertices are held by folded hexes only — the 3D analogue of the 2D
/// collapse of folded quads (a valence-1 vertex): the hex and its apexes
/// disappear, the two cells glued to its two far faces (which are one face
/// of the folded hex) become neighbours. Returns the new mesh and the
/// number of hexes collapsed; the mesh is returned unchanged when the
/// result would not be a valid hex mesh.
pub fn collapse_folded(mesh: &HexMesh) -> (HexMesh, usize) {
    let (out, n, _) = collapse_folded_traced(mesh);
    (out, n)
}

/// [`collapse_folded`], also returning for each output hex the input hex
/// it is.
pub fn collapse_folded_traced(mesh: &HexMesh) -> (HexMesh, usize, Vec<u32>) {
    let unchanged = || (mesh.clone(), 0, (0..mesh.cells.len() as u32).collect());
    let apexes: Vec<Option<[[u32; 2]; 2]>> = mesh.cells.iter().map(folded).collect();
    if apexes.iter().all(Option::is_none) {
        return unchanged();
    }
    let mut holders = vec![0u32; mesh.positions.len()];
    for (h, a) in mesh.cells.iter().zip(&apexes) {
        if a.is_none() {
            let mut seen = h.to_vec();
            seen.sort_unstable();
            seen.dedup();
            for v in seen {
                holders[v as usize] += 1;
            }
        }
    }
    let cells: Vec<Option<[u32; 8]>> = mesh
        .cells
        .iter()
        .zip(&apexes)
        .map(|(&h, a)| match a {
            // one corner per layer held by no unfolded hex: the apex
            Some(ap)
                if ap
                    .iter()
                    .all(|l| l.iter().filter(|&&v| holders[v as usize] == 0).count() == 1) =>
            {
                None
            }
            _ => Some(h),
        })
        .collect();
    let n = cells.iter().filter(|c| c.is_none()).count();
    let out = compact(mesh, &cells);
    let r = dualex_check::check_hex_mesh(out.positions.len(), &out.cells, None);
    if r.is_valid() {
        (out, n, kept(&cells))
    } else {
        unchanged()
    }
}

/// The live cells, with the vertices they use renumbered in order.
fn compact(mesh: &HexMesh, cells: &[Option<[u32; 8]>]) -> HexMesh {
    let mut new_id = vec![u32::MAX; mesh.positions.len()];
    for h in cells.iter().flatten() {
        for &v in h {
            new_id[v as usize] = 0;
        }
    }
    let mut out = HexMesh::default();
    for (v, id) in new_id.iter_mut().enumerate() {
        if *id == 0 {
            *id = out.positions.len() as u32;
            out.positions.push(mesh.positions[v]);
        }
    }
    out.cells = cells
        .iter()
        .flatten()
        .map(|h| h.map(|v| new_id[v as usize]))
        .collect();
    out
}

#[cfg(test)]
mod tests;

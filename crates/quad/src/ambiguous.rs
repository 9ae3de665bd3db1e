//! Step 10a: edges and faces that vertex pairs cannot tell apart, split
//! before the repair.
//!
//! The glued mesh is a surface in the graph (every edge is a glued pair of
//! sides or an unmatched side), but an output file names an edge by its
//! two vertices. On messy maps (folds, singular vertices off the grid) the
//! gluing can make two configurations that vertex pairs cannot represent,
//! and that the repair (`dualex_cells::repair_local`, `crate::repair`) would
//! otherwise mistake for one edge:
//! - **parallel edges**: two edges (glued pairs or unmatched sides) between
//!   the same two vertices — a loop of two edges around a handle that
//!   `crate::digons` could not pinch, or a hole whose side runs beside a
//!   glued edge;
//! - **folded cells**: a cell whose two opposite corners are one vertex
//!   (`[a, b, a, c]`).
//!
//! Each is split by new points at edge midpoints, chosen by the edge's
//! identity in the graph, not by its vertex pair: of parallel edges all
//! but one get a point (unmatched sides first, they touch one cell); a
//! folded cell gets a point on two opposite edges and is cut between them
//! into two cells with distinct corners. A point on an edge goes into both
//! faces beside it (a cell, or the hole behind an unmatched side), so the
//! faces stay glued; faces with a new point have an odd or even number of
//! sides and are made quads by the repair that follows, as the triangles
//! of singular vertices are.
//!
//! Input: the glued cells, each cell edge's partner (its glued slot) and
//! the unmatched sides that are holes. Output: [`Split`] — the cells as
//! polygons (the identity when nothing is ambiguous), the hole edges with
//! the new points, and counts. Preconditions, checked before any change:
//! a folded cell is cut only when its two cut edges are distinct edges
//! (not one side glued to the other); invariants: every new point lies on
//! exactly one edge and is used by exactly the faces beside that edge.

use dualex_cells::QuadMesh;
use std::collections::HashMap;

/// A cell edge: `4 · cell + k`, the edge from corner k to corner k + 1.
pub type Slot = u32;

/// The cells and hole edges after the split (module docs).
#[derive(Clone, Debug, Default)]
pub struct Split {
    /// Positions: the mesh's, then one per new point.
    pub positions: Vec<[f64; 3]>,
    /// Each new point's two edge ends (its position is their mean).
    pub new_points: Vec<[u32; 2]>,
    /// The cells as polygons (consecutive repeated corners removed, as
    /// `dualex_cells::polygons::polygon`); a cut cell gives two.
    pub polys: Vec<Vec<u32>>,
    /// For each polygon, its cell.
    pub origin: Vec<u32>,
    /// For each polygon, whether it is its cell unchanged.
    pub intact: Vec<bool>,
    /// The hole edges as traversed by their cells, with the new points.
    pub hole_edges: Vec<(u32, u32)>,
    /// Edges that had a parallel edge, given a point.
    pub parallel_edges: usize,
    /// Folded cells cut in two.
    pub folded_cells: usize,
}

impl Split {
    /// Whether anything was split.
    pub fn changed(&self) -> bool {
        !self.new_points.is_empty()
    }
}

/// The edge of a slot: the smaller slot of a glued pair, else the slot.
fn edge_of(partner: &[Option<Slot>], s: Slot) -> Slot {
    partner[s as usize].map_or(s, |t| t.min(s))
}

/// The ends of slot `s` in `cells`, as traversed by its cell.
pub(crate) fn ends(cells: &[[u32; 4]], s: Slot) -> (u32, u32) {
    let (c, k) = (s as usize / 4, s as usize % 4);
    (cells[c][k], cells[c][(k + 1) % 4])
}

/// Whether cell `c` has a corner repeated at opposite positions (and no
/// consecutive repeat): the position of the first of the pair.
fn folded(cell: &[u32; 4]) -> Option<usize> {
    let consecutive = (0..4).any(|k| cell[k] == cell[(k + 1) % 4]);
    if consecutive {
        return None;
    }
    (0..2).find(|&r| cell[r] == cell[r + 2])
}

/// The edges to split and the folded cells to cut (module docs), found
/// before any change.
#[derive(Clone, Debug, Default)]
pub struct Marks {
    /// The edges to split (each its smaller slot) → its new point (filled
    /// by [`split_marked`]).
    marked: HashMap<Slot, u32>,
    /// The folded cells to cut: (cell, position of the first repeated
    /// corner).
    cut: Vec<(usize, usize)>,
    /// Edges that had a parallel edge.
    parallel_edges: usize,
}

impl Marks {
    /// Whether nothing is to split.
    pub fn is_empty(&self) -> bool {
        self.marked.is_empty()
    }
}

/// Splits the parallel edges and folded cells of `mesh` (module docs).
/// `partner[s]` is the slot glued to slot `s` (`None`: unmatched);
/// `holes` the unmatched slots that are holes.
pub fn split(mesh: &QuadMesh, partner: &[Option<Slot>], holes: &[Slot]) -> Split {
    split_marked(mesh, partner, holes, marks(&mesh.cells, partner))
}

/// The edges and cells [`split`] changes (none when `partner` does not
/// have one entry per cell edge).
pub fn marks(cells: &[[u32; 4]], partner: &[Option<Slot>]) -> Marks {
    let mut m = Marks::default();
    if partner.len() != 4 * cells.len() {
        return m;
    }
    for (c, cell) in cells.iter().enumerate() {
        let Some(r) = folded(cell) else { continue };
        let (e1, e2) = (
            edge_of(partner, (4 * c + r) as Slot),
            edge_of(partner, (4 * c + r + 2) as Slot),
        );
        if e1 != e2 {
            m.marked.insert(e1, u32::MAX);
            m.marked.insert(e2, u32::MAX);
            m.cut.push((c, r));
        }
    }
    for run in parallel_runs(cells, partner, &m.marked).chunk_by(|x, y| x.0 == y.0) {
        if run.len() < 2 {
            continue;
        }
        // keep a glued edge (a point there changes two cells), else the first
        let mut g: Vec<Slot> = run.iter().map(|&(_, s)| s).collect();
        g.sort_unstable_by_key(|&s| (partner[s as usize].is_none(), s));
        for &s in &g[1..] {
            m.marked.insert(s, u32::MAX);
            m.parallel_edges += 1;
        }
    }
    m
}

/// The edges not `marked`, keyed by vertex pair (smaller vertex in the
/// high half), sorted: parallel edges are runs of one key. Bucketed by
/// the smaller vertex, each bucket sorted (no sort of them all).
fn parallel_runs(
    cells: &[[u32; 4]],
    partner: &[Option<Slot>],
    marked: &HashMap<Slot, u32>,
) -> Vec<(u64, Slot)> {
    let n = cells.iter().flatten().max().map_or(0, |&v| v as usize + 1);
    let (_, by_pair) = dualex_util::bucket::sorted(n, |emit| {
        for s in 0..4 * cells.len() as Slot {
            let (a, b) = ends(cells, s);
            let skip = a == b || edge_of(partner, s) != s || marked.contains_key(&s);
            if !skip {
                let key = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
                emit(a.min(b) as usize, (key, s));
            }
        }
    });
    by_pair
}

/// [`split`] with its [`Marks`] found before.
pub fn split_marked(
    mesh: &QuadMesh,
    partner: &[Option<Slot>],
    holes: &[Slot],
    marks: Marks,
) -> Split {
    let cells = &mesh.cells;
    let mut out = Split {
        positions: mesh.positions.clone(),
        parallel_edges: marks.parallel_edges,
        ..Default::default()
    };
    if partner.len() != 4 * cells.len() {
        // a broken invariant of the caller: leave everything as it is
        debug_assert!(false, "one partner entry per cell edge");
        return identity(mesh, holes, out);
    }
    let Marks {
        mut marked, cut, ..
    } = marks;
    if marked.is_empty() {
        return identity(mesh, holes, out);
    }
    // the new points, in slot order (deterministic)
    let mut order: Vec<Slot> = marked.keys().copied().collect();
    order.sort_unstable();
    for s in order {
        let (a, b) = ends(cells, s);
        let m = out.positions.len() as u32;
        out.positions
            .push(dualex_cells::repair_local::mean(&out.positions, &[a, b]));
        out.new_points.push([a, b]);
        marked.insert(s, m);
    }
    let point = |s: Slot| marked.get(&edge_of(partner, s)).copied();
    let cut_at: HashMap<usize, usize> = cut.into_iter().collect();
    for (c, cell) in cells.iter().enumerate() {
        let mut p: Vec<u32> = Vec::with_capacity(6);
        let mut at = [usize::MAX; 4];
        for k in 0..4 {
            p.push(cell[k]);
            if let Some(m) = point((4 * c + k) as Slot) {
                at[k] = p.len();
                p.push(m);
            }
        }
        let intact = p.len() == 4;
        match cut_at.get(&c) {
            Some(&r) => {
                // cut between the points of edges r and r + 2
                let (i, j) = (at[r], at[r + 2]);
                out.polys.push(p[i..=j].to_vec());
                out.polys
                    .push(p[j..].iter().chain(&p[..=i]).copied().collect());
                out.origin.extend([c as u32; 2]);
                out.intact.extend([false; 2]);
                out.folded_cells += 1;
            }
            None => {
                out.polys.push(dualex_cells::polygons::polygon_of(&p));
                out.origin.push(c as u32);
                out.intact.push(intact);
            }
        }
    }
    for &s in holes {
        let (a, b) = ends(cells, s);
        match point(s) {
            Some(m) => out.hole_edges.extend([(a, m), (m, b)]),
            None => out.hole_edges.push((a, b)),
        }
    }
    out
}

/// The split that changes nothing.
fn identity(mesh: &QuadMesh, holes: &[Slot], mut out: Split) -> Split {
    out.polys = mesh
        .cells
        .iter()
        .map(dualex_cells::polygons::polygon)
        .collect();
    out.origin = (0..mesh.cells.len() as u32).collect();
    out.intact = vec![true; mesh.cells.len()];
    out.hole_edges = holes
        .iter()
        .filter(|&&s| (s as usize) < 4 * mesh.cells.len())
        .map(|&s| ends(&mesh.cells, s))
        .collect();
    out
}

#[cfg(test)]
mod tests;

//! Step 10, D = 3: the local repair of holes through columns — the
//! extrusion of the 2D local repair (`dualex_cells::repair_local`),
//! replayed in every layer ([`repair_open`], run on the placed hexes when
//! the graph has open interior faces).
//!
//! In a map extruded from a 2D map (`dualex extrude`), a 90° singular
//! vertex on a dual node becomes a singular edge along w through nodes:
//! the walks that reach it get lost, and a hole is left through all
//! layers whose section is the 2D face quads cannot represent (3 or 5
//! sides: a triangle- or pentagon-prism). The hex mesh is then made of
//! *columns*:
//!
//! ```text
//!   level 2   4───5          a hex's corners 0–3 (VTK) are its bottom
//!   layer 1   │ h'│          face, 4–7 its top face; h' stands on h
//!   level 1   4───5 = 0'──1'  (h's top face is h' 's bottom face), and
//!   layer 0   │ h │          `up` takes each corner i of h to corner
//!   level 0   0───1          i + 4 (the same vertex one level up)
//! ```
//!
//! The bottom faces of the lowest hexes are the 2D mesh of level 0, and
//! the level-0 edges of the open faces are its holes. The holes are closed
//! by polygons, the 2D repair pairs the odd ones along shortest paths of
//! quads and splits what the paths cross, and its result — every new point
//! with the points it is the mean of — is replayed at every level: each 2D
//! quad becomes a column of L hexes. So each crossed column's hexes are
//! split into two (three where the path turns), an end column's hole is
//! filled (triangle-prism → one hex, pentagon-prism → two hexes), in every
//! layer alike.
//!
//! Input: a hex mesh (VTK corner order) and its open interior faces
//! (corner sets). Output: `None` when the mesh is not made of columns
//! (preconditions, checked before anything is built: every hex has 8
//! distinct corners; stacks of one height L from a bottom to a top face,
//! every hex in one; `up` a one-to-one function; every open face a lateral
//! face `{a, b, up a, up b}`, each hole edge of level 0 under L of them;
//! hole cycles simple), when the 2D repair does not apply, or when the
//! result is not a valid hex mesh; else the repaired mesh, what was done,
//! and for each hex the input hex it comes from.

use dualex_cells::{HexMesh, QuadMesh};
use dualex_graph::{Glued, NodeGraph};
use dualex_segment::place::Placed;
use dualex_segment::trace::End;
use std::collections::{HashMap, HashSet};

const NONE: u32 = u32::MAX;

/// Step 10 on the placed hexes: counts the cracks (unmatched sides that
/// are not on the input's boundary, `closed`: the input has none) and,
/// when there are some, repairs them as holes through columns ([`repair`]),
/// the sources and corners carried.
pub fn repair_open(
    graph: &NodeGraph<3>,
    glued: &Glued<3>,
    ends: &[End<3>],
    closed: bool,
    out: &mut Placed<3, 8>,
    st: &mut crate::HexStats,
) {
    st.open_interior_faces = graph.lost_unmatched_sides(ends, closed);
    if st.open_interior_faces == 0 {
        return;
    }
    let open = open_faces(graph, glued, ends, closed);
    if let Some(rep) = repair(&out.mesh, &open) {
        st.columns = rep.report;
        st.open_interior_faces -= open.len().min(st.open_interior_faces);
        out.remake(rep.mesh, &rep.origin);
        st.finish_mesh(&out.mesh);
    }
}

/// The corners of the unmatched sides that are cracks, not boundary (see
/// `NodeGraph::lost_unmatched_sides`).
fn open_faces(
    graph: &NodeGraph<3>,
    glued: &Glued<3>,
    ends: &[End<3>],
    closed: bool,
) -> Vec<[u32; 4]> {
    graph
        .lost_sides(ends, closed)
        .map(|s| {
            let (node, d) = (graph.node_of(s), graph.dir_of(s));
            // the side's corners: cube codes with the axis bit of its side
            let (axis, want) = (d >> 1, usize::from(d & 1 == 0));
            let mut f = [0u32; 4];
            let codes = (0..8).filter(|c| (c >> axis) & 1 == want);
            for (k, c) in codes.enumerate() {
                f[k] = glued.vertex(node, c);
            }
            f
        })
        .collect()
}

/// What [`repair`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ColumnRepair {
    /// Holes through all layers closed (columns of polygons added).
    pub holes: usize,
    /// Paths of columns repaired (pairs of odd columns, or an odd column
    /// and the boundary).
    pub paths: usize,
    /// Columns of the input split along the paths (each crossed column's
    /// hexes into two, or three where a path turns).
    pub split: usize,
    /// Layers of the columns.
    pub layers: usize,
}

/// The repaired mesh.
#[derive(Clone, Debug)]
pub struct Repaired {
    /// The hex mesh.
    pub mesh: HexMesh,
    /// What was done.
    pub report: ColumnRepair,
    /// For each hex, the input hex it comes from (a filled hole: the hex
    /// next to it across its first side).
    pub origin: Vec<u32>,
}

fn key4(f: [u32; 4]) -> [u32; 4] {
    let mut k = f;
    k.sort_unstable();
    k
}

fn bottom(h: &[u32; 8]) -> [u32; 4] {
    [h[0], h[1], h[2], h[3]]
}

fn top(h: &[u32; 8]) -> [u32; 4] {
    [h[4], h[5], h[6], h[7]]
}

/// The columns of a hex mesh: the stacks (lowest hex first), the vertex
/// one level up (`NONE` on the top level) and down.
#[derive(Debug)]
pub(crate) struct Columns {
    pub stacks: Vec<Vec<usize>>,
    pub up: Vec<u32>,
    pub down: Vec<u32>,
}

impl Columns {
    /// The columns of `mesh`, or `None` (module docs, preconditions).
    pub fn find(mesh: &HexMesh) -> Option<Columns> {
        let cells = &mesh.cells;
        let nv = mesh.positions.len();
        let mut by_bottom: HashMap<[u32; 4], usize> = HashMap::new();
        let mut tops: HashSet<[u32; 4]> = HashSet::new();
        for (i, h) in cells.iter().enumerate() {
            let mut s = h.to_vec();
            s.sort_unstable();
            s.dedup();
            if s.len() != 8 || h.iter().any(|&v| v as usize >= nv) {
                return None;
            }
            if by_bottom.insert(key4(bottom(h)), i).is_some() {
                return None;
            }
            tops.insert(key4(top(h)));
        }
        let mut up = vec![NONE; nv];
        let mut in_stack = vec![false; cells.len()];
        let mut stacks = Vec::new();
        for (i, h) in cells.iter().enumerate() {
            if tops.contains(&key4(bottom(h))) {
                continue; // not the lowest of its stack
            }
            let (mut stack, mut cur) = (Vec::new(), i);
            loop {
                if std::mem::replace(&mut in_stack[cur], true) {
                    return None; // a hex in two stacks, or a cycle
                }
                stack.push(cur);
                let h = &cells[cur];
                for c in 0..4 {
                    let (a, b) = (h[c] as usize, h[c + 4]);
                    if up[a] != NONE && up[a] != b {
                        return None;
                    }
                    up[a] = b;
                }
                match by_bottom.get(&key4(top(h))) {
                    Some(&next) => cur = next,
                    None => break,
                }
            }
            stacks.push(stack);
        }
        let layers = stacks.first()?.len();
        if in_stack.contains(&false) || stacks.iter().any(|s| s.len() != layers) {
            return None;
        }
        let mut down = vec![NONE; nv];
        for (v, &u) in up.iter().enumerate() {
            if u != NONE {
                if down[u as usize] != NONE {
                    return None; // two vertices below one
                }
                down[u as usize] = v as u32;
            }
        }
        Some(Columns { stacks, up, down })
    }

    /// Layers (hexes per stack).
    pub fn layers(&self) -> usize {
        self.stacks.first().map_or(0, Vec::len)
    }

    /// Vertex `v` of level 0 taken `k` levels up.
    fn lift(&self, v: u32, k: usize) -> Option<u32> {
        let mut x = v;
        for _ in 0..k {
            x = *self.up.get(x as usize).filter(|&&u| u != NONE)?;
        }
        Some(x)
    }

    /// The level-0 edges of the open faces, oriented as their base quad
    /// traverses them, or `None` when an open face is not lateral or the
    /// faces are not L per level-0 edge.
    fn hole_edges(&self, base: &[[u32; 4]], open: &[[u32; 4]]) -> Option<Vec<(u32, u32)>> {
        let mut directed: HashSet<(u32, u32)> = HashSet::new();
        for q in base {
            for i in 0..4 {
                directed.insert((q[i], q[(i + 1) % 4]));
            }
        }
        let mut per_edge: HashMap<(u32, u32), usize> = HashMap::new();
        for f in open {
            // the two corners whose `up` is the other two
            let lower: Vec<u32> = f
                .iter()
                .copied()
                .filter(|&v| f.contains(&self.up[v as usize]))
                .collect();
            let [a, b] = lower[..] else { return None };
            let (mut a0, mut b0) = (a, b);
            while self.down[a0 as usize] != NONE && self.down[b0 as usize] != NONE {
                (a0, b0) = (self.down[a0 as usize], self.down[b0 as usize]);
            }
            if self.down[a0 as usize] != NONE || self.down[b0 as usize] != NONE {
                return None; // not one level for both
            }
            *per_edge.entry((a0.min(b0), a0.max(b0))).or_default() += 1;
        }
        let mut edges = Vec::with_capacity(per_edge.len());
        let mut keys: Vec<_> = per_edge.into_iter().collect();
        keys.sort_unstable();
        for ((a, b), n) in keys {
            if n != self.layers() {
                return None;
            }
            edges.push(
                match (directed.contains(&(a, b)), directed.contains(&(b, a))) {
                    (true, false) => (a, b),
                    (false, true) => (b, a),
                    _ => return None, // not a boundary edge of level 0
                },
            );
        }
        Some(edges)
    }
}

/// The column repair (module docs).
pub fn repair(mesh: &HexMesh, open: &[[u32; 4]]) -> Option<Repaired> {
    let cols = Columns::find(mesh)?;
    let layers = cols.layers();
    let base: Vec<[u32; 4]> = cols
        .stacks
        .iter()
        .map(|s| bottom(&mesh.cells[s[0]]))
        .collect();
    let edges = cols.hole_edges(&base, open)?;
    let (fill, left_open) = dualex_cells::polygons::hole_polygons(&edges);
    if left_open > 0 || fill.is_empty() {
        return None;
    }
    let flat = QuadMesh {
        positions: mesh.positions.clone(),
        cells: base.clone(),
    };
    let local = dualex_cells::repair_local::repair(&flat, &fill)?;
    let n0 = mesh.positions.len();
    let mut positions = local.mesh.positions.clone();
    // the new points at levels 1..=L, replayed from their recipes
    let mut new_at: Vec<Vec<u32>> = vec![(n0 as u32..positions.len() as u32).collect()];
    for k in 1..=layers {
        let mut ids: Vec<u32> = Vec::with_capacity(local.new_points.len());
        for pts in &local.new_points {
            let lifted: Vec<u32> = pts
                .iter()
                .map(|&p| lift_any(&cols, &ids, p, k, n0))
                .collect::<Option<_>>()?;
            positions.push(dualex_cells::repair_local::mean(&positions, &lifted));
            ids.push((positions.len() - 1) as u32);
        }
        new_at.push(ids);
    }
    let at = |v: u32, k: usize| lift_any(&cols, &new_at[k], v, k, n0);
    // the input hex next to each filled hole (its first edge's base quad)
    let by_edge: HashMap<(u32, u32), usize> = base
        .iter()
        .enumerate()
        .flat_map(|(i, q)| (0..4).map(move |j| ((q[(j + 1) % 4], q[j]), i)))
        .collect();
    let hole_base: Vec<usize> = fill
        .iter()
        .map(|p| by_edge.get(&(p[0], p[1])).copied())
        .collect::<Option<_>>()?;
    let mut cells = Vec::with_capacity(local.mesh.cells.len() * layers);
    let mut origin = Vec::with_capacity(cells.capacity());
    for (q, &o) in local.mesh.cells.iter().zip(&local.origin) {
        let o = o as usize;
        let b = if o < base.len() {
            o
        } else {
            *hole_base.get(o - base.len())?
        };
        for (k, &input) in cols.stacks[b].iter().enumerate() {
            let lo = q.map(|v| at(v, k));
            let hi = q.map(|v| at(v, k + 1));
            let mut h = [0u32; 8];
            for i in 0..4 {
                h[i] = lo[i]?;
                h[i + 4] = hi[i]?;
            }
            cells.push(h);
            origin.push(input as u32);
        }
    }
    let out = HexMesh { positions, cells };
    let r = dualex_check::check_hex_mesh(out.positions.len(), &out.cells, None);
    r.is_valid().then_some(Repaired {
        mesh: out,
        report: ColumnRepair {
            holes: fill.len(),
            paths: local.paths,
            split: split_columns(&local.origin, base.len()),
            layers,
        },
        origin,
    })
}

/// Input quads (`origin` below `n_base`) that became more than one quad.
fn split_columns(origin: &[u32], n_base: usize) -> usize {
    let mut count: HashMap<u32, usize> = HashMap::new();
    for &o in origin.iter().filter(|&&o| (o as usize) < n_base) {
        *count.entry(o).or_default() += 1;
    }
    count.values().filter(|&&n| n > 1).count()
}

/// Vertex `v` of the repaired level 0 at level `k`: an input vertex
/// lifted by `up`, a new point by its id at that level (`new_k`).
fn lift_any(cols: &Columns, new_k: &[u32], v: u32, k: usize, n0: usize) -> Option<u32> {
    if (v as usize) < n0 {
        cols.lift(v, k)
    } else if k == 0 {
        Some(v)
    } else {
        new_k.get(v as usize - n0).copied()
    }
}

#[cfg(test)]
mod tests;

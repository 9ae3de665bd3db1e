//! A local repair of the faces quads cannot represent, instead of
//! subdividing the whole mesh: quad's step 10, first choice
//! (`dualex_quad::repair`), and each layer of hex's columns.
//!
//! Input: the glued cells (a triangle is a cell with a repeated corner) and
//! the hole-filling polygons. Output: an all-quad mesh, or `None` when the
//! local repair does not apply (the caller then subdivides globally).
//!
//! A face with an odd number of sides cannot be split into quads; faces
//! with an even number can (a fan of quads from one corner). Odd faces are
//! paired up (or sent to the boundary) by the cheapest paths of quads
//! between them, chosen independently of the faces' order (`paths`: the
//! quads a path adds, a minimum-cost matching). Every edge the path
//! crosses gets a new point at its midpoint; every quad the path crosses
//! is split: into two quads when the path leaves through the opposite
//! edge, into three around a new centre point when it turns. Each end
//! face gets one new point, so a triangle becomes a quad and a pentagon a
//! hexagon (two quads, fanned from the corner that leaves the best
//! valences). Orientation is kept; only the faces along the path change.
//! Every new point is returned with the points it is the mean of, so the
//! same repair can be replayed on copies of the mesh (`dualex_hex::columns`).
//!
//! Invariants checked before any write: every polygon has distinct
//! corners; interior edges have two faces. The result is checked by the
//! caller like any output.

use crate::QuadMesh;
use fast_hash::FastMap as HashMap;

mod fast_hash;
mod paths;

/// The oriented edges of polygon `p`.
fn edges(p: &[u32]) -> impl Iterator<Item = (u32, u32)> + '_ {
    (0..p.len()).map(move |i| (p[i], p[(i + 1) % p.len()]))
}

fn key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// Faces of each undirected edge.
fn edge_faces(polys: &[Vec<u32>]) -> HashMap<(u32, u32), Vec<usize>> {
    let mut m: HashMap<(u32, u32), Vec<usize>> = HashMap::default();
    for (f, p) in polys.iter().enumerate() {
        for (a, b) in edges(p) {
            m.entry(key(a, b)).or_default().push(f);
        }
    }
    m
}

/// Inserts `m` into polygon `p` on its edge `{a, b}`.
fn insert_on(p: &mut Vec<u32>, e: (u32, u32), m: u32) -> Option<()> {
    let i = (0..p.len()).find(|&i| key(p[i], p[(i + 1) % p.len()]) == key(e.0, e.1))?;
    p.insert(i + 1, m);
    Some(())
}

/// A path: its faces and the edges between consecutive ones (and a last
/// boundary edge when it ends on the boundary).
pub(crate) type Path = (Vec<usize>, Vec<(u32, u32)>);

/// Splits quad `q` crossed by the path through its edges `e1` (points
/// `p1`) and `e2` (`p2`): two quads when the edges are opposite, three
/// around the new centre `c` when they are adjacent.
fn split_quad(
    q: &[u32],
    e1: ((u32, u32), u32),
    e2: ((u32, u32), u32),
    centre: impl FnOnce() -> u32,
) -> Option<Vec<Vec<u32>>> {
    let at = |e: (u32, u32)| (0..4).find(|&i| key(q[i], q[(i + 1) % 4]) == e);
    let (i, j) = (at(e1.0)?, at(e2.0)?);
    let (pi, pj) = (e1.1, e2.1);
    let v = |k: usize| q[k % 4];
    let turn = (j + 4 - i) % 4;
    let c = if turn % 2 == 1 { centre() } else { u32::MAX };
    match turn {
        2 => Some(vec![
            vec![v(i + 1), v(i + 2), pj, pi],
            vec![v(i + 3), v(i + 4), pi, pj],
        ]),
        1 => Some(vec![
            // turn at corner i+1: [pi, v(i+1), pj, c] and the rest
            vec![pi, v(i + 1), pj, c],
            vec![c, pj, v(i + 2), v(i + 3)],
            vec![v(i), pi, c, v(i + 3)],
        ]),
        3 => Some(vec![
            // turn at corner i (= j+1)
            vec![pj, v(i), pi, c],
            vec![c, pi, v(i + 1), v(i + 2)],
            vec![v(i + 3), pj, c, v(i + 2)],
        ]),
        _ => None,
    }
}

/// The mean of the positions of `pts`.
pub fn mean(pos: &[[f64; 3]], pts: &[u32]) -> [f64; 3] {
    let k = pts.len() as f64;
    let mut m = [0.0; 3];
    for &v in pts {
        for (mk, x) in m.iter_mut().zip(pos[v as usize]) {
            *mk += x / k;
        }
    }
    m
}

/// Distinct edges at each vertex of `polys`.
fn degrees(polys: &[Vec<u32>], nv: usize) -> Vec<u32> {
    let mut all: Vec<(u32, u32)> = polys
        .iter()
        .flat_map(|p| edges(p).map(|(a, b)| key(a, b)))
        .collect();
    all.sort_unstable();
    all.dedup();
    let mut d = vec![0u32; nv];
    for (a, b) in all {
        d[a as usize] += 1;
        d[b as usize] += 1;
    }
    d
}

/// The corner of even polygon `p` to fan its quads from: the one whose
/// diagonals leave the fewest corners of valence ≤ 2, then the valences
/// nearest 4 (so the choice does not depend on where `p` starts, except
/// between equally good corners).
fn fan_corner(p: &[u32], degree: &[u32]) -> usize {
    let n = p.len();
    if n <= 4 {
        return 0;
    }
    let score = |r: usize| {
        let (mut low, mut off) = (0u32, 0u32);
        for k in 0..n {
            // the fan's diagonals: r to r+3, r+5, …, r+n−3
            let extra = if k == r {
                (n as u32 - 4) / 2
            } else {
                let d = (k + n - r) % n;
                u32::from(d >= 3 && d <= n - 3 && d % 2 == 1)
            };
            let v = degree[p[k] as usize] + extra;
            low += u32::from(v <= 2);
            off += v.abs_diff(4);
        }
        (low, off)
    };
    (0..n).min_by_key(|&r| score(r)).unwrap_or(0)
}

/// What [`repair`] made.
pub struct Local {
    /// The all-quad mesh.
    pub mesh: QuadMesh,
    /// Paths repaired (pairs of odd faces, or an odd face and the
    /// boundary).
    pub paths: usize,
    /// For each cell, the polygon it comes from: an index into the input
    /// cells followed by `extra`.
    pub origin: Vec<u32>,
    /// The new points in order (ids from the input's vertex count on): the
    /// points each is the mean of (new points only refer to earlier ones),
    /// so that the same repair can be replayed on copies of the mesh (the
    /// layers of an extruded hex mesh, `dualex_hex::columns`).
    pub new_points: Vec<Vec<u32>>,
}

/// The local repair (module docs): `None` when it does not apply.
pub fn repair(mesh: &QuadMesh, extra: &[Vec<u32>]) -> Option<Local> {
    let polys: Vec<Vec<u32>> = mesh
        .cells
        .iter()
        .map(crate::polygons::polygon)
        .chain(extra.iter().cloned())
        .collect();
    repair_polys(&mesh.positions, &polys)
}

/// [`repair`] of polygons (origins index `polys`).
pub fn repair_polys(positions: &[[f64; 3]], polys: &[Vec<u32>]) -> Option<Local> {
    let n_input = polys.len();
    let mut positions = positions.to_vec();
    let mut polys = polys.to_vec();
    for p in &polys {
        let mut s = p.clone();
        s.sort_unstable();
        s.dedup();
        if s.len() != p.len() || p.len() < 3 {
            return None;
        }
    }
    let mut origin: Vec<u32> = (0..polys.len() as u32).collect();
    let mut paths = 0;
    // each new point: its position and the points it is the mean of
    let mut made: Vec<Vec<u32>> = Vec::new();
    let mut midpoint = |pos: &mut Vec<[f64; 3]>, pts: &[u32]| -> u32 {
        pos.push(mean(pos, pts));
        made.push(pts.to_vec());
        (pos.len() - 1) as u32
    };
    while polys.iter().any(|p| p.len() % 2 == 1) {
        let by_edge = edge_faces(&polys);
        let (faces, shared) = paths::next(&polys, &by_edge)?;
        let mut distinct = faces.clone();
        distinct.sort_unstable();
        distinct.dedup();
        if distinct.len() != faces.len() {
            return None; // a path through a face twice
        }
        let points: Vec<u32> = shared
            .iter()
            .map(|&(a, b)| midpoint(&mut positions, &[a, b]))
            .collect();
        let mut replaced: Vec<(usize, Vec<Vec<u32>>)> = Vec::new();
        for (k, &f) in faces.iter().enumerate() {
            let before = (k > 0).then(|| (shared[k - 1], points[k - 1]));
            let after = shared.get(k).map(|&e| (e, points[k]));
            let p = &polys[f];
            let odd = p.len() % 2 == 1;
            match (before, after) {
                (Some(e), Some(g)) if !odd => {
                    let centre = || midpoint(&mut positions, p);
                    replaced.push((f, split_quad(p, e, g, centre)?));
                }
                (Some((e, m)), None) | (None, Some((e, m))) if odd => {
                    let mut q = p.clone();
                    insert_on(&mut q, e, m)?;
                    replaced.push((f, vec![q]));
                }
                _ => return None,
            }
        }
        let mut next: Vec<Vec<u32>> = Vec::with_capacity(polys.len() + 2 * faces.len());
        let mut next_origin = Vec::with_capacity(next.capacity());
        let mut repl: HashMap<usize, Vec<Vec<u32>>> = replaced.into_iter().collect();
        for (f, p) in polys.into_iter().enumerate() {
            match repl.remove(&f) {
                Some(list) => {
                    next_origin.extend(std::iter::repeat_n(origin[f], list.len()));
                    next.extend(list);
                }
                None => {
                    next_origin.push(origin[f]);
                    next.push(p);
                }
            }
        }
        polys = next;
        origin = next_origin;
        paths += 1;
        if paths > n_input {
            return None;
        }
    }
    let mut cells = Vec::with_capacity(polys.len());
    let mut cell_origin = Vec::with_capacity(polys.len());
    let degree = degrees(&polys, positions.len());
    for (p, &o) in polys.iter().zip(&origin) {
        // fan of quads from the corner that leaves the best valences
        let r = fan_corner(p, &degree);
        let n = p.len();
        for i in (1..n - 1).step_by(2) {
            cells.push([p[r], p[(r + i) % n], p[(r + i + 1) % n], p[(r + i + 2) % n]]);
            cell_origin.push(o);
        }
    }
    Some(Local {
        mesh: QuadMesh { positions, cells },
        paths,
        origin: cell_origin,
        new_points: made,
    })
}

#[cfg(test)]
mod tests;

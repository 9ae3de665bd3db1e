//! Step 8, first choice: a local repair of the faces quads cannot
//! represent, instead of subdividing the whole mesh (issue: clean output).
//!
//! Input: the glued cells (a triangle is a cell with a repeated corner) and
//! the hole-filling polygons. Output: an all-quad mesh, or `None` when the
//! local repair does not apply (the caller then subdivides globally).
//!
//! A face with an odd number of sides cannot be split into quads; faces
//! with an even number can (a fan of quads from one corner). Odd faces are
//! paired up: from an odd face, a breadth-first search over the quads finds
//! the nearest other odd face (or, when there is none left in reach, the
//! nearest boundary edge). Every edge the path crosses gets a new point at its
//! midpoint; every quad the path crosses is split: into two quads when the
//! path leaves through the opposite edge, into three around a new centre
//! point when it turns. Each end face gets one new point, so a triangle
//! becomes a quad and a pentagon a hexagon (two quads). Orientation is
//! kept; only the faces along the path change.
//!
//! Invariants checked before any write: every polygon has distinct
//! corners; interior edges have two faces. The result is checked by the
//! caller like any output.

use dualex_map::QuadMesh;
use std::collections::{HashMap, VecDeque};

/// The oriented edges of polygon `p`.
fn edges(p: &[u32]) -> impl Iterator<Item = (u32, u32)> + '_ {
    (0..p.len()).map(move |i| (p[i], p[(i + 1) % p.len()]))
}

fn key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// Faces of each undirected edge.
fn edge_faces(polys: &[Vec<u32>]) -> HashMap<(u32, u32), Vec<usize>> {
    let mut m: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
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
type Path = (Vec<usize>, Vec<(u32, u32)>);

/// A path from odd face `s` to the nearest other odd face, or with
/// `to_boundary` to the nearest odd face or boundary edge: the faces and,
/// between consecutive faces, the edge they share; a last edge without a
/// face when the path ends on the boundary.
fn path_from(
    s: usize,
    polys: &[Vec<u32>],
    by_edge: &HashMap<(u32, u32), Vec<usize>>,
    to_boundary: bool,
) -> Option<Path> {
    let mut prev: HashMap<usize, (usize, (u32, u32))> = HashMap::new();
    let mut queue = VecDeque::from([s]);
    let mut seen = vec![false; polys.len()];
    seen[s] = true;
    while let Some(f) = queue.pop_front() {
        let end_here = f != s && polys[f].len() % 2 == 1;
        // a boundary end only on the start face or a quad
        let boundary = if !to_boundary || end_here || (f != s && polys[f].len() != 4) {
            None
        } else {
            edges(&polys[f]).find(|&(a, b)| by_edge.get(&key(a, b)).is_some_and(|l| l.len() == 1))
        };
        if end_here || boundary.is_some() {
            let mut faces = vec![f];
            let mut shared = Vec::new();
            let mut g = f;
            while let Some(&(p, e)) = prev.get(&g) {
                faces.push(p);
                shared.push(e);
                g = p;
            }
            faces.reverse();
            shared.reverse();
            if let Some(b) = boundary {
                shared.push(key(b.0, b.1));
            }
            return Some((faces, shared));
        }
        // only quads are crossed (and the start face left)
        if f != s && polys[f].len() != 4 {
            continue;
        }
        for (a, b) in edges(&polys[f]) {
            let Some(list) = by_edge.get(&key(a, b)) else {
                continue;
            };
            if list.len() != 2 {
                continue;
            }
            let g = if list[0] == f { list[1] } else { list[0] };
            if !seen[g] {
                seen[g] = true;
                prev.insert(g, (f, key(a, b)));
                queue.push_back(g);
            }
        }
    }
    None
}

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
}

/// The local repair (module docs): `None` when it does not apply.
pub fn repair(mesh: &QuadMesh, extra: &[Vec<u32>]) -> Option<Local> {
    let mut positions = mesh.positions.clone();
    let mut polys: Vec<Vec<u32>> = mesh
        .cells
        .iter()
        .map(crate::repair::polygon)
        .chain(extra.iter().cloned())
        .collect();
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
    let midpoint = |pos: &mut Vec<[f64; 3]>, pts: &[u32]| -> u32 {
        let k = pts.len() as f64;
        let mut m = [0.0; 3];
        for &v in pts {
            for (mk, x) in m.iter_mut().zip(pos[v as usize]) {
                *mk += x / k;
            }
        }
        pos.push(m);
        (pos.len() - 1) as u32
    };
    while let Some(s) = polys.iter().position(|p| p.len() % 2 == 1) {
        let by_edge = edge_faces(&polys);
        // another odd face first; the boundary when there is none
        let (faces, shared) = path_from(s, &polys, &by_edge, false)
            .or_else(|| path_from(s, &polys, &by_edge, true))?;
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
        if paths > mesh.cells.len() + extra.len() {
            return None;
        }
    }
    let mut cells = Vec::with_capacity(polys.len());
    let mut cell_origin = Vec::with_capacity(polys.len());
    for (p, &o) in polys.iter().zip(&origin) {
        // fan of quads from corner 0 (even polygons)
        for i in (1..p.len() - 1).step_by(2) {
            cells.push([p[0], p[i], p[i + 1], p[(i + 2) % p.len()]]);
            cell_origin.push(o);
        }
    }
    Some(Local {
        mesh: QuadMesh { positions, cells },
        paths,
        origin: cell_origin,
    })
}

#[cfg(test)]
mod tests;

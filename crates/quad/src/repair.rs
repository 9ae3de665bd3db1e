//! Step 10b: the last resort for configurations no quad can represent.
//!
//! A 90° singularity sitting exactly on a node of the dual grid (a non-SoG
//! map: `../shared/data/directional/horsers-param-full-seamless.obj` has
//! 25) is a *triangle* of the quad mesh: one side of a node walks into the
//! singular vertex and finds no partner, and its two corners are the same
//! vertex. No perturbation can move such a vertex (its charts disagree
//! around it) and no local gluing of quads can close a 3-sided face (the
//! sides around it are odd in number). Such faces are paired up and made
//! quads along a path of faces between them (`dualex_cells::repair_local`); where
//! that does not apply, what is left is to make the mesh all-quad by one
//! step of linear subdivision — each quad into 4, each triangle into 3
//! quads (face centroid, edge midpoints) — which keeps the surface, the
//! singularities and the topology. Both are reported.
//!
//! Input: the glued cells and positions. Output: `None` when every cell has
//! four distinct corners in cyclic order (nothing to do), else the
//! repaired all-quad mesh.

use dualex_cells::polygons::polygon;
use dualex_cells::QuadMesh;
use std::collections::HashMap;

/// Number of cells that are not proper quads (see the module docs).
pub fn odd_cells(mesh: &QuadMesh) -> usize {
    mesh.cells.iter().filter(|c| polygon(c).len() != 4).count()
}

/// What [`subdivide_if_odd`] made of the glued cells.
#[derive(Clone, Debug)]
pub struct Repaired {
    /// The all-quad mesh.
    pub mesh: QuadMesh,
    /// Cells of fewer than 3 distinct corners dropped.
    pub dropped: usize,
    /// Whether every cell was subdivided (else the quads of `extra` were
    /// only added, or the local repair did it).
    pub subdivided: bool,
    /// Paths of the local repair (`dualex_cells::repair_local`): pairs of faces
    /// quads cannot represent, made quads along a path between them.
    pub local_paths: usize,
    /// For each cell of `mesh`, the polygon it comes from: an index into
    /// the input cells followed by `extra`.
    pub origin: Vec<u32>,
    /// Vertex copies made where the surface was pinched
    /// (`crate::pinched`).
    pub pinched: usize,
}

/// Subdivides every cell once when some cell is a triangle or some polygon
/// of `extra` (hole-filling polygons) is not a quad (module docs); cells of
/// fewer than 3 distinct corners are dropped and counted. Quads in `extra`
/// alone are added as they are.
pub fn subdivide_if_odd(mesh: &QuadMesh, extra: &[Vec<u32>]) -> Option<Repaired> {
    let polys: Vec<Vec<u32>> = mesh.cells.iter().map(polygon).collect();
    repair_polygons(&mesh.positions, &polys, extra, false)
}

/// Whether `p` has four distinct corners.
pub(crate) fn proper_quad(p: &[u32]) -> bool {
    p.len() == 4 && (0..4).all(|i| (i + 1..4).all(|j| p[i] != p[j]))
}

/// [`subdivide_if_odd`] on polygons (the cells after
/// `crate::ambiguous`): `None` when every polygon is a proper quad, there
/// is no hole and `changed` is false; else the local repair when it gives
/// a valid mesh, the subdivision otherwise. Origins index `polys` then
/// `extra`.
pub fn repair_polygons(
    positions: &[[f64; 3]],
    polys: &[Vec<u32>],
    extra: &[Vec<u32>],
    changed: bool,
) -> Option<Repaired> {
    let all = || polys.iter().chain(extra);
    if all().all(|p| proper_quad(p)) {
        if extra.is_empty() && !changed {
            return None;
        }
        return Some(Repaired {
            mesh: QuadMesh {
                positions: positions.to_vec(),
                cells: all().map(|p| [p[0], p[1], p[2], p[3]]).collect(),
            },
            dropped: 0,
            subdivided: false,
            local_paths: 0,
            origin: (0..(polys.len() + extra.len()) as u32).collect(),
            pinched: 0,
        });
    }
    // first choice: the local repair, kept when its result is a valid
    // all-quad mesh; polygons of fewer than 3 distinct corners (a cell
    // folded flat) are dropped, as the subdivision drops them
    // (and a polygon through one vertex twice is cut there into two)
    let joined: Vec<Vec<u32>> = all().cloned().collect();
    let (mut kept, mut polys_kept, mut dropped) = (Vec::new(), Vec::new(), 0);
    for (i, p) in joined.iter().enumerate() {
        let before = kept.len();
        // the pieces pass through each vertex once: their length is their
        // number of distinct corners
        for piece in cut_at_repeats(p).into_iter().filter(|q| q.len() >= 3) {
            kept.push(i as u32);
            polys_kept.push(piece);
        }
        dropped += usize::from(kept.len() == before);
    }
    if let Some(local) = dualex_cells::repair_local::repair_polys(positions, &polys_kept) {
        let mut mesh = local.mesh;
        let pinched = valid_or_unpinched(&mut mesh);
        if let Some(pinched) = pinched {
            return Some(Repaired {
                mesh,
                dropped,
                subdivided: false,
                local_paths: local.paths,
                origin: local.origin.iter().map(|&o| kept[o as usize]).collect(),
                pinched,
            });
        }
    }
    let mut rep = subdivide_polys(positions, &joined);
    rep.pinched = valid_or_unpinched(&mut rep.mesh).unwrap_or(0);
    Some(rep)
}

/// `p` cut at its repeated corners into polygons through each vertex
/// once (the corner belongs to both pieces).
fn cut_at_repeats(p: &[u32]) -> Vec<Vec<u32>> {
    let n = p.len();
    for i in 0..n {
        if let Some(d) = (1..n).find(|&d| p[(i + d) % n] == p[i]) {
            let a: Vec<u32> = (0..d).map(|k| p[(i + k) % n]).collect();
            let b: Vec<u32> = (d..n).map(|k| p[(i + k) % n]).collect();
            let mut out = cut_at_repeats(&a);
            out.extend(cut_at_repeats(&b));
            return out;
        }
    }
    vec![p.to_vec()]
}

/// `Some(copies)` when `mesh` is valid, after splitting its pinched
/// vertices (`crate::pinched`) if that is all that keeps it from being
/// valid; `None` (mesh unchanged) otherwise.
fn valid_or_unpinched(mesh: &mut QuadMesh) -> Option<usize> {
    let r = dualex_check::check_quad_mesh(mesh.positions.len(), &mesh.cells);
    if r.is_valid() {
        return Some(0);
    }
    if r.non_manifold_vertices.is_empty() {
        return None;
    }
    let mut split = mesh.clone();
    let copies = crate::pinched::split_pinched(&mut split);
    let r = dualex_check::check_quad_mesh(split.positions.len(), &split.cells);
    if copies == 0 || !r.is_valid() {
        return None;
    }
    *mesh = split;
    Some(copies)
}

/// One step of linear subdivision of the cells and the polygons of
/// `extra` (module docs); cells of fewer than 3 distinct corners dropped.
pub fn subdivide(mesh: &QuadMesh, extra: &[Vec<u32>]) -> Repaired {
    let polys: Vec<Vec<u32>> = mesh
        .cells
        .iter()
        .map(polygon)
        .chain(extra.iter().cloned())
        .collect();
    subdivide_polys(&mesh.positions, &polys)
}

/// [`subdivide`] of polygons.
fn subdivide_polys(positions: &[[f64; 3]], polys: &[Vec<u32>]) -> Repaired {
    let polygons = polys.iter().cloned();
    let mut out = QuadMesh {
        positions: positions.to_vec(),
        cells: Vec::with_capacity(4 * polys.len()),
    };
    let mut edge_point: HashMap<(u32, u32), u32> = HashMap::new();
    let mut dropped = 0;
    let mut origin = Vec::with_capacity(4 * polys.len());
    for (polygon_id, p) in polygons.enumerate() {
        if p.len() < 3 {
            dropped += 1;
            continue;
        }
        let k = p.len();
        let mut centre = [0.0; 3];
        for &v in &p {
            for (c, x) in centre.iter_mut().zip(out.positions[v as usize]) {
                *c += x / k as f64;
            }
        }
        let f = out.positions.len() as u32;
        out.positions.push(centre);
        let mut mid = |a: u32, b: u32, pos: &mut Vec<[f64; 3]>| {
            *edge_point.entry((a.min(b), a.max(b))).or_insert_with(|| {
                let (pa, pb) = (pos[a as usize], pos[b as usize]);
                pos.push(std::array::from_fn(|i| 0.5 * (pa[i] + pb[i])));
                (pos.len() - 1) as u32
            })
        };
        for i in 0..k {
            let (prev, v, next) = (p[(i + k - 1) % k], p[i], p[(i + 1) % k]);
            let e_next = mid(v, next, &mut out.positions);
            let e_prev = mid(prev, v, &mut out.positions);
            out.cells.push([v, e_next, f, e_prev]);
            origin.push(polygon_id as u32);
        }
    }
    Repaired {
        mesh: out,
        dropped,
        subdivided: true,
        local_paths: 0,
        origin,
        pinched: 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_polygon_through_a_vertex_twice_is_cut_there() {
        let pieces = cut_at_repeats(&[1, 2, 1, 3, 4]);
        assert_eq!(pieces, vec![vec![1, 2], vec![1, 3, 4]]);
        assert_eq!(cut_at_repeats(&[1, 2, 3]), vec![vec![1, 2, 3]]);
        // every edge of the polygon is in one piece, in its direction
        let pieces = cut_at_repeats(&[5, 1, 6, 1, 7, 8]);
        let mut edges: Vec<(u32, u32)> = pieces
            .iter()
            .flat_map(|q| (0..q.len()).map(move |i| (q[i], q[(i + 1) % q.len()])))
            .collect();
        edges.sort_unstable();
        let mut want = vec![(5, 1), (1, 6), (6, 1), (1, 7), (7, 8), (8, 5)];
        want.sort_unstable();
        assert_eq!(edges, want);
    }

    #[test]
    fn a_triangle_and_a_quad_become_seven_quads() {
        // quad 0-1-2-3 and triangle 1-4-2 (written as a quad with a repeated corner)
        let mesh = QuadMesh {
            positions: vec![
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [1.0, 1.0, 0.0],
                [0.0, 1.0, 0.0],
                [2.0, 0.5, 0.0],
            ],
            cells: vec![[0, 1, 2, 3], [1, 4, 4, 2]],
        };
        assert_eq!(odd_cells(&mesh), 1);
        // the local repair pairs the triangle with the boundary
        let local = subdivide_if_odd(&mesh, &[]).expect("repaired");
        assert!(!local.subdivided && local.local_paths == 1);
        let rep = subdivide(&mesh, &[]);
        assert!(rep.subdivided);
        // the quad's 4 pieces, then the triangle's 3
        assert_eq!(rep.origin, [0, 0, 0, 0, 1, 1, 1]);
        let (out, dropped) = (rep.mesh, rep.dropped);
        assert_eq!(dropped, 0);
        assert_eq!(out.cells.len(), 7);
        // V = 5 + 2 face points + 6 edge points (the shared edge once)
        assert_eq!(out.positions.len(), 13);
        for c in &out.cells {
            assert_eq!(polygon(c).len(), 4, "{c:?}");
        }
    }

    #[test]
    fn proper_quads_are_left_alone() {
        let mesh = QuadMesh {
            positions: vec![[0.0; 3]; 4],
            cells: vec![[0, 1, 2, 3]],
        };
        assert!(subdivide_if_odd(&mesh, &[]).is_none());
    }
}

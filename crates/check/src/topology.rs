//! The topology of an output compared with its input's, for the CLI's last
//! check before writing (an extraction must not silently change it).
//!
//! Input: the input simplices (triangles, or tets and their boundary
//! triangles) and the output's [`crate::QuadReport`] / [`crate::HexReport`].
//! Output: a [`Shape`] per side and a [`Comparison`] (match flag, JSON).
//!
//! The counts use the checker's own definitions on both sides, so that they
//! compare like with like: components through shared vertices, Euler
//! characteristic `V_used − E + F` of a surface, boundary components as the
//! components of the boundary edges. A volume's shape is (cell components,
//! Euler characteristic and components of its boundary surface).

use dualex_util::union_find::UnionFind;
use serde_json::{json, Value};

/// The topology compared between input and output.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Shape {
    /// Connected components (of the faces, or of the cells of a volume).
    pub components: usize,
    /// Euler characteristic of the surface (of a volume: of its boundary).
    pub euler: i64,
    /// Boundary loops of a surface; boundary surfaces of a volume.
    pub boundary_components: usize,
}

/// What the last check and the geometric stage read of an input map:
/// its [`Shape`] and its boundary as the stage reads it (of a tet map,
/// its faces of one tet: their places `4·tet + f`, in no order; of a
/// triangle map, nothing: `()`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct InputShape<B> {
    /// Its components, Euler characteristic and boundary components, as
    /// the check compares them with the output's.
    pub shape: Shape,
    /// Its boundary (see above).
    pub boundary: B,
}

impl Shape {
    fn to_json(self) -> Value {
        json!({
            "components": self.components,
            "euler": self.euler,
            "boundary_components": self.boundary_components,
        })
    }
}

/// Components of cells joined through shared vertices (indices
/// `>= n_vertices` ignored): per cell, each corner's root joined to the
/// cell's (one find per corner); the components are the used roots.
pub fn cell_components<const K: usize>(n_vertices: usize, cells: &[[u32; K]]) -> usize {
    use dualex_util::union_find::find;
    let mut parent: Vec<u32> = (0..n_vertices as u32).collect();
    let mut used = vec![false; n_vertices];
    for c in cells
        .iter()
        .filter(|c| c.iter().all(|&v| (v as usize) < n_vertices))
    {
        // the cell's root so far, each corner's root joined to it (the
        // smaller root wins, as in `UnionFind::union`)
        used[c[0] as usize] = true;
        let mut root = find(&mut parent, c[0]);
        for &v in &c[1..] {
            used[v as usize] = true;
            let r = find(&mut parent, v);
            if r != root {
                parent[r.max(root) as usize] = r.min(root);
                root = r.min(root);
            }
        }
    }
    // a set joins used vertices only, its root among them
    (0..n_vertices)
        .filter(|&v| used[v] && parent[v] == v as u32)
        .count()
}

/// An undirected edge as one key, `lo << 32 | hi` (the checkers' edge
/// runs).
pub(crate) fn edge_key(a: u32, b: u32) -> u64 {
    u64::from(a.min(b)) << 32 | u64::from(a.max(b))
}

/// The face of tet `t` opposite its corner `f`, in the tet's orientation.
fn opposite_face(t: &[u32; 4], f: usize) -> [u32; 3] {
    [t[(f + 1) % 4], t[(f + 2) % 4], t[(f + 3) % 4]]
}

/// The shape of a polygon surface (faces of `K` corners, indices
/// `>= n_vertices` ignored).
///
/// Every side of a good face is an undirected edge, its larger end put in
/// the bucket of its smaller (a counting sort). A bucket `a` is read
/// twice, its ends stamped with `a`: the first read counts each end's
/// sides (a new stamp is a new edge, which joins the components: a face's
/// sides join all its corners), the second finds the ends met once
/// (boundary edges, which join the boundary's components). No sort.
pub fn surface_shape<const K: usize>(n_vertices: usize, faces: &[[u32; K]]) -> Shape {
    let n = n_vertices;
    let good = move |f: &&[u32; K]| f.iter().all(|&v| (v as usize) < n);
    let sides = |f: &[u32; K]| {
        std::array::from_fn::<_, K, _>(|k| {
            let (a, b) = (f[k], f[(k + 1) % K]);
            (a.min(b) as usize, a.max(b))
        })
    };
    let (mut start, mut used, mut n_faces) = (vec![0usize; n + 1], vec![false; n], 0i64);
    for f in faces.iter().filter(good) {
        n_faces += 1;
        for (&v, (a, _)) in f.iter().zip(sides(f)) {
            used[v as usize] = true;
            start[a + 1] += 1;
        }
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let (mut ends, mut next) = (vec![0u32; start[n]], start[..n].to_vec());
    for f in faces.iter().filter(good) {
        for (a, b) in sides(f) {
            ends[next[a]] = b;
            next[a] += 1;
        }
    }
    drop(next);
    // per end `b` of the bucket read: that bucket's `a + 1`, its sides to `b`
    let (mut stamp, mut met) = (vec![0u32; n], vec![0u32; n]);
    let (mut cells, mut loops) = (UnionFind::new(n), UnionFind::new(n));
    let (mut on_boundary, mut n_edges) = (vec![false; n], 0i64);
    for a in 0..n {
        let (bucket, mark) = (&ends[start[a]..start[a + 1]], a as u32 + 1);
        for &b in bucket {
            let b = b as usize;
            if stamp[b] != mark {
                (stamp[b], met[b]) = (mark, 0);
                n_edges += 1;
                cells.union(a, b);
            }
            met[b] += 1;
        }
        for &b in bucket.iter().filter(|&&b| met[b as usize] == 1) {
            loops.union(a, b as usize);
            (on_boundary[a], on_boundary[b as usize]) = (true, true);
        }
    }
    let n_used = used.iter().filter(|&&u| u).count() as i64;
    Shape {
        components: cells.count_sets((0..n).filter(|&v| used[v])),
        euler: n_used - n_edges + n_faces,
        boundary_components: loops.count_sets((0..n).filter(|&v| on_boundary[v])),
    }
}

/// The faces of a tet mesh that belong to exactly one tet (its boundary),
/// each as its place `4·tet + f` (the face opposite corner `f`), in no
/// particular order: the callers orient them. Faces are equal
/// when their three vertices are, whatever their order.
///
/// Every face, its corners sorted `a ≤ b ≤ c`, is bucketed by `a` (a
/// counting sort in tet order, into parallel arrays: the key `b << 32 |
/// c`, the place). A bucket holds one vertex's few faces: its keys are
/// counted in a small hash table ([`LoneTable`], no sort), a key met once
/// is a boundary face. Buckets are read in parallel blocks, the places
/// collected in bucket order, each bucket's in tet order: the result
/// depends only on the tets, not on the threads.
pub fn lone_tet_faces(tets: &[[u32; 4]]) -> Vec<usize> {
    use rayon::prelude::*;
    let nb = tets.len().max(1);
    // a face's bucket: its least corner, folded beyond `nb` (only a mesh
    // with more vertices than tets has such; `a` is compared then too)
    let bucket = |a: u32| {
        let a = a as usize;
        if a < nb {
            a
        } else {
            a % nb
        }
    };
    let mut start = vec![0usize; nb + 1];
    let mut folded = false;
    for t in tets {
        // three faces hold the least corner, the fourth the second least
        let (lo, second, hi) = least_two_greatest(t);
        start[bucket(lo) + 1] += 3;
        start[bucket(second) + 1] += 1;
        folded |= hi as usize >= nb;
    }
    for i in 0..nb {
        start[i + 1] += start[i];
    }
    let n = start[nb];
    // `a` is kept only when buckets are folded (then part of the key)
    let (mut keys, mut places) = (vec![0u64; n], vec![0usize; n]);
    let mut least = vec![0u32; if folded { n } else { 0 }];
    let mut next = start[..nb].to_vec();
    for (i, t) in tets.iter().enumerate() {
        for (a, bc, f) in sorted_faces(t) {
            let j = &mut next[bucket(a)];
            (keys[*j], places[*j]) = (bc, 4 * i + f);
            if folded {
                least[*j] = a;
            }
            *j += 1;
        }
    }
    drop(next);
    let lone_in = |s: usize, e: usize, out: &mut Vec<usize>, table: &mut LoneTable| {
        if folded {
            let mut run: Vec<(u64, u32, usize)> =
                (s..e).map(|j| (keys[j], least[j], places[j])).collect();
            run.sort_unstable();
            out.extend(
                run.chunk_by(|x, y| (x.0, x.1) == (y.0, y.1))
                    .filter_map(|r| (r.len() == 1).then_some(r[0].2)),
            );
            return;
        }
        table.lone_keys(&keys[s..e], s + 1);
        out.extend((s..e).filter(|&j| table.met[j - s] == 1).map(|j| places[j]));
    };
    (0..nb.div_ceil(LONE_FACE_BLOCK))
        .into_par_iter()
        .flat_map_iter(|blk| {
            let b0 = blk * LONE_FACE_BLOCK;
            let b1 = (b0 + LONE_FACE_BLOCK).min(nb);
            let (mut out, mut table) = (Vec::new(), LoneTable::default());
            for b in b0..b1 {
                lone_in(start[b], start[b + 1], &mut out, &mut table);
            }
            out
        })
        .collect()
}

/// One bucket's faces counted by key, with no sort: an open-addressing
/// table of `(stamp, first face)` (a stamp other than the bucket's marks
/// an empty slot, so the table is never cleared) and per face how often
/// its key was met (0 for a face whose key met an earlier face).
#[derive(Default)]
struct LoneTable {
    slots: Vec<(usize, u32)>,
    met: Vec<u32>,
}

impl LoneTable {
    /// Counts the keys of one bucket (`mark`: unique per non-empty bucket,
    /// never 0) into `met[j]` of its first face `j` with that key.
    fn lone_keys(&mut self, keys: &[u64], mark: usize) {
        let size = (2 * keys.len()).next_power_of_two().max(8);
        if self.slots.len() < size {
            self.slots.resize(size, (0, 0));
        }
        if self.met.len() < keys.len() {
            self.met.resize(keys.len(), 0);
        }
        let mask = size - 1;
        for (j, &key) in keys.iter().enumerate() {
            let mut h = (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 32) as usize & mask;
            loop {
                let (stamp, first) = self.slots[h];
                if stamp != mark {
                    (self.slots[h], self.met[j]) = ((mark, j as u32), 1);
                    break;
                }
                if keys[first as usize] == key {
                    (self.met[first as usize], self.met[j]) = (self.met[first as usize] + 1, 0);
                    break;
                }
                h = (h + 1) & mask;
            }
        }
    }
}

/// Buckets per parallel block of [`lone_tet_faces`].
const LONE_FACE_BLOCK: usize = 4096;

/// The least, the second least (with repeats) and the greatest of `t`'s
/// corners.
#[inline]
fn least_two_greatest(t: &[u32; 4]) -> (u32, u32, u32) {
    let (a, b) = (t[0].min(t[1]), t[0].max(t[1]));
    let (c, d) = (t[2].min(t[3]), t[2].max(t[3]));
    (a.min(c), a.max(c).min(b.min(d)), b.max(d))
}

/// The four faces of `t`, each as `(a, b << 32 | c, f)`: its corners
/// sorted `a ≤ b ≤ c`, and the corner `f` it is opposite. The tet's
/// corners are sorted once (a network of five exchanges on `v << 2 |
/// corner`); a face leaves one of them out.
#[inline]
fn sorted_faces(t: &[u32; 4]) -> [(u32, u64, usize); 4] {
    let mut s: [u64; 4] = std::array::from_fn(|k| u64::from(t[k]) << 2 | k as u64);
    for (i, j) in [(0, 1), (2, 3), (0, 2), (1, 3), (1, 2)] {
        (s[i], s[j]) = (s[i].min(s[j]), s[i].max(s[j]));
    }
    let v = s.map(|x| x >> 2);
    let face = |a: u64, b: u64, c: u64, out: u64| (a as u32, b << 32 | c, (out & 3) as usize);
    [
        face(v[1], v[2], v[3], s[0]),
        face(v[0], v[2], v[3], s[1]),
        face(v[0], v[1], v[3], s[2]),
        face(v[0], v[1], v[2], s[3]),
    ]
}

/// The boundary triangles of a tet mesh (faces of exactly one tet), each
/// read in its tet's orientation, sorted.
pub fn tet_boundary(tets: &[[u32; 4]]) -> Vec<[u32; 3]> {
    let mut out = tet_boundary_of(tets, &lone_tet_faces(tets));
    out.sort_unstable();
    out
}

/// The boundary triangles of the faces `lone` ([`lone_tet_faces`] of
/// `tets`), in `lone`'s order (unsorted: a surface's shape does not depend
/// on the order of its faces, and the sort cost ~12 M instructions on one
/// thread for 1M tets).
pub fn tet_boundary_of(tets: &[[u32; 4]], lone: &[usize]) -> Vec<[u32; 3]> {
    lone.iter()
        .map(|&place| opposite_face(&tets[place / 4], place % 4))
        .collect()
}

/// The shape of a tet mesh: its components, and its boundary surface's
/// Euler characteristic and components.
pub fn tet_shape(n_vertices: usize, tets: &[[u32; 4]]) -> Shape {
    tet_shape_of(n_vertices, tets, &lone_tet_faces(tets))
}

/// [`tet_shape`] with the boundary faces `lone` ([`lone_tet_faces`] of
/// `tets`) given; the components and the boundary surface in parallel.
pub fn tet_shape_of(n_vertices: usize, tets: &[[u32; 4]], lone: &[usize]) -> Shape {
    let (components, b) = rayon::join(
        || cell_components(n_vertices, tets),
        || surface_shape(n_vertices, &tet_boundary_of(tets, lone)),
    );
    volume_shape(components, b)
}

/// [`tet_shape`] and the boundary faces ([`lone_tet_faces`]) it found:
/// the faces and the components in parallel, then the boundary surface.
pub fn tet_shape_and_boundary(n_vertices: usize, tets: &[[u32; 4]]) -> (Shape, Vec<usize>) {
    let (lone, components) = rayon::join(
        || lone_tet_faces(tets),
        || cell_components(n_vertices, tets),
    );
    let b = surface_shape(n_vertices, &tet_boundary_of(tets, &lone));
    (volume_shape(components, b), lone)
}

/// A volume's shape: its cell components and its boundary surface's
/// Euler characteristic and components (`boundary`).
pub(crate) fn volume_shape(components: usize, boundary: Shape) -> Shape {
    Shape {
        components,
        euler: boundary.euler,
        boundary_components: boundary.components,
    }
}

/// The shape of a checked quad mesh.
pub fn quad_shape(r: &crate::QuadReport) -> Shape {
    Shape {
        components: r.components,
        euler: r.euler,
        boundary_components: r.boundary_loops,
    }
}

/// The shape of a checked hex mesh.
pub fn hex_shape(r: &crate::HexReport) -> Shape {
    Shape {
        components: r.components,
        euler: r.boundary.euler,
        boundary_components: r.boundary.components,
    }
}

/// Input and output shapes side by side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Comparison {
    /// The input's.
    pub input: Shape,
    /// The output's.
    pub output: Shape,
}

impl Comparison {
    /// Whether the output has the input's topology.
    pub fn matches(&self) -> bool {
        self.input == self.output
    }

    /// One line naming what differs (`None` when nothing does).
    pub fn mismatch(&self) -> Option<String> {
        let (i, o) = (self.input, self.output);
        let mut diffs = Vec::new();
        for (name, a, b) in [
            ("components", i.components as i64, o.components as i64),
            ("Euler characteristic", i.euler, o.euler),
            (
                "boundary components",
                i.boundary_components as i64,
                o.boundary_components as i64,
            ),
        ] {
            if a != b {
                diffs.push(format!("{name} {b} (input {a})"));
            }
        }
        (!diffs.is_empty()).then(|| diffs.join(", "))
    }

    /// `{"matches_input", "input": {..}, "output": {..}}`.
    pub fn to_json(&self) -> Value {
        json!({
            "matches_input": self.matches(),
            "input": self.input.to_json(),
            "output": self.output.to_json(),
        })
    }
}

#[cfg(test)]
mod tests;

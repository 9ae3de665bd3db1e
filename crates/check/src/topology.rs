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

use dualex_util::bucket;
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
/// `>= n_vertices` ignored).
pub fn cell_components<const K: usize>(n_vertices: usize, cells: &[[u32; K]]) -> usize {
    let mut uf = UnionFind::new(n_vertices);
    let mut used = vec![false; n_vertices];
    for c in cells
        .iter()
        .filter(|c| c.iter().all(|&v| (v as usize) < n_vertices))
    {
        used[c[0] as usize] = true;
        for &v in &c[1..] {
            used[v as usize] = true;
            uf.union(c[0] as usize, v as usize);
        }
    }
    uf.count_sets((0..n_vertices).filter(|&v| used[v]))
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
pub fn surface_shape<const K: usize>(n_vertices: usize, faces: &[[u32; K]]) -> Shape {
    let good = |f: &&[u32; K]| f.iter().all(|&v| (v as usize) < n_vertices);
    // every side of a good face as an undirected edge `lo << 32 | hi`,
    // bucketed by `lo`: one run per edge, a run of one is a boundary edge
    let (_, edges) = bucket::sorted(n_vertices, |emit| {
        for f in faces.iter().filter(good) {
            for k in 0..K {
                let (a, b) = (f[k], f[(k + 1) % K]);
                emit(a.min(b) as usize, edge_key(a, b));
            }
        }
    });
    let mut used = vec![false; n_vertices];
    for f in faces.iter().filter(good) {
        for &v in f {
            used[v as usize] = true;
        }
    }
    let mut uf = UnionFind::new(n_vertices);
    let mut on_boundary = vec![false; n_vertices];
    let mut n_edges = 0i64;
    for run in edges.chunk_by(|x, y| x == y) {
        n_edges += 1;
        if let [e] = run {
            let (a, b) = ((e >> 32) as usize, (e & 0xffff_ffff) as usize);
            uf.union(a, b);
            on_boundary[a] = true;
            on_boundary[b] = true;
        }
    }
    let v = used.iter().filter(|&&u| u).count() as i64;
    Shape {
        components: cell_components(n_vertices, faces),
        euler: v - n_edges + faces.iter().filter(good).count() as i64,
        boundary_components: uf.count_sets((0..n_vertices).filter(|&v| on_boundary[v])),
    }
}

/// The faces of a tet mesh that belong to exactly one tet (its boundary),
/// each as its place `4·tet + f` (the face opposite corner `f`), in no
/// particular order: the callers orient and sort them. Faces are equal
/// when their three vertices are, whatever their order.
///
/// Every face, its corners sorted `a ≤ b ≤ c`, is bucketed by `a` (a
/// counting sort in tet order, into parallel arrays: the key `b << 32 |
/// c`, the place). A bucket holds one vertex's few faces: its keys are
/// sorted (plain `u64`s), a key met once is a boundary face, whose place
/// is then looked up in the bucket. Buckets are read in parallel blocks,
/// the places collected in bucket order: the result depends only on the
/// tets, not on the threads.
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
        for f in 0..4 {
            let (a, bc) = sorted_face(t, f);
            let j = &mut next[bucket(a)];
            (keys[*j], places[*j]) = (bc, 4 * i + f);
            if folded {
                least[*j] = a;
            }
            *j += 1;
        }
    }
    drop(next);
    let lone_in = |s: usize, e: usize, out: &mut Vec<usize>, sorted: &mut Vec<u64>| {
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
        sorted.clear();
        sorted.extend_from_slice(&keys[s..e]);
        sorted.sort_unstable();
        for run in sorted.chunk_by(|x, y| x == y) {
            if let [key] = run {
                let at = keys[s..e].iter().position(|k| k == key);
                out.extend(at.map(|j| places[s + j]));
            }
        }
    };
    (0..nb.div_ceil(LONE_FACE_BLOCK))
        .into_par_iter()
        .flat_map_iter(|blk| {
            let b0 = blk * LONE_FACE_BLOCK;
            let b1 = (b0 + LONE_FACE_BLOCK).min(nb);
            let (mut out, mut sorted) = (Vec::new(), Vec::new());
            for b in b0..b1 {
                lone_in(start[b], start[b + 1], &mut out, &mut sorted);
            }
            out
        })
        .collect()
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

/// The face of `t` opposite corner `f`, its corners sorted `a ≤ b ≤ c`, as
/// `(a, b << 32 | c)`.
#[inline]
fn sorted_face(t: &[u32; 4], f: usize) -> (u32, u64) {
    let [x, y, z] = opposite_face(t, f);
    let (lo, hi) = (x.min(y).min(z), x.max(y).max(z));
    // the middle one: the three's xor without the least and the greatest
    let mid = x ^ y ^ z ^ lo ^ hi;
    (lo, u64::from(mid) << 32 | u64::from(hi))
}

/// The boundary triangles of a tet mesh (faces of exactly one tet), each
/// read in its tet's orientation, sorted.
pub fn tet_boundary(tets: &[[u32; 4]]) -> Vec<[u32; 3]> {
    tet_boundary_of(tets, &lone_tet_faces(tets))
}

/// [`tet_boundary`] of the faces `lone` ([`lone_tet_faces`] of `tets`).
pub fn tet_boundary_of(tets: &[[u32; 4]], lone: &[usize]) -> Vec<[u32; 3]> {
    let mut out: Vec<[u32; 3]> = lone
        .iter()
        .map(|&place| opposite_face(&tets[place / 4], place % 4))
        .collect();
    out.sort_unstable();
    out
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
    Shape {
        components,
        euler: b.euler,
        boundary_components: b.components,
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
mod tests {
    use super::*;

    #[test]
    fn square_annulus_and_tet_shapes() {
        // a 3×3 grid of quads, then without its centre quad (an annulus)
        let q = |i: u32, j: u32| {
            let v = |a: u32, b: u32| a + 4 * b;
            [v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)]
        };
        let full: Vec<[u32; 4]> = (0..3).flat_map(|j| (0..3).map(move |i| q(i, j))).collect();
        let disk = surface_shape(16, &full);
        assert_eq!(
            disk,
            Shape {
                components: 1,
                euler: 1,
                boundary_components: 1
            }
        );
        let ring: Vec<[u32; 4]> = full.iter().copied().filter(|f| *f != q(1, 1)).collect();
        let annulus = surface_shape(16, &ring);
        assert_eq!(
            annulus,
            Shape {
                components: 1,
                euler: 0,
                boundary_components: 2
            }
        );
        let c = Comparison {
            input: annulus,
            output: disk,
        };
        assert!(!c.matches());
        assert_eq!(
            c.mismatch().as_deref(),
            Some("Euler characteristic 1 (input 0), boundary components 1 (input 2)")
        );
        assert_eq!(c.to_json()["matches_input"], false);
        // two disjoint tets: 2 components, two spheres
        let tets = [[0, 1, 2, 3], [4, 5, 6, 7]];
        assert_eq!(tet_boundary(&tets).len(), 8);
        let s = tet_shape(8, &tets);
        assert_eq!(
            s,
            Shape {
                components: 2,
                euler: 4,
                boundary_components: 2
            }
        );
        let same = Comparison {
            input: s,
            output: s,
        };
        assert!(same.matches() && same.mismatch().is_none());
    }

    /// A block of `n³` cubes of 6 tets each (`DUALEX_BLOCK_N`, default 8:
    /// `valgrind --tool=callgrind --toggle-collect='*lone_tet_faces*'` on
    /// this test with a larger `n` measures the bucketing): `12·n²`
    /// boundary triangles, a ball.
    #[test]
    fn block_boundary() {
        let n: u32 = std::env::var("DUALEX_BLOCK_N")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(8);
        let v = |x: u32, y: u32, z: u32| x + (n + 1) * (y + (n + 1) * z);
        // a cube's 6 tets: the paths 0 → one axis → two axes → 7 (corner
        // bits x = 1, y = 2, z = 4)
        let axes = [[0, 1], [1, 0], [1, 2], [2, 1], [2, 0], [0, 2]];
        let kuhn = axes.map(|[i, j]| [0, 1 << i, 1 << i | 1 << j, 7]);
        let mut tets = Vec::new();
        for (x, y, z) in
            (0..n).flat_map(|z| (0..n).flat_map(move |y| (0..n).map(move |x| (x, y, z))))
        {
            let corner = |c: u32| v(x + (c & 1), y + (c >> 1 & 1), z + (c >> 2));
            tets.extend(kuhn.iter().map(|t: &[u32; 4]| t.map(corner)));
        }
        let lone = lone_tet_faces(&tets);
        assert_eq!(lone.len(), 12 * (n * n) as usize);
        let nv = ((n + 1) * (n + 1) * (n + 1)) as usize;
        let shape = tet_shape_of(nv, &tets, &lone);
        assert_eq!(
            (shape.components, shape.euler, shape.boundary_components),
            (1, 2, 1)
        );
    }

    /// The bucketed counts equal those of hash maps (the former code) on
    /// random small meshes: repeated faces, degenerate and out-of-range
    /// cells, isolated vertices.
    #[test]
    fn bucketed_counts_equal_hash_maps() {
        use std::collections::HashMap;
        fn reference_boundary(tets: &[[u32; 4]]) -> Vec<[u32; 3]> {
            let mut count: HashMap<[u32; 3], (usize, [u32; 3])> = HashMap::new();
            for t in tets {
                for f in 0..4 {
                    let tri = [t[(f + 1) % 4], t[(f + 2) % 4], t[(f + 3) % 4]];
                    let mut key = tri;
                    key.sort_unstable();
                    count.entry(key).or_insert((0, tri)).0 += 1;
                }
            }
            let mut out: Vec<[u32; 3]> = count
                .into_values()
                .filter(|(n, _)| *n == 1)
                .map(|(_, t)| t)
                .collect();
            out.sort_unstable();
            out
        }
        fn reference_edges(n: usize, faces: &[[u32; 3]]) -> (i64, usize) {
            let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
            let good = faces.iter().filter(|f| f.iter().all(|&v| (v as usize) < n));
            for f in good {
                for k in 0..3 {
                    let (a, b) = (f[k], f[(k + 1) % 3]);
                    *edges.entry((a.min(b), a.max(b))).or_default() += 1;
                }
            }
            let once = edges.values().filter(|&&c| c == 1).count();
            (edges.len() as i64, once)
        }
        let mut z = 5u64;
        let mut next = |m: u64| {
            z = z
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((z >> 33) % m) as u32
        };
        for case in 0..300 {
            let n = 3 + case % 17;
            let tets: Vec<[u32; 4]> = (0..case % 40)
                .map(|_| [0; 4].map(|_| next(n as u64 + 1)))
                .collect();
            assert_eq!(tet_boundary(&tets), reference_boundary(&tets), "{tets:?}");
            let tris = reference_boundary(&tets);
            let shape = surface_shape(n, &tris);
            let (e, once) = reference_edges(n, &tris);
            let good: Vec<[u32; 3]> = tris
                .iter()
                .copied()
                .filter(|f| f.iter().all(|&v| (v as usize) < n))
                .collect();
            let mut used: Vec<u32> = good.iter().flatten().copied().collect();
            used.sort_unstable();
            used.dedup();
            let euler = used.len() as i64 - e + good.len() as i64;
            assert_eq!(shape.euler, euler, "{tris:?}");
            assert_eq!(shape.boundary_components == 0, once == 0, "{tris:?}");
        }
        // more buckets than one parallel block holds, and vertices beyond
        // the bucket count (folded buckets)
        for (count, n) in [
            (9000, 40u64),
            (3 * LONE_FACE_BLOCK, 20_000),
            (50, 1000),
            (2000, 8),
            (40_000, 4000),
        ] {
            let tets: Vec<[u32; 4]> = (0..count).map(|_| [0; 4].map(|_| next(n))).collect();
            assert_eq!(
                tet_boundary(&tets),
                reference_boundary(&tets),
                "{count} {n}"
            );
        }
    }
}

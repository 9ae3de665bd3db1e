//! Welding of cut surfaces: an OBJ written with a texture atlas often
//! repeats the vertices along its seams. Boundary vertices at exactly the
//! same position are merged, so the surface is whole again before the
//! cross field is computed.
//!
//! Input: positions and triangles. Output: the same triangles over merged
//! vertex indices, the unused vertices dropped, and how many vertices were
//! merged away. Interior vertices are never merged (a surface touching
//! itself stays apart), and a merge that would put two corners of one
//! triangle on the same vertex is skipped.

use std::collections::HashMap;

/// A welded triangle soup.
#[derive(Clone, Debug)]
pub struct Welded {
    /// Positions of the vertices kept.
    pub positions: Vec<[f64; 3]>,
    /// Triangles over the kept vertices.
    pub triangles: Vec<[u32; 3]>,
    /// Vertices merged into another one.
    pub merged: usize,
}

/// Welds boundary vertices at equal positions (see the module docs).
/// Indices must be in range (the reader checks them).
pub fn weld(positions: &[[f64; 3]], triangles: &[[u32; 3]]) -> Welded {
    // boundary vertices: ends of edges used by one triangle only
    let mut uses: HashMap<(u32, u32), u32> = HashMap::new();
    for t in triangles {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            *uses.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    let mut on_boundary = vec![false; positions.len()];
    for (&(a, b), &n) in &uses {
        if n == 1 {
            on_boundary[a as usize] = true;
            on_boundary[b as usize] = true;
        }
    }
    let mut rep: Vec<u32> = (0..positions.len() as u32).collect();
    let mut first: HashMap<[u64; 3], u32> = HashMap::new();
    for (v, p) in positions.iter().enumerate() {
        if on_boundary[v] {
            // -0.0 and 0.0 are one position
            let key = p.map(|x| (x + 0.0).to_bits());
            rep[v] = *first.entry(key).or_insert(v as u32);
        }
    }
    let mut merged_tris: Vec<[u32; 3]> = triangles
        .iter()
        .map(|t| {
            let m = t.map(|v| rep[v as usize]);
            if m[0] == m[1] || m[1] == m[2] || m[0] == m[2] {
                *t
            } else {
                m
            }
        })
        .collect();
    let mut new_index = vec![u32::MAX; positions.len()];
    let mut kept = Vec::new();
    for t in &mut merged_tris {
        for v in t.iter_mut() {
            let slot = &mut new_index[*v as usize];
            if *slot == u32::MAX {
                *slot = kept.len() as u32;
                kept.push(positions[*v as usize]);
            }
            *v = *slot;
        }
    }
    let used_before = {
        let mut used = vec![false; positions.len()];
        for t in triangles {
            for &v in t {
                used[v as usize] = true;
            }
        }
        used.iter().filter(|&&u| u).count()
    };
    Welded {
        merged: used_before - kept.len(),
        positions: kept,
        triangles: merged_tris,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_cut_along_its_diagonal_is_welded() {
        // two triangles that share the diagonal's positions but not indices
        let p = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let w = weld(&p, &[[0, 1, 2], [3, 4, 5]]);
        assert_eq!(w.merged, 2);
        assert_eq!(w.positions.len(), 4);
        assert_eq!(w.triangles, vec![[0, 1, 2], [0, 2, 3]]);
        let s = crate::Surface::new(w.positions, w.triangles).expect("a surface");
        assert_eq!(s.edges.len(), 5);
    }

    #[test]
    fn interior_vertices_are_not_merged() {
        // a closed tetrahedron surface plus a second, disjoint one at the
        // same place: every vertex interior, nothing merges
        let p = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let tets = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
        let mut pos = p.to_vec();
        pos.extend(p);
        let mut tris = tets.to_vec();
        tris.extend(tets.map(|t| t.map(|v| v + 4)));
        let w = weld(&pos, &tris);
        assert_eq!((w.merged, w.positions.len()), (0, 8));
    }
}

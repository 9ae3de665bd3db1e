//! The prism of each tet from its nodes, so that TetGen can run without
//! region attributes (`-A` costs ~15 % of its instructions on fandisk:
//! spreading the 14 454 regions and printing one float per tet).
//!
//! Input: the [`Slab`] and tets over slab points only (no Steiner point).
//! Output: per tet `prism + 1`, or 0 for a tet of the cavity enclosed by a
//! closed surface's slab; `None` when a tet fits none of the cases below
//! (the caller then asks TetGen for its labels).
//!
//! A tet inside prism `(t, l)` has nodes on levels `l` and `l + 1` only:
//! - over 3 distinct vertices: they are triangle `t`'s;
//! - over 2 (a tet on the 4 points of a bent wall over edge `ab`): it lies
//!   in one of the edge's two prisms, the one of the tets across its two
//!   faces that are not wall facets (those are inside its prism);
//! - a cavity tet has all 4 nodes on one level (the slab's inner side).
//!
//! [`crate::chart::tet_map`] then checks the labels like TetGen's: every
//! face between two prisms is a wall facet, and every node is a point of
//! the tet's prism.

use crate::slab::Slab;

/// Labels of `tets` (module docs).
pub fn regions(slab: &Slab, tets: &[[u32; 4]]) -> Option<Vec<u64>> {
    let mut by_vertices: Vec<([u32; 3], usize)> = slab
        .tris
        .iter()
        .enumerate()
        .map(|(t, tri)| (sorted3(*tri), t))
        .collect();
    by_vertices.sort_unstable();
    if by_vertices.windows(2).any(|w| w[0].0 == w[1].0) {
        return None; // two triangles over the same vertices
    }
    let nv = slab.nv as u32;
    let mut out = vec![0u64; tets.len()];
    let mut walls = Vec::new();
    for (k, tet) in tets.iter().enumerate() {
        if tet.iter().any(|&v| v as usize >= slab.points.len()) {
            return None;
        }
        let level = tet.map(|v| v / nv);
        let (lo, hi) = (*level.iter().min()?, *level.iter().max()?);
        if lo == hi {
            continue; // the cavity
        }
        if hi != lo + 1 {
            return None;
        }
        let mut vs = tet.map(|v| v % nv);
        vs.sort_unstable();
        let mut distinct = [0u32; 4];
        let mut n = 0;
        for (i, &v) in vs.iter().enumerate() {
            if i == 0 || v != vs[i - 1] {
                distinct[n] = v;
                n += 1;
            }
        }
        match n {
            3 => {
                let key = [distinct[0], distinct[1], distinct[2]];
                let i = by_vertices.binary_search_by(|x| x.0.cmp(&key)).ok()?;
                out[k] = (lo as usize * slab.tris.len() + by_vertices[i].1 + 1) as u64;
            }
            2 => walls.push((k, distinct[0], distinct[1], lo as usize)),
            _ => return None,
        }
    }
    label_wall_tets(slab, tets, &walls, &mut out)?;
    Some(out)
}

/// Labels the tets on the 4 points of a wall (`(tet, a, b, layer)`, `a <
/// b`) by the tets across their faces that are not wall facets.
fn label_wall_tets(
    slab: &Slab,
    tets: &[[u32; 4]],
    walls: &[(usize, u32, u32, usize)],
    out: &mut [u64],
) -> Option<()> {
    if walls.is_empty() {
        return Some(());
    }
    // (face, wall tet) for the 2 inner faces of every wall tet
    let mut inner: Vec<([u32; 3], usize)> = Vec::with_capacity(2 * walls.len());
    for &(k, a, b, l) in walls {
        let facets = crate::plc::wall(slab, a, b, l).map(sorted3);
        for f in faces(&tets[k]) {
            if !facets.contains(&f) {
                inner.push((f, k));
            }
        }
    }
    inner.sort_unstable();
    // an inner face has 3 nodes over a wall's 2 vertices: only tets with 3
    // such nodes can share one
    let nv = slab.nv as u32;
    let mut on_wall = vec![false; slab.nv];
    for &(_, a, b, _) in walls {
        on_wall[a as usize] = true;
        on_wall[b as usize] = true;
    }
    // a wall tet may sit next to another one: repeat while that helps
    loop {
        let mut changed = false;
        for (j, tet) in tets.iter().enumerate() {
            let marked = tet.iter().filter(|&&v| on_wall[(v % nv) as usize]).count();
            if out[j] == 0 || marked < 3 {
                continue;
            }
            for f in faces(tet) {
                let start = inner.partition_point(|x| x.0 < f);
                for &(_, k) in inner[start..].iter().take_while(|x| x.0 == f) {
                    if k == j {
                        continue;
                    }
                    if out[k] == 0 {
                        out[k] = out[j];
                        changed = true;
                    } else if out[k] != out[j] {
                        return None;
                    }
                }
            }
        }
        if !changed || walls.iter().all(|&(k, ..)| out[k] != 0) {
            break;
        }
    }
    walls.iter().all(|&(k, ..)| out[k] != 0).then_some(())
}

/// The 4 faces of a tet, each sorted.
fn faces(t: &[u32; 4]) -> [[u32; 3]; 4] {
    std::array::from_fn(|f| sorted3(std::array::from_fn(|j| t[(f + 1 + j) % 4])))
}

fn sorted3(mut k: [u32; 3]) -> [u32; 3] {
    k.sort_unstable();
    k
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::split::prism_split;
    use dualex_map::TriMap;

    fn slab() -> Slab {
        let m = TriMap {
            positions: vec![[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]],
            simplices: vec![[0, 1, 2], [0, 2, 3]],
            coords: vec![[[0.; 2]; 3]; 2],
        };
        Slab::new(&m, 2, Some(1.0)).expect("valid")
    }

    #[test]
    fn the_split_is_labelled_by_its_prisms() {
        let s = slab();
        let split = prism_split(&s);
        assert_eq!(regions(&s, &split.tets), Some(split.regions));
    }

    #[test]
    fn wall_and_cavity_tets() {
        let s = slab();
        let mut tets = prism_split(&s).tets;
        let mut want = prism_split(&s).regions;
        // a tet on the 4 points of the wall over edge 0–2 in layer 0, next
        // to prism 1's tet across face (0, 2, 0') — here tet 3 of the split
        // has that face only if it is an inner face; add the wall tet and a
        // neighbour sharing its inner face (0₀, 2₀, 0₁) inside prism 1
        let (a0, b0, a1, b1) = (s.point(0, 0), s.point(2, 0), s.point(0, 1), s.point(2, 1));
        tets.push([a0, b0, a1, b1]);
        tets.push([a0, b0, a1, s.point(3, 0)]);
        want.extend([2, 2]);
        // a cavity tet: one level
        tets.push([s.point(0, 0), s.point(1, 0), s.point(2, 0), s.point(3, 0)]);
        want.push(0);
        assert_eq!(regions(&s, &tets), Some(want));
        // a tet across two layers is not a prism's
        tets.push([s.point(0, 0), s.point(1, 0), s.point(2, 1), s.point(3, 2)]);
        assert_eq!(regions(&s, &tets), None);
    }
}

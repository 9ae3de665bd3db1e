//! Map coordinates of the output's corners (issue 13: `--uv`): each
//! cell's corners in the input chart of the simplex that holds its node.
//!
//! A node is an integer point `n` of the local chart of simplex `s`
//! (`dualex_segment::local::LocalMap`: `input = local + offset − h`, `h`
//! the grid offset's
//! shift: ½ for `Half`, 0 for `Zero`). Its dual cell's corners are
//! `n ± ½` on each axis, so in `s`'s input chart they are
//! `n + offset − h ± ½`: integers with the offset `Half`, half-integers
//! with `Zero`. They are computed (`dualex_segment::local::node_corner`)
//! in integers plus one exact float
//! addition, so they are exact grid points of the input map — not values
//! interpolated from the sanitized (perturbed) map, and not the map's value
//! at the output vertex's position (which differs by the map's distortion
//! and, on a seam, by the chart).
//!
//! Steps that remake cells (hole filling, local repair, doublet merges,
//! folded-cell collapses) pass the corners on with [`carry`]: each vertex
//! of a new cell takes the coordinates of the corner of its origin cell at
//! the same position (these steps copy positions; they may renumber
//! vertices); a cell with a vertex that is not such a corner, or that two
//! corners with different coordinates could be, has none.

use crate::cells::CellMesh;

/// The map coordinates of a cell's `K` corners in one chart, in the cell's
/// corner order; `None` when the cell has none (module docs).
pub type Corners<const D: usize, const K: usize> = Option<[[f64; D]; K]>;

/// The corners of the cells of `new`, each made from cell `origin[c]` of
/// `old` (whose corners are `corners`); an origin past `old`'s cells (a
/// polygon added by the step) has none.
pub fn carry<const D: usize, const K: usize>(
    old: &CellMesh<K>,
    corners: &[Corners<D, K>],
    new: &CellMesh<K>,
    origin: &[u32],
) -> Vec<Corners<D, K>> {
    let (old_pos, new_pos) = (&old.positions, &new.positions);
    new.cells
        .iter()
        .zip(origin)
        .map(|(cell, &o)| {
            let (oc, ov) = (
                old.cells.get(o as usize)?,
                corners.get(o as usize)?.as_ref()?,
            );
            let mut out = [[0.0; D]; K];
            for (x, &w) in out.iter_mut().zip(cell) {
                let p = new_pos.get(w as usize)?;
                let mut found: Option<[f64; D]> = None;
                for (&v, uv) in oc.iter().zip(ov) {
                    if old_pos.get(v as usize) != Some(p) {
                        continue;
                    }
                    match found {
                        Some(f) if f != *uv => return None,
                        _ => found = Some(*uv),
                    }
                }
                *x = found?;
            }
            Some(out)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn carry_follows_positions_and_drops_new_corners() {
        let pos = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        let mesh = |positions: &[[f64; 3]], cells: &[[u32; 4]]| CellMesh {
            positions: positions.to_vec(),
            cells: cells.to_vec(),
        };
        let before = mesh(&pos, &[[0, 1, 2, 3]]);
        let uv = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let old = [Some(uv)];
        // renumbered (reversed) and rotated
        let new_pos: Vec<[f64; 3]> = pos.iter().rev().copied().collect();
        let got = carry(&before, &old, &mesh(&new_pos, &[[2, 1, 0, 3]]), &[0]);
        assert_eq!(got, [Some([uv[1], uv[2], uv[3], uv[0]])]);
        // a vertex that is no corner of the origin, an added polygon
        let mut far = new_pos.clone();
        far.push([5.0, 5.0, 0.0]);
        let got = carry(
            &before,
            &old,
            &mesh(&far, &[[4, 1, 0, 3], [0, 1, 2, 3]]),
            &[0, 1],
        );
        assert_eq!(got, [None, None]);
    }
}

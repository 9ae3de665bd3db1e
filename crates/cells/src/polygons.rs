//! Cells as polygons, and the holes of a glued cell mesh as polygons: the
//! input of the local repair ([`crate::repair_local`]) in quad's step 10
//! and in hex's columns.
//!
//! - [`polygon`] / [`polygon_of`]: a cell without its consecutive repeated
//!   corners (a glued quad with a repeated corner is a triangle);
//! - [`hole_polygons`]: from the unmatched edges of the cells, as the cells
//!   traverse them, the cycles they form, oriented to close them (opposite
//!   to the cells' traversal), and the count of cycles left open.
//!
//! Invariant: every returned hole polygon has distinct corners; an edge is
//! used by at most one polygon.

use std::collections::HashMap;

/// The cell without consecutive repeated corners (cyclically).
pub fn polygon(cell: &[u32; 4]) -> Vec<u32> {
    polygon_of(cell)
}

/// [`polygon`] of any polygon.
pub fn polygon_of(cell: &[u32]) -> Vec<u32> {
    let mut p: Vec<u32> = Vec::with_capacity(cell.len());
    for &v in cell {
        if p.last() != Some(&v) {
            p.push(v);
        }
    }
    while p.len() > 1 && p.first() == p.last() {
        p.pop();
    }
    p
}

/// The holes of the glued mesh: cycles of unmatched cell edges, as polygons
/// oriented to close them (opposite to the cells' traversal). `edges` are
/// the unmatched edges as traversed by their cells. A cycle that passes a
/// vertex twice is not returned (it is left open and reported).
pub fn hole_polygons(edges: &[(u32, u32)]) -> (Vec<Vec<u32>>, usize) {
    let mut next: HashMap<u32, Vec<u32>> = HashMap::new();
    for &(a, b) in edges {
        next.entry(b).or_default().push(a); // reversed: b → a
    }
    let mut used: HashMap<(u32, u32), bool> = HashMap::new();
    let (mut out, mut skipped) = (Vec::new(), 0);
    for &(a, b) in edges {
        if used.contains_key(&(b, a)) {
            continue;
        }
        let mut poly = vec![b];
        let mut cur = b;
        let mut ok = true;
        loop {
            let cands = next.get(&cur).map(|v| v.as_slice()).unwrap_or(&[]);
            let [nx] = cands[..] else {
                ok = false;
                break;
            };
            used.insert((cur, nx), true);
            if nx == b {
                break;
            }
            if poly.contains(&nx) || poly.len() > edges.len() {
                ok = false;
                break;
            }
            poly.push(nx);
            cur = nx;
        }
        if ok {
            out.push(poly);
        } else {
            skipped += 1;
        }
    }
    (out, skipped)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_triangular_hole_is_closed_against_its_cells() {
        // cells traverse 0→1, 1→2, 2→0: the hole face goes 0→2→1... reversed
        let (polys, open) = hole_polygons(&[(0, 1), (1, 2), (2, 0)]);
        assert_eq!(open, 0);
        assert_eq!(polys.len(), 1);
        let p = &polys[0];
        assert_eq!(p.len(), 3);
        // every cell edge a→b appears as b→a in the polygon
        for (a, b) in [(0u32, 1u32), (1, 2), (2, 0)] {
            let i = p.iter().position(|&v| v == b).expect("vertex");
            assert_eq!(p[(i + 1) % 3], a, "{p:?}");
        }
    }

    #[test]
    fn a_figure_eight_is_left_open() {
        let (polys, open) = hole_polygons(&[(0, 1), (1, 2), (2, 0), (0, 3), (3, 4), (4, 0)]);
        assert!(polys.is_empty());
        assert!(open > 0);
    }
}

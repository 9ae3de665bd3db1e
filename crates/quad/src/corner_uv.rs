//! The map coordinates of each quad's corners (`--uv`) through the
//! subdivision of step 10b: each quad's corners are those of its node's
//! dual cell in the input chart of the triangle holding the node
//! (`dualex_segment::place`, step 9c; [`dualex_cells::corners`] for the
//! definition: node ± ½, exact grid points of the input map, integers
//! with the grid offset `Half`, half-integers with `Zero`), carried by
//! the steps that remake cells ([`dualex_cells::corners::carry`]).
//!
//! Input: the quads before a subdivision, their corners, the subdivided
//! quads and their origins. Output: per quad, its 4 corners' coordinates
//! in its cell order, or `None` (a face closing a hole, a quad merged from
//! a doublet, a quad of a local repair path): the 4 quads of a cell get
//! its corners, edge midpoints and centre (half-size squares).

use dualex_cells::corners::Corners;
use dualex_cells::polygons::polygon;
use dualex_cells::QuadMesh;

/// The map coordinates of a quad's corners (module docs).
pub type QuadCorners = Corners<2, 4>;

/// The corners after a subdivision of every cell of `old` (see
/// [`crate::repair::subdivide`]: cell `i` of a polygon is `[p_i, mid(p_i,
/// p_i+1), centre, mid(p_i−1, p_i)]`); quads of a polygon that was not a
/// quad with coordinates have none.
pub fn subdivided(
    old: &QuadMesh,
    old_uv: &[QuadCorners],
    new: &QuadMesh,
    origin: &[u32],
) -> Vec<QuadCorners> {
    let mid = |a: [f64; 2], b: [f64; 2]| [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
    new.cells
        .iter()
        .zip(origin)
        .map(|(cell, &o)| {
            let oc = old.cells.get(o as usize)?;
            let uv = old_uv.get(o as usize)?.as_ref()?;
            if polygon(oc).len() != 4 {
                return None;
            }
            let i = oc.iter().position(|&v| v == cell[0])?;
            let (p, n, q) = (uv[(i + 3) % 4], uv[i], uv[(i + 1) % 4]);
            let centre = mid(mid(uv[0], uv[2]), mid(uv[1], uv[3]));
            Some([n, mid(n, q), centre, mid(p, n)])
        })
        .collect()
}

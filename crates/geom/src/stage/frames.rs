//! The quads' frames: the tangent plane of the input triangle nearest
//! each quad's centre (the measure's definition), taken for every cell
//! or only for the cells that moved.

use crate::quality::{cross, unit};
use crate::reference::Reference;

/// A quad's frame: two unit tangents, right-handed about the normal `n`.
pub(super) fn quad_frame(n: [f64; 3]) -> [[f64; 3]; 2] {
    let t1 = unit(crate::constraint::perpendicular(n));
    [t1, cross(n, t1)]
}

pub(super) type Reframe<'a, const D: usize> =
    dyn Fn(&[[f64; 3]], usize, &Reference) -> [[f64; 3]; D] + Sync + 'a;

/// Every cell's frame by `reframe`.
pub(super) fn all_frames<const D: usize>(
    reframe: &Reframe<D>,
    x: &[[f64; 3]],
    cells: usize,
    r: &Reference,
) -> Vec<[[f64; 3]; D]> {
    use rayon::prelude::*;
    (0..cells)
        .into_par_iter()
        .map(|ci| reframe(x, ci, r))
        .collect()
}
/// The frames of the cells with a vertex at another position in `x`
/// than in `before`, by `reframe`.
pub(super) fn reframe_moved<const D: usize, const K: usize>(
    reframe: &Reframe<D>,
    x: &[[f64; 3]],
    before: &[[f64; 3]],
    cells: &[[u32; K]],
    frames: &mut [[[f64; 3]; D]],
    r: &Reference,
) {
    use rayon::prelude::*;
    frames.par_iter_mut().enumerate().for_each(|(ci, f)| {
        if cells[ci]
            .iter()
            .any(|&v| x[v as usize] != before[v as usize])
        {
            *f = reframe(x, ci, r);
        }
    });
}

//! Step 1: local, shifted coordinates.
//!
//! Input: the map, its topology and transitions. Output: [`LocalMap`], where
//! each triangle's corners are expressed relative to an integer offset of
//! that triangle (`global = local + offset`) and shifted by (½, ½): the
//! integer points of the local coordinates are the dual grid (nodes), and
//! local values stay small whatever the magnitude of the input (a map
//! translated by 2^40 behaves like one at the origin; the subtraction of an
//! integer offset from a float of the same magnitude is exact).
//!
//! Invariant: for each interior edge, `local(n) = rot · local(s) + trans`
//! with an integer `trans` (the input transitions, with offsets and shift
//! folded in), up to the map's own GP residual.

use dualex_map::{Rot2, Topology, Transitions, TriMap};

/// Triangle map in local shifted coordinates.
#[derive(Clone, Debug)]
pub struct LocalMap {
    /// Local shifted map coordinates per corner.
    pub coords: Vec<[[f64; 2]; 3]>,
    /// Integer offset of each triangle (global shifted = local + offset).
    pub offset: Vec<[i64; 2]>,
    /// Transitions between local charts.
    pub trans: Transitions<3, 2>,
}

/// `h − R·h` for `h = (½, ½)`: an integer vector.
fn shift_defect(r: &Rot2) -> [i64; 2] {
    let rh = r.apply(&[0.5, 0.5]);
    [(0.5 - rh[0]) as i64, (0.5 - rh[1]) as i64]
}

impl LocalMap {
    /// Builds local shifted coordinates and the matching transitions.
    pub fn new(map: &TriMap, topo: &Topology<3>, trans: &Transitions<3, 2>) -> Self {
        let offset: Vec<[i64; 2]> = map
            .coords
            .iter()
            .map(|c| [c[0][0].floor() as i64, c[0][1].floor() as i64])
            .collect();
        let coords = map
            .coords
            .iter()
            .zip(&offset)
            .map(|(c, o)| c.map(|p| [(p[0] - o[0] as f64) + 0.5, (p[1] - o[1] as f64) + 0.5]))
            .collect();
        let mut t = trans.clone();
        for s in 0..map.len() {
            for f in 0..3 {
                let Some((n, _)) = topo.neighbour(s, f) else {
                    continue;
                };
                let r = trans.rot[s][f];
                let ro = r.apply_i(&offset[s]);
                let d = shift_defect(&r);
                let tt = trans.trans[s][f];
                t.trans[s][f] = [
                    ro[0] + tt[0] - offset[n][0] + d[0],
                    ro[1] + tt[1] - offset[n][1] + d[1],
                ];
            }
        }
        LocalMap {
            coords,
            offset,
            trans: t,
        }
    }

    /// Maps a local point of triangle `s` into the local chart of its
    /// neighbour across edge `f`.
    #[inline]
    pub fn across(&self, s: usize, f: usize, p: &[f64; 2]) -> [f64; 2] {
        self.trans.apply(s, f, p)
    }

    /// Signed doubled area of triangle `s`'s image.
    #[inline]
    pub fn det(&self, s: usize) -> f64 {
        dualex_map::mesh::det_of::<3, 2>(&self.coords[s])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shift_defect_is_integral() {
        for r in Rot2::all() {
            let d = shift_defect(&r);
            let rh = r.apply(&[0.5, 0.5]);
            assert_eq!(d[0] as f64, 0.5 - rh[0]);
            assert_eq!(d[1] as f64, 0.5 - rh[1]);
        }
    }
}

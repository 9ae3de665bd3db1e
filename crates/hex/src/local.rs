//! Step 1: local, shifted coordinates.
//!
//! Input: the map, its topology and transitions. Output: [`LocalMap`], where
//! each tet's corners are expressed relative to an integer offset of that
//! tet (`global = local + offset`) and shifted by (½, ½, ½): the integer
//! points of the local coordinates are the dual grid (nodes), and local
//! values stay small whatever the magnitude of the input (a map translated
//! by 2^40 behaves like one at the origin).
//!
//! Invariant: for each interior face, `local(n) = rot · local(s) + trans`
//! with an integer `trans` (the input transitions with offsets and shift
//! folded in: `h − R·h` is integral for `h = (½, ½, ½)` and every cube
//! rotation), up to the map's own GP residual.

use dualex_map::{Rot3, TetMap, Topology, Transitions};

/// Tet map in local shifted coordinates.
#[derive(Clone, Debug)]
pub struct LocalMap {
    /// Local shifted map coordinates per corner.
    pub coords: Vec<[[f64; 3]; 4]>,
    /// Integer offset of each tet (global shifted = local + offset).
    pub offset: Vec<[i64; 3]>,
    /// Transitions between local charts.
    pub trans: Transitions<4, 3>,
}

/// `h − R·h` for `h = (½, ½, ½)`: an integer vector.
fn shift_defect(r: &Rot3) -> [i64; 3] {
    let rh = r.apply(&[0.5; 3]);
    [0, 1, 2].map(|k| (0.5 - rh[k]) as i64)
}

impl LocalMap {
    /// Builds local shifted coordinates and the matching transitions.
    pub fn new(map: &TetMap, topo: &Topology<4>, trans: &Transitions<4, 3>) -> Self {
        let offset: Vec<[i64; 3]> = map
            .coords
            .iter()
            .map(|c| c[0].map(|x| x.floor() as i64))
            .collect();
        let coords = map
            .coords
            .iter()
            .zip(&offset)
            .map(|(c, o)| c.map(|p| [0, 1, 2].map(|k| (p[k] - o[k] as f64) + 0.5)))
            .collect();
        let mut t = trans.clone();
        for s in 0..map.len() {
            for f in 0..4 {
                let Some((n, _)) = topo.neighbour(s, f) else {
                    continue;
                };
                let r = trans.rot[s][f];
                let ro = r.apply_i(&offset[s]);
                let d = shift_defect(&r);
                let tt = trans.trans[s][f];
                t.trans[s][f] = [0, 1, 2].map(|k| ro[k] + tt[k] - offset[n][k] + d[k]);
            }
        }
        LocalMap {
            coords,
            offset,
            trans: t,
        }
    }

    /// Maps a local point of tet `s` into the local chart of its neighbour
    /// across face `f`.
    #[inline]
    pub fn across(&self, s: usize, f: usize, p: &[f64; 3]) -> [f64; 3] {
        self.trans.apply(s, f, p)
    }

    /// Signed 6× volume of tet `s`'s image.
    #[inline]
    pub fn det(&self, s: usize) -> f64 {
        dualex_map::mesh::det_of::<4, 3>(&self.coords[s])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shift_defect_is_integral_for_all_24_rotations() {
        let all = Rot3::all();
        assert_eq!(all.len(), 24);
        for r in all {
            let d = shift_defect(&r);
            let rh = r.apply(&[0.5; 3]);
            for k in 0..3 {
                assert_eq!(d[k] as f64, 0.5 - rh[k], "{r:?}");
            }
        }
    }
}

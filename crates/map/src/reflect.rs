//! The refusal of reflected charts (3D): [`TetMap::check_not_reflected`],
//! the sequential check, and [`Reflect`], its sums tallied per block by
//! the input checks' walk (`crate::scan`), which decide alone when no
//! rounding can change the answer.
//!
//! Input: a validated tet map. Output: `Ok`, or the error naming the
//! first reverted tet and the share of the volume reverted or flat.
//! Invariants: every per-tet value (geometric and map determinants, the
//! flat bound `1e-12·L³`) is computed by the same functions in both; the
//! sequential check sums in tet order, so its error is bit-identical
//! whatever the thread count; [`Reflect::surely_kept`] answers `true`
//! only for a map the sequential check keeps.

use crate::error::{ElementKind, InputError, MapError};
use crate::mesh::{det_of, flat_bound, longest_edge};
use crate::scan::rounding;
use crate::TetMap;
use rayon::prelude::*;

/// The least share of the map's unsigned volume (the sum of the map's
/// |determinants|) its signed volume keeps in a map taken as folded, not
/// reflected ([`TetMap::check_not_reflected`]).
pub const FOLDED_SIGNED: f64 = 1e-3;

/// The largest share of the geometric volume flat tets make up in a map
/// taken as folded, not reflected ([`TetMap::check_not_reflected`]).
pub const FOLDED_FLAT: f64 = 1e-3;

impl TetMap {
    /// Refuses a 3D map whose charts are reflected: when tets whose map is
    /// reverted (orientation opposite to the geometry's) or flat make up at
    /// least half of the mesh's geometric volume, and some of them are
    /// reverted (e.g. HexEx's `minimal_invalid_charts`), the map turns the
    /// volume inside out as a whole rather than folding it locally — unless
    /// the map is folded: its signed volume (the sum of the map's
    /// determinants, each tet oriented by the geometry) stays positive
    /// ([`FOLDED_SIGNED`] of the unsigned sum; moving vertices inside the
    /// volume does not change it, reflecting the charts makes it negative)
    /// and almost none of the volume is flat ([`FOLDED_FLAT`]; HexEx's map,
    /// a third of it flat, stays refused). Issue 22's refined folds on a
    /// small mesh revert over half its volume. Folds over less than half
    /// the volume, and collapsed maps (flat tets, none reverted: the
    /// paper's collapsed stress test), are the messy maps that extraction
    /// repairs.
    pub fn check_not_reflected(&self) -> Result<(), InputError> {
        // per tet (in parallel): geometric det, map det, flat bound; the
        // sums below stay sequential, in tet order
        let per_tet: Vec<(f64, f64, f64)> = (0..self.len())
            .into_par_iter()
            .map(|s| {
                let tiny = flat_bound::<3>(longest_edge(&self.coords[s]));
                (self.geo_det(s), self.map_det(s), tiny)
            })
            .collect();
        let total: f64 = per_tet.iter().map(|t| t.0).sum();
        let sign = if total < 0.0 { -1.0 } else { 1.0 };
        let (mut bad, mut all, mut worst, mut reverted) = (0.0, 0.0, None, 0.0);
        let (mut signed, mut unsigned) = (0.0, 0.0);
        for (s, &(geo_s, map_s, tiny)) in per_tet.iter().enumerate() {
            let g = (geo_s * sign).max(0.0);
            all += g;
            let m = map_s * sign;
            signed += m;
            unsigned += m.abs();
            if m <= tiny {
                bad += g;
                if m < -tiny {
                    reverted += g;
                    worst.get_or_insert(s);
                }
            }
        }
        // a fold inside the volume keeps the map's signed volume: positive,
        // where reflected charts make it negative; flat tets are no fold
        let folded = signed > FOLDED_SIGNED * unsigned && bad - reverted < FOLDED_FLAT * all;
        match worst {
            Some(s) if all > 0.0 && bad >= 0.5 * all && reverted > 0.0 && !folded => {
                let percent = 100.0 * bad / all;
                let e = ElementKind::Tet
                    .at(s)
                    .error(MapError::Reflected { percent });
                Err(e.into())
            }
            _ => Ok(()),
        }
    }

    /// Determinant of the geometric edge vectors of tet `s` (its indices
    /// in range).
    #[inline]
    pub(crate) fn geo_det(&self, s: usize) -> f64 {
        let p: [[f64; 3]; 4] = self.simplices[s].map(|v| self.positions[v as usize]);
        det_of::<4, 3>(&p)
    }
}

/// The sums of [`TetMap::check_not_reflected`] over a block of tets, for
/// both signs the geometric total may take (index 0: `+1`, 1: `−1`), and
/// the degenerate tets ([`crate::singularity::is_degenerate`]).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Reflect {
    /// Tets whose map is degenerate.
    pub degenerate: usize,
    /// Sum of the geometric determinants.
    geo: f64,
    /// Sum of their absolute values.
    geo_abs: f64,
    /// Per sign: the volume ("all": `Σ max(sign·geo, 0)`).
    all: [f64; 2],
    /// Per sign: the volume of the tets whose map is flat or reverted.
    bad: [f64; 2],
    /// Per sign: the tets whose map is reverted.
    reverted: [usize; 2],
}

impl Reflect {
    /// Adds valid tet `s` of `map`, its map determinant `det`.
    #[inline]
    pub fn add(&mut self, map: &TetMap, s: usize, det: f64) {
        let p = &map.coords[s];
        let len = longest_edge(p);
        let tiny = flat_bound::<3>(len);
        self.degenerate += usize::from(crate::mesh::degenerate_bounded(p, det, len));
        let geo = map.geo_det(s);
        self.geo += geo;
        self.geo_abs += geo.abs();
        self.add_signed(0, geo.max(0.0), det, tiny);
        self.add_signed(1, (-geo).max(0.0), -det, tiny);
    }

    /// Adds a tet to the sums of sign `i`: `g` its volume, `m` its map
    /// determinant, both times the sign, `tiny` its flat bound.
    #[inline]
    fn add_signed(&mut self, i: usize, g: f64, m: f64, tiny: f64) {
        self.all[i] += g;
        if m <= tiny {
            self.bad[i] += g;
            self.reverted[i] += usize::from(m < -tiny);
        }
    }

    /// Adds the tally of the next block.
    pub fn merge(&mut self, next: &Reflect) {
        self.degenerate += next.degenerate;
        self.geo += next.geo;
        self.geo_abs += next.geo_abs;
        for i in 0..2 {
            self.all[i] += next.all[i];
            self.bad[i] += next.bad[i];
            self.reverted[i] += next.reverted[i];
        }
    }

    /// Whether [`TetMap::check_not_reflected`] surely keeps the map of
    /// these `n` tets: for each sign its total may take (the blocks' and
    /// the sequential sums differ by [`rounding`] at most), no tet is
    /// reverted, or the flat and reverted volume stays below half with
    /// room for the rounding.
    pub fn surely_kept(&self, n: usize) -> bool {
        let r = rounding(n);
        // (sums far from overflow, of normal floats: halving them is exact)
        let signs: &[usize] = match self.geo_abs < 1e300 {
            true if self.geo > r * self.geo_abs => &[0],
            true if self.geo < -r * self.geo_abs => &[1],
            _ => &[0, 1],
        };
        signs.iter().all(|&i| {
            let all = self.all[i];
            self.reverted[i] == 0
                || ((1e-300..1e300).contains(&all) && self.bad[i] < 0.5 * (1.0 - r) * all)
        })
    }
}

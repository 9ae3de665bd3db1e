//! Local, shifted coordinates: step 2 of both extractions.
//!
//! Input: a map, its topology and transitions, and a grid offset
//! ([`crate::grid_offset`]). Output: [`LocalMap`], where
//! each simplex's corners are expressed relative to an integer offset of
//! that simplex (`global = local + offset`) and shifted by `h` = (½, …, ½)
//! (the default) or 0: the
//! integer points of the local coordinates are the dual grid (nodes), and
//! local values stay small whatever the magnitude of the input (a map
//! translated by 2^40 behaves like one at the origin: subtracting an integer
//! offset from a float of the same magnitude is exact).
//!
//! Invariant: across each interior facet, `local(n) = rot · local(s) +
//! trans` with an integer `trans` (the input transitions with offsets and
//! shift folded in: `h − R·h` is integral for `h = (½, …, ½)`, `h = 0` and
//! every grid rotation), up to the map's own GP residual.

use crate::grid_offset::GridOffset;
use crate::scatter::{self, Buckets};
use dualex_map::topology::NONE;
use dualex_map::{Rot, SimplexMap, Stars, Topology, Transitions};
use dualex_util::round::{round_small, FAST};
use rayon::prelude::*;

/// A map in local shifted coordinates.
#[derive(Clone, Debug)]
pub struct LocalMap<const N: usize, const D: usize> {
    /// Local shifted map coordinates per corner.
    pub coords: Vec<[[f64; D]; N]>,
    /// Integer offset of each simplex (global shifted = local + offset).
    pub offset: Vec<[i64; D]>,
    /// The grid offset used (`Half` or `Zero`).
    pub grid: GridOffset,
    /// Transitions between local charts.
    pub trans: Transitions<N, D>,
}

/// `h − R·h` for `h = (½, …, ½)`: an integer vector. `R` permutes the
/// axes with signs, so `R·h = ½·R·(1, …, 1)` has entries `±½` and the
/// defect is `(1 − (R·1)_k) / 2`, 0 or 1, in integers (no float
/// conversion per facet).
#[inline]
pub fn shift_defect<const D: usize>(r: &Rot<D>) -> [i64; D] {
    let r1 = r.apply_i(&[1; D]);
    std::array::from_fn(|k| (1 - r1[k]) / 2)
}

/// The integer offset of a simplex (its corners `c`): the floor of its
/// first corner.
#[inline]
pub fn simplex_offset<const N: usize, const D: usize>(c: &[[f64; D]; N]) -> [i64; D] {
    c[0].map(|x| dualex_util::round::floor(x) as i64)
}

/// [`simplex_offset`] of every simplex of `map`, in order.
pub fn simplex_offsets<const N: usize, const D: usize>(map: &SimplexMap<N, D>) -> Vec<[i64; D]> {
    map.coords.par_iter().map(simplex_offset).collect()
}

/// The local translation across a facet whose input transition is
/// `(r, t)`, from a simplex with offset `os` to one with offset `on`,
/// under the shift `h` (½ or 0).
#[inline]
pub fn local_transition<const D: usize>(
    r: &Rot<D>,
    t: &[i64; D],
    os: &[i64; D],
    on: &[i64; D],
    h: f64,
) -> [i64; D] {
    // the identity: `R·os = os` and no shift defect (the same integers)
    if r.is_identity() {
        return std::array::from_fn(|k| os[k] + t[k] - on[k]);
    }
    rotated_transition(r, [t, os, on], h)
}

/// [`local_transition`] across a transition whose rotation is not the
/// identity (kept out of line: the identity's case is inlined).
#[inline(never)]
fn rotated_transition<const D: usize>(r: &Rot<D>, [t, os, on]: [&[i64; D]; 3], h: f64) -> [i64; D] {
    let ro = r.apply_i(os);
    let d = if h == 0.0 { [0; D] } else { shift_defect(r) };
    std::array::from_fn(|k| ro[k] + t[k] - on[k] + d[k])
}

impl<const N: usize, const D: usize> LocalMap<N, D> {
    /// Builds local shifted coordinates and the matching transitions (per
    /// simplex, in parallel: each writes only its own entries).
    pub fn new(map: &SimplexMap<N, D>, topo: &Topology<N>, trans: &Transitions<N, D>) -> Self {
        Self::from_transitions(map, topo, trans.clone())
    }

    /// [`Self::new`] taking the input transitions and rewriting them in
    /// place (the extractions do not need them afterwards: one copy less
    /// at the peak of memory).
    pub fn from_transitions(
        map: &SimplexMap<N, D>,
        topo: &Topology<N>,
        trans: Transitions<N, D>,
    ) -> Self {
        Self::with_grid(map, topo, trans, GridOffset::Half)
    }

    /// [`Self::from_transitions`] with the shift of `grid` (`Auto` counts
    /// as `Half`: resolve it first, [`crate::grid_offset::local_map`]).
    pub fn with_grid(
        map: &SimplexMap<N, D>,
        topo: &Topology<N>,
        trans: Transitions<N, D>,
        grid: GridOffset,
    ) -> Self {
        let offset = simplex_offsets(map);
        Self::with_grid_in(map, topo, trans, offset, grid, grid)
    }

    /// [`Self::with_grid`] whose coordinates are rounded in the chart of
    /// `chart`: `((x − offset) + c) − (c − h)` with `c` the shift of
    /// `chart` and `h` that of `grid` (the same as `(x − offset) + h` when
    /// `chart == grid`). [`crate::grid_offset::local_map`] builds the
    /// `Zero` an `Auto` choice gives in the chart `Half` the choice was
    /// made in. `offset`: [`simplex_offsets`] of `map` (computed once by
    /// the caller, which also reads them to make the choice).
    pub fn with_grid_in(
        map: &SimplexMap<N, D>,
        topo: &Topology<N>,
        trans: Transitions<N, D>,
        offset: Vec<[i64; D]>,
        grid: GridOffset,
        chart: GridOffset,
    ) -> Self {
        let h = grid.shift();
        let (c, back) = (chart.shift(), chart.shift() - h);
        let grid = match grid {
            GridOffset::Zero => GridOffset::Zero,
            GridOffset::Auto | GridOffset::Half => GridOffset::Half,
        };
        let coords = map
            .coords
            .par_iter()
            .zip(&offset)
            .map(|(cs, o)| cs.map(|p| std::array::from_fn(|k| ((p[k] - o[k] as f64) + c) - back)))
            .collect();
        let mut t = trans;
        let rot = &t.rot;
        t.trans.par_iter_mut().enumerate().for_each(|(s, ts)| {
            // the rows of `s`, read once for its facets
            let (adj, rs, os) = (&topo.adj[s], &rot[s], &offset[s]);
            for ((tf, r), &n) in ts.iter_mut().zip(rs).zip(adj) {
                if n == NONE {
                    continue;
                }
                *tf = local_transition(r, tf, os, &offset[n as usize], h);
            }
        });
        LocalMap {
            coords,
            offset,
            grid,
            trans: t,
        }
    }

    /// Maps a local point of simplex `s` into the local chart of its
    /// neighbour across facet `f`.
    #[inline]
    pub fn across(&self, s: usize, f: usize, p: &[f64; D]) -> [f64; D] {
        self.trans.apply(s, f, p)
    }

    /// Snaps every non-singular vertex's corners to one exactly-GP value:
    /// its reference corner carried through the star's rotations plus the
    /// nearest integer translation, so that sign tests agree between its
    /// charts. Returns the number of vertices snapped and the largest move.
    ///
    /// Each corner belongs to one star and a vertex's new corners depend on
    /// its own old corners only, so blocks of vertices are snapped in
    /// parallel into [`Buckets`] (only the corners whose bits change), then
    /// written back in parallel by range of simplices ([`scatter::apply`]);
    /// the count and the maximum do not depend on the split.
    pub fn snap(&mut self, stars: &Stars<D>) -> (usize, f64) {
        /// Vertices per parallel task, and per wave (bounds the buffers).
        const TASK: usize = 1024;
        const WAVE: usize = 8 * TASK;
        let nv = stars.singular.len();
        let ranges = scatter::ranges(self.coords.len());
        let (mut count, mut max_move) = (0, 0.0f64);
        // the blocks' buffers, kept from wave to wave
        let mut blocks: Vec<Buckets<D>> = Vec::new();
        blocks.resize_with(WAVE / TASK, || Buckets::new(ranges));
        for wave in (0..nv).step_by(WAVE) {
            let end = (wave + WAVE).min(nv);
            let coords = &self.coords;
            let found: Vec<(usize, f64)> = blocks
                .par_iter_mut()
                .enumerate()
                .map(|(i, out)| {
                    let v0 = (wave + i * TASK).min(end);
                    snap_block(coords, stars, v0..(v0 + TASK).min(end), out)
                })
                .collect();
            for (c, m) in found {
                count += c;
                if m > max_move {
                    max_move = m;
                }
            }
            scatter::apply(&mut self.coords, &blocks, |x, y| *x = *y);
        }
        (count, max_move)
    }

    /// Adds `delta` (given in `v`'s reference chart) to every corner of
    /// `v`, rotated into each corner's chart: no transition changes.
    pub fn move_vertex(&mut self, stars: &Stars<D>, v: usize, delta: &[f64; D]) {
        for e in stars.of(v) {
            let d = e.rot.apply(delta);
            let x = &mut self.coords[e.simplex as usize][e.corner as usize];
            for (xk, dk) in x.iter_mut().zip(d) {
                *xk += dk;
            }
        }
    }

    /// Signed determinant of simplex `s`'s image (< 0: reverted).
    #[inline]
    pub fn det(&self, s: usize) -> f64 {
        dualex_map::mesh::det_of::<N, D>(&self.coords[s])
    }
}

/// [`LocalMap::snap`] of the vertices `vs`, reading `coords`: the
/// corners whose bits change, into `out` (cleared first); returns the
/// number of vertices snapped and the largest move.
///
/// A corner whose difference from its snapped place is below [`FAST`] on
/// every axis (every corner of a valid local map) is snapped in the loop
/// without a library call ([`round_small`]); the others (huge or not
/// finite) after it, by [`snap_corner`]. Each corner is in one star and
/// written once, and the largest move does not depend on the order: the
/// same result as one pass in order.
fn snap_block<const N: usize, const D: usize>(
    coords: &[[[f64; D]; N]],
    stars: &Stars<D>,
    vs: std::ops::Range<usize>,
    out: &mut Buckets<D>,
) -> (usize, f64) {
    out.clear();
    let (mut count, mut max_move) = (0, 0.0f64);
    // the corners left for after the loop, with their places `y`
    let mut slow: Vec<(u32, u8, [f64; D])> = Vec::new();
    for v in vs {
        let star = stars.of(v);
        let Some(first) = star.first() else { continue };
        if stars.singular[v] {
            continue;
        }
        let x_ref = coords[first.simplex as usize][first.corner as usize];
        for e in star {
            let y = e.rot.apply(&x_ref);
            let old = coords[e.simplex as usize][e.corner as usize];
            // (branch-free: `==` per axis, no early exit)
            let same = (0..D).fold(true, |same, k| same & (old[k] == y[k]));
            let x = if same {
                // the common case in 3D, the same point: `x − y = +0`,
                // which rounds to itself, and the move is 0
                y.map(|yk| yk + 0.0)
            } else {
                let d: [f64; D] = std::array::from_fn(|k| old[k] - y[k]);
                // (branch-free: one test for every axis)
                let fast = (0..D).fold(true, |f, k| f & (d[k].abs() < FAST));
                if !fast {
                    slow.push((e.simplex, e.corner, y));
                    continue;
                }
                let x: [f64; D] = std::array::from_fn(|k| y[k] + round_small(d[k]));
                for k in 0..D {
                    // not NaN (`fast`): as `f64::max`
                    let m = (x[k] - old[k]).abs();
                    max_move = if m > max_move { m } else { max_move };
                }
                x
            };
            if changed(&x, &old) {
                out.push(e.simplex, e.corner, x);
            }
        }
        count += 1;
    }
    for (s, c, y) in slow {
        let old = coords[s as usize][c as usize];
        let x = snap_corner(&old, &y, &mut max_move);
        if changed(&x, &old) {
            out.push(s, c, x);
        }
    }
    (count, max_move)
}

/// Whether `x` differs from `old` in some bit (branch-free).
#[inline]
fn changed<const D: usize>(x: &[f64; D], old: &[f64; D]) -> bool {
    (0..D).fold(false, |c, k| c | (x[k].to_bits() != old[k].to_bits()))
}

/// A corner `x` snapped onto `y` plus the nearest integer translation
/// ([`LocalMap::snap`]), `max_move` raised to its move.
#[inline]
fn snap_corner<const D: usize>(x: &[f64; D], y: &[f64; D], max_move: &mut f64) -> [f64; D] {
    std::array::from_fn(|k| {
        let snapped = y[k] + dualex_util::round::round(x[k] - y[k]);
        // not NaN (validated input): as `f64::max`
        let m = (snapped - x[k]).abs();
        if m > *max_move {
            *max_move = m;
        }
        snapped
    })
}

/// The input-chart coordinates of corner `code` (bit `a` set: the + side
/// of axis `a`) of the dual cell of the integer point `node` of simplex
/// `s`'s local chart (`dualex_cells::corners`). `s` must be a simplex of `local`.
pub fn node_corner<const N: usize, const D: usize>(
    local: &LocalMap<N, D>,
    s: usize,
    node: &[i64; D],
    code: usize,
) -> [f64; D] {
    let h = local.grid.shift();
    let o = local.offset[s];
    std::array::from_fn(|a| {
        let half = if code >> a & 1 == 1 { 0.5 } else { -0.5 };
        (node[a] + o[a]) as f64 + (half - h)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn integral<const D: usize>(n: usize) {
        let all = Rot::<D>::all();
        assert_eq!(all.len(), n);
        for r in all {
            let d = shift_defect(&r);
            let rh = r.apply(&[0.5; D]);
            for k in 0..D {
                assert_eq!(d[k] as f64, 0.5 - rh[k], "{r:?}");
            }
        }
    }

    /// The sequential snap that [`LocalMap::snap`] parallelises.
    fn snap_reference<const N: usize, const D: usize>(
        local: &mut LocalMap<N, D>,
        stars: &Stars<D>,
    ) -> (usize, f64) {
        let (mut count, mut max_move) = (0, 0.0f64);
        for v in 0..stars.singular.len() {
            if stars.singular[v] {
                continue;
            }
            let star = stars.of(v);
            let Some(first) = star.first() else { continue };
            let x_ref = local.coords[first.simplex as usize][first.corner as usize];
            for e in star {
                let y = e.rot.apply(&x_ref);
                let x = &mut local.coords[e.simplex as usize][e.corner as usize];
                for (xk, yk) in x.iter_mut().zip(y) {
                    let snapped = yk + (*xk - yk).round();
                    max_move = max_move.max((snapped - *xk).abs());
                    *xk = snapped;
                }
            }
            count += 1;
        }
        (count, max_move)
    }

    /// Snaps `local` and checks the result against the sequential
    /// reference: the counts and every coordinate's bits; the counts.
    fn snap_as_reference(local: &mut LocalMap<3, 2>, stars: &Stars<2>) -> (usize, f64) {
        let mut want = local.clone();
        let got = local.snap(stars);
        assert_eq!(got, snap_reference(&mut want, stars));
        let bits = |l: &LocalMap<3, 2>| -> Vec<u64> {
            l.coords
                .iter()
                .flatten()
                .flatten()
                .map(|x| x.to_bits())
                .collect()
        };
        assert_eq!(bits(local), bits(&want));
        got
    }

    /// A grid of `n` cells a side, its charts turned at random (`seed`):
    /// its stars and local map.
    fn recharted_grid(n: u32, seed: u64) -> (Stars<2>, LocalMap<3, 2>) {
        use dualex_map::test_maps::{grid, rechart};
        use dualex_map::{Topology, Transitions};
        let mut map = grid(n);
        rechart(&mut map, seed);
        let topo = Topology::build(&map).unwrap_or_else(|e| panic!("{e}"));
        let (trans, _) =
            Transitions::derive(&map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
        let stars = Stars::build(&map, &topo, &trans);
        let local = LocalMap::new(&map, &topo, &trans);
        (stars, local)
    }

    /// The parallel snap equals the sequential one bit for bit, on a map
    /// with random charts and per-corner noise spanning several waves.
    #[test]
    fn snap_equals_sequential_reference() {
        use dualex_map::test_maps::Lcg;
        let (stars, mut local) = recharted_grid(130, 5);
        let mut rng = Lcg(3);
        for x in local.coords.iter_mut().flatten().flatten() {
            *x += (rng.below(2001) as f64 - 1000.0) * 1e-9;
        }
        let got = snap_as_reference(&mut local, &stars);
        assert!(got.0 > 16000 && got.1 > 0.0, "{got:?}");
    }

    /// The snap equals the sequential one bit for bit on corners set to
    /// quarters (ties of the rounding both ways), signed zeros, and values
    /// at and beyond [`FAST`] (the path after the loop).
    #[test]
    fn snap_equals_reference_on_ties_zeros_and_huge_values() {
        use dualex_map::test_maps::Lcg;
        let (stars, mut local) = recharted_grid(60, 3);
        let mut rng = Lcg(11);
        for x in local.coords.iter_mut().flatten().flatten() {
            let q = rng.below(33) as f64 * 0.25 - 4.0;
            *x = match rng.below(40) {
                0 => -0.0,
                1 => 0.0,
                2 => 3e15 + q,
                3 => -1e300,
                _ => q,
            };
        }
        snap_as_reference(&mut local, &stars);
    }

    #[test]
    fn shift_defect_is_integral_for_every_rotation() {
        integral::<2>(4);
        integral::<3>(24);
    }
}

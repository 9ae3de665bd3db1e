//! Exact placement of singular vertices: every singular vertex is put on
//! the fixed set of its holonomies, in every chart at once.
//!
//! Input: a [`LocalMap`] (corners and integer local transitions), its
//! [`Topology`] and [`Stars`]. Output: the same map where the corners of
//! each singular vertex `v` are `rot_e · x + τ_e` for one point `x` of
//! `v`'s reference chart, with `τ_e` the integer translation of corner `e`
//! and `x` the point nearest to the old reference corner that satisfies
//! every transition of the facets around `v` exactly:
//! `rot_j · x + τ_j = R · (rot_i · x + τ_i) + t` for each facet `(i → j)`.
//!
//! In 2D that point is the fixed point of the holonomy (a 90° or 180°
//! rotation plus an integer translation: a point of the half-integer grid).
//! In 3D a vertex inside one singular edge goes onto the edge's axis (its
//! coordinate along the axis is kept), a vertex where singular edges meet
//! onto the intersection of their axes. The constrained coordinates are
//! then exact (quotients of small integers), so no chart disagreement
//! below the map's tolerance reaches the sign tests: float jitter at
//! singular vertices (a map file written with 7 significant digits) gives
//! the same mesh as the exact map.
//!
//! Invariants: transitions are not changed; regular vertices are not
//! touched ([`LocalMap::snap`] places them). A vertex whose constraints are
//! inconsistent (the rounded translations disagree: a residual near ½) or
//! whose snap would move a corner by more than [`MAX_MOVE`] is left as it
//! is and counted in [`SingularSnap::left`].

use crate::local::LocalMap;
use dualex_map::{Rot, Stars, Topology};

/// Largest corner move accepted (map units): beyond it the translations
/// recovered by rounding are not trustworthy.
pub const MAX_MOVE: f64 = 0.25;

/// What [`snap_singular`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SingularSnap {
    /// Singular vertices placed on their fixed set.
    pub snapped: usize,
    /// Largest corner move among them.
    pub max_move: f64,
    /// Singular vertices left as they were (inconsistent or too far).
    pub left: usize,
}

/// Local coordinates and transitions, as [`fixed_corners`] reads them: a
/// built [`LocalMap`], or a chart computed on demand for the few simplices
/// around singular vertices (`crate::grid_offset`, which chooses the
/// offset before the local map is built).
pub trait Chart<const N: usize, const D: usize> {
    /// Corner `c` of simplex `s`.
    fn corner(&self, s: usize, c: usize) -> [f64; D];
    /// The local transition across facet `f` of `s` (an interior facet).
    fn transition(&self, s: usize, f: usize) -> (Rot<D>, [i64; D]);
}

impl<const N: usize, const D: usize> Chart<N, D> for LocalMap<N, D> {
    #[inline]
    fn corner(&self, s: usize, c: usize) -> [f64; D] {
        self.coords[s][c]
    }

    #[inline]
    fn transition(&self, s: usize, f: usize) -> (Rot<D>, [i64; D]) {
        (self.trans.rot[s][f], self.trans.trans[s][f])
    }
}

/// Puts every singular vertex of `local` on the fixed set of its
/// holonomies (see the module docs).
pub fn snap_singular<const N: usize, const D: usize>(
    local: &mut LocalMap<N, D>,
    topo: &Topology<N>,
    stars: &Stars<D>,
) -> SingularSnap {
    let (rep, snapped) = singular_corners(&*local, topo, stars);
    for (v, corners) in snapped {
        for (e, x) in stars.of(v as usize).iter().zip(corners) {
            local.coords[e.simplex as usize][e.corner as usize] = x;
        }
    }
    rep
}

/// The report of [`snap_singular`] and, per singular vertex snapped, its
/// corners in star order.
pub type Snapped<const D: usize> = (SingularSnap, Vec<(u32, Vec<[f64; D]>)>);

/// The snapped corners (in star order) of every singular vertex that can
/// be snapped, read from `chart`, with the report of [`snap_singular`].
pub fn singular_corners<const N: usize, const D: usize>(
    chart: &impl Chart<N, D>,
    topo: &Topology<N>,
    stars: &Stars<D>,
) -> Snapped<D> {
    let mut rep = SingularSnap::default();
    let mut out = Vec::new();
    for v in 0..stars.singular.len() {
        if !stars.singular[v] {
            continue;
        }
        match fixed_corners(chart, topo, stars, v) {
            Some((corners, m)) => {
                out.push((v as u32, corners));
                rep.snapped += 1;
                if m > rep.max_move {
                    rep.max_move = m;
                }
            }
            None => rep.left += 1,
        }
    }
    (rep, out)
}

/// The snapped corners of singular vertex `v`, in star order, with the
/// largest move; `None` when the vertex must be left as it is.
fn fixed_corners<const N: usize, const D: usize>(
    chart: &impl Chart<N, D>,
    topo: &Topology<N>,
    stars: &Stars<D>,
    v: usize,
) -> Option<(Vec<[f64; D]>, f64)> {
    let star = stars.of(v);
    let first = star.first()?;
    let corner = |s: u32, c: u8| chart.corner(s as usize, c as usize);
    let x_ref = corner(first.simplex, first.corner);
    // integer translation of each corner relative to the reference chart
    let tau: Vec<[i64; D]> = star
        .iter()
        .map(|e| {
            let x = corner(e.simplex, e.corner);
            let y = e.rot.apply(&x_ref);
            std::array::from_fn(|k| dualex_util::round::round(x[k] - y[k]) as i64)
        })
        .collect();
    let mut sys = Echelon::<D>::default();
    for (i, e) in star.iter().enumerate() {
        let s = e.simplex as usize;
        for f in (0..N).filter(|&f| f != e.corner as usize) {
            let Some((n, _)) = topo.neighbour(s, f) else {
                continue;
            };
            let j = star.iter().position(|x| x.simplex as usize == n)?;
            let (r, t) = chart.transition(s, f);
            let lhs = matrix(&star[j].rot);
            let rhs_rot = matrix(&e.rot.then(&r));
            let rt = r.apply_i(&tau[i]);
            for row in 0..D {
                let a: [i64; D] = std::array::from_fn(|c| lhs[row][c] - rhs_rot[row][c]);
                let b = rt[row] + t[row] - tau[j][row];
                if !sys.add(a, b) {
                    return None; // inconsistent: 0 = b ≠ 0
                }
            }
        }
    }
    let x = sys.project(&x_ref);
    let mut max_move = 0.0f64;
    let out: Vec<[f64; D]> = star
        .iter()
        .zip(&tau)
        .map(|(e, t)| {
            let y = e.rot.apply(&x);
            let old = corner(e.simplex, e.corner);
            let new: [f64; D] = std::array::from_fn(|k| y[k] + t[k] as f64);
            for k in 0..D {
                max_move = max_move.max((new[k] - old[k]).abs());
            }
            new
        })
        .collect();
    (max_move <= MAX_MOVE).then_some((out, max_move))
}

/// The integer matrix of a grid rotation (`m[row][col]`).
fn matrix<const D: usize>(r: &Rot<D>) -> [[i64; D]; D] {
    let mut m = [[0i64; D]; D];
    // column `col` is the image of axis `col`: direction `d` = axis d/2,
    // negative when odd
    for (col, d) in r.images().into_iter().enumerate() {
        m[(d >> 1) as usize][col] = if d & 1 == 1 { -1 } else { 1 };
    }
    m
}

/// A linear system `a · x = b` over the integers kept in reduced row
/// echelon form (at most `D` independent rows, each with a positive pivot
/// and zeros in the other rows' pivot columns, entries divided by their
/// gcd): exact, whatever the order the rows come in.
#[derive(Default)]
struct Echelon<const D: usize> {
    rows: Vec<([i64; D], i64)>,
}

fn gcd(a: i64, b: i64) -> i64 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

impl<const D: usize> Echelon<D> {
    fn pivot(a: &[i64; D]) -> Option<usize> {
        a.iter().position(|&x| x != 0)
    }

    /// Divides a row by the gcd of its entries, pivot made positive.
    fn normalize(a: &mut [i64; D], b: &mut i64) {
        let g = a.iter().fold(*b, |g, &x| gcd(g, x));
        let sign = match Self::pivot(a) {
            Some(p) if a[p] < 0 => -1,
            _ => 1,
        };
        if g > 0 {
            for x in a.iter_mut() {
                *x = sign * *x / g;
            }
            *b = sign * *b / g;
        }
    }

    /// Eliminates the pivot column of row `(p, pa, pb)` from `(a, b)`.
    fn eliminate(a: &mut [i64; D], b: &mut i64, pa: &[i64; D], pb: i64, p: usize) {
        let (m, n) = (a[p], pa[p]);
        if m == 0 {
            return;
        }
        for k in 0..D {
            a[k] = a[k] * n - pa[k] * m;
        }
        *b = *b * n - pb * m;
        Self::normalize(a, b);
    }

    /// Adds the equation `a · x = b`; `false` when it contradicts the
    /// others.
    fn add(&mut self, mut a: [i64; D], mut b: i64) -> bool {
        for (pa, pb) in &self.rows {
            if let Some(p) = Self::pivot(pa) {
                Self::eliminate(&mut a, &mut b, pa, *pb, p);
            }
        }
        let Some(p) = Self::pivot(&a) else {
            return b == 0;
        };
        Self::normalize(&mut a, &mut b);
        for (ra, rb) in self.rows.iter_mut() {
            Self::eliminate(ra, rb, &a, b, p);
        }
        self.rows.push((a, b));
        true
    }

    /// The point of `{x : a·x = b}` nearest to `x0`. A row with a single
    /// entry fixes its coordinate exactly (`b / a`); the other coordinates
    /// are projected orthogonally.
    fn project(&self, x0: &[f64; D]) -> [f64; D] {
        let mut x = *x0;
        let single: Vec<bool> = self
            .rows
            .iter()
            .map(|(a, _)| a.iter().filter(|&&c| c != 0).count() == 1)
            .collect();
        // general rows: x ← x − Aᵀ (A Aᵀ)⁻¹ (A x − b), at most 3 rows
        let general: Vec<&([i64; D], i64)> = self
            .rows
            .iter()
            .zip(&single)
            .filter(|(_, &s)| !s)
            .map(|(r, _)| r)
            .collect();
        if !general.is_empty() {
            let m = general.len();
            let af = |r: usize, k: usize| general[r].0[k] as f64;
            let mut g = vec![vec![0.0; m]; m];
            let mut res = vec![0.0; m];
            for (r, gr) in g.iter_mut().enumerate() {
                for (q, grq) in gr.iter_mut().enumerate() {
                    *grq = (0..D).map(|k| af(r, k) * af(q, k)).sum();
                }
                res[r] = (0..D).map(|k| af(r, k) * x[k]).sum::<f64>() - general[r].1 as f64;
            }
            if let Some(y) = solve(g, res) {
                for (k, xk) in x.iter_mut().enumerate() {
                    *xk -= (0..m).map(|r| af(r, k) * y[r]).sum::<f64>();
                }
            }
        }
        for ((a, b), &s) in self.rows.iter().zip(&single) {
            if s {
                if let Some(p) = Self::pivot(a) {
                    x[p] = *b as f64 / a[p] as f64;
                }
            }
        }
        x
    }
}

/// Solves the small symmetric positive definite system `g · y = r` by
/// Gaussian elimination with partial pivoting.
fn solve(mut g: Vec<Vec<f64>>, mut r: Vec<f64>) -> Option<Vec<f64>> {
    let m = r.len();
    for c in 0..m {
        let p = (c..m).max_by(|&i, &j| g[i][c].abs().total_cmp(&g[j][c].abs()))?;
        if g[p][c] == 0.0 {
            return None;
        }
        g.swap(c, p);
        r.swap(c, p);
        let (top, rest) = g.split_at_mut(c + 1);
        let pivot_row = &top[c];
        for (i, gi) in rest.iter_mut().enumerate() {
            let f = gi[c] / pivot_row[c];
            for (gik, pk) in gi[c..].iter_mut().zip(&pivot_row[c..]) {
                *gik -= f * pk;
            }
            r[c + 1 + i] -= f * r[c];
        }
    }
    let mut y = vec![0.0; m];
    for c in (0..m).rev() {
        let s: f64 = (c + 1..m).map(|k| g[c][k] * y[k]).sum();
        y[c] = (r[c] - s) / g[c][c];
    }
    Some(y)
}

#[cfg(test)]
mod tests;

//! 3D maps of a box (tet meshes with a `(u, v, w)` map per corner).
//!
//! Mesh: the unit cube split into `nx × ny × nz` cells, each cell into the
//! 6 Kuhn tets around its main diagonal `(0,0,0)–(1,1,1)` (conforming
//! between cells), every tet with positive volume. Vertex `(i, j, k)` has
//! index `(k·(ny+1) + j)·(nx+1) + i`.
//!
//! Map: per axis affine onto `[lo, hi]`, then perturbed (interior vertices
//! only, so the expected hex mesh is the `c³` grid, `c =
//! cells_between(lo, hi)`, when the method recovers it):
//! - [`block`]: none; [`block_noise`]: white noise;
//! - [`block_fold`]: the fold of `square_fold` along `u`, in a ball;
//! - [`block_half_rotated`]: noise, then tets with centroid `x > ½` get the
//!   chart `R·m + T` (`R` a quarter turn around `w`, `T` integer);
//! - [`block_degenerate`]: a few interior vertices moved onto the map
//!   position of a neighbour, making their tets zero-volume in the map.

use crate::build::bump;
use crate::expected::cells_between;
use crate::rng::SplitMix64;
use dualex_map::{Rot3, TetMap};

/// What the extracted hex mesh should be, when known.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ExpectedHex {
    /// Number of hexes.
    pub hexes: Option<usize>,
    /// Connected components of the boundary surface.
    pub boundary_components: Option<usize>,
    /// Euler characteristic of the boundary surface.
    pub boundary_euler: Option<i64>,
}

impl ExpectedHex {
    /// A `c × c × c` grid of hexes.
    pub fn grid(c: usize) -> Self {
        let solid = c > 0;
        ExpectedHex {
            hexes: Some(c * c * c),
            boundary_components: Some(usize::from(solid)),
            boundary_euler: Some(2 * i64::from(solid)),
        }
    }
}

/// The block mesh with per-vertex map values `value[v]` (one chart).
struct Block {
    param: Vec<[f64; 3]>,
    tets: Vec<[u32; 4]>,
}

impl Block {
    fn new(nx: usize, ny: usize, nz: usize) -> Self {
        let dims = [nx.max(1), ny.max(1), nz.max(1)];
        let id =
            |i: usize, j: usize, k: usize| ((k * (dims[1] + 1) + j) * (dims[0] + 1) + i) as u32;
        let mut param = Vec::new();
        for k in 0..=dims[2] {
            for j in 0..=dims[1] {
                for i in 0..=dims[0] {
                    param.push([
                        i as f64 / dims[0] as f64,
                        j as f64 / dims[1] as f64,
                        k as f64 / dims[2] as f64,
                    ]);
                }
            }
        }
        const PERMS: [([usize; 3], bool); 6] = [
            ([0, 1, 2], true),
            ([1, 2, 0], true),
            ([2, 0, 1], true),
            ([1, 0, 2], false),
            ([0, 2, 1], false),
            ([2, 1, 0], false),
        ];
        let mut tets = Vec::with_capacity(6 * dims.iter().product::<usize>());
        for k in 0..dims[2] {
            for j in 0..dims[1] {
                for i in 0..dims[0] {
                    for (perm, even) in PERMS {
                        let mut c = [i, j, k];
                        let mut t = [id(c[0], c[1], c[2]); 4];
                        for (s, &axis) in perm.iter().enumerate() {
                            c[axis] += 1;
                            t[s + 1] = id(c[0], c[1], c[2]);
                        }
                        if !even {
                            t.swap(2, 3);
                        }
                        tets.push(t);
                    }
                }
            }
        }
        Block { param, tets }
    }

    fn on_boundary(&self, v: usize) -> bool {
        self.param[v].iter().any(|&x| x == 0.0 || x == 1.0)
    }

    fn affine(&self, lo: f64, hi: f64) -> Vec<[f64; 3]> {
        self.param
            .iter()
            .map(|p| snap3(p.map(|x| lo + (hi - lo) * x)))
            .collect()
    }

    fn map(&self, value: &[[f64; 3]]) -> TetMap {
        TetMap {
            positions: self.param.clone(),
            simplices: self.tets.clone(),
            coords: self
                .tets
                .iter()
                .map(|t| t.map(|v| value[v as usize]))
                .collect(),
        }
    }

    fn add_noise(&self, value: &mut [[f64; 3]], amplitude: f64, seed: u64) {
        let mut rng = SplitMix64::new(seed);
        for (v, m) in value.iter_mut().enumerate() {
            let d = [
                rng.symmetric(amplitude),
                rng.symmetric(amplitude),
                rng.symmetric(amplitude),
            ];
            if !self.on_boundary(v) {
                *m = snap3([m[0] + d[0], m[1] + d[1], m[2] + d[2]]);
            }
        }
    }
}

/// Rounds to a multiple of 2⁻³² (see `build::snap`).
fn snap3(x: [f64; 3]) -> [f64; 3] {
    const S: f64 = 4_294_967_296.0;
    x.map(|c| (c * S).round() / S)
}

fn expected(lo: f64, hi: f64) -> ExpectedHex {
    ExpectedHex::grid(cells_between(lo, hi))
}

/// The affine map of the box onto `[lo, hi]³`.
pub fn block(nx: usize, ny: usize, nz: usize, lo: f64, hi: f64) -> (TetMap, ExpectedHex) {
    let b = Block::new(nx, ny, nz);
    (b.map(&b.affine(lo, hi)), expected(lo, hi))
}

/// White noise uniform in `[-amplitude, amplitude]³` on interior vertices.
pub fn block_noise(n: usize, lo: f64, hi: f64, amplitude: f64, seed: u64) -> (TetMap, ExpectedHex) {
    let b = Block::new(n, n, n);
    let mut value = b.affine(lo, hi);
    b.add_noise(&mut value, amplitude, seed);
    (b.map(&value), expected(lo, hi))
}

/// The fold of `square_fold` along `u`, with the bump of the 3D distance
/// to the centre (a ball of radius 0.3).
pub fn block_fold(n: usize, lo: f64, hi: f64, strength: f64) -> (TetMap, ExpectedHex) {
    let b = Block::new(n, n, n);
    let value: Vec<[f64; 3]> = b
        .param
        .iter()
        .map(|p| {
            let d = [p[0] - 0.5, p[1] - 0.5, p[2] - 0.5];
            let s = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() / 0.3;
            let q = [p[0] + strength * 0.3 * bump(s), p[1], p[2]];
            snap3(q.map(|x| lo + (hi - lo) * x))
        })
        .collect();
    (b.map(&value), expected(lo, hi))
}

/// The rotation (quarter turn around `w`) and translation of the right half.
pub fn half_rotation() -> (Rot3, [f64; 3]) {
    // +u → +v, +v → −u, +w → +w
    let r = Rot3::from_images([2, 1, 4]).unwrap_or_else(|| panic!("bug: not a rotation"));
    (r, [9.0, -2.0, 3.0])
}

/// Noise, then the right half (tet centroid `x > ½`) in the chart `R·m + T`.
pub fn block_half_rotated(
    n: usize,
    lo: f64,
    hi: f64,
    amplitude: f64,
    seed: u64,
) -> (TetMap, ExpectedHex) {
    let b = Block::new(n, n, n);
    let mut value = b.affine(lo, hi);
    b.add_noise(&mut value, amplitude, seed);
    let mut map = b.map(&value);
    let (r, t) = half_rotation();
    for (tet, coords) in map.simplices.iter().zip(map.coords.iter_mut()) {
        let cx: f64 = tet.iter().map(|&v| b.param[v as usize][0]).sum::<f64>() / 4.0;
        if cx > 0.5 {
            for c in coords.iter_mut() {
                let p = r.apply(c);
                *c = [p[0] + t[0], p[1] + t[1], p[2] + t[2]];
            }
        }
    }
    (map, expected(lo, hi))
}

/// `count` interior vertices (chosen by `seed`) moved onto the map value of
/// their `+x` neighbour: each makes the tets containing both zero-volume.
pub fn block_degenerate(
    n: usize,
    lo: f64,
    hi: f64,
    count: usize,
    seed: u64,
) -> (TetMap, ExpectedHex) {
    let b = Block::new(n, n, n);
    let mut value = b.affine(lo, hi);
    let mut rng = SplitMix64::new(seed);
    let interior: Vec<usize> = (0..b.param.len()).filter(|&v| !b.on_boundary(v)).collect();
    for _ in 0..count.min(interior.len()) {
        let v = interior[(rng.next_u64() % interior.len() as u64) as usize];
        value[v] = value[v + 1];
    }
    (b.map(&value), expected(lo, hi))
}

#[cfg(test)]
mod tests;

//! Shared building blocks: regular grid triangulations, per-vertex maps,
//! the C¹ bump used by the folds.
//!
//! Grid numbering: vertex `(i, j)`, `0 <= i, j <= res`, has index
//! `j·(res+1) + i` and parameter `(i/res, j/res)`. Cell `(i, j)` is split
//! along one diagonal, into counter-clockwise triangles:
//! ```text
//!   d ---- c     Fixed (and even cells of Alternating): a-b-c, a-c-d
//!   |      |     odd cells of Alternating:              a-b-d, b-c-d
//!   a ---- b     (a = (i,j), b = (i+1,j), c = (i+1,j+1), d = (i,j+1))
//! ```

use dualex_map::TriMap;

/// How each grid cell `(i, j)` of a regular grid is split into two
/// counter-clockwise triangles:
/// ```text
///   d ---- c     Fixed (and even cells of Alternating): a-b-c, a-c-d
///   |      |     odd cells (i + j odd) of Alternating:  a-b-d, b-c-d
///   a ---- b     (a = (i,j), b = (i+1,j), c = (i+1,j+1), d = (i,j+1))
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Diagonal {
    /// Every cell along `(i,j)–(i+1,j+1)`.
    Fixed,
    /// Cells with `i + j` even as `Fixed`, odd ones along the other diagonal.
    #[default]
    Alternating,
}

/// A `res × res` grid triangulation of the unit square.
pub(crate) struct Grid {
    /// Cells per side.
    pub res: usize,
    /// Parameter `(x, y)` in `[0,1]²` of each vertex.
    pub param: Vec<[f64; 2]>,
    /// Counter-clockwise triangles.
    pub tris: Vec<[u32; 3]>,
}

impl Grid {
    /// The grid with `res >= 1` cells per side.
    pub(crate) fn new(res: usize, diagonal: Diagonal) -> Self {
        let res = res.max(1);
        let id = |i: usize, j: usize| (j * (res + 1) + i) as u32;
        let mut param = Vec::with_capacity((res + 1) * (res + 1));
        for j in 0..=res {
            for i in 0..=res {
                param.push([i as f64 / res as f64, j as f64 / res as f64]);
            }
        }
        let mut tris = Vec::with_capacity(2 * res * res);
        for j in 0..res {
            for i in 0..res {
                let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
                if diagonal == Diagonal::Fixed || (i + j) % 2 == 0 {
                    tris.extend([[a, b, c], [a, c, d]]);
                } else {
                    tris.extend([[a, b, d], [b, c, d]]);
                }
            }
        }
        Grid { res, param, tris }
    }

    /// Whether vertex `v` is on the boundary of the square.
    pub(crate) fn on_boundary(&self, v: usize) -> bool {
        let (i, j) = (v % (self.res + 1), v / (self.res + 1));
        i == 0 || j == 0 || i == self.res || j == self.res
    }

    /// Planar positions `(x, y, 0)`.
    pub(crate) fn positions(&self) -> Vec<[f64; 3]> {
        self.param.iter().map(|p| [p[0], p[1], 0.0]).collect()
    }
}

/// A map with one chart: every corner of a vertex gets the vertex's value.
pub(crate) fn single_chart(
    positions: Vec<[f64; 3]>,
    tris: &[[u32; 3]],
    value: &[[f64; 2]],
) -> TriMap {
    TriMap {
        positions,
        simplices: tris.to_vec(),
        coords: tris.iter().map(|t| t.map(|v| value[v as usize])).collect(),
    }
}

/// The C¹ bump `(1 − s²)²` for `s < 1`, else 0.
pub(crate) fn bump(s: f64) -> f64 {
    if s < 1.0 {
        (1.0 - s * s) * (1.0 - s * s)
    } else {
        0.0
    }
}

/// A fold of the plane: `p + e_x · strength·radius·bump(|p − centre| / radius)`.
/// `∂x/∂x = 1 − 4·strength·s(1 − s²)·cos θ`, negative where
/// `4·strength·s(1−s²)·cos θ > 1`: a region inside the disk exists when
/// `strength > 3√3/8 ≈ 0.65`. Identity outside the disk.
pub(crate) fn fold(p: [f64; 2], centre: [f64; 2], radius: f64, strength: f64) -> [f64; 2] {
    let s = ((p[0] - centre[0]).hypot(p[1] - centre[1])) / radius;
    [p[0] + strength * radius * bump(s), p[1]]
}

/// Rounds `x` to a multiple of 2⁻³²: adding integers or applying a grid
/// rotation to snapped values (of magnitude < 2²⁰) is then exact, so maps
/// built from snapped per-vertex values are exactly GP.
pub(crate) fn snap(x: [f64; 2]) -> [f64; 2] {
    const S: f64 = 4_294_967_296.0;
    x.map(|c| (c * S).round() / S)
}

/// `R·p + T` with `T` the integer translation that best maps `from` to `to`
/// (`to ≈ R·from + T`).
pub(crate) fn carry(r: &dualex_map::Rot2, p: [f64; 2], from: [f64; 2], to: [f64; 2]) -> [f64; 2] {
    let rf = r.apply(&from);
    let t = [(to[0] - rf[0]).round(), (to[1] - rf[1]).round()];
    let rp = r.apply(&p);
    [rp[0] + t[0], rp[1] + t[1]]
}

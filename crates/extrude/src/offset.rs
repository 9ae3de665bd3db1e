//! Offset directions of a surface's vertices: along which unit vector each
//! vertex moves to make the slab's upper levels.
//!
//! Input: the surface's points and triangles. Output: one unit vector per
//! vertex, plus how many were *turned* away from the area-weighted normal
//! and how many are *folded* (no direction sees all incident triangles from
//! above).
//!
//! The area-weighted vertex normal `n` is kept where it makes an angle of
//! less than `acos(MIN_COS)` with the normal of every incident triangle. At
//! a sharp saddle or a crease it can point *below* an incident triangle
//! (`n · n_t ≤ 0`): that triangle's prism is then inverted whatever the
//! thickness, its walls cross its neighbours', and TetGen aborts (measured:
//! 30 such vertices on Directional's knight, 2 on the horse, worst cosine
//! −0.92 and −0.22; none on fandisk, spherer, lilium, whose worst is +0.19).
//! There the direction is the axis of the narrowest cone around the
//! incident unit normals `u_i`: `d = x / |x|` with `x` the point of their
//! convex hull nearest the origin (Gilbert's algorithm), which maximises
//! `min_i d · u_i`. When the origin lies in the hull (the surface folds
//! back on itself at the vertex, as on the ducks' and the dragon's
//! self-intersecting spots), no direction works: the area-weighted normal is
//! kept and the vertex counted as folded.
//!
//! Invariant: a turned vertex's least cosine to its incident triangles is
//! larger than the area-weighted normal's was.

use crate::slab::cross;
use dualex_map::error::Extrusion;
use dualex_map::{ElementKind, InputError};

/// Least cosine between the area-weighted normal and an incident
/// triangle's normal below which the direction is turned (module docs).
pub const MIN_COS: f64 = 0.1;

/// Directions and counts (module docs).
#[derive(Clone, Debug, Default)]
pub struct Offsets {
    /// Unit direction per vertex.
    pub dirs: Vec<[f64; 3]>,
    /// Vertices whose direction was turned from the area-weighted normal.
    pub turned: usize,
    /// Vertices where no direction sees every incident triangle from above.
    pub folded: usize,
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn unit(a: [f64; 3]) -> Option<[f64; 3]> {
    let l = dot(a, a).sqrt();
    (l > 0.0 && l.is_finite()).then(|| [a[0] / l, a[1] / l, a[2] / l])
}

/// Offset directions of a surface (module docs); an error names a vertex
/// whose area-weighted normal vanishes.
pub fn surface_offsets(p: &[[f64; 3]], tris: &[[u32; 3]]) -> Result<Offsets, InputError> {
    let fnorm: Vec<[f64; 3]> = tris
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| p[v as usize]);
            cross(sub(b, a), sub(c, a))
        })
        .collect();
    let mut n = vec![[0.0; 3]; p.len()];
    for (t, f) in tris.iter().zip(&fnorm) {
        for &v in t {
            for k in 0..3 {
                n[v as usize][k] += f[k];
            }
        }
    }
    let mut dirs = Vec::with_capacity(p.len());
    for (v, x) in n.iter().enumerate() {
        dirs.push(unit(*x).ok_or_else(|| {
            InputError::new(ElementKind::Vertex.at(v).error(Extrusion::VanishingNormal))
        })?);
    }
    let unit_normals: Vec<Option<[f64; 3]>> = fnorm.iter().map(|f| unit(*f)).collect();
    let mut least = vec![f64::INFINITY; p.len()];
    for (t, u) in tris.iter().zip(&unit_normals) {
        for &v in t {
            let c = u.map_or(f64::INFINITY, |u| dot(dirs[v as usize], u));
            least[v as usize] = least[v as usize].min(c);
        }
    }
    // the incident unit normals of the vertices to turn, by vertex
    let mut star: Vec<(u32, [f64; 3])> = tris
        .iter()
        .zip(&unit_normals)
        .flat_map(|(t, u)| t.iter().filter_map(move |&v| u.map(|u| (v, u))))
        .filter(|&(v, _)| least[v as usize] < MIN_COS)
        .collect();
    star.sort_by_key(|s| s.0);
    let (mut turned, mut folded) = (0, 0);
    for group in star.chunk_by(|a, b| a.0 == b.0) {
        let v = group[0].0 as usize;
        let us: Vec<[f64; 3]> = group.iter().map(|s| s.1).collect();
        match cone_axis(&us) {
            Some((d, c)) if c > least[v] => {
                dirs[v] = d;
                turned += 1;
            }
            Some(_) => {}
            None => folded += 1,
        }
    }
    Ok(Offsets {
        dirs,
        turned,
        folded,
    })
}

/// The axis `d` maximising `min_i d · u_i` over unit vectors `us` and that
/// least cosine, or `None` when it is not positive (module docs).
pub fn cone_axis(us: &[[f64; 3]]) -> Option<([f64; 3], f64)> {
    let mean = us
        .iter()
        .fold([0.0; 3], |a, u| [a[0] + u[0], a[1] + u[1], a[2] + u[2]]);
    let k = 1.0 / us.len().max(1) as f64;
    let mut x = [mean[0] * k, mean[1] * k, mean[2] * k];
    for _ in 0..1000 {
        let (i, xu) =
            us.iter()
                .map(|u| dot(x, *u))
                .enumerate()
                .fold(
                    (0, f64::INFINITY),
                    |b, (i, c)| if c < b.1 { (i, c) } else { b },
                );
        let xx = dot(x, x);
        if xx - xu <= 1e-15 * xx.max(1e-300) {
            break;
        }
        let d = sub(us[i], x);
        let t = (-dot(x, d) / dot(d, d)).clamp(0.0, 1.0);
        x = [x[0] + t * d[0], x[1] + t * d[1], x[2] + t * d[2]];
        if dot(x, x) < 1e-24 {
            return None;
        }
    }
    let d = unit(x)?;
    let c = us.iter().map(|u| dot(d, *u)).fold(f64::INFINITY, f64::min);
    (c > 0.0).then_some((d, c))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cone_axis_of_a_few_normals() {
        let s = 0.5f64.sqrt();
        // two normals 90° apart: the bisector, cos 45°
        let (d, c) = cone_axis(&[[1., 0., 0.], [0., 1., 0.]]).expect("a cone");
        assert!((d[0] - s).abs() < 1e-9 && (d[1] - s).abs() < 1e-9 && (c - s).abs() < 1e-9);
        // a mean dragged by many normals on one side still sees the lone one
        let mut us = vec![[s, s, 0.]; 8];
        us.push([0., -s, s]);
        let (d, c) = cone_axis(&us).expect("a cone");
        assert!(c > 0.4 && us.iter().all(|u| dot(d, *u) >= c - 1e-12));
        // opposite normals: no direction
        assert!(cone_axis(&[[0., 0., 1.], [0., 0., -1.]]).is_none());
        assert!(cone_axis(&[[1., 0., 0.], [-s, s, 0.], [-s, -s, 0.]]).is_none());
    }

    /// A vertex at the bottom of a valley whose far side is much larger:
    /// the area-weighted normal is nearly parallel to the small steep side
    /// (cosine 0.06), the turned one sees both sides at ~47°.
    #[test]
    fn a_lopsided_valley_is_turned() {
        let p = [
            [0., 0., 0.],
            [0., 1., 0.],
            [-0.01, 0., 1.],
            [-0.01, 1., 1.],
            [10., 0., 0.5],
            [10., 1., 0.5],
        ];
        let tris = [[0, 1, 3], [0, 3, 2], [0, 4, 5], [0, 5, 1]];
        let o = surface_offsets(&p, &tris).expect("normals");
        // both valley-bottom vertices, 0 and 1
        assert_eq!((o.turned, o.folded), (2, 0), "{:?}", o.dirs[0]);
        let steep = unit(cross(sub(p[1], p[0]), sub(p[3], p[0]))).expect("normal");
        assert!(dot(o.dirs[0], steep) > 0.6, "{:?}", o.dirs[0]);
    }
}

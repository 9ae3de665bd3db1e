//! The fixed orthographic view of a mesh in 3-space.
//!
//! Input: vertex positions. Output: a [`View`], a rotation taking model
//! coordinates to view coordinates `(x right, y up, z towards the eye)`.
//!
//! - A mesh flat along a coordinate axis (extent ≤ 1e-9 of its diagonal) is
//!   seen straight along that axis, from its positive side, with the other
//!   two axes in cyclic order: a planar mesh in `z = 0` is drawn in its
//!   `(x, y)` plane, counter-clockwise quads staying counter-clockwise.
//! - Any other mesh is seen from the front-right and above (y up, as in
//!   most OBJ files): yaw −30° about y, then pitch 20° about x.

/// An orthographic view: `view(p) = rot · (p − centre)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    rot: [[f64; 3]; 3],
    centre: [f64; 3],
    /// Whether the mesh is flat (seen along one axis).
    pub planar: bool,
}

impl View {
    /// The view of points with these positions (see the module docs).
    pub fn fixed(positions: &[[f64; 3]]) -> View {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in positions {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if positions.is_empty() {
            (lo, hi) = ([0.0; 3], [0.0; 3]);
        }
        let centre = [0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k]));
        let ext = [0, 1, 2].map(|k| hi[k] - lo[k]);
        let diag = ext.iter().map(|e| e * e).sum::<f64>().sqrt();
        let flat = (0..3).rev().find(|&k| ext[k] <= 1e-9 * diag);
        let rot = match flat {
            Some(k) => {
                let mut r = [[0.0; 3]; 3];
                r[0][(k + 1) % 3] = 1.0;
                r[1][(k + 2) % 3] = 1.0;
                r[2][k] = 1.0;
                r
            }
            None => {
                let (yaw, pitch) = ((-30f64).to_radians(), 20f64.to_radians());
                let (sy, cy) = yaw.sin_cos();
                let (sp, cp) = pitch.sin_cos();
                let ry = [[cy, 0.0, sy], [0.0, 1.0, 0.0], [-sy, 0.0, cy]];
                let rx = [[1.0, 0.0, 0.0], [0.0, cp, -sp], [0.0, sp, cp]];
                mat_mul(&rx, &ry)
            }
        };
        View {
            rot,
            centre,
            planar: flat.is_some(),
        }
    }

    /// View coordinates of `p`.
    pub fn apply(&self, p: &[f64; 3]) -> [f64; 3] {
        let d = [0, 1, 2].map(|k| p[k] - self.centre[k]);
        self.rot
            .map(|row| row[0] * d[0] + row[1] * d[1] + row[2] * d[2])
    }
}

fn mat_mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

/// Unit normal of a polygon by Newell's method (zero for a degenerate one).
pub fn newell_normal(p: &[[f64; 3]]) -> [f64; 3] {
    let mut n = [0.0; 3];
    for (i, a) in p.iter().enumerate() {
        let b = &p[(i + 1) % p.len()];
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    let len = n.iter().map(|x| x * x).sum::<f64>().sqrt();
    if len > 0.0 {
        n.map(|x| x / len)
    } else {
        [0.0; 3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn planar_xy_mesh_is_seen_from_above() {
        let v = View::fixed(&[[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 4.0, 0.0]]);
        assert!(v.planar);
        assert_eq!(v.apply(&[2.0, 4.0, 0.0]), [1.0, 2.0, 0.0]);
    }

    #[test]
    fn planar_yz_mesh_keeps_cyclic_axes() {
        let v = View::fixed(&[[3.0, 0.0, 0.0], [3.0, 2.0, 0.0], [3.0, 0.0, 2.0]]);
        assert!(v.planar);
        // x is the view axis: screen (y, z)
        assert_eq!(v.apply(&[3.0, 2.0, 0.0]), [1.0, -1.0, 0.0]);
    }

    #[test]
    fn view_rotation_is_orthonormal() {
        let v = View::fixed(&[[0.0; 3], [1.0, 1.0, 1.0]]);
        assert!(!v.planar);
        for i in 0..3 {
            for j in 0..3 {
                let dot: f64 = (0..3).map(|k| v.rot[i][k] * v.rot[j][k]).sum();
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((dot - want).abs() < 1e-12, "{i} {j} {dot}");
            }
        }
        // y stays up-ish: the model's +y has a positive screen y
        let up = v.apply(&[0.5, 1.5, 0.5]);
        assert!(up[1] > 0.9);
    }

    #[test]
    fn newell_of_ccw_square_points_up() {
        let sq = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ];
        assert_eq!(newell_normal(&sq), [0.0, 0.0, 1.0]);
        assert_eq!(newell_normal(&[[1.0; 3]; 4]), [0.0; 3]);
    }
}

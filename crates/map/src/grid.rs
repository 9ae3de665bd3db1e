//! Closeness to the integer grid, shared by the sanitization of both
//! dimensions: values on an iso, 2D segments through a grid point.
//! Coordinates are local (see [`crate::local`]), so [`EPS`] is absolute.

/// Distance below which a value counts as "on" an iso.
pub const EPS: f64 = 1e-9;

/// Whether `x` is within [`EPS`] of an integer.
#[inline]
pub fn near_int(x: f64) -> bool {
    (x - x.round()).abs() < EPS
}

/// Distance between two points of the plane.
pub fn dist2d(a: &[f64; 2], b: &[f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Distance from `p` to the segment `a`–`b`.
pub fn point_segment_dist(p: &[f64; 2], a: &[f64; 2], b: &[f64; 2]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let l2 = d[0] * d[0] + d[1] * d[1];
    let t = if l2 == 0.0 {
        0.0
    } else {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / l2).clamp(0.0, 1.0)
    };
    dist2d(&[a[0] + t * d[0], a[1] + t * d[1]], p)
}

/// An integer point within [`EPS`] of the segment `a`–`b`, if any: for each
/// axis, the integers in the segment's range on it, each with the nearest
/// integer on the other axis at that place (terminates: the loop runs over
/// the integers of a bounded range; callers bound map sizes up front).
pub fn grid_point_near_segment(a: &[f64; 2], b: &[f64; 2]) -> Option<[f64; 2]> {
    for axis in 0..2 {
        let o = 1 - axis;
        let (lo, hi) = (a[axis].min(b[axis]), a[axis].max(b[axis]));
        let len = b[axis] - a[axis];
        let mut i = (lo - EPS).ceil();
        while i <= hi + EPS {
            let t = if len == 0.0 {
                0.0
            } else {
                ((i - a[axis]) / len).clamp(0.0, 1.0)
            };
            let mut g = [0.0; 2];
            g[axis] = i;
            g[o] = (a[o] + t * (b[o] - a[o])).round();
            if point_segment_dist(&g, a, b) < EPS {
                return Some(g);
            }
            i += 1.0;
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_through_grid_points() {
        assert!(grid_point_near_segment(&[0.5, 0.5], &[1.5, 1.5]).is_some());
        assert!(grid_point_near_segment(&[0.5, 0.6], &[1.5, 1.7]).is_none());
        assert!(grid_point_near_segment(&[2.0, 0.3], &[2.0, 0.3]).is_none());
        let g = grid_point_near_segment(&[3.0, -1.5], &[3.0, 1.5]).expect("on the segment");
        assert!(g[0] == 3.0 && [-1.0, 0.0, 1.0].contains(&g[1]), "{g:?}");
        assert!(grid_point_near_segment(&[4.0, 4.0], &[4.0, 4.0]).is_some());
        assert!(near_int(2.0 + 0.5 * EPS) && !near_int(2.0 + 2.0 * EPS));
    }
}

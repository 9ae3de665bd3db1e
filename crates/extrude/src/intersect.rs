//! A cheap self-intersection check of the base surface, run before TetGen:
//! TetGen 1.5 aborts on any PLC whose triangles cross, and no slab over a
//! surface that crosses itself is free of crossings, so such a surface goes
//! straight to the built-in prism split (saving TetGen's aborted run and
//! its `-d` check: 0.5 s + 0.3 s on Directional's dragon).
//!
//! Input: points and triangles. Output: the pairs of triangles that cross
//! (ascending), found through a uniform grid of cell size = the mean edge
//! length over the triangles' bounding boxes.
//!
//! Two triangles *cross* when a side of one passes strictly through the
//! interior of the other (every orientation test strictly signed), sides
//! next to a shared vertex excepted. Touching, coplanar overlaps and
//! triangles sharing a side are not reported: the check is conservative
//! (floating-point orientations, no exact predicates); a crossing it misses
//! is still caught after TetGen's refusal by TetGen's own `-d`
//! ([`crate::chain`]). Measured: it finds the crossings TetGen's `-d`
//! reports on QEx's ducks and Directional's dragon, and none on fandisk,
//! spherer, lilium, knight and horse.

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// Sign of the volume of `(a, b, c, d)`: positive when `d` is above the
/// plane of `a b c` (counter-clockwise seen from `d`'s side).
fn orient(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> f64 {
    let (u, v, w) = (sub(b, a), sub(c, a), sub(d, a));
    u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
        + u[2] * (v[0] * w[1] - v[1] * w[0])
}

/// Whether segment `p q` passes strictly through the interior of triangle
/// `t`.
fn segment_crosses(p: [f64; 3], q: [f64; 3], t: [[f64; 3]; 3]) -> bool {
    let (sp, sq) = (orient(t[0], t[1], t[2], p), orient(t[0], t[1], t[2], q));
    let through_plane = sp * sq < 0.0;
    if !through_plane {
        return false;
    }
    let s: [f64; 3] = std::array::from_fn(|k| orient(p, q, t[k], t[(k + 1) % 3]));
    (s[0] > 0.0 && s[1] > 0.0 && s[2] > 0.0) || (s[0] < 0.0 && s[1] < 0.0 && s[2] < 0.0)
}

/// Whether triangles `a` and `b` (vertex ids into `p`) cross (module docs).
pub fn triangles_cross(p: &[[f64; 3]], a: [u32; 3], b: [u32; 3]) -> bool {
    let shared = a.iter().filter(|v| b.contains(v)).count();
    if shared >= 2 {
        return false;
    }
    let pts = |t: [u32; 3]| t.map(|v| p[v as usize]);
    let (ta, tb) = (pts(a), pts(b));
    // sides of `x` that do not touch a shared vertex, against `y`
    let sides_cross = |x: [u32; 3], tx: [[f64; 3]; 3], ty: [[f64; 3]; 3], other: [u32; 3]| {
        (0..3).any(|k| {
            let (i, j) = (k, (k + 1) % 3);
            !other.contains(&x[i]) && !other.contains(&x[j]) && segment_crosses(tx[i], tx[j], ty)
        })
    };
    sides_cross(a, ta, tb, b) || sides_cross(b, tb, ta, a)
}

/// The pairs `(i, j)`, `i < j`, of triangles that cross (module docs).
pub fn crossing_pairs(p: &[[f64; 3]], tris: &[[u32; 3]]) -> Vec<(u32, u32)> {
    if tris.is_empty() {
        return Vec::new();
    }
    let len = |a: [f64; 3], b: [f64; 3]| {
        let d = sub(a, b);
        (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
    };
    let mut mean = 0.0;
    for t in tris {
        let [a, b, c] = t.map(|v| p[v as usize]);
        mean += len(a, b) + len(b, c) + len(c, a);
    }
    let cell = mean / (3 * tris.len()) as f64;
    if !(cell > 0.0 && cell.is_finite()) {
        return Vec::new();
    }
    // cells per axis counted from the lowest corner, packed 21 bits each
    let lo_all: [f64; 3] =
        std::array::from_fn(|k| p.iter().map(|q| q[k]).fold(f64::INFINITY, f64::min));
    let key = |x: f64, k: usize| ((x - lo_all[k]) / cell).floor().clamp(0.0, 2e6) as u64;
    let mut entries: Vec<(u64, u32)> = Vec::with_capacity(4 * tris.len());
    // per triangle: bounding box and its lowest cell
    let mut boxes = Vec::with_capacity(tris.len());
    for (i, t) in tris.iter().enumerate() {
        let q = t.map(|v| p[v as usize]);
        let bl: [f64; 3] = std::array::from_fn(|k| q[0][k].min(q[1][k]).min(q[2][k]));
        let bh: [f64; 3] = std::array::from_fn(|k| q[0][k].max(q[1][k]).max(q[2][k]));
        let lo: [u64; 3] = std::array::from_fn(|k| key(bl[k], k));
        let hi: [u64; 3] = std::array::from_fn(|k| key(bh[k], k));
        boxes.push((bl, bh, lo));
        // a sliver across many cells is rare; cap the cells per triangle
        if (0..3).map(|k| hi[k] - lo[k] + 1).product::<u64>() > 4096 {
            continue;
        }
        for x in lo[0]..=hi[0] {
            for y in lo[1]..=hi[1] {
                for z in lo[2]..=hi[2] {
                    entries.push(((x << 42) | (y << 21) | z, i as u32));
                }
            }
        }
    }
    entries.sort_unstable();
    let mut out: Vec<(u32, u32)> = Vec::new();
    for members in entries.chunk_by(|a, b| a.0 == b.0) {
        let c = members[0].0;
        let cell_of = |l: [u64; 3]| (l[0] << 42) | (l[1] << 21) | l[2];
        for (k, &(_, i)) in members.iter().enumerate() {
            let (li, hi, ci) = boxes[i as usize];
            for &(_, j) in &members[k + 1..] {
                let (lj, hj, cj) = boxes[j as usize];
                // each overlapping pair once: in the lowest cell of the overlap
                let overlap = (0..3).all(|d| li[d] <= hj[d] && lj[d] <= hi[d]);
                let first: [u64; 3] = std::array::from_fn(|d| ci[d].max(cj[d]));
                if overlap
                    && cell_of(first) == c
                    && triangles_cross(p, tris[i as usize], tris[j as usize])
                {
                    out.push((i.min(j), i.max(j)));
                }
            }
        }
    }
    out.sort_unstable();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every pair of a few configurations: crossing through the interior,
    /// sharing a vertex with the opposite side crossing, touching only,
    /// sharing a side, far apart.
    #[test]
    fn pairs_of_triangles() {
        let p = [
            [0., 0., 0.],    // 0
            [2., 0., 0.],    // 1
            [0., 2., 0.],    // 2
            [0.5, 0.5, -1.], // 3
            [0.5, 0.5, 1.],  // 4
            [1.5, 1.5, 0.],  // 5
            [0., 0., 5.],    // 6
            [1., 0., 5.],    // 7
            [0., 1., 5.],    // 8
            [1., -1., 1.],   // 9
        ];
        // a side 3-4 piercing 0 1 2
        assert!(triangles_cross(&p, [0, 1, 2], [3, 4, 9]));
        // sharing vertex 0, its opposite side 4-3 piercing the other
        let q = [
            [0., 0., 0.],
            [2., 0., 0.],
            [0., 2., 0.],
            [0.5, 0.5, -1.],
            [0.5, 0.5, 1.],
        ];
        assert!(triangles_cross(&q, [0, 1, 2], [0, 3, 4]));
        // sharing a side, or a vertex only, or far apart: no
        assert!(!triangles_cross(&p, [0, 1, 2], [1, 5, 2]));
        assert!(!triangles_cross(&p, [0, 1, 2], [0, 7, 8]));
        assert!(!triangles_cross(&p, [0, 1, 2], [6, 7, 8]));
        assert_eq!(
            crossing_pairs(&p, &[[0, 1, 2], [6, 7, 8], [3, 4, 9]]),
            vec![(0, 2)]
        );
    }
}

//! Element quality: the scaled Jacobian of quads and hexes (verdict's
//! definitions), and its summary (inverted, degenerate, min, 5th
//! percentile, median).
//!
//! - Quad corner `i` (cell order, counter-clockwise from the front):
//!   `(e1 × e2)·n / (|e1| |e2|)` with `e1 = p[i+1] − p[i]`,
//!   `e2 = p[i−1] − p[i]` and `n` the unit normal of the reference surface
//!   under the quad (see [`crate::Reference`]).
//! - Hex corner `i` (VTK order): the triple product of its 3 edges, in the
//!   right-handed order of [`HEX_CORNER_EDGES`], over the product of their
//!   lengths.
//!
//! An element's value is the least of its corners'. It is **inverted**
//! when that value is ≤ 0, **degenerate** (a subset of inverted) when a
//! corner has an edge of length 0 (value 0 there) or a value within
//! [`DEGENERATE`] of 0. Values lie in [−1, 1]; a unit square or cube has 1.

/// A corner whose |scaled Jacobian| is at most this is degenerate.
pub const DEGENERATE: f64 = 1e-9;

/// Per hex corner (VTK order), its 3 neighbours in right-handed order: the
/// corner tet `(c, a, b, d)` of a hex of positive volume has positive
/// volume.
pub const HEX_CORNER_EDGES: [[usize; 4]; 8] = [
    [0, 1, 3, 4],
    [1, 2, 0, 5],
    [2, 3, 1, 6],
    [3, 0, 2, 7],
    [4, 7, 5, 0],
    [5, 4, 6, 1],
    [6, 5, 7, 2],
    [7, 6, 4, 3],
];

/// Per quad corner, the corner triangle `(c, next, previous)`.
pub const QUAD_CORNER_EDGES: [[usize; 3]; 4] = [[0, 1, 3], [1, 2, 0], [2, 3, 1], [3, 0, 2]];

/// `a − b`.
pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a · b`.
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a × b`.
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `|a|`.
pub fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// `a / |a|`, or zero.
pub fn unit(a: [f64; 3]) -> [f64; 3] {
    let l = norm(a);
    if l > 0.0 {
        a.map(|x| x / l)
    } else {
        [0.0; 3]
    }
}

/// The scaled Jacobian of a quad's corners `p` (cell order) against the
/// unit normal `n`: the least over its 4 corners.
pub fn quad_scaled_jacobian(p: &[[f64; 3]; 4], n: [f64; 3]) -> f64 {
    let mut min = f64::INFINITY;
    for [c, a, b] in QUAD_CORNER_EDGES {
        let e1 = sub(p[a], p[c]);
        let e2 = sub(p[b], p[c]);
        let l = norm(e1) * norm(e2);
        let v = if l > 0.0 {
            dot(cross(e1, e2), n) / l
        } else {
            0.0
        };
        min = min.min(v);
    }
    min
}

/// The scaled Jacobian of a hex's corners `p` (VTK order): the least over
/// its 8 corners.
pub fn hex_scaled_jacobian(p: &[[f64; 3]; 8]) -> f64 {
    let mut min = f64::INFINITY;
    for [c, a, b, d] in HEX_CORNER_EDGES {
        let e1 = sub(p[a], p[c]);
        let e2 = sub(p[b], p[c]);
        let e3 = sub(p[d], p[c]);
        let l = norm(e1) * norm(e2) * norm(e3);
        let v = if l > 0.0 {
            dot(cross(e1, e2), e3) / l
        } else {
            0.0
        };
        min = min.min(v);
    }
    min
}

/// The corners of cell `c` of a mesh.
pub fn corners<const K: usize>(positions: &[[f64; 3]], cell: &[u32; K]) -> [[f64; 3]; K] {
    cell.map(|v| positions[v as usize])
}

/// The summary of a measure over a mesh's elements.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Summary {
    /// Elements measured.
    pub elements: usize,
    /// Elements whose least corner value is ≤ 0.
    pub inverted: usize,
    /// Elements whose least value is within [`DEGENERATE`] of 0 (a flat
    /// corner or an edge of length 0): the flat ones among the inverted,
    /// and flat ones just above 0, which `inverted` does not count.
    pub degenerate: usize,
    /// The least value (1 for an empty mesh).
    pub min: f64,
    /// The 5th percentile (the value below which 5 % of the elements lie).
    pub p5: f64,
    /// The median.
    pub median: f64,
}

impl Summary {
    /// The summary of per-element values.
    pub fn of(values: &[f64]) -> Summary {
        if values.is_empty() {
            return Summary {
                min: 1.0,
                p5: 1.0,
                median: 1.0,
                ..Default::default()
            };
        }
        // the order statistics by selection (no sort): under the total
        // order an order statistic is one float, bit for bit
        let n = values.len();
        let at = |q: f64| ((q * (n - 1) as f64).round() as usize).min(n - 1);
        let (i5, i50) = (at(0.05), at(0.5));
        let mut s = values.to_vec();
        let median = *s.select_nth_unstable_by(i50, f64::total_cmp).1;
        // the `i50` least values lie before the median now
        let p5 = if i5 < i50 {
            *s[..i50].select_nth_unstable_by(i5, f64::total_cmp).1
        } else {
            median
        };
        Summary {
            elements: n,
            inverted: values.iter().filter(|&&v| v <= 0.0).count(),
            degenerate: values.iter().filter(|&&v| v.abs() <= DEGENERATE).count(),
            min: values.iter().copied().min_by(f64::total_cmp).unwrap_or(1.0),
            p5,
            median,
        }
    }

    /// As JSON: `{elements, inverted, degenerate, min, p5, median}`.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "elements": self.elements,
            "inverted": self.inverted,
            "degenerate": self.degenerate,
            "min": self.min,
            "p5": self.p5,
            "median": self.median,
        })
    }
}

/// Per-quad scaled Jacobians, `normals[q]` the unit normal under quad `q`.
pub fn quad_values(positions: &[[f64; 3]], quads: &[[u32; 4]], normals: &[[f64; 3]]) -> Vec<f64> {
    use rayon::prelude::*;
    quads
        .par_iter()
        .zip(normals.par_iter())
        .map(|(q, &n)| quad_scaled_jacobian(&corners(positions, q), n))
        .collect()
}

/// Per-hex scaled Jacobians.
pub fn hex_values(positions: &[[f64; 3]], hexes: &[[u32; 8]]) -> Vec<f64> {
    use rayon::prelude::*;
    hexes
        .par_iter()
        .map(|h| hex_scaled_jacobian(&corners(positions, h)))
        .collect()
}

#[cfg(test)]
mod tests {
    /// [`Summary::of`] as first written: the values sorted.
    fn summary_by_sort(values: &[f64]) -> Summary {
        let mut s = values.to_vec();
        s.sort_by(f64::total_cmp);
        let at = |q: f64| s[((q * (s.len() - 1) as f64).round() as usize).min(s.len() - 1)];
        Summary {
            elements: s.len(),
            inverted: s.iter().filter(|&&v| v <= 0.0).count(),
            degenerate: s.iter().filter(|&&v| v.abs() <= DEGENERATE).count(),
            min: s[0],
            p5: at(0.05),
            median: at(0.5),
        }
    }

    #[test]
    fn summary_by_selection_as_by_sort() {
        let mut rng = dualex_util::rng::SplitMix::new(5);
        let special = [0.0, -0.0, 1.0, -1.0, DEGENERATE, f64::NAN, -f64::NAN, 0.5];
        for n in [1, 2, 3, 19, 20, 21, 40, 101, 1000] {
            for round in 0..20 {
                let values: Vec<f64> = (0..n)
                    .map(|_| match rng.below(4) {
                        0 if round % 2 == 0 => special[rng.below(special.len())],
                        1 => (rng.unit() * 8.0).round() / 4.0 - 1.0,
                        _ => 2.0 * rng.unit() - 1.0,
                    })
                    .collect();
                let (got, want) = (Summary::of(&values), summary_by_sort(&values));
                let bits = |s: &Summary| [s.min, s.p5, s.median].map(f64::to_bits);
                assert_eq!(bits(&got), bits(&want), "{values:?}");
                assert_eq!(
                    (got.elements, got.inverted, got.degenerate),
                    (want.elements, want.inverted, want.degenerate)
                );
            }
        }
    }

    use super::*;

    fn unit_cube() -> [[f64; 3]; 8] {
        let b = [[0., 0.], [1., 0.], [1., 1.], [0., 1.]];
        std::array::from_fn(|i| [b[i % 4][0], b[i % 4][1], (i / 4) as f64])
    }

    #[test]
    fn unit_elements_measure_one() {
        let sq = [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]];
        assert!((quad_scaled_jacobian(&sq, [0., 0., 1.]) - 1.0).abs() < 1e-15);
        assert!((quad_scaled_jacobian(&sq, [0., 0., -1.]) + 1.0).abs() < 1e-15);
        assert!((hex_scaled_jacobian(&unit_cube()) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn a_moved_corner_inverts() {
        // corner 2 pulled past the diagonal 1-3: corner 2 reflex
        let q = [[0., 0., 0.], [1., 0., 0.], [0.2, 0.2, 0.], [0., 1., 0.]];
        assert!(quad_scaled_jacobian(&q, [0., 0., 1.]) < 0.0);
        let mut h = unit_cube();
        h[6] = [0.2, 0.2, 0.2];
        assert!(hex_scaled_jacobian(&h) < 0.0);
        // a 45° shear: sin 45° at the sheared corners
        let mut s = unit_cube();
        for p in &mut s[4..] {
            p[0] += 1.0;
        }
        let v = hex_scaled_jacobian(&s);
        assert!((v - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-12, "{v}");
    }

    #[test]
    fn a_zero_edge_is_degenerate() {
        let mut h = unit_cube();
        h[1] = h[0];
        let v = hex_scaled_jacobian(&h);
        assert_eq!(v, 0.0);
        let s = Summary::of(&[v, 1.0, 0.5]);
        assert_eq!(
            (s.inverted, s.degenerate, s.min, s.median),
            (1, 1, 0.0, 0.5)
        );
    }

    #[test]
    fn percentiles_of_a_ramp() {
        let v: Vec<f64> = (0..=100).map(|i| i as f64 / 100.0).collect();
        let s = Summary::of(&v);
        assert_eq!((s.min, s.p5, s.median), (0.0, 0.05, 0.5));
        assert_eq!(Summary::of(&[]).elements, 0);
    }
}

//! The per-dimension predicates on one simplex image: the only code of the
//! nodes, the traced sides and the diagonal walk that differs between
//! D = 2 and D = 3. As in fidget, the dimension is a const generic (here
//! the pair `N = D + 1` corners, `D` map axes, as in
//! [`crate::local::LocalMap`]) and the per-dimension code sits in one
//! `impl` block per dimension: of the trait [`Simplex`] on the marker
//! [`Dim<N, D>`]. The generic steps ([`crate::nodes`], [`crate::trace`],
//! [`crate::diagonal`]) ask for `Dim<N, D>: Simplex<N, D>`.
//!
//! Numbering (as in `dualex_map::mesh`): facet `f` of a simplex is the one
//! opposite corner `f`; its corners are `f+1, …, f+D` (mod `N`).
//!
//! - **barycentric weights** ([`Simplex::bary_weights`]): `w[c]` is the
//!   signed measure of the simplex with corner `c` replaced by `q`
//!   (`Σ w = det`); each dimension keeps its own formula (the float
//!   operations, hence the outputs, depend on it);
//! - **pierced facets** ([`Simplex::pierced`]) of an axis line (one moving
//!   axis, the others fixed at integers): 2D, the edges whose endpoints lie
//!   strictly on both sides of the iso (a crossing exactly at a corner is
//!   flagged); 3D, the faces whose projection along the moving axis holds
//!   the line strictly inside (three 2D orientations of one strict sign),
//!   the moving coordinate there interpolated barycentrically. Which
//!   facets ([`Simplex::crossed`], a bit set) and where
//!   ([`Simplex::crossing_at`], one facet) are separate: a walk step needs
//!   the points only in a simplex holding nodes.
//!
//! One step of the diagonal walk, the third thing that differs, has its
//! `impl` blocks in [`crate::diagonal`] ([`crate::diagonal::DiagonalStep`]).

/// The dimension marker: `N` corners per simplex, `D` map axes.
#[derive(Clone, Copy, Debug, Default)]
pub struct Dim<const N: usize, const D: usize>;

/// An axis-parallel line of the dual grid in one simplex's chart: the
/// coordinate `axis` moves, the others are fixed at integers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Line<const D: usize> {
    /// The moving axis.
    pub axis: usize,
    /// +1 or −1: the walking sense along `axis`.
    pub sgn: f64,
    /// The fixed integer values, by axis (the entry of `axis` unused, 0).
    pub val: [i64; D],
}

impl<const D: usize> Line<D> {
    /// The direction index of the walk (`2·axis + negative`, as in
    /// `dualex_map::rotation`).
    #[inline]
    pub fn dir(&self) -> usize {
        2 * self.axis + usize::from(self.sgn < 0.0)
    }
}

/// A facet pierced by an axis line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pierce {
    /// The facet (opposite corner).
    pub face: usize,
    /// The moving coordinate at the piercing point.
    pub at: f64,
    /// Whether the line passes exactly through a corner of the facet
    /// (2D only: a vertex on the iso; after sanitization a singular one,
    /// which no walk can pass consistently).
    pub at_corner: bool,
}

const NO_PIERCE: Pierce = Pierce {
    face: 0,
    at: 0.0,
    at_corner: false,
};

/// The per-dimension predicates (module docs), one `impl` per dimension.
pub trait Simplex<const N: usize, const D: usize> {
    /// Simplices per parallel chunk when finding the nodes.
    const NODE_CHUNK: usize;

    /// Unnormalised barycentric coordinates of `q` in the image `p`
    /// (`Σ w = det`).
    fn bary_weights(p: &[[f64; D]; N], q: &[f64; D]) -> [f64; N];

    /// The facets of `p` pierced by `line`, without the piercing points
    /// (the walk needs these only where a node may end it).
    fn crossed(p: &[[f64; D]; N], line: &Line<D>) -> Crossed;

    /// The moving coordinate where `line` pierces facet `f` of `p` (one of
    /// [`Self::crossed`]'s).
    fn crossing_at(p: &[[f64; D]; N], line: &Line<D>, f: usize) -> f64;

    /// The facets of `p` pierced by `line` (at most `N`, usually 0 or 2)
    /// and their number, in facet order.
    #[inline]
    fn pierced(p: &[[f64; D]; N], line: &Line<D>) -> ([Pierce; N], usize) {
        let crossed = Self::crossed(p, line);
        let mut out = [NO_PIERCE; N];
        let mut n = 0;
        for f in (0..N).filter(|&f| crossed.facets >> f & 1 == 1) {
            out[n] = Pierce {
                face: f,
                at: Self::crossing_at(p, line, f),
                at_corner: crossed.corners >> f & 1 == 1,
            };
            n += 1;
        }
        (out, n)
    }
}

/// The facets an axis line pierces, as bit sets (bit `f`: facet `f`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Crossed {
    /// The pierced facets.
    pub facets: u8,
    /// Those pierced exactly at a corner (2D only, see [`Pierce`]).
    pub corners: u8,
}

impl Crossed {
    /// The other facet when exactly two are pierced, `entry` one of them.
    #[inline]
    pub fn exit(&self, entry: usize) -> Option<usize> {
        let rest = self.facets ^ (1 << entry);
        (self.facets.count_ones() == 2 && rest.count_ones() == 1)
            .then_some(rest.trailing_zeros() as usize)
    }
}

/// Corners of face `f` of a tet (the face opposite corner `f`).
#[inline]
pub fn face_corners(f: usize) -> [usize; 3] {
    [(f + 1) % 4, (f + 2) % 4, (f + 3) % 4]
}

/// The two fixed axes when `a` moves (D = 3), in increasing order.
#[inline]
fn fixed_axes(a: usize) -> [usize; 2] {
    match a {
        0 => [1, 2],
        1 => [0, 2],
        _ => [0, 1],
    }
}

impl Simplex<3, 2> for Dim<3, 2> {
    const NODE_CHUNK: usize = 4096;

    /// D = 2: `(a − q) × (b − q)` for the edge `a`, `b` opposite `c`.
    #[inline]
    fn bary_weights(p: &[[f64; 2]; 3], q: &[f64; 2]) -> [f64; 3] {
        std::array::from_fn(|c| {
            let a = p[(c + 1) % 3];
            let b = p[(c + 2) % 3];
            (a[0] - q[0]) * (b[1] - q[1]) - (a[1] - q[1]) * (b[0] - q[0])
        })
    }

    /// D = 2: the edges crossed by the iso `x[1 − axis] = val` (edge `f`
    /// opposite corner `f`, endpoints strictly on both sides; the signs
    /// change an even number of times around the triangle: at most 2).
    #[inline]
    fn crossed(p: &[[f64; 2]; 3], line: &Line<2>) -> Crossed {
        let fixed = 1 - line.axis;
        let v = line.val[fixed] as f64;
        // each corner's offset from the iso, once, as bit sets by corner
        let d = p.map(|c| c[fixed] - v);
        let (mut pos, mut zero) = (0u8, 0u8);
        for (i, &x) in d.iter().enumerate() {
            pos |= u8::from(x > 0.0) << i;
            zero |= u8::from(x == 0.0) << i;
        }
        // bit f of `next(m, k)`: bit (f + k) % 3 of m (edge f's corners)
        let next = |m: u8, k: u32| ((m >> k) | (m << (3 - k))) & 7;
        let facets = next(pos, 1) ^ next(pos, 2);
        Crossed {
            facets,
            corners: facets & (next(zero, 1) | next(zero, 2)),
        }
    }

    /// D = 2: linear interpolation along edge `f`.
    #[inline]
    fn crossing_at(p: &[[f64; 2]; 3], line: &Line<2>, f: usize) -> f64 {
        let (mv, fixed) = (line.axis, 1 - line.axis);
        let v = line.val[fixed] as f64;
        let (i, j) = ((f + 1) % 3, (f + 2) % 3);
        let (da, db) = (p[i][fixed] - v, p[j][fixed] - v);
        let (a, b) = (p[i][mv], p[j][mv]);
        a + (b - a) * da / (da - db)
    }
}

impl Simplex<4, 3> for Dim<4, 3> {
    const NODE_CHUNK: usize = 2048;

    /// D = 3: the determinant of the tet with corner `c` replaced by `q`.
    #[inline]
    fn bary_weights(p: &[[f64; 3]; 4], q: &[f64; 3]) -> [f64; 4] {
        std::array::from_fn(|c| {
            let mut r = *p;
            r[c] = *q;
            dualex_map::mesh::det_of::<4, 3>(&r)
        })
    }

    /// D = 3: the faces whose projection along the moving axis holds the
    /// line's point `(vb, vc)` strictly inside: the three 2D orientations
    /// of face `f`'s edges (as seen from the point) of one strict sign.
    /// Each edge serves two faces: its orientation is computed once
    /// (negating a difference of products is exact, so each face sees the
    /// very values [`Self::crossing_at`] computes).
    #[inline]
    fn crossed(p: &[[f64; 3]; 4], line: &Line<3>) -> Crossed {
        let [b, c] = fixed_axes(line.axis);
        let (vb, vc) = (line.val[b] as f64, line.val[c] as f64);
        let (x, y) = (p.map(|r| r[b] - vb), p.map(|r| r[c] - vc));
        let o = |i: usize, j: usize| x[i] * y[j] - y[i] * x[j];
        let (o01, o02, o03, o12, o13, o23) = (o(0, 1), o(0, 2), o(0, 3), o(1, 2), o(1, 3), o(2, 3));
        // face f's orientations are those of its edges (k1, k2), (k2, k0),
        // (k0, k1) with k = f+1, f+2, f+3 mod 4: two edges taken forwards
        // (`o`), one backwards (`-o`)
        //
        //   face 0 (1 2 3): 23, 12 forwards; 13 backwards (3 → 1)
        //   face 1 (2 3 0): 02, 23 forwards; 03 backwards (3 → 0)
        //   face 2 (3 0 1): 01, 13 forwards; 03 backwards (3 → 0)
        //   face 3 (0 1 2): 12, 01 forwards; 02 backwards (2 → 0)
        let face = |f1: f64, f2: f64, b1: f64| {
            (f1 > 0.0) & (f2 > 0.0) & (b1 < 0.0) | (f1 < 0.0) & (f2 < 0.0) & (b1 > 0.0)
        };
        let hit = [
            face(o23, o12, o13),
            face(o02, o23, o03),
            face(o01, o13, o03),
            face(o12, o01, o02),
        ];
        Crossed {
            facets: (0..4).fold(0, |m, f| m | u8::from(hit[f]) << f),
            corners: 0,
        }
    }

    /// D = 3: the moving coordinate interpolated barycentrically on face
    /// `f` (its edges' orientations as weights).
    #[inline]
    fn crossing_at(p: &[[f64; 3]; 4], line: &Line<3>, f: usize) -> f64 {
        let a = line.axis;
        let [b, c] = fixed_axes(a);
        let (vb, vc) = (line.val[b] as f64, line.val[c] as f64);
        let k = face_corners(f);
        let q = k.map(|i| [p[i][b] - vb, p[i][c] - vc]);
        let lam: [f64; 3] = std::array::from_fn(|i| {
            let (u, v) = (q[(i + 1) % 3], q[(i + 2) % 3]);
            u[0] * v[1] - u[1] * v[0]
        });
        let sum = lam[0] + lam[1] + lam[2];
        (0..3).map(|i| lam[i] * p[k[i]][a]).sum::<f64>() / sum
    }
}

#[cfg(test)]
#[path = "simplex_tests.rs"]
mod tests;

#[cfg(test)]
#[path = "simplex_oracle_tests.rs"]
mod oracle_tests;

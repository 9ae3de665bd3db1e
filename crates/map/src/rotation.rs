//! Rotations of the integer grid: the 4 quarter turns of ℤ² and the 24
//! chiral cube rotations of ℤ³, as one const-generic type.
//!
//! A rotation is a signed permutation matrix with determinant +1. It is
//! described by the image of each positive axis as a **direction** index:
//!
//! ```text
//!   direction d = 2·axis + neg        D = 2:  0:+u 1:-u 2:+v 3:-v
//!   d ^ 1 is the reverse direction    D = 3:  ... 4:+w 5:-w
//! ```
//!
//! `img[i]` is the direction of `R·e_i`. Applying `R` to direction `d` is
//! `img[d >> 1] ^ (d & 1)`. Composition `a.then(b)` means "first `a`, then
//! `b`" (`b·a` as matrices), which is the order in which transitions are
//! crossed while walking from chart to chart.
//!
//! Stored as one byte, the rank of `img` among the group's image arrays in
//! lexicographic order (the identity, `[0, 2, 4]`, is rank 0), so that
//! the identity test is one comparison, composition and inverse are
//! table lookups (tables built at compile time), and the derived
//! order is the order of the image arrays.
//!
//! Invariants: the rank is below the group's size; its `img` is a signed
//! permutation with determinant +1. [`Rot::all`] enumerates the group (4
//! resp. 24 elements), identity first.

/// A grid rotation in dimension `D` (see the module docs for the encoding).
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Rot<const D: usize> {
    rank: u8,
}

/// A 2D rotation (one of 4 quarter turns).
pub type Rot2 = Rot<2>;
/// A 3D rotation (one of the 24 chiral cube rotations).
pub type Rot3 = Rot<3>;

/// Size of the largest group (3D).
const MOST: usize = 24;

/// The group of one dimension, by rank.
struct Tables {
    /// Number of rotations.
    len: usize,
    /// `img[r]`: the images of the axes (entries past `D` unused).
    img: [[u8; 3]; MOST],
    /// `then[a][b]`: the rank of `a` then `b`.
    then: [[u8; MOST]; MOST],
    /// `inverse[a]`: the rank of the inverse of `a`.
    inverse: [u8; MOST],
    /// `rank[code]` for `code = Σ img[i]·6^i`, or `u8::MAX` for a
    /// non-rotation.
    rank: [u8; 216],
}

/// Whether `img[..d]` is a signed permutation with determinant +1.
const fn is_rotation(img: &[u8; 3], d: usize) -> bool {
    let mut seen = [false; 3];
    let mut sign = 1;
    let mut i = 0;
    while i < d {
        let a = (img[i] >> 1) as usize;
        if a >= d || seen[a] {
            return false;
        }
        seen[a] = true;
        if img[i] & 1 == 1 {
            sign = -sign;
        }
        let mut j = i + 1;
        while j < d {
            if img[i] >> 1 > img[j] >> 1 {
                sign = -sign;
            }
            j += 1;
        }
        i += 1;
    }
    sign == 1
}

/// `Σ img[i]·6^i` over the first `d` axes.
const fn code(img: &[u8; 3], d: usize) -> usize {
    let (mut c, mut i) = (0, d);
    while i > 0 {
        i -= 1;
        c = 6 * c + img[i] as usize;
    }
    c
}

/// The tables of dimension `d` (2 or 3).
const fn tables(d: usize) -> Tables {
    let mut t = Tables {
        len: 0,
        img: [[0; 3]; MOST],
        then: [[0; MOST]; MOST],
        inverse: [0; MOST],
        rank: [u8::MAX; 216],
    };
    // the image arrays in lexicographic order: the first axis's image
    // varies slowest
    let n = 2 * d as u8;
    let mut img = [0u8; 3];
    loop {
        if is_rotation(&img, d) {
            t.img[t.len] = img;
            t.rank[code(&img, d)] = t.len as u8;
            t.len += 1;
        }
        // next array: the last axis's image varies fastest
        let mut i = d;
        while i > 0 {
            i -= 1;
            img[i] += 1;
            if img[i] < n {
                break;
            }
            img[i] = 0;
        }
        if code(&img, d) == 0 {
            break;
        }
    }
    let mut a = 0;
    while a < t.len {
        let mut b = 0;
        while b < t.len {
            let mut ab = [0u8; 3];
            let mut i = 0;
            while i < d {
                let x = t.img[a][i];
                ab[i] = t.img[b][(x >> 1) as usize] ^ (x & 1);
                i += 1;
            }
            t.then[a][b] = t.rank[code(&ab, d)];
            b += 1;
        }
        let mut inv = [0u8; 3];
        let mut i = 0;
        while i < d {
            let x = t.img[a][i];
            inv[(x >> 1) as usize] = (2 * i) as u8 | (x & 1);
            i += 1;
        }
        t.inverse[a] = t.rank[code(&inv, d)];
        a += 1;
    }
    t
}

/// The tables of 2D.
static TABLES_2: Tables = tables(2);
/// The tables of 3D.
static TABLES_3: Tables = tables(3);

impl<const D: usize> std::fmt::Debug for Rot<D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        const NAMES: [&str; 6] = ["+u", "-u", "+v", "-v", "+w", "-w"];
        write!(f, "Rot[")?;
        for (i, d) in self.images().iter().enumerate() {
            if i > 0 {
                write!(f, ",")?;
            }
            write!(f, "{}", NAMES[*d as usize])?;
        }
        write!(f, "]")
    }
}

impl<const D: usize> Default for Rot<D> {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl<const D: usize> Rot<D> {
    /// The identity rotation (rank 0: `[0, 2, 4]` comes first).
    pub const IDENTITY: Self = Rot { rank: 0 };

    /// The tables of dimension `D`.
    #[inline]
    fn tables() -> &'static Tables {
        const { assert!(D == 2 || D == 3, "grid rotations are 2D or 3D") };
        if D == 2 {
            &TABLES_2
        } else {
            &TABLES_3
        }
    }

    /// Builds a rotation from the directions of the images of the axes;
    /// `None` unless it is a signed permutation with determinant +1.
    pub fn from_images(img: [u8; D]) -> Option<Self> {
        let mut padded = [0u8; 3];
        for (p, &d) in padded.iter_mut().zip(&img) {
            if d as usize >= 2 * D {
                return None;
            }
            *p = d;
        }
        let rank = Self::tables().rank[code(&padded, D)];
        (rank != u8::MAX).then_some(Rot { rank })
    }

    /// Images of the positive axes, as directions.
    #[inline]
    pub fn images(&self) -> [u8; D] {
        let img = &Self::tables().img[self.rank as usize];
        std::array::from_fn(|i| img[i])
    }

    /// All rotations of the group, identity first (4 for D = 2, 24 for
    /// D = 3), the others in the order of `Σ img[i]·(2D)^i`.
    pub fn all() -> Vec<Self> {
        let mut out = vec![Self::IDENTITY];
        let n = (2 * D) as u32;
        let total = n.pow(D as u32);
        for code in 0..total {
            let mut img = [0u8; D];
            let mut c = code;
            for slot in img.iter_mut() {
                *slot = (c % n) as u8;
                c /= n;
            }
            if let Some(r) = Self::from_images(img) {
                if r != Self::IDENTITY {
                    out.push(r);
                }
            }
        }
        out
    }

    /// Image of a direction index.
    #[inline]
    pub fn apply_dir(&self, d: usize) -> usize {
        (Self::tables().img[self.rank as usize][d >> 1] ^ (d as u8 & 1)) as usize
    }

    /// `self` then `next`: the rotation `next · self`.
    #[inline]
    pub fn then(&self, next: &Self) -> Self {
        Rot {
            rank: Self::tables().then[self.rank as usize][next.rank as usize],
        }
    }

    /// The inverse rotation.
    #[inline]
    pub fn inverse(&self) -> Self {
        Rot {
            rank: Self::tables().inverse[self.rank as usize],
        }
    }

    /// `R · x` for a real vector (the identity returns `x`'s floats as
    /// they are, with no table lookup).
    #[inline]
    pub fn apply(&self, x: &[f64; D]) -> [f64; D] {
        if self.is_identity() {
            return *x;
        }
        let img = &Self::tables().img[self.rank as usize];
        let mut out = [0.0; D];
        for i in 0..D {
            let d = img[i];
            let v = if d & 1 == 1 { -x[i] } else { x[i] };
            out[(d >> 1) as usize] = v;
        }
        out
    }

    /// `R · x` for an integer vector.
    #[inline]
    pub fn apply_i(&self, x: &[i64; D]) -> [i64; D] {
        let img = &Self::tables().img[self.rank as usize];
        let mut out = [0i64; D];
        for i in 0..D {
            let d = img[i];
            let v = if d & 1 == 1 { -x[i] } else { x[i] };
            out[(d >> 1) as usize] = v;
        }
        out
    }

    /// The rank of this rotation among the group's (below 24; the
    /// identity's is 0): a one-byte key.
    #[inline]
    pub(crate) fn rank(&self) -> u8 {
        self.rank
    }

    /// Whether this is the identity.
    #[inline]
    pub fn is_identity(&self) -> bool {
        self.rank == 0
    }

    /// A compact index of this rotation in [`Rot::all`] order.
    pub fn index(&self) -> usize {
        Self::all().iter().position(|r| r == self).unwrap_or(0)
    }
}

impl Rot<2> {
    /// The rotation by `k` counter-clockwise quarter turns.
    pub fn quarter_turns(k: i64) -> Self {
        // +u → +v → -u → -v
        const CYCLE: [u8; 4] = [0, 2, 1, 3];
        let k = k.rem_euclid(4) as usize;
        let Some(r) = Self::from_images([CYCLE[k], CYCLE[(k + 1) % 4]]) else {
            panic!("bug: a quarter turn is a rotation");
        };
        r
    }

    /// Number of counter-clockwise quarter turns, in `0..4`.
    pub fn turns(&self) -> i64 {
        match self.images()[0] {
            0 => 0,
            2 => 1,
            1 => 2,
            _ => 3,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn group_laws<const D: usize>(n: usize) {
        let all = Rot::<D>::all();
        assert_eq!(all.len(), n);
        for a in &all {
            assert_eq!(a.then(&a.inverse()), Rot::IDENTITY, "{a:?}");
            assert_eq!(a.inverse().inverse(), *a);
            for b in &all {
                let ab = a.then(b);
                assert!(all.contains(&ab));
                // composition agrees with applying one after the other
                let x: [f64; D] = std::array::from_fn(|i| (i as f64 + 1.0) * 1.5);
                assert_eq!(ab.apply(&x), b.apply(&a.apply(&x)), "{a:?} {b:?}");
                for c in &all {
                    assert_eq!(ab.then(c), a.then(&b.then(c)));
                }
            }
            for d in 0..2 * D {
                assert_eq!(a.apply_dir(d ^ 1), a.apply_dir(d) ^ 1);
                assert_eq!(a.inverse().apply_dir(a.apply_dir(d)), d);
            }
        }
    }

    /// The tables against the images: composition and inverse as first
    /// written (on the image arrays), ranks in the order of the arrays.
    fn tables_agree<const D: usize>() {
        let all = Rot::<D>::all();
        let mut by_images: Vec<([u8; D], Rot<D>)> = all.iter().map(|r| (r.images(), *r)).collect();
        by_images.sort();
        for (w, pair) in by_images.windows(2).enumerate() {
            assert!(pair[0].1 < pair[1].1, "rank order at {w}");
        }
        assert_eq!(by_images[0].1, Rot::IDENTITY);
        for a in &all {
            let img = a.images();
            assert_eq!(Rot::from_images(img), Some(*a));
            let mut inv = [0u8; D];
            for (i, &d) in img.iter().enumerate() {
                inv[(d >> 1) as usize] = (2 * i) as u8 | (d & 1);
            }
            assert_eq!(a.inverse().images(), inv, "{a:?}");
            assert_eq!(a.is_identity(), img == Rot::<D>::IDENTITY.images());
            for b in &all {
                let ab: [u8; D] = std::array::from_fn(|i| b.apply_dir(img[i] as usize) as u8);
                assert_eq!(a.then(b).images(), ab, "{a:?} {b:?}");
            }
        }
    }

    #[test]
    fn tables_agree_2d_3d() {
        tables_agree::<2>();
        tables_agree::<3>();
    }

    #[test]
    fn group_2d() {
        group_laws::<2>(4);
        for k in 0..8 {
            let r = Rot2::quarter_turns(k);
            assert_eq!(r.turns(), k % 4);
            assert_eq!(r.apply(&[1.0, 0.0]), {
                let a = std::f64::consts::FRAC_PI_2 * k as f64;
                [a.cos().round(), a.sin().round()]
            });
        }
    }

    #[test]
    fn group_3d() {
        group_laws::<3>(24);
        // reflections are rejected
        assert!(Rot3::from_images([1, 2, 4]).is_none());
        assert!(Rot3::from_images([2, 0, 4]).is_none());
        assert!(Rot3::from_images([2, 1, 4]).is_some());
    }
}

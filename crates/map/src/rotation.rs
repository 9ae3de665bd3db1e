//! Rotations of the integer grid: the 4 quarter turns of ℤ² and the 24
//! chiral cube rotations of ℤ³, as one const-generic type.
//!
//! A rotation is a signed permutation matrix with determinant +1. It is stored
//! as the image of each positive axis as a **direction** index:
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
//! Invariants: `img` is a signed permutation (each axis appears once) and its
//! determinant is +1. [`Rot::all`] enumerates the group (4 resp. 24 elements).

/// A grid rotation in dimension `D` (see the module docs for the encoding).
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Rot<const D: usize> {
    img: [u8; D],
}

/// A 2D rotation (one of 4 quarter turns).
pub type Rot2 = Rot<2>;
/// A 3D rotation (one of the 24 chiral cube rotations).
pub type Rot3 = Rot<3>;

impl<const D: usize> std::fmt::Debug for Rot<D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        const NAMES: [&str; 6] = ["+u", "-u", "+v", "-v", "+w", "-w"];
        write!(f, "Rot[")?;
        for (i, d) in self.img.iter().enumerate() {
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
    /// The identity rotation.
    pub const IDENTITY: Self = {
        let mut img = [0u8; D];
        let mut i = 0;
        while i < D {
            img[i] = (2 * i) as u8;
            i += 1;
        }
        Rot { img }
    };

    /// Builds a rotation from the directions of the images of the axes;
    /// `None` unless it is a signed permutation with determinant +1.
    pub fn from_images(img: [u8; D]) -> Option<Self> {
        let mut seen = [false; 3];
        for &d in &img {
            let a = (d >> 1) as usize;
            if a >= D || seen[a] {
                return None;
            }
            seen[a] = true;
        }
        let r = Rot { img };
        (r.det() == 1).then_some(r)
    }

    /// Images of the positive axes, as directions.
    pub fn images(&self) -> [u8; D] {
        self.img
    }

    /// Determinant (±1) of the signed permutation.
    fn det(&self) -> i32 {
        let mut sign = 1;
        for i in 0..D {
            if self.img[i] & 1 == 1 {
                sign = -sign;
            }
            for j in (i + 1)..D {
                if self.img[i] >> 1 > self.img[j] >> 1 {
                    sign = -sign;
                }
            }
        }
        sign
    }

    /// All rotations of the group, identity first (4 for D = 2, 24 for D = 3).
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
        (self.img[d >> 1] ^ (d as u8 & 1)) as usize
    }

    /// `self` then `next`: the rotation `next · self`.
    #[inline]
    pub fn then(&self, next: &Self) -> Self {
        let mut img = [0u8; D];
        for (i, slot) in img.iter_mut().enumerate() {
            *slot = next.apply_dir(self.img[i] as usize) as u8;
        }
        Rot { img }
    }

    /// The inverse rotation.
    #[inline]
    pub fn inverse(&self) -> Self {
        let mut img = [0u8; D];
        for i in 0..D {
            let d = self.img[i];
            img[(d >> 1) as usize] = (2 * i) as u8 | (d & 1);
        }
        Rot { img }
    }

    /// `R · x` for a real vector.
    #[inline]
    pub fn apply(&self, x: &[f64; D]) -> [f64; D] {
        let mut out = [0.0; D];
        for i in 0..D {
            let d = self.img[i];
            let v = if d & 1 == 1 { -x[i] } else { x[i] };
            out[(d >> 1) as usize] = v;
        }
        out
    }

    /// `R · x` for an integer vector.
    #[inline]
    pub fn apply_i(&self, x: &[i64; D]) -> [i64; D] {
        let mut out = [0i64; D];
        for i in 0..D {
            let d = self.img[i];
            let v = if d & 1 == 1 { -x[i] } else { x[i] };
            out[(d >> 1) as usize] = v;
        }
        out
    }

    /// Whether this is the identity.
    #[inline]
    pub fn is_identity(&self) -> bool {
        // each axis sent to its own positive direction (no early exit: a
        // few branch-free byte operations)
        let mut differ = 0u8;
        for (i, &d) in self.img.iter().enumerate() {
            differ |= d ^ (2 * i) as u8;
        }
        differ == 0
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
        Rot {
            img: [CYCLE[k], CYCLE[(k + 1) % 4]],
        }
    }

    /// Number of counter-clockwise quarter turns, in `0..4`.
    pub fn turns(&self) -> i64 {
        match self.img[0] {
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

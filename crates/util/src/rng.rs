//! A tiny deterministic random generator (splitmix64), shared by every
//! stage that needs reproducible randomness (sanitization perturbations,
//! worklist shuffles in tests): the same seed gives the same output.

/// splitmix64 state.
#[derive(Clone, Debug)]
pub struct SplitMix(u64);

/// What each draw adds to the state.
const GOLDEN: u64 = 0x9E37_79B9_7F4A_7C15;

impl SplitMix {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        SplitMix(seed ^ GOLDEN)
    }

    /// The generator `n` draws ([`Self::next_u64`]) ahead: each draw adds
    /// one constant to the state, so this is one multiplication (to draw
    /// from many places of one sequence in parallel).
    pub fn ahead(&self, n: u64) -> Self {
        SplitMix(self.0.wrapping_add(n.wrapping_mul(GOLDEN)))
    }

    /// How many draws `f` takes from a copy of this generator, if at most
    /// `max`.
    pub fn draws_of(&self, max: u64, f: impl FnOnce(&mut SplitMix)) -> Option<u64> {
        let mut copy = self.clone();
        f(&mut copy);
        (0..=max).find(|&n| self.ahead(n).0 == copy.0)
    }

    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(GOLDEN);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform number in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A uniform angle in [0, 2π).
    pub fn angle(&mut self) -> f64 {
        self.unit() * std::f64::consts::TAU
    }

    /// A uniform unit vector of 3-space.
    pub fn direction(&mut self) -> [f64; 3] {
        let z = 2.0 * self.unit() - 1.0;
        let a = self.angle();
        let r = (1.0 - z * z).max(0.0).sqrt();
        [r * a.cos(), r * a.sin(), z]
    }

    /// A uniform integer in `0..n` (0 when `n == 0`).
    pub fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            return 0;
        }
        (self.next_u64() % n as u64) as usize
    }

    /// Fisher–Yates shuffle.
    pub fn shuffle<T>(&mut self, v: &mut [T]) {
        for i in (1..v.len()).rev() {
            let j = self.below(i + 1);
            v.swap(i, j);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::SplitMix;

    /// [`SplitMix::ahead`] lands where as many draws land, and
    /// [`SplitMix::draws_of`] counts them.
    #[test]
    fn ahead_equals_drawing() {
        let rng = SplitMix::new(7);
        for n in 0..20u64 {
            let mut drawn = rng.clone();
            for _ in 0..n {
                drawn.next_u64();
            }
            assert_eq!(rng.ahead(n).next_u64(), drawn.next_u64(), "{n}");
        }
        assert_eq!(
            rng.draws_of(4, |r| {
                r.angle();
            }),
            Some(1)
        );
        assert_eq!(
            rng.draws_of(4, |r| {
                r.direction();
            }),
            Some(2)
        );
        assert_eq!(
            rng.draws_of(1, |r| {
                r.direction();
            }),
            None
        );
    }
}

//! A fast hash for the local repair's maps of small integer keys (faces,
//! vertex pairs, search states): the multiply-rotate word hash of
//! rustc's `FxHasher`. Not resistant to chosen keys, which these are not
//! (they come from the mesh); deterministic, like the standard hasher's
//! iteration is not relied upon anywhere here.

use std::hash::{BuildHasherDefault, Hasher};

/// The hasher (one 64-bit state, one multiply per word).
#[derive(Clone, Copy, Default)]
pub struct WordHasher(u64);

const K: u64 = 0x517c_c1b7_2722_0a95;

impl WordHasher {
    fn add(&mut self, w: u64) {
        self.0 = (self.0.rotate_left(5) ^ w).wrapping_mul(K);
    }
}

impl Hasher for WordHasher {
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut w = [0u8; 8];
            w[..chunk.len()].copy_from_slice(chunk);
            self.add(u64::from_le_bytes(w));
        }
    }
    fn write_u8(&mut self, i: u8) {
        self.add(u64::from(i));
    }
    fn write_u32(&mut self, i: u32) {
        self.add(u64::from(i));
    }
    fn write_u64(&mut self, i: u64) {
        self.add(i);
    }
    fn write_usize(&mut self, i: usize) {
        self.add(i as u64);
    }
    fn finish(&self) -> u64 {
        self.0
    }
}

/// A `HashMap` with [`WordHasher`].
pub type FastMap<K, V> = std::collections::HashMap<K, V, BuildHasherDefault<WordHasher>>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_found_and_distinct_keys_spread() {
        let mut m: FastMap<(usize, Option<(u32, u32)>), u32> = FastMap::default();
        for f in 0..1000usize {
            m.insert((f, Some((f as u32, f as u32 + 1))), f as u32);
            m.insert((f, None), 7);
        }
        assert_eq!(m.len(), 2000);
        assert_eq!(m.get(&(500, Some((500, 501)))), Some(&500));
        assert_eq!(m.get(&(500, None)), Some(&7));
        let h = |x: u64| {
            let mut s = WordHasher::default();
            s.write_u64(x);
            s.finish()
        };
        assert_ne!(h(1), h(2));
    }
}

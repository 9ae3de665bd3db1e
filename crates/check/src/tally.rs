//! Histograms of small counts (valences) counted in a vector and only then
//! moved into the reports' ordered maps: one vector increment per item
//! instead of a map lookup.
//!
//! Input: keys (small non-negative integers). Output: per key, how many
//! times it was added, added into a `BTreeMap<u32, usize>`. Invariant: the
//! map receives exactly the non-zero counts, so it is the map that one
//! `entry(k).or_insert(0) += 1` per item would have built.

use std::collections::BTreeMap;

/// Counts per key, the key being the index.
#[derive(Clone, Debug, Default)]
pub(crate) struct Tally(Vec<usize>);

impl Tally {
    /// One more of `key`.
    pub(crate) fn add(&mut self, key: u32) {
        let k = key as usize;
        if self.0.len() <= k {
            self.0.resize(k + 1, 0);
        }
        self.0[k] += 1;
    }

    /// `other`'s counts added.
    pub(crate) fn merge(&mut self, other: Tally) {
        if self.0.len() < other.0.len() {
            self.0.resize(other.0.len(), 0);
        }
        for (a, b) in self.0.iter_mut().zip(other.0) {
            *a += b;
        }
    }

    /// The non-zero counts added into `map`.
    pub(crate) fn into_map(self, map: &mut BTreeMap<u32, usize>) {
        for (k, n) in self.0.into_iter().enumerate().filter(|&(_, n)| n > 0) {
            // k came from a u32 key
            *map.entry(k as u32).or_insert(0) += n;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_map_as_one_entry_per_item() {
        let keys = [4u32, 3, 4, 0, 7, 4, 3];
        let mut by_entry = BTreeMap::new();
        for &k in &keys {
            *by_entry.entry(k).or_insert(0usize) += 1;
        }
        let mut t = Tally::default();
        keys.iter().for_each(|&k| t.add(k));
        let mut map = BTreeMap::new();
        t.into_map(&mut map);
        assert_eq!(map, by_entry);
        assert_eq!(map.get(&5), None);
        // split anywhere, counted apart, merged either way: the same map
        for cut in 0..=keys.len() {
            let (mut a, mut b) = (Tally::default(), Tally::default());
            keys[..cut].iter().for_each(|&k| a.add(k));
            keys[cut..].iter().for_each(|&k| b.add(k));
            let (mut ab, mut ba) = (a.clone(), b.clone());
            ab.merge(b);
            ba.merge(a);
            for t in [ab, ba] {
                let mut got = BTreeMap::new();
                t.into_map(&mut got);
                assert_eq!(got, by_entry, "cut {cut}");
            }
        }
    }
}

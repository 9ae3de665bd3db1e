//! What the extracted quad mesh of a generated map should be, when known.

use std::collections::BTreeMap;

/// Expected properties of the quad mesh extracted from a generated map;
/// `None` where the generator does not know (or the paper reports that the
/// method cannot recover it).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Expected {
    /// Number of quads.
    pub quads: Option<usize>,
    /// Valence → number of interior vertices with it (the full histogram).
    pub interior_valence: Option<BTreeMap<u32, usize>>,
    /// Euler characteristic `V − E + F`.
    pub euler: Option<i64>,
    /// Number of boundary loops.
    pub boundary_loops: Option<usize>,
}

impl Expected {
    /// Nothing known.
    pub fn unknown() -> Self {
        Expected::default()
    }

    /// An `nx × ny` grid of quads (a disk when both are positive).
    pub fn grid(nx: usize, ny: usize) -> Self {
        let quads = nx * ny;
        let mut valence = BTreeMap::new();
        let interior = nx.saturating_sub(1) * ny.saturating_sub(1);
        if interior > 0 {
            valence.insert(4, interior);
        }
        let disk = quads > 0;
        Expected {
            quads: Some(quads),
            interior_valence: Some(valence),
            euler: Some(i64::from(disk)),
            boundary_loops: Some(usize::from(disk)),
        }
    }

    /// A closed surface of `quads` quads with the given interior valences.
    pub fn closed(quads: usize, valence: &[(u32, usize)], euler: i64) -> Self {
        Expected {
            quads: Some(quads),
            interior_valence: Some(valence.iter().copied().filter(|p| p.1 > 0).collect()),
            euler: Some(euler),
            boundary_loops: Some(0),
        }
    }
}

/// Number of unit cells `[i, i+1]` whose centre `i + ½` lies strictly inside
/// `(lo, hi)`: the quads along one axis of a map onto `[lo, hi]`.
pub fn cells_between(lo: f64, hi: f64) -> usize {
    let first = (lo - 0.5).floor() + 1.0;
    let last = (hi - 0.5).ceil() - 1.0;
    if last >= first {
        (last - first + 1.0) as usize
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells() {
        assert_eq!(cells_between(0.2, 7.2), 7);
        assert_eq!(cells_between(0.0, 7.0), 7);
        assert_eq!(cells_between(-0.4, 0.4), 0);
        assert_eq!(cells_between(-0.6, 0.6), 2);
        assert_eq!(cells_between(0.4, 1.2), 1);
        assert_eq!(cells_between(3.0, 1.0), 0);
    }

    #[test]
    fn grid_expectation() {
        let e = Expected::grid(3, 4);
        assert_eq!(e.quads, Some(12));
        assert_eq!(e.interior_valence, Some([(4, 6)].into_iter().collect()));
        assert_eq!((e.euler, e.boundary_loops), (Some(1), Some(1)));
        assert_eq!(Expected::grid(0, 5).euler, Some(0));
    }
}

//! The checks the end-to-end tests of the integration share: a grid
//! transition across every interior edge, reverted triangles, the real
//! `dualex quad`'s counts, edges on integer iso-lines, and the options of a
//! run at a quad count.

use super::*;

/// Every interior edge: the two triangles' coordinates of the shared
/// vertices differ by a quarter-turn rotation and an integer translation.
/// Returns the number of edges with a nonzero rotation.
pub(super) fn assert_grid_transitions(s: &Surface, map: &TriMap) -> usize {
    let uv = |f: u32, v: u32| {
        let i = s.triangles[f as usize]
            .iter()
            .position(|&x| x == v)
            .unwrap();
        map.coords[f as usize][i]
    };
    let mut rotated = 0;
    for (e, &[f0, f1]) in s.edge_faces.iter().enumerate() {
        if f1 == crate::NO_FACE {
            continue;
        }
        let [a, b] = s.edges[e];
        let (a0, b0, a1, b1) = (uv(f0, a), uv(f0, b), uv(f1, a), uv(f1, b));
        let found = (0..4u8).find(|&p| {
            let m = constraints::seam_rotation(p);
            let t = |w0: [f64; 2], w1: [f64; 2]| {
                [0, 1].map(|c| w1[c] - m[c][0] * w0[0] - m[c][1] * w0[1])
            };
            let (ta, tb) = (t(a0, a1), t(b0, b1));
            (0..2).all(|c| (ta[c] - tb[c]).abs() < 1e-9 && (ta[c] - ta[c].round()).abs() < 1e-9)
        });
        match found {
            Some(p) => rotated += usize::from(p != 0),
            None => panic!("edge {a}–{b}: no grid transition: {a0:?} {b0:?} | {a1:?} {b1:?}"),
        }
    }
    rotated
}

/// Triangles whose map is reverted (negative signed area).
pub(super) fn reverted(map: &TriMap) -> usize {
    map.coords
        .iter()
        .filter(|[a, b, c]| (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0.0)
        .count()
}

/// Extracts with the real `dualex quad`; returns (quads, vertex valences,
/// Euler characteristic of the quad mesh).
pub(super) fn extract(map: &TriMap) -> (usize, Vec<usize>, i64) {
    let out = dualex::quad(map, &dualex::Options::default()).expect("extraction");
    let m = &out.mesh;
    let mut valence = vec![0; m.positions.len()];
    let mut edges = std::collections::HashSet::new();
    for q in &m.cells {
        for i in 0..4 {
            valence[q[i] as usize] += 1;
            let (a, b) = (q[i], q[(i + 1) % 4]);
            edges.insert((a.min(b), a.max(b)));
        }
    }
    let chi = m.positions.len() as i64 - edges.len() as i64 + m.cells.len() as i64;
    (m.cells.len(), valence, chi)
}

/// Edge `e` lies on an integer iso-line of face `f`'s chart: one
/// coordinate is the same integer at both ends.
pub(super) fn on_integer_iso_line(s: &Surface, map: &TriMap, e: usize, f: u32) -> bool {
    let t = s.triangles[f as usize];
    let on = s.edges[e].map(|v| map.coords[f as usize][t.iter().position(|&x| x == v).unwrap()]);
    (0..2).any(|c| (on[0][c] - on[1][c]).abs() < 1e-9 && (on[0][c] - on[0][c].round()).abs() < 1e-9)
}

/// The options of a run at `quads` quads with `rounding`.
pub(super) fn opts(quads: usize, rounding: Rounding) -> IntegrateOptions {
    IntegrateOptions {
        quads: Some(quads),
        rounding,
        ..IntegrateOptions::default()
    }
}

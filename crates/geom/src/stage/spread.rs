//! Wide folds: the cells a fold stretched across it, and its vertices
//! spread out before the untangling.
//!
//! A map folded over tens of cells puts whole rows of the mesh on the
//! wrong sheet: the quads that join the sheets are stretched across the
//! fold (on `torus_fold` 900, up to 84 edge lengths), and the untangler,
//! whose steps are a fraction of an edge a round, cannot carry vertices
//! that far. [`stretched`] finds those cells; [`fold`] the cells of each
//! fold (inverted ones and the stretched ones joined to them);
//! [`harmonic`] puts each vertex inside at the average of its edge
//! neighbours (a Tutte-like harmonic map with the rim fixed), solved by
//! conjugate gradients. The caller projects the result onto the
//! reference and untangles what is left.
//!
//! Also the cells' sizes: [`mean_edge`] (the mesh's mean edge, step 1)
//! and [`sizes`] (each cell's mean edge, the median).
//!
//! Deterministic: sequential sums in vertex order (the mean edge's
//! lengths are taken in parallel, summed in cell and edge order).

use crate::quality::{norm, sub};

/// A cell whose mean edge is more than this many times the mesh's median
/// is stretched (a fold's bridge between sheets); while its fold is
/// spread, its target size in the functional is the median.
pub(super) const STRETCHED: f64 = 6.0;

/// The cells' target sizes (their mean edge at `x`; `mean_edge`, else 1,
/// for a cell of length 0), which ones are stretched, and the median size.
pub(super) fn sizes<const K: usize>(
    cells: &[[u32; K]],
    edges: &[[usize; 2]],
    x: &[[f64; 3]],
    mean_edge: f64,
) -> (Vec<f64>, Vec<bool>, f64) {
    use rayon::prelude::*;
    let h: Vec<f64> = cells
        .par_iter()
        .map(|c| {
            let l = edges
                .iter()
                .map(|e| norm(sub(x[c[e[1]] as usize], x[c[e[0]] as usize])));
            let m = l.sum::<f64>() / edges.len() as f64;
            if m > 0.0 {
                m
            } else if mean_edge > 0.0 {
                mean_edge
            } else {
                1.0
            }
        })
        .collect();
    let median = median_of(&h);
    let flags = h.par_iter().map(|&v| v > STRETCHED * median).collect();
    (h, flags, median)
}

/// Cells per block of [`mean_edge`]: a block's lengths (12 a hex) in
/// 96 KiB, under glibc's mmap threshold.
const MEAN_EDGE_BLOCK: usize = 1 << 10;

/// The mean length of the cells' edges (each cell's edges counted; 0 for
/// none): the lengths of a block of cells in parallel, summed in cell and
/// edge order (the serial sum's rounding).
pub(super) fn mean_edge<const K: usize>(
    x: &[[f64; 3]],
    cells: &[[u32; K]],
    edges: &[[usize; 2]],
) -> f64 {
    use rayon::prelude::*;
    let n = cells.len() * edges.len();
    if n == 0 {
        return 0.0;
    }
    let mut sum = 0.0;
    let mut lengths = vec![0.0; MEAN_EDGE_BLOCK.min(cells.len()) * edges.len()];
    for block in cells.chunks(MEAN_EDGE_BLOCK) {
        let lengths = &mut lengths[..block.len() * edges.len()];
        lengths
            .par_chunks_mut(edges.len())
            .zip(block)
            .for_each(|(l, c)| {
                for (l, e) in l.iter_mut().zip(edges) {
                    *l = norm(sub(x[c[e[1]] as usize], x[c[e[0]] as usize]));
                }
            });
        for &l in lengths.iter() {
            sum += l;
        }
    }
    sum / n as f64
}

/// The element at place `len / 2` of `values` sorted by
/// [`f64::total_cmp`] (1 when empty): found by selection, not a sort
/// (a total order: the same element).
fn median_of(values: &[f64]) -> f64 {
    let mut v = values.to_vec();
    if v.is_empty() {
        return 1.0;
    }
    let mid = v.len() / 2;
    *v.select_nth_unstable_by(mid, f64::total_cmp).1
}

/// The cells of the folds: the `flagged` ones and the `stretched` ones
/// joined to them through stretched cells sharing a vertex; `None` when
/// no stretched cell is joined (no wide fold).
pub(super) fn fold<const K: usize>(
    cells: &[[u32; K]],
    around: &(Vec<usize>, Vec<u32>),
    flagged: &[bool],
    stretched: &[bool],
) -> Option<Vec<bool>> {
    let mut inside = flagged.to_vec();
    let mut stack: Vec<usize> = (0..cells.len()).filter(|&c| flagged[c]).collect();
    let mut wide = false;
    while let Some(c) = stack.pop() {
        for &v in &cells[c] {
            for &d in &around.1[around.0[v as usize]..around.0[v as usize + 1]] {
                let d = d as usize;
                if !inside[d] && stretched.get(d) == Some(&true) {
                    inside[d] = true;
                    wide = true;
                    stack.push(d);
                }
            }
        }
    }
    wide.then_some(inside)
}

/// Moves every `region` vertex of `x` to the harmonic interpolation
/// (uniform weights over the mesh's edges) of the vertices around the
/// region; returns the vertices moved. At most `iterations` conjugate
/// gradient steps.
pub(super) fn harmonic<const K: usize>(
    x: &mut [[f64; 3]],
    cells: &[[u32; K]],
    edges: &[[usize; 2]],
    region: &[bool],
    iterations: usize,
) -> usize {
    // unknowns and their neighbours (CSR, unknown ids or fixed vertices)
    let mut id = vec![u32::MAX; x.len()];
    let vars: Vec<usize> = (0..x.len()).filter(|&v| region[v]).collect();
    for (i, &v) in vars.iter().enumerate() {
        id[v] = i as u32;
    }
    let mut pairs: Vec<(u32, u32)> = Vec::new();
    for c in cells {
        for e in edges {
            let (a, b) = (c[e[0]], c[e[1]]);
            if id[a as usize] != u32::MAX {
                pairs.push((id[a as usize], b));
            }
            if id[b as usize] != u32::MAX {
                pairs.push((id[b as usize], a));
            }
        }
    }
    // an edge shared by two cells appears twice: once is enough
    pairs.sort_unstable();
    pairs.dedup();
    let n = vars.len();
    if n == 0 {
        return 0;
    }
    let mut start = vec![0usize; n + 1];
    for &(i, _) in &pairs {
        start[i as usize + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    // b = Σ fixed neighbours; A = deg·I − adjacency among unknowns
    let mut b = vec![[0.0; 3]; n];
    for &(i, u) in &pairs {
        if id[u as usize] == u32::MAX {
            for a in 0..3 {
                b[i as usize][a] += x[u as usize][a];
            }
        }
    }
    let apply = |p: &[[f64; 3]], out: &mut [[f64; 3]]| {
        for i in 0..n {
            let deg = (start[i + 1] - start[i]) as f64;
            let mut s = [deg * p[i][0], deg * p[i][1], deg * p[i][2]];
            for &(_, u) in &pairs[start[i]..start[i + 1]] {
                let j = id[u as usize];
                if j != u32::MAX {
                    for a in 0..3 {
                        s[a] -= p[j as usize][a];
                    }
                }
            }
            out[i] = s;
        }
    };
    let dot = |p: &[[f64; 3]], q: &[[f64; 3]]| -> [f64; 3] {
        let mut s = [0.0; 3];
        for (u, v) in p.iter().zip(q) {
            for a in 0..3 {
                s[a] += u[a] * v[a];
            }
        }
        s
    };
    // three independent systems (one per coordinate), Jacobi preconditioned
    let inv_deg: Vec<f64> = (0..n)
        .map(|i| 1.0 / ((start[i + 1] - start[i]).max(1) as f64))
        .collect();
    let mut y: Vec<[f64; 3]> = vars.iter().map(|&v| x[v]).collect();
    let mut ay = vec![[0.0; 3]; n];
    apply(&y, &mut ay);
    let mut r: Vec<[f64; 3]> = (0..n)
        .map(|i| [0, 1, 2].map(|a| b[i][a] - ay[i][a]))
        .collect();
    let precond = |r: &[[f64; 3]]| -> Vec<[f64; 3]> {
        r.iter()
            .zip(&inv_deg)
            .map(|(r, d)| r.map(|v| v * d))
            .collect()
    };
    let mut z = precond(&r);
    let mut p = z.clone();
    let mut rz = dot(&r, &z);
    let rz0 = rz;
    let mut ap = vec![[0.0; 3]; n];
    for _ in 0..iterations {
        if (0..3).all(|a| rz[a] <= 1e-20 * rz0[a].max(f64::MIN_POSITIVE)) {
            break;
        }
        apply(&p, &mut ap);
        let pap = dot(&p, &ap);
        let alpha = [0, 1, 2].map(|a| if pap[a] > 0.0 { rz[a] / pap[a] } else { 0.0 });
        for i in 0..n {
            for a in 0..3 {
                y[i][a] += alpha[a] * p[i][a];
                r[i][a] -= alpha[a] * ap[i][a];
            }
        }
        z = precond(&r);
        let rz_next = dot(&r, &z);
        let beta = [0, 1, 2].map(|a| if rz[a] > 0.0 { rz_next[a] / rz[a] } else { 0.0 });
        for i in 0..n {
            for a in 0..3 {
                p[i][a] = z[i][a] + beta[a] * p[i][a];
            }
        }
        rz = rz_next;
    }
    for (i, &v) in vars.iter().enumerate() {
        x[v] = y[i];
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 6 × 6 grid of quads with its inner vertices thrown about: the
    /// harmonic spread with the rim fixed puts them back on the grid.
    #[test]
    fn harmonic_restores_a_scrambled_grid() {
        let n = 7;
        let id = |i: usize, j: usize| (j * n + i) as u32;
        let grid: Vec<[f64; 3]> = (0..n * n)
            .map(|v| [(v % n) as f64, (v / n) as f64, 0.0])
            .collect();
        let cells: Vec<[u32; 4]> = (0..n - 1)
            .flat_map(|j| {
                (0..n - 1).map(move |i| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
            })
            .collect();
        let inner = |v: usize| (1..n - 1).contains(&(v % n)) && (1..n - 1).contains(&(v / n));
        let region: Vec<bool> = (0..n * n).map(inner).collect();
        let mut x = grid.clone();
        for (v, p) in x.iter_mut().enumerate() {
            if inner(v) {
                // all folded onto one corner, with some spread
                *p = [5.0 - 0.1 * (v % 3) as f64, 0.5, 0.3 * (v % 2) as f64];
            }
        }
        let edges = [[0, 1], [1, 2], [2, 3], [3, 0]];
        assert_eq!(harmonic(&mut x, &cells, &edges, &region, 100), 25);
        for (p, q) in x.iter().zip(&grid) {
            assert!(norm(sub(*p, *q)) < 1e-9, "{p:?} vs {q:?}");
        }
    }

    /// Stretched cells are found against the median, and a fold joins only
    /// the stretched cells reachable from a flagged one.
    #[test]
    fn a_fold_is_the_flagged_cells_and_their_stretched_neighbours() {
        // a row of 6 quads; quads 2 and 5 are 20 long (mean edge 10.5 against a median of 1)
        let xs = [0.0, 1.0, 2.0, 22.0, 23.0, 24.0, 44.0];
        let x: Vec<[f64; 3]> = xs
            .iter()
            .flat_map(|&a| [[a, 0.0, 0.0], [a, 1.0, 0.0]])
            .collect();
        let cells: Vec<[u32; 4]> = (0..6u32)
            .map(|i| [2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1])
            .collect();
        let edges = [[0, 1], [1, 2], [2, 3], [3, 0]];
        let (_, stretched, median) = sizes(&cells, &edges, &x, 1.0);
        assert_eq!(stretched, [false, false, true, false, false, true]);
        assert_eq!(median, 1.0);
        let around = super::super::topology::vertex_cells(x.len(), &cells);
        let flagged = [false, true, false, false, false, false];
        let joined = fold(&cells, &around, &flagged, &stretched).expect("a wide fold");
        assert_eq!(joined, [false, true, true, false, false, false]);
        let flagged = [true, false, false, false, false, false];
        assert!(fold(&cells, &around, &flagged, &stretched).is_none());
    }

    /// The median by selection is the element a sort puts at `len / 2`
    /// (ties, signed zeros, infinities; 1 when empty).
    #[test]
    fn median_by_selection_as_by_sort() {
        let mut rng = dualex_util::rng::SplitMix::new(7);
        let special = [0.0, -0.0, 1.0, 2.5, f64::INFINITY, 1e-300];
        for n in [0, 1, 2, 3, 4, 5, 20, 21, 100, 1001] {
            for _ in 0..20 {
                let values: Vec<f64> = (0..n)
                    .map(|_| match rng.below(3) {
                        0 => special[rng.below(special.len())],
                        1 => (rng.unit() * 4.0).round(),
                        _ => rng.unit() * 10.0,
                    })
                    .collect();
                let mut sorted = values.clone();
                sorted.sort_unstable_by(f64::total_cmp);
                let want = sorted.get(sorted.len() / 2).copied().unwrap_or(1.0);
                assert_eq!(median_of(&values).to_bits(), want.to_bits(), "{values:?}");
            }
        }
    }

    /// The mean edge by blocks of lengths taken in parallel is the serial
    /// sum's, bit for bit: lengths of many magnitudes (the order of the
    /// sum shows in its rounding), across several blocks.
    #[test]
    fn mean_edge_as_the_serial_sum() {
        let mut rng = dualex_util::rng::SplitMix::new(11);
        let edges = [[0, 1], [1, 2], [2, 3], [3, 0]];
        for cells_n in [
            0,
            1,
            7,
            MEAN_EDGE_BLOCK - 1,
            MEAN_EDGE_BLOCK,
            3 * MEAN_EDGE_BLOCK + 5,
        ] {
            let x: Vec<[f64; 3]> = (0..500)
                .map(|_| {
                    let s = 10f64.powi(rng.below(12) as i32 - 6);
                    [0; 3].map(|_| rng.unit() * s)
                })
                .collect();
            let cells: Vec<[u32; 4]> = (0..cells_n)
                .map(|_| [0; 4].map(|_| rng.below(x.len()) as u32))
                .collect();
            let (mut sum, mut n) = (0.0, 0usize);
            for c in &cells {
                for e in &edges {
                    sum += norm(sub(x[c[e[1]] as usize], x[c[e[0]] as usize]));
                    n += 1;
                }
            }
            let want = if n > 0 { sum / n as f64 } else { 0.0 };
            assert_eq!(mean_edge(&x, &cells, &edges).to_bits(), want.to_bits());
        }
    }
}

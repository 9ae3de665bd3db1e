//! Combinatorial refinement of a quad / hex mesh into `k^D` sub-cells per
//! element, with shared sub-vertices.
//!
//! Input: positions, elements in VTK corner order (`2^D` corners), `k`.
//! Output: [`Refined`]: the global id of every lattice point `(i, j[, l])`,
//! `0 <= i, j, l <= k`, of every element, and the sub-vertex positions
//! (multilinear interpolation of the corners).
//!
//! Invariant: a lattice point is keyed by its multilinear weights on the
//! element's corner *vertices* (integers summing to `k^D`), so a point on
//! an edge or face shared by two elements gets one id whatever the two
//! frames are (the weights of a shared face only involve its corners).
//!
//! ```text
//!   corner bits b = x + 2y + 4z  ↔  VTK index BIT_TO_VTK[b] = [0,1,3,2][x+2y] + 4z
//! ```

use super::FromMeshError;
use std::collections::HashMap;

/// VTK corner index of the cube corner with bits `x + 2y + 4z`.
pub(crate) const BIT_TO_VTK: [usize; 8] = [0, 1, 3, 2, 4, 5, 7, 6];

/// The refined mesh (module docs).
pub(crate) struct Refined<const D: usize> {
    /// Sub-cells per element edge.
    pub k: usize,
    /// Number of elements.
    pub elements: usize,
    /// Positions of the sub-vertices (global ids).
    pub positions: Vec<[f64; 3]>,
    /// `ids[e·(k+1)^D + lattice index]`: the global id of a lattice point,
    /// lattice index `i + (k+1)·j + (k+1)²·l`.
    ids: Vec<u32>,
}

impl<const D: usize> Refined<D> {
    /// Refines `cells` (each of `2^D` corners, VTK order).
    pub(crate) fn new<const K: usize>(
        positions: &[[f64; 3]],
        cells: &[[u32; K]],
        k: usize,
    ) -> Result<Self, FromMeshError> {
        debug_assert_eq!(K, 1 << D);
        if cells.is_empty() {
            return Err(FromMeshError::Empty);
        }
        if let Some(v) = positions
            .iter()
            .position(|p| p.iter().any(|x| !x.is_finite()))
        {
            return Err(FromMeshError::NonFinite { vertex: v });
        }
        for (e, c) in cells.iter().enumerate() {
            let bad = c
                .iter()
                .enumerate()
                .any(|(i, &v)| v as usize >= positions.len() || c[..i].contains(&v));
            if bad {
                return Err(FromMeshError::BadElement { element: e });
            }
        }
        let side = k + 1;
        let per = side.pow(D as u32);
        let mut keys: HashMap<Vec<(u32, u64)>, u32> = HashMap::new();
        let mut out = Refined {
            k,
            elements: cells.len(),
            positions: Vec::new(),
            ids: Vec::with_capacity(cells.len() * per),
        };
        let total = (k as f64).powi(D as i32);
        for cell in cells {
            for idx in 0..per {
                let lat = lattice::<D>(idx, side);
                let mut key: Vec<(u32, u64)> = Vec::with_capacity(K);
                for bits in 0..K {
                    let w: u64 = (0..D)
                        .map(|a| {
                            if bits >> a & 1 == 1 {
                                lat[a] as u64
                            } else {
                                (k - lat[a]) as u64
                            }
                        })
                        .product();
                    if w > 0 {
                        key.push((cell[BIT_TO_VTK[bits]], w));
                    }
                }
                key.sort_unstable();
                let next = out.positions.len() as u32;
                let id = *keys.entry(key).or_insert_with_key(|key| {
                    let mut p = [0.0; 3];
                    for &(v, w) in key {
                        for (a, x) in p.iter_mut().enumerate() {
                            *x += w as f64 * positions[v as usize][a];
                        }
                    }
                    out.positions.push(p.map(|x| x / total));
                    next
                });
                out.ids.push(id);
            }
        }
        Ok(out)
    }

    /// Global id of lattice point `lat` of element `e`.
    pub(crate) fn id(&self, e: usize, lat: [usize; D]) -> u32 {
        let side = self.k + 1;
        let mut idx = 0;
        for a in (0..D).rev() {
            idx = idx * side + lat[a];
        }
        self.ids[e * side.pow(D as u32) + idx]
    }

    /// Every sub-cell as `(element, min lattice corner)`.
    pub(crate) fn sub_cells(&self) -> impl Iterator<Item = (usize, [usize; D])> + '_ {
        let per = self.k.pow(D as u32);
        (0..self.elements).flat_map(move |e| (0..per).map(move |i| (e, lattice::<D>(i, self.k))))
    }

    /// Lattice point of corner `bits` of the sub-cell at `min`.
    pub(crate) fn corner(min: [usize; D], bits: usize) -> [usize; D] {
        std::array::from_fn(|a| min[a] + (bits >> a & 1))
    }

    fn cells<const K: usize>(&self) -> Vec<[u32; K]> {
        self.sub_cells()
            .map(|(e, min)| {
                let mut c = [0u32; K];
                for bits in 0..K {
                    c[BIT_TO_VTK[bits]] = self.id(e, Self::corner(min, bits));
                }
                c
            })
            .collect()
    }
}

impl Refined<2> {
    /// `M_k` as a quad mesh.
    pub(crate) fn quad_mesh(&self) -> dualex_cells::QuadMesh {
        dualex_cells::QuadMesh {
            positions: self.positions.clone(),
            cells: self.cells::<4>(),
        }
    }
}

impl Refined<3> {
    /// `M_k` as a hex mesh.
    pub(crate) fn hex_mesh(&self) -> dualex_cells::HexMesh {
        dualex_cells::HexMesh {
            positions: self.positions.clone(),
            cells: self.cells::<8>(),
        }
    }
}

/// Lattice coordinates of index `idx` (first axis fastest) with `side`
/// points per axis.
fn lattice<const D: usize>(mut idx: usize, side: usize) -> [usize; D] {
    std::array::from_fn(|_| {
        let x = idx % side;
        idx /= side;
        x
    })
}

//! Test maps: a box of cubes, 6 positive tets per cube (Kuhn subdivision,
//! conforming), with the map given per vertex by a function of its grid
//! index; and the checks every test output must pass.

use dualex_cells::HexMesh;
use dualex_map::{Rot3, TetMap};

/// Grid lines along one axis.
pub type Lines = Vec<f64>;

/// Evenly spaced lines from `lo` to `hi`, `n` cells.
pub fn even(lo: f64, hi: f64, n: usize) -> Lines {
    (0..=n)
        .map(|i| lo + (hi - lo) * i as f64 / n as f64)
        .collect()
}

/// The box with grid lines `l[axis]`; positions = map values = the grid
/// point (identity map), then `f` applied to each corner's map value with
/// the tet's index and centroid (to re-chart or perturb).
pub fn block(l: &[Lines; 3], f: impl Fn(usize, [f64; 3], [f64; 3]) -> [f64; 3]) -> TetMap {
    let n = [l[0].len() - 1, l[1].len() - 1, l[2].len() - 1];
    let id = |i: usize, j: usize, k: usize| ((k * (n[1] + 1) + j) * (n[0] + 1) + i) as u32;
    let mut m = TetMap::default();
    for k in 0..=n[2] {
        for j in 0..=n[1] {
            for i in 0..=n[0] {
                m.positions.push([l[0][i], l[1][j], l[2][k]]);
            }
        }
    }
    const PERMS: [[usize; 3]; 6] = [
        [0, 1, 2],
        [1, 2, 0],
        [2, 0, 1],
        [1, 0, 2],
        [0, 2, 1],
        [2, 1, 0],
    ];
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                for (pi, perm) in PERMS.iter().enumerate() {
                    let mut c = [i, j, k];
                    let mut t = [id(c[0], c[1], c[2]); 4];
                    for (s, &a) in perm.iter().enumerate() {
                        c[a] += 1;
                        t[s + 1] = id(c[0], c[1], c[2]);
                    }
                    if pi >= 3 {
                        t.swap(2, 3); // odd permutation: restore positive orientation
                    }
                    m.simplices.push(t);
                }
            }
        }
    }
    for (s, t) in m.simplices.iter().enumerate() {
        let p = t.map(|v| m.positions[v as usize]);
        let centroid: [f64; 3] = std::array::from_fn(|a| p.iter().map(|x| x[a]).sum::<f64>() / 4.0);
        m.coords.push(p.map(|x| f(s, x, centroid)));
    }
    m
}

/// The identity map.
pub fn identity(_: usize, x: [f64; 3], _: [f64; 3]) -> [f64; 3] {
    x
}

/// `R·x + T`.
pub fn rechart(r: &Rot3, t: [i64; 3], x: [f64; 3]) -> [f64; 3] {
    let y = r.apply(&x);
    [0, 1, 2].map(|k| y[k] + t[k] as f64)
}

/// Asserts that `mesh` is a valid n0×n1×n2 block of hexes: counts,
/// interior edge valences 4, one component, Euler characteristic 1,
/// checked by the independent checker; with `exact_geometry`, no inverted
/// cell either (noisy maps place vertices at noisy preimages). Returns the
/// number of inverted cells.
pub fn assert_block(
    mesh: &HexMesh,
    st: &crate::HexStats,
    n: [usize; 3],
    what: &str,
    exact_geometry: bool,
) -> usize {
    let js = st.to_json();
    assert_eq!(mesh.cells.len(), n[0] * n[1] * n[2], "{what}: {js}");
    assert_eq!(st.components, 1, "{what}: {js}");
    assert_eq!(st.euler, 1, "{what}: {js}");
    let interior: usize = (0..3)
        .map(|a| {
            n[a] * (0..3)
                .filter(|&b| b != a)
                .map(|b| n[b] - 1)
                .product::<usize>()
        })
        .sum();
    let mut want = std::collections::BTreeMap::new();
    want.insert(4, interior);
    assert_eq!(st.edge_valence_interior, want, "{what}: {js}");
    let boundary = 2 * (n[0] * n[1] + n[1] * n[2] + n[0] * n[2]);
    assert_eq!(st.unmatched_sides, boundary, "{what}: {js}");
    let rep =
        dualex_check::check_hex_mesh(mesh.positions.len(), &mesh.cells, Some(&mesh.positions));
    let inverted = rep.inverted_cells.as_ref().map_or(usize::MAX, |c| c.len());
    let combinatorial = rep.errors().into_iter().filter(|e| !e.contains("inverted"));
    assert_eq!(
        combinatorial.collect::<Vec<_>>(),
        Vec::<String>::new(),
        "{what}"
    );
    assert_eq!(rep.boundary_faces, boundary, "{what}");
    assert_eq!(rep.euler, 1, "{what}");
    assert_eq!(rep.components, 1, "{what}");
    if exact_geometry {
        assert_eq!(inverted, 0, "{what}");
    }
    inverted
}

//! Hex meshes with dense singular structure, as real hex meshes have:
//! singular vertices where 3 to 6 singular edges meet, interior singular
//! edges of valence 3, 5 and 6, for [`super::from_hexes`].
//!
//! Input: sizes. Output: valid, conforming, consistently oriented
//! [`HexMesh`]es (VTK order; the unit tests check them with
//! `dualex_check::check_hex_mesh`, positions included: no corner Jacobian
//! `<= 0`).
//!
//! - [`ball_cutout`]: a box of `n³` unit cells minus the cells meeting an
//!   open ball, plus one padding layer along the staircase surface left by
//!   the ball, its new vertices on a smaller concentric sphere (the classic
//!   dual-contoured / grid-based mesh of a cube minus a ball);
//! - [`polycube_notch`]: a `3×3×2` block with a notch (one cube cut out of
//!   the middle of a top edge) and a pit (the top centre cube), padded
//!   outwards all around;
//! - [`cubed_ball_sub`]: [`super::meshes::cubed_ball`] split linearly
//!   once (every hex into 8).
//!
//! Padding ([`pad`]): every chosen boundary quad `abcd` (outward) becomes
//! the hex `abcd a'b'c'd'`; a staircase edge with `m` old hexes around it
//! becomes an interior edge of valence `m + 2` (convex 1 → 3, concave
//! 3 → 5), and the edge `aa'` gets the valence of `a` on the padded
//! surface (3 … 6).
//!
//! ```text
//!        a'───b'        padding hex over the old boundary quad abcd
//!       ╱│   ╱│        (outward normal of abcd points to a'b'c'd')
//!     d'───c' │
//!     │  a──│─b
//!     │ ╱   │╱
//!     d─────c
//! ```

use super::refine::Refined;
use dualex_cells::HexMesh;
use std::collections::{BTreeMap, HashMap};

pub use dualex_cells::cells::{HEX_EDGES, HEX_FACES};

/// The unit cells `(i, j, l)`, `0 <= i, j, l < n`, for which `keep` holds,
/// as hexes with corners at integer points shifted by `-n/2` (the box is
/// centred at the origin); unused lattice points are dropped.
pub fn grid_cells(n: usize, keep: impl Fn([usize; 3]) -> bool) -> HexMesh {
    let m = n + 1;
    let lat = |i: usize, j: usize, l: usize| ((l * m + j) * m + i) as u32;
    let mut cells = Vec::new();
    for l in 0..n {
        for j in 0..n {
            for i in 0..n {
                if keep([i, j, l]) {
                    // VTK: (0,0), (1,0), (1,1), (0,1) at z = 0, then z = 1
                    let sq = [(0, 0), (1, 0), (1, 1), (0, 1)];
                    cells.push(std::array::from_fn(|c| {
                        let (x, y) = sq[c % 4];
                        lat(i + x, j + y, l + c / 4)
                    }));
                }
            }
        }
    }
    let h = n as f64 / 2.0;
    let positions = (0..m * m * m)
        .map(|v| [v % m, v / m % m, v / (m * m)].map(|x| x as f64 - h))
        .collect();
    HexMesh { positions, cells }.without_unused_vertices()
}

/// The boundary quads (faces of one hex), outward, in hex order.
pub fn boundary_quads(mesh: &HexMesh) -> Vec<[u32; 4]> {
    let mut uses: HashMap<[u32; 4], (usize, [u32; 4])> = HashMap::new();
    for h in &mesh.cells {
        for f in HEX_FACES {
            let q = f.map(|i| h[i]);
            let mut key = q;
            key.sort_unstable();
            uses.entry(key).or_insert((0, q)).0 += 1;
        }
    }
    let mut out = Vec::new();
    for h in &mesh.cells {
        for f in HEX_FACES {
            let q = f.map(|i| h[i]);
            let mut key = q;
            key.sort_unstable();
            if uses[&key].0 == 1 {
                out.push(q);
            }
        }
    }
    out
}

fn sub(p: [f64; 3], q: [f64; 3]) -> [f64; 3] {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn unit(a: [f64; 3]) -> [f64; 3] {
    let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    a.map(|x| x / l)
}

/// One padding layer over the boundary quads for which `chosen` holds
/// (module docs). `place(position, normal)` gives the new vertex of an old
/// one from its position and the sum of the unit outward normals of its
/// chosen quads.
pub fn pad(
    mesh: &HexMesh,
    chosen: impl Fn(&HexMesh, &[u32; 4]) -> bool,
    place: impl Fn([f64; 3], [f64; 3]) -> [f64; 3],
) -> HexMesh {
    let quads: Vec<[u32; 4]> = boundary_quads(mesh)
        .into_iter()
        .filter(|q| chosen(mesh, q))
        .collect();
    let mut normal: BTreeMap<u32, [f64; 3]> = BTreeMap::new();
    for q in &quads {
        let p = q.map(|v| mesh.positions[v as usize]);
        let n = unit(cross(sub(p[2], p[0]), sub(p[3], p[1])));
        for v in q {
            let s = normal.entry(*v).or_insert([0.0; 3]);
            for a in 0..3 {
                s[a] += n[a];
            }
        }
    }
    let mut positions = mesh.positions.clone();
    let mut new: HashMap<u32, u32> = HashMap::new();
    for (&v, &n) in &normal {
        new.insert(v, positions.len() as u32);
        positions.push(place(mesh.positions[v as usize], n));
    }
    let mut cells = mesh.cells.clone();
    for q in &quads {
        cells.push(std::array::from_fn(|i| {
            if i < 4 {
                q[i]
            } else {
                new[&q[i - 4]]
            }
        }));
    }
    HexMesh { positions, cells }
}

/// Closest distance from the origin to the unit cell with lower corner
/// `lo` (coordinates already centred).
fn cell_distance(lo: [f64; 3], centre: [f64; 3]) -> f64 {
    let d: f64 = (0..3)
        .map(|a| {
            let x = (centre[a] - lo[a]).clamp(0.0, 1.0) + lo[a] - centre[a];
            x * x
        })
        .sum();
    d.sqrt()
}

/// Centre of the ball of [`ball_cutout`], off the lattice so that the
/// staircase is not symmetric (cell units, relative to the box centre).
pub const BALL_CENTRE: [f64; 3] = [0.21, 0.13, 0.07];

/// A box of `n³` unit cells (centred at the origin) minus the cells that
/// meet the open ball of radius `r` around [`BALL_CENTRE`], plus one
/// padding layer on the hole's staircase surface, its new vertices on the
/// concentric sphere of radius `r − ½` (module docs). Note: one padding
/// layer over a staircase of a convex set gives interior singular
/// vertices of 4 edges (hole corners: 3 of valence 5, 1 of valence 3) and
/// 7 edges (saddles: 3 of valence 3, 3 of valence 5, 1 of valence 6) only. Refuses (`None`) a
/// ball that reaches the box's outer layer of cells or leaves no hole.
pub fn ball_cutout(n: usize, r: f64) -> Option<HexMesh> {
    ball_cutout_rule(n, r, false)
}

/// [`ball_cutout`]; with `by_centre` the cells whose centre is inside the
/// ball are dropped instead (a staircase with vertices inside the ball:
/// those move `½` towards the centre instead of onto the sphere).
pub fn ball_cutout_rule(n: usize, r: f64, by_centre: bool) -> Option<HexMesh> {
    let h = n as f64 / 2.0;
    let c = BALL_CENTRE;
    let lo = |i: [usize; 3]| i.map(|x| x as f64 - h);
    let inside = |i: [usize; 3]| {
        if by_centre {
            let d: f64 = (0..3).map(|a| (lo(i)[a] + 0.5 - c[a]).powi(2)).sum();
            d.sqrt() < r
        } else {
            cell_distance(lo(i), c) < r
        }
    };
    let layer = |i: [usize; 3]| i.iter().any(|&x| x == 0 || x + 1 == n);
    let all = (0..n * n * n).map(|v| [v % n, v / n % n, v / (n * n)]);
    if n < 3 || r <= 0.5 || all.clone().any(|i| inside(i) && layer(i)) {
        return None;
    }
    if !all.clone().any(inside) {
        return None;
    }
    let grid = grid_cells(n, |i| !inside(i));
    let on_box = |p: [f64; 3]| p.iter().any(|x| x.abs() == h);
    let chosen = |m: &HexMesh, q: &[u32; 4]| !q.iter().all(|&v| on_box(m.positions[v as usize]));
    Some(pad(&grid, chosen, |p, _| {
        let d = sub(p, c);
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let s = (r - 0.5).min(l - (0.5f64).min(l / 2.0));
        let d = unit(d);
        std::array::from_fn(|a| c[a] + s * d[a])
    }))
}

/// The `3×3×2` block with a notch and a pit (module docs), padded
/// outwards by `0.3` along the vertex normals.
pub fn polycube_notch() -> HexMesh {
    // cells of a 4-grid: keep 3×3×2 at i, j in 0..3, l in 0..2
    let keep = |[i, j, l]: [usize; 3]| {
        let notch = [i, j, l] == [1, 0, 1];
        let pit = [i, j, l] == [1, 1, 1];
        i < 3 && j < 3 && l < 2 && !notch && !pit
    };
    let block = grid_cells(4, keep);
    pad(
        &block,
        |_, _| true,
        |p, n| {
            let n = unit(n);
            std::array::from_fn(|a| p[a] + 0.3 * n[a])
        },
    )
}

/// [`super::meshes::cubed_ball`] with every hex split into 8.
pub fn cubed_ball_sub() -> HexMesh {
    let m = super::meshes::cubed_ball();
    let r = Refined::<3>::new(&m.positions, &m.cells, 2).expect("the cubed ball is valid");
    r.hex_mesh()
}

/// Singular structure of a hex mesh: interior edges of valence `≠ 4`, and
/// for every vertex on one of them, how many meet there.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SingularStructure {
    /// Valence → number of interior singular edges.
    pub edges: BTreeMap<usize, usize>,
    /// Interior vertices: incident singular edges → count (2 only when
    /// the two valences differ).
    pub vertices: BTreeMap<usize, usize>,
    /// Boundary vertices on a singular edge (its ends).
    pub boundary_ends: usize,
}

/// The [`SingularStructure`] of `mesh`.
pub fn singular_structure(mesh: &HexMesh) -> SingularStructure {
    let mut valence: HashMap<[u32; 2], usize> = HashMap::new();
    for h in &mesh.cells {
        for [a, b] in HEX_EDGES {
            *valence.entry([h[a].min(h[b]), h[a].max(h[b])]).or_default() += 1;
        }
    }
    let mut on_boundary = vec![false; mesh.positions.len()];
    let mut boundary_edge = std::collections::HashSet::new();
    for q in boundary_quads(mesh) {
        for i in 0..4 {
            let (a, b) = (q[i], q[(i + 1) % 4]);
            on_boundary[a as usize] = true;
            boundary_edge.insert([a.min(b), a.max(b)]);
        }
    }
    let mut s = SingularStructure::default();
    // per vertex: the valences of its singular edges
    let mut incident: Vec<Vec<usize>> = vec![Vec::new(); mesh.positions.len()];
    for (e, &v) in &valence {
        if v != 4 && !boundary_edge.contains(e) {
            *s.edges.entry(v).or_default() += 1;
            incident[e[0] as usize].push(v);
            incident[e[1] as usize].push(v);
        }
    }
    for (v, vals) in incident.iter().enumerate() {
        if vals.is_empty() {
            continue;
        }
        if on_boundary[v] {
            s.boundary_ends += 1;
        } else if vals.len() != 2 || vals[0] != vals[1] {
            *s.vertices.entry(vals.len()).or_default() += 1;
        }
    }
    s
}

/// Names of the meshes of [`dense_mesh_by_name`], small first.
pub fn dense_mesh_names() -> Vec<String> {
    [
        "ball_hole69",
        "ball_cutout4",
        "ball_cutout5",
        "ball_cutout6",
        "ball_cutout8",
        "ball_centre8",
        "polycube_notch",
        "cubed_ball_sub",
    ]
    .map(String::from)
    .to_vec()
}

/// The parameters `(n, r, by_centre)` of the named ball cut-outs
/// ([`ball_cutout_rule`]).
pub fn ball_cutout_size(name: &str) -> Option<(usize, f64, bool)> {
    match name {
        "ball_cutout4" => Some((4, 0.6, false)),
        "ball_hole69" => Some((4, 0.7, true)),
        "ball_cutout5" => Some((5, 0.8, false)),
        "ball_cutout6" => Some((6, 1.3, false)),
        "ball_cutout8" => Some((8, 2.4, false)),
        "ball_centre8" => Some((8, 3.0, true)),
        // by hand (about 10k hexes)
        "ball_cutout_full" => Some((22, 8.1, false)),
        "ball_centre_full" => Some((22, 7.2, true)),
        _ => None,
    }
}

/// The mesh called `name` (see [`dense_mesh_names`]; also
/// `ball_cutout_full` and `ball_centre_full`, about 10k hexes each).
pub fn dense_mesh_by_name(name: &str) -> Option<HexMesh> {
    if let Some((n, r, by_centre)) = ball_cutout_size(name) {
        return ball_cutout_rule(n, r, by_centre);
    }
    match name {
        "polycube_notch" => Some(polycube_notch()),
        "cubed_ball_sub" => Some(cubed_ball_sub()),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn valid(name: &str, m: &HexMesh) {
        let r = dualex_check::check_hex_mesh(m.positions.len(), &m.cells, Some(&m.positions));
        assert!(r.is_valid(), "{name}: {:?}", r.errors());
        assert_eq!(r.vertices_used, m.positions.len(), "{name}");
    }

    #[test]
    fn dense_meshes_are_valid_and_singular_where_expected() {
        for name in dense_mesh_names() {
            let m = dense_mesh_by_name(&name).unwrap_or_else(|| panic!("{name}"));
            valid(&name, &m);
            let s = singular_structure(&m);
            eprintln!("{name}: {} hexes, {s:?}", m.cells.len());
            assert!(!s.edges.is_empty(), "{name}: no singular edge");
        }
    }

    #[test]
    fn the_ball_cutouts_have_valence_3_5_6_and_vertices_of_4_and_7_edges() {
        let m = dense_mesh_by_name("ball_cutout8").unwrap();
        let s = singular_structure(&m);
        for v in [3, 5, 6] {
            assert!(s.edges.contains_key(&v), "valence {v}: {s:?}");
        }
        for n in [4, 7] {
            assert!(s.vertices.contains_key(&n), "{n} edges: {s:?}");
        }
    }

    #[test]
    fn a_ball_touching_the_outer_layer_is_refused() {
        assert!(ball_cutout(4, 1.6).is_none());
        assert!(ball_cutout(6, 0.4).is_none());
    }

    #[test]
    fn a_broken_padding_is_caught_by_the_checker() {
        let mut m = ball_cutout(4, 0.6).unwrap();
        let last = m.cells.len() - 1;
        m.cells[last].swap(1, 3);
        let r = dualex_check::check_hex_mesh(m.positions.len(), &m.cells, None);
        assert!(!r.is_valid());
    }
}

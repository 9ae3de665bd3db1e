//! Vertex classes and the chart rotations around every vertex.
//!
//! Input: a clean (unperturbed) map of [`super::from_quads`] /
//! [`super::from_hexes`]: exact integer transitions. Output: per vertex a
//! [`Star`]: its corners with the rotation of each corner's chart relative
//! to the vertex's home chart (the first simplex holding it), found by a
//! walk through the facets around the vertex; the holonomy group (the
//! rotations met when the walk closes a loop); the [`VertexClass`].
//!
//! Class (computed independently of dualex-map): `Boundary` when the vertex
//! is on a boundary facet; else from the refined mesh `M_k` (2D: interior
//! valence ≠ 4 → `Singular`; 3D: on 2 interior edges of valence ≠ 4 →
//! `SingularEdge`, on 1 or more than 2 → `Singular`), raised to `Singular`
//! when the holonomy fixes no direction. The holonomy alone cannot see a
//! cone of a whole number of turns (valence 8: trivial holonomy), hence
//! the combinatorial test.

use dualex_cells::cells::{HEX_EDGES, HEX_FACES};
use dualex_cells::{HexMesh, QuadMesh};
use dualex_map::{Rot, SimplexMap};
use std::collections::HashMap;

/// What kind of vertex a map vertex is (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum VertexClass {
    /// Interior, trivial holonomy.
    Regular,
    /// On the boundary.
    Boundary,
    /// Interior, inside a singular edge (3D only).
    SingularEdge,
    /// Interior, no direction fixed by the holonomy.
    Singular,
}

/// The corners of one vertex with their chart rotations (module docs).
pub(crate) struct Star<const D: usize> {
    /// `(simplex, corner, rotation home → that simplex's chart)`.
    pub corners: Vec<(usize, usize, Rot<D>)>,
    /// The holonomy group (in the home chart), identity included.
    pub group: Vec<Rot<D>>,
    /// On a boundary facet.
    pub boundary: bool,
}

impl<const D: usize> Star<D> {
    /// Projects `d` (home chart) onto the subspace fixed by the holonomy.
    pub(crate) fn project(&self, d: [f64; D]) -> [f64; D] {
        let mut s = [0.0; D];
        for g in &self.group {
            let gd = g.apply(&d);
            for a in 0..D {
                s[a] += gd[a];
            }
        }
        s.map(|x| x / self.group.len() as f64)
    }

    fn class(&self, combinatorial: VertexClass) -> VertexClass {
        if self.boundary {
            return VertexClass::Boundary;
        }
        if combinatorial == VertexClass::Singular {
            return combinatorial;
        }
        // dimension of the fixed subspace: rank of the projector
        let dim = (0..D)
            .filter(|&a| {
                let mut e = [0.0; D];
                e[a] = 1.0;
                self.project(e)[a] != 0.0
            })
            .count();
        match dim {
            0 => VertexClass::Singular,
            d if d == D => combinatorial,
            _ => VertexClass::SingularEdge,
        }
    }
}

/// The rotation `R` with `q_i − q_0 = R·(p_i − p_0)` for the shared
/// vertices, if any.
fn facet_rotation<const D: usize>(p: &[[f64; D]], q: &[[f64; D]]) -> Option<Rot<D>> {
    Rot::<D>::all().into_iter().find(|r| {
        (1..p.len()).all(|i| {
            let dp: [f64; D] = std::array::from_fn(|a| p[i][a] - p[0][a]);
            let dq: [f64; D] = std::array::from_fn(|a| q[i][a] - q[0][a]);
            r.apply(&dp) == dq
        })
    })
}

/// The closure of `gens` under composition.
fn closure<const D: usize>(gens: &[Rot<D>]) -> Vec<Rot<D>> {
    let mut group = vec![Rot::<D>::IDENTITY];
    let mut i = 0;
    while i < group.len() {
        for g in gens {
            let h = group[i].then(g);
            if !group.contains(&h) {
                group.push(h);
            }
        }
        i += 1;
    }
    group
}

/// The star of every vertex (module docs).
pub(crate) fn stars<const N: usize, const D: usize>(map: &SimplexMap<N, D>) -> Vec<Star<D>> {
    let nv = map.positions.len();
    let mut incident: Vec<Vec<(usize, usize)>> = vec![Vec::new(); nv];
    let mut facets: HashMap<Vec<u32>, Vec<usize>> = HashMap::new();
    for (s, simplex) in map.simplices.iter().enumerate() {
        for (c, &v) in simplex.iter().enumerate() {
            incident[v as usize].push((s, c));
            let mut f: Vec<u32> = simplex.iter().copied().filter(|&w| w != v).collect();
            f.sort_unstable();
            facets.entry(f).or_default().push(s);
        }
    }
    (0..nv)
        .map(|v| star_of(map, v as u32, &incident[v], &facets))
        .collect()
}

fn star_of<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    v: u32,
    incident: &[(usize, usize)],
    facets: &HashMap<Vec<u32>, Vec<usize>>,
) -> Star<D> {
    let mut rot: HashMap<usize, Rot<D>> = HashMap::new();
    let (mut holonomy, mut boundary) = (Vec::new(), false);
    let mut queue: Vec<usize> = Vec::new();
    if let Some(&(s0, _)) = incident.first() {
        rot.insert(s0, Rot::IDENTITY);
        queue.push(s0);
    }
    while let Some(s) = queue.pop() {
        let rs = rot[&s];
        for &w in map.simplices[s].iter().filter(|&&w| w != v) {
            let mut f: Vec<u32> = map.simplices[s]
                .iter()
                .copied()
                .filter(|&x| x != w)
                .collect();
            f.sort_unstable();
            let others: Vec<usize> = facets.get(&f).map_or(Vec::new(), |l| {
                l.iter().copied().filter(|&t| t != s).collect()
            });
            if others.is_empty() {
                boundary = true;
            }
            for t in others {
                let at = |x: usize, u: u32| {
                    let c = map.simplices[x].iter().position(|&y| y == u).unwrap_or(0);
                    map.coords[x][c]
                };
                let p: Vec<[f64; D]> = f.iter().map(|&u| at(s, u)).collect();
                let q: Vec<[f64; D]> = f.iter().map(|&u| at(t, u)).collect();
                // no rotation: not a GP map; no direction is trusted then
                let r = facet_rotation(&p, &q).unwrap_or(Rot::IDENTITY);
                let rt = rs.then(&r);
                match rot.get(&t) {
                    None => {
                        rot.insert(t, rt);
                        queue.push(t);
                    }
                    Some(old) if *old != rt => holonomy.push(rt.then(&old.inverse())),
                    Some(_) => {}
                }
            }
        }
    }
    let corners = incident
        .iter()
        .map(|&(s, c)| (s, c, rot.get(&s).copied().unwrap_or(Rot::IDENTITY)))
        .collect();
    Star {
        corners,
        group: closure(&holonomy),
        boundary,
    }
}

/// The class of every vertex from its star ([`stars`]), given its class
/// in `M_k` (`Regular` for vertices not in it).
pub(crate) fn classify<const D: usize>(
    stars: &[Star<D>],
    combinatorial: &[VertexClass],
) -> Vec<VertexClass> {
    stars
        .iter()
        .enumerate()
        .map(|(v, s)| {
            s.class(
                combinatorial
                    .get(v)
                    .copied()
                    .unwrap_or(VertexClass::Regular),
            )
        })
        .collect()
}

/// Classes from the quad mesh `M_k` (interior valence ≠ 4: `Singular`;
/// boundary vertices are told apart by the map).
pub(crate) fn from_quad_mesh(mesh: &QuadMesh) -> Vec<VertexClass> {
    let mut valence = vec![0u32; mesh.positions.len()];
    for q in &mesh.cells {
        for &v in q {
            valence[v as usize] += 1;
        }
    }
    valence
        .iter()
        .map(|&n| match n {
            4 => VertexClass::Regular,
            _ => VertexClass::Singular,
        })
        .collect()
}

/// Classes from the hex mesh `M_k` (module docs).
pub(crate) fn from_hex_mesh(mesh: &HexMesh) -> Vec<VertexClass> {
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
    let mut boundary: HashMap<(u32, u32), ()> = HashMap::new();
    let mut faces: HashMap<[u32; 4], (u32, [u32; 4])> = HashMap::new();
    for h in &mesh.cells {
        for [a, b] in HEX_EDGES {
            *edges.entry(key(h[a], h[b])).or_insert(0) += 1;
        }
        for f in HEX_FACES {
            let cyc = f.map(|i| h[i]);
            let mut k = cyc;
            k.sort_unstable();
            faces.entry(k).or_insert((0, cyc)).0 += 1;
        }
    }
    for (n, cyc) in faces.values() {
        if *n == 1 {
            for i in 0..4 {
                boundary.insert(key(cyc[i], cyc[(i + 1) % 4]), ());
            }
        }
    }
    let mut count = vec![0u32; mesh.positions.len()];
    for (&(a, b), &n) in &edges {
        if n != 4 && !boundary.contains_key(&(a, b)) {
            count[a as usize] += 1;
            count[b as usize] += 1;
        }
    }
    count
        .iter()
        .map(|&c| match c {
            0 => VertexClass::Regular,
            2 => VertexClass::SingularEdge,
            _ => VertexClass::Singular,
        })
        .collect()
}

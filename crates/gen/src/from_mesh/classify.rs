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
//! is on a boundary facet; else by the subspace fixed by the holonomy:
//! everything → `Regular`, a line (3D: a vertex inside a singular edge) →
//! `SingularEdge`, only 0 → `Singular` (2D: a cone vertex, valence ≠ 4;
//! 3D: where non-collinear singular edges meet).

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

    fn class(&self) -> VertexClass {
        if self.boundary {
            return VertexClass::Boundary;
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
            d if d == D => VertexClass::Regular,
            0 => VertexClass::Singular,
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

/// The class of every vertex.
pub(crate) fn classify<const N: usize, const D: usize>(map: &SimplexMap<N, D>) -> Vec<VertexClass> {
    stars(map).iter().map(Star::class).collect()
}

//! The linear constraints of a seamless map and its integer unknowns.
//!
//! Input: the [`Surface`], the [`Charts`] and the singular vertices.
//! Unknown `2·w + c` is coordinate `c` (0: u, 1: v) of wedge `w`.
//!
//! **Seams.** Across a seam with combed matching `p` (the field of face
//! `f1` is the transported field of `f0` turned by `p` quarter turns
//! counter-clockwise, see [`crate::field`]), the gradients of `f1`'s chart
//! are `f0`'s turned by `p` quarter turns, so in the `(u, v)` plane
//! `w₁ = M_p·w₀ + t` with `M_p` the rotation by `−p·90°`
//! (`M_1 = [[0, 1], [−1, 0]]`: `u₁ = v₀`, `v₁ = −u₀`) and one translation
//! `t` for the whole edge: at the seam's endpoints `a`, `b`,
//! `A₁ − M·A₀ = B₁ − M·B₀` (two rows). The translation is left implicit
//! (it is `A₁ − M·A₀`), which is what the rounding makes integer.
//!
//! **Boundary alignment.** A boundary edge within `tolerance` of a field
//! direction of its face is an iso-line: of `v` when it runs along the
//! field's first direction `d` (or `−d`), of `u` along `±d⊥`; rows
//! `A_c = B_c`, and `A_c` is an integer unknown.
//!
//! **Feature alignment.** A sharp edge (given per edge) is aligned the
//! same way, in the chart of its first face: across a seam the other
//! side's coordinate differs by a quarter-turn rotation and an integer
//! translation, so it is an integer iso-line there too. Its iso-value
//! is rounded with the boundary ones, before the seam translations
//! (rounded after them, the genus-3 plate kept inverted quads at 100
//! quads on 2 of 10 runs of `tools/remesh-table`). Feature curves do not always
//! fit the grid: a closed feature loop around singular vertices (the CAD
//! box's boss rim) leaves a seam translation at a half-integer (the
//! extraction then refused the map: 7 of 16 runs at 300 and 1000 quads);
//! the rounding counts it as a conflict, and the integration then makes
//! the map without sharp edges ([`super::IntegrateOptions::sharp`]).
//!
//! **Gauge.** The map of a component can be translated in the directions
//! that every row leaves free; [`Gauge::rows`] fixes exactly those at one
//! wedge (after rounding, the integer unknowns usually fix the translation
//! already, and an arbitrary wedge must not be pinned to an integer point).
//!
//! Output: [`Constraints`]: the rows, and the integer unknowns as forms
//! (the coordinates of one wedge per singular vertex first, then boundary
//! iso-values, then sharp iso-values, then seam translations).

use super::charts::Charts;
use super::elim::Form;
use crate::error::RemeshError;
use crate::field::wrap;
use crate::surface::{Surface, NO_FACE};
use std::f64::consts::FRAC_PI_2;

/// Rows and integer unknowns (module docs).
#[derive(Clone, Debug, Default)]
pub struct Constraints {
    /// Rows `form = 0`, always imposed.
    pub rows: Vec<Form>,
    /// The gauge (module docs).
    pub gauge: Gauge,
    /// Integer unknowns of the singular vertices (one wedge each).
    pub singular: Vec<Form>,
    /// Integer unknowns of the aligned boundary edges.
    pub boundary: Vec<Form>,
    /// Per entry of `boundary`: its edge, face and coordinate.
    pub boundary_edges: Vec<AlignedEdge>,
    /// Integer unknowns of the aligned sharp edges (module docs).
    pub sharp: Vec<Form>,
    /// Integer unknowns of the seams (two per seam edge).
    pub translations: Vec<Form>,
    /// Boundary edges aligned.
    pub aligned_edges: usize,
}

/// An aligned boundary edge: an iso-line of `coordinate` (0: u, 1: v)
/// in the chart of `face`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AlignedEdge {
    /// The edge.
    pub edge: u32,
    /// Its face.
    pub face: u32,
    /// The coordinate constant along it.
    pub coordinate: u32,
}

/// Where the translations of the components are fixed (module docs).
#[derive(Clone, Debug, Default)]
pub struct Gauge {
    /// Per component: the wedge fixed.
    pub wedge: Vec<u32>,
    /// Per wedge: its component.
    pub component: Vec<u32>,
    /// Where the fixed wedges sit (`(0, 0)` by default): moving it moves
    /// the continuous map against the grid, so the rounding lands
    /// elsewhere (the remesher's seed).
    pub offset: [f64; 2],
}

impl Gauge {
    /// Rows fixing, at each component's gauge wedge, the translations
    /// that all of `rows` leave free: a translation by `(a, b)` changes
    /// a row by `a·Σ(u coefficients) + b·Σ(v coefficients)`.
    pub fn rows<'a>(&self, rows: impl Iterator<Item = &'a Form>) -> Vec<Form> {
        // per component: Σ over rows of gᵀg, g = (Σ u coeffs, Σ v coeffs)
        let mut gram = vec![[0.0f64; 3]; self.wedge.len()];
        let mut some = vec![[0.0f64; 2]; self.wedge.len()];
        for r in rows {
            let Some(&(x, _)) = r.terms.first() else {
                continue;
            };
            let c = self.component[(x / 2) as usize] as usize;
            let mut g = [0.0; 2];
            for &(x, k) in &r.terms {
                g[(x % 2) as usize] += k;
            }
            gram[c][0] += g[0] * g[0];
            gram[c][1] += g[0] * g[1];
            gram[c][2] += g[1] * g[1];
            if g[0].abs() + g[1].abs() > 1e-9 {
                some[c] = g;
            }
        }
        let mut out = Vec::new();
        for (c, &w) in self.wedge.iter().enumerate() {
            let [a, b, d] = gram[c];
            let [ou, ov] = self.offset;
            let row = |ku: f64, kv: f64| Form {
                terms: vec![(2 * w, ku), (2 * w + 1, kv)],
                constant: -(ku * ou + kv * ov),
            };
            if a + d <= 1e-9 {
                out.extend([row(1.0, 0.0), row(0.0, 1.0)]);
            } else if a * d - b * b <= 1e-9 * (a + d) * (a + d) {
                // one free direction, perpendicular to the rows' g
                let [x, y] = some[c];
                out.push(row(-y, x));
            }
        }
        out
    }
}

/// The rotation `M_p` of the `(u, v)` plane across a seam of matching `p`:
/// by `−p` quarter turns.
pub fn seam_rotation(p: u8) -> [[f64; 2]; 2] {
    match p % 4 {
        0 => [[1.0, 0.0], [0.0, 1.0]],
        1 => [[0.0, 1.0], [-1.0, 0.0]],
        2 => [[-1.0, 0.0], [0.0, -1.0]],
        _ => [[0.0, -1.0], [1.0, 0.0]],
    }
}

/// `A₁,c − (M·A₀)_c` as a form (`a0`, `a1` wedges).
fn translation(a0: u32, a1: u32, m: &[[f64; 2]; 2], c: usize) -> Form {
    let mut f = Form::default();
    f.add(2 * a1 + c as u32, 1.0);
    for (d, &md) in m[c].iter().enumerate() {
        if md != 0.0 {
            f.add(2 * a0 + d as u32, -md);
        }
    }
    f
}

/// Builds the [`Constraints`] (module docs).
pub fn build(
    surface: &Surface,
    charts: &Charts,
    singular_vertices: &[u32],
    align_boundary: Option<f64>,
    sharp: &[bool],
) -> Result<Constraints, RemeshError> {
    let mut out = Constraints::default();
    // gauge: the first wedge of each component
    out.gauge.component = vec![0; charts.wedges];
    for (f, &c) in charts.component.iter().enumerate() {
        if out.gauge.wedge.len() == c as usize {
            out.gauge.wedge.push(charts.corner_wedge[3 * f]);
        }
        for i in 0..3 {
            out.gauge.component[charts.corner_wedge[3 * f + i] as usize] = c;
        }
    }
    for (e, seam) in charts.seam.iter().enumerate() {
        let Some(p) = *seam else { continue };
        let [f0, f1] = surface.edge_faces[e];
        let [a, b] = surface.edges[e];
        let m = seam_rotation(p);
        let (a0, a1) = (charts.wedge(surface, f0, a), charts.wedge(surface, f1, a));
        let (b0, b1) = (charts.wedge(surface, f0, b), charts.wedge(surface, f1, b));
        for c in 0..2 {
            let ta = translation(a0, a1, &m, c);
            let mut row = ta.clone();
            for &(x, k) in &translation(b0, b1, &m, c).terms {
                row.add(x, -k);
            }
            out.rows.push(row);
            out.translations.push(ta);
        }
    }
    if let Some(tolerance) = align_boundary {
        align(surface, charts, tolerance, sharp, &mut out);
    }
    for &v in singular_vertices {
        if v as usize >= surface.positions.len() {
            return Err(RemeshError::SingularOutOfRange { vertex: v });
        }
    }
    let mut is_singular = vec![false; surface.positions.len()];
    for &v in singular_vertices {
        is_singular[v as usize] = true;
    }
    for (corner, &w) in charts.corner_wedge.iter().enumerate() {
        let v = surface.triangles[corner / 3][corner % 3];
        // one wedge per singular vertex: its other wedges follow from it
        // and the seam translations (rounding them too could break the
        // parity that a quarter turn's fixed point asks of them)
        if is_singular[v as usize] {
            is_singular[v as usize] = false;
            for c in 0..2 {
                out.singular.push(Form {
                    terms: vec![(2 * w + c, 1.0)],
                    constant: 0.0,
                });
            }
        }
    }
    Ok(out)
}

/// Boundary and feature alignment rows and integer unknowns (module
/// docs).
fn align(
    surface: &Surface,
    charts: &Charts,
    tolerance: f64,
    sharp: &[bool],
    out: &mut Constraints,
) {
    for (e, &[f, f1]) in surface.edge_faces.iter().enumerate() {
        if f1 != NO_FACE && !sharp.get(e).copied().unwrap_or(false) {
            continue;
        }
        let [a, b] = surface.edges[e];
        let dir = surface.edge_angle(e as u32, f);
        let turns = (wrap(dir - charts.angle[f as usize]) / FRAC_PI_2).round();
        let residual = wrap(dir - charts.angle[f as usize] - turns * FRAC_PI_2);
        if residual.abs() > tolerance {
            continue;
        }
        // along ±d: v is constant; along ±d⊥: u is
        let c = if (turns as i64).rem_euclid(2) == 0 {
            1u32
        } else {
            0
        };
        let (wa, wb) = (charts.wedge(surface, f, a), charts.wedge(surface, f, b));
        out.rows.push(Form {
            terms: vec![(2 * wa + c, 1.0), (2 * wb + c, -1.0)],
            constant: 0.0,
        });
        let value = Form {
            terms: vec![(2 * wa + c, 1.0)],
            constant: 0.0,
        };
        if f1 == NO_FACE {
            out.boundary.push(value);
            out.boundary_edges.push(AlignedEdge {
                edge: e as u32,
                face: f,
                coordinate: c,
            });
        } else {
            out.sharp.push(value);
        }
        out.aligned_edges += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::elim::form;

    /// Fixed directions per row kind: differences fix none, a pinned
    /// coordinate one, a quarter-turn translation the direction (1, −1).
    #[test]
    fn gauge_fixes_only_free_translations() {
        let gauge = Gauge {
            wedge: vec![1],
            component: vec![0; 3],
            offset: [0.0, 0.0],
        };
        let difference = form(&[(0, 1.0), (2, -1.0)], 0.0);
        assert_eq!(gauge.rows([difference.clone()].iter()).len(), 2);
        let pinned_u = form(&[(4, 1.0)], -3.0);
        let rows = gauge.rows([difference.clone(), pinned_u.clone()].iter());
        assert_eq!(rows, vec![form(&[(2, -0.0), (3, 1.0)], 0.0)]);
        let pinned_v = form(&[(5, 1.0)], -2.0);
        assert!(gauge.rows([pinned_u, pinned_v].iter()).is_empty());
        // t = A₁ − M₁·A₀ = (u_a1 − v_a0, v_a1 + u_a0): one row fixes (1, −1)
        let m = seam_rotation(1);
        let tu = translation(0, 2, &m, 0);
        let rows = gauge.rows([tu].iter());
        assert_eq!(rows.len(), 1);
        let r = &rows[0].terms;
        assert!((r[0].1 * 1.0 + r[1].1 * 1.0).abs() > 0.5, "{r:?}");
    }
}

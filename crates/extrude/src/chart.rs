//! Charts of the extruded tets: every tet takes the chart of its prism's
//! triangle plus `w`, so the 3D map is grid preserving by construction
//! (transitions are the 2D ones, identity in `w`).
//!
//! Input: the [`Slab`] and a tet mesh over its points plus Steiner points,
//! each tet labelled with its prism (`region = prism + 1`). Output: a
//! [`TetMap`] whose tets have positive geometric volume. Tets of no prism
//! (TetGen meshes the cavity enclosed by a closed surface's slab and gives
//! it a fresh region number) are dropped; every prism must keep ≥ 3 tets. Slab points take
//! the map of their (triangle corner, level); a Steiner point takes the
//! prism's map *piecewise linear on the prism's 3-tet split* (the one of
//! [`crate::split`], whose wall triangles are the PLC facets): on a wall or
//! a level triangle both neighbouring prisms then interpolate on the same
//! triangle, so their charts agree up to the 2D transition (a Newton
//! inverse of the bilinear prism missed by 1e-3 on bent walls). A tet with
//! a slab point that is not one of its prism's 6 points is an error:
//! TetGen did not keep the walls.
//!
//! With `--quality` on a curved slab, TetGen sometimes labels a tet with a
//! prism `P` although it lies across `P`'s wall, with a Steiner point inside
//! the neighbouring prism `Q` (torus_fold, slab 0.5 × the mean edge thick:
//! 3 of 10 941 points, least barycentric −0.04 in `P`'s split, 5.6e-3 off
//! the wall). Clamped into `P`, that point's map disagreed with `Q`'s by up
//! to 0.06. Such a point (least barycentric below −1e-9) takes the
//! map of the prism whose split holds it best, carried into `P`'s chart by
//! the 2D transition across their shared edge: every face then has one
//! map up to the transitions, and points inside their prism are unchanged.

use crate::slab::{cross, Slab};
use crate::split::prism_tets;
use crate::tetgen::TetgenMesh;
use crate::ExtrudeError;
use dualex_map::TetMap;

/// Least barycentric coordinate below which a Steiner point is outside
/// its prism's split (a point on a wall is off by rounding, ~1e-16).
const OUTSIDE: f64 = 1e-9;

/// Builds the tet map (see the module docs); also returns the number of
/// Steiner points.
pub fn tet_map(slab: &Slab, mesh: &TetgenMesh) -> Result<(TetMap, usize), ExtrudeError> {
    let n_in = slab.points.len();
    check_input_points(slab, &mesh.nodes)?;
    check_faces(slab, mesh)?;
    let mut out = TetMap {
        positions: slab.points.clone(),
        ..Default::default()
    };
    // per tet in a prism: (prism, node ids, corner maps, depths)
    let mut cells = Vec::with_capacity(mesh.tets.len());
    // per Steiner point: the prism whose split holds it deepest, its map there
    let mut home: Vec<Option<(usize, f64, [f64; 3])>> =
        vec![None; mesh.nodes.len().saturating_sub(n_in)];
    let mut per_prism = vec![0usize; slab.prisms()];
    for (k, (tet, &region)) in mesh.tets.iter().zip(&mesh.regions).enumerate() {
        let prism = region as usize;
        if prism == 0 || prism > slab.prisms() {
            continue; // an enclosed cavity (inside a closed surface's slab)
        }
        let prism = prism - 1;
        per_prism[prism] += 1;
        let mut coords = [[0.0; 3]; 4];
        let mut depth = [0.0; 4];
        for ((c, d), &v) in coords.iter_mut().zip(&mut depth).zip(tet) {
            let p = mesh.nodes[v as usize];
            (*c, *d) = corner_map(slab, prism, v, &p).ok_or_else(|| {
                ExtrudeError::Output(format!("tet {k}: node {v} is not in prism {prism}"))
            })?;
            if let Some(h) = (v as usize).checked_sub(n_in).and_then(|i| home.get_mut(i)) {
                let deeper = match h {
                    Some((_, hd, _)) => *d > *hd,
                    None => true,
                };
                if deeper {
                    *h = Some((prism, *d, *c));
                }
            }
        }
        cells.push((prism, *tet, coords, depth));
    }
    // Steiner points get new ids on first use (cavity points are dropped)
    let mut new_id = vec![u32::MAX; home.len()];
    for (prism, mut ids, mut coords, depth) in cells {
        for ((c, &d), v) in coords.iter_mut().zip(&depth).zip(&mut ids) {
            let Some(i) = (*v as usize).checked_sub(n_in) else {
                continue;
            };
            if d < -OUTSIDE {
                // TetGen put this point outside the prism (module docs)
                if let Some((h, hd, m)) = home[i] {
                    if hd >= -OUTSIDE {
                        *c = carry(slab, h, prism, m).unwrap_or(*c);
                    }
                }
            }
            if new_id[i] == u32::MAX {
                out.positions.push(mesh.nodes[*v as usize]);
                new_id[i] = out.positions.len() as u32 - 1;
            }
            *v = new_id[i];
        }
        if !mesh.oriented && volume(&out.positions, &ids) < 0.0 {
            ids.swap(0, 1);
            coords.swap(0, 1);
        }
        out.simplices.push(ids);
        out.coords.push(coords);
    }
    if let Some(p) = per_prism.iter().position(|&n| n < 3) {
        return Err(ExtrudeError::Output(format!(
            "prism {p} has {} tets (its region seed was lost)",
            per_prism[p]
        )));
    }
    let steiner = out.positions.len() - n_in;
    Ok((out, steiner))
}

/// No face has more than 2 tets; without Steiner points (`-Y`), every tet
/// face is also a PLC facet (a wall or a level triangle) or lies inside
/// one prism (exactly 2 tets of that prism). With Steiner points the
/// facets may be split and only the region labels tell the prisms.
/// Sorting, not hashing: the faces are checked in the order of their
/// sorted node ids, so the reported face does not depend on a hash seed.
fn check_faces(slab: &Slab, mesh: &TetgenMesh) -> Result<(), ExtrudeError> {
    let strict = mesh.nodes.len() == slab.points.len();
    let key = |mut k: [u32; 3]| {
        k.sort_unstable();
        k
    };
    let mut plc: Vec<[u32; 3]> = crate::plc::facets(slab).into_iter().map(key).collect();
    plc.sort_unstable();
    let is_facet = |k: &[u32; 3]| plc.binary_search(k).is_ok();
    // (face, region) packed into one integer, which sorts faster than a
    // tuple; regions past u32 (none is a prism's) saturate
    let pack = |k: [u32; 3], r: u64| {
        let r = r.min(u64::from(u32::MAX));
        (u128::from(k[0]) << 96)
            | (u128::from(k[1]) << 64)
            | (u128::from(k[2]) << 32)
            | u128::from(r)
    };
    let face = |x: u128| [(x >> 96) as u32, (x >> 64) as u32, (x >> 32) as u32];
    let mut faces: Vec<u128> = Vec::with_capacity(4 * mesh.tets.len());
    for (t, &r) in mesh.tets.iter().zip(&mesh.regions) {
        for f in 0..4 {
            faces.push(pack(key(std::array::from_fn(|j| t[(f + 1 + j) % 4])), r));
        }
    }
    faces.sort_unstable();
    for group in faces.chunk_by(|&a, &b| a >> 32 == b >> 32) {
        let k = &face(group[0]);
        let crosses = strict && group.len() == 2 && group[0] != group[1] && !is_facet(k);
        if group.len() > 2 || crosses {
            return Err(ExtrudeError::Output(format!(
                "face {k:?} crosses a prism wall or is shared by 3 tets"
            )));
        }
        if strict && group.len() == 1 && !is_facet(k) {
            return Err(ExtrudeError::Output(format!(
                "face {k:?} is a hole inside a prism"
            )));
        }
    }
    Ok(())
}

/// The input points must come back first and unmoved.
fn check_input_points(slab: &Slab, nodes: &[[f64; 3]]) -> Result<(), ExtrudeError> {
    let scale = slab
        .points
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()))
        .max(1e-300);
    if nodes.len() < slab.points.len() {
        return Err(ExtrudeError::Output(format!(
            "{} nodes for {} input points",
            nodes.len(),
            slab.points.len()
        )));
    }
    for (i, (a, b)) in slab.points.iter().zip(nodes).enumerate() {
        if (0..3).any(|k| (a[k] - b[k]).abs() > 1e-9 * scale) {
            return Err(ExtrudeError::Output(format!(
                "input point {i} came back moved or renumbered (duplicate points?)"
            )));
        }
    }
    Ok(())
}

/// Map value of node `v` (at `p`) in the chart of `prism`, and how deep
/// inside the prism's split it lies (the least barycentric coordinate in
/// the best of its 3 tets: `< 0` outside, where the coordinates are
/// clamped; `+∞` for a slab point); `None` when a slab point is not one of
/// the prism's points.
fn corner_map(slab: &Slab, prism: usize, v: u32, p: &[f64; 3]) -> Option<([f64; 3], f64)> {
    if (v as usize) < slab.points.len() {
        return slab_point_map(slab, prism, v).map(|m| (m, f64::INFINITY));
    }
    let tets = prism_tets(slab, prism);
    let bary = tets.map(|t| barycentric(t.map(|x| slab.points[x as usize]), *p));
    let min = |b: &[f64; 4]| b.iter().fold(f64::INFINITY, |m, x| m.min(*x));
    let best = (0..3).max_by(|&i, &j| min(&bary[i]).total_cmp(&min(&bary[j])))?;
    let depth = min(&bary[best]);
    let b = bary[best].map(|x| if x.is_finite() { x.max(0.0) } else { 0.0 });
    let sum: f64 = b.iter().sum();
    if sum <= 0.0 {
        return None;
    }
    let mut out = [0.0; 3];
    for (x, &bi) in tets[best].iter().zip(&b) {
        let m = slab_point_map(slab, prism, *x)?;
        for k in 0..3 {
            out[k] += bi / sum * m[k];
        }
    }
    Some((out, depth))
}

/// The map `m` of a point in the chart of prism `from` carried into the
/// chart of prism `to` by the 2D transition across their triangles'
/// shared edge (identity for the same triangle in another layer); `None`
/// when the triangles share no edge.
fn carry(slab: &Slab, from: usize, to: usize, m: [f64; 3]) -> Option<[f64; 3]> {
    let (tf, tt) = (slab.prism_of(from).0, slab.prism_of(to).0);
    if tf == tt {
        return Some(m);
    }
    let mut shared = (0..3).filter_map(|kf| {
        let kt = slab.tris[tt].iter().position(|&v| v == slab.tris[tf][kf])?;
        Some((slab.coords[tf][kf], slab.coords[tt][kt]))
    });
    let ((af, at), (bf, bt)) = (shared.next()?, shared.next()?);
    // z ↦ at + r (z − af), r = (bt − at) / (bf − af) as complex numbers
    let (df, dt) = (
        [bf[0] - af[0], bf[1] - af[1]],
        [bt[0] - at[0], bt[1] - at[1]],
    );
    let n = df[0] * df[0] + df[1] * df[1];
    if n <= 0.0 {
        return None;
    }
    let r = [
        (dt[0] * df[0] + dt[1] * df[1]) / n,
        (dt[1] * df[0] - dt[0] * df[1]) / n,
    ];
    let z = [m[0] - af[0], m[1] - af[1]];
    Some([
        at[0] + r[0] * z[0] - r[1] * z[1],
        at[1] + r[0] * z[1] + r[1] * z[0],
        m[2],
    ])
}

/// Map value of slab point `v` in the chart of `prism`, `None` when it is
/// not one of the prism's 6 points.
fn slab_point_map(slab: &Slab, prism: usize, v: u32) -> Option<[f64; 3]> {
    let (t, l) = slab.prism_of(prism);
    let (level, vv) = (v as usize / slab.nv, v % slab.nv as u32);
    let corner = slab.tris[t].iter().position(|&x| x == vv)?;
    (level == l || level == l + 1).then(|| slab.corner_map(t, corner, level))
}

/// Barycentric coordinates of `p` in the tet `q` (NaN if it is flat).
fn barycentric(q: [[f64; 3]; 4], p: [f64; 3]) -> [f64; 4] {
    let e = |a: [f64; 3], b: [f64; 3]| -> [f64; 3] { std::array::from_fn(|k| a[k] - b[k]) };
    let (e1, e2, e3, ep) = (e(q[1], q[0]), e(q[2], q[0]), e(q[3], q[0]), e(p, q[0]));
    let det = dot(e1, cross(e2, e3));
    let b1 = dot(ep, cross(e2, e3)) / det;
    let b2 = dot(e1, cross(ep, e3)) / det;
    let b3 = dot(e1, cross(e2, ep)) / det;
    [1.0 - b1 - b2 - b3, b1, b2, b3]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Six times the signed volume of a tet.
pub fn volume(p: &[[f64; 3]], t: &[u32; 4]) -> f64 {
    let q = t.map(|v| p[v as usize]);
    let e = |i: usize| std::array::from_fn(|k| q[i][k] - q[0][k]);
    dot(e(1), cross(e(2), e(3)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_map::TriMap;

    fn bent_slab() -> Slab {
        let m = TriMap {
            positions: vec![[0., 0., 0.], [1., 0., 0.2], [0., 1., 0.]],
            simplices: vec![[0, 1, 2]],
            coords: vec![[[0., 0.], [3., 0.], [0., 3.]]],
        };
        Slab::new(&m, 2, Some(0.5)).expect("valid")
    }

    #[test]
    fn wall_points_agree_between_neighbouring_prisms() {
        // two triangles sharing the bent edge 1–2, one layer
        let m = TriMap {
            positions: vec![[0., 0., 0.], [1., 0., 0.2], [0., 1., 0.], [1., 1., 0.5]],
            simplices: vec![[0, 1, 2], [1, 3, 2]],
            coords: vec![
                [[0., 0.], [3., 0.], [0., 3.]],
                [[3., 0.], [3., 3.], [0., 3.]],
            ],
        };
        let s = Slab::new(&m, 1, Some(0.5)).expect("valid");
        let [w0, w1] = crate::plc::wall(&s, 1, 2, 0);
        for (tri, b) in [(w0, [0.2, 0.3, 0.5]), (w1, [0.6, 0.1, 0.3])] {
            let p: [f64; 3] =
                std::array::from_fn(|k| (0..3).map(|i| b[i] * s.points[tri[i] as usize][k]).sum());
            let (x, y) = (corner_map(&s, 0, 99, &p), corner_map(&s, 1, 99, &p));
            let (x, y) = (x.expect("in 0").0, y.expect("in 1").0);
            assert!((0..3).all(|k| (x[k] - y[k]).abs() < 1e-12), "{x:?} {y:?}");
        }
    }

    /// A point of prism 1 carried into the chart of prism 0 is where the
    /// chart of prism 0, extended linearly, puts it (planar slab; the
    /// charts differ by a quarter turn and a shift across the edge 1–2).
    #[test]
    fn carry_crosses_the_shared_edge_by_the_transition() {
        let m = TriMap {
            positions: vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [1., 1., 0.]],
            simplices: vec![[0, 1, 2], [1, 3, 2]],
            coords: vec![
                // chart 0: (u, v) = 2 (x, y)
                [[0., 0.], [2., 0.], [0., 2.]],
                // chart 1: chart 0 turned by a quarter, shifted by (5, 1)
                [[5., 3.], [3., 3.], [3., 1.]],
            ],
        };
        let s = Slab::new(&m, 1, Some(0.5)).expect("valid");
        let p = [0.7, 0.6, 0.2];
        let (m1, depth) = corner_map(&s, 1, 99, &p).expect("in prism 1");
        assert!(depth > 0.0 && corner_map(&s, 0, 99, &p).expect("clamped").1 < 0.0);
        let m0 = carry(&s, 1, 0, m1).expect("shared edge");
        let want = [1.4, 1.2, 0.4];
        assert!((0..3).all(|k| (m0[k] - want[k]).abs() < 1e-12), "{m0:?}");
        assert_eq!(carry(&s, 0, 0, m1), Some(m1));
    }

    #[test]
    fn slab_and_steiner_corners_get_the_prism_chart() {
        let s = bent_slab();
        // prism 1 = layer 1: levels 1 and 2
        let p = s.points[s.point(1, 2) as usize];
        let slab_point = corner_map(&s, 1, s.point(1, 2), &p);
        assert_eq!(slab_point, Some(([3.0, 0.0, 2.0], f64::INFINITY)));
        assert_eq!(corner_map(&s, 1, s.point(1, 0), &p), None);
        let pts = s.prism_points(1).map(|v| s.points[v as usize]);
        let mid: [f64; 3] = std::array::from_fn(|k| pts.iter().map(|q| q[k] / 6.0).sum());
        let (m, depth) = corner_map(&s, 1, 99, &mid).expect("steiner");
        assert!(depth > 0.0, "{depth}");
        assert!((m[2] - 1.5).abs() < 1e-12, "{m:?}");
        assert!((m[0] + m[1] - 2.0).abs() < 0.1, "{m:?}");
    }
}

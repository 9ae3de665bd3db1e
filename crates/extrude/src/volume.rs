//! Tets of a closed surface with a scaled, optionally noisy identity map:
//! real shapes for hex extraction with free boundaries (`tools/`).
//!
//! Input: a closed, consistently oriented triangle surface (positions and
//! triangles), a scale `s`, an offset `o`, a noise amplitude `a` and a seed.
//! Output: a [`TetMap`] over TetGen's tetrahedralization of the enclosed
//! volume (`tetgen -pq`: quality, Steiner points allowed), every tet
//! positively oriented, whose map is `s·x + o` per vertex plus a random
//! vector of length ≤ `a` per vertex (one chart: the map stays GP).

use crate::tetgen::run_poly;
use crate::ExtrudeError;
use dualex_map::TetMap;
use dualex_util::rng::SplitMix;
use std::fmt::Write;
use std::path::Path;

/// Parameters of [`tetrahedralize_identity`].
#[derive(Clone, Debug)]
pub struct IdentityOptions {
    /// Map scale (map units per length unit).
    pub scale: f64,
    /// Map offset, added after scaling.
    pub offset: [f64; 3],
    /// Noise amplitude in map units (0: the exact identity).
    pub noise: f64,
    /// Noise seed.
    pub seed: u64,
}

/// Tetrahedralizes the volume inside `positions`/`triangles` with TetGen at
/// `program` and puts the map of [`IdentityOptions`] on it.
pub fn tetrahedralize_identity(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    opts: &IdentityOptions,
    program: &Path,
) -> Result<TetMap, ExtrudeError> {
    let mut poly = String::new();
    let _ = writeln!(poly, "{} 3 0 0", positions.len());
    for (i, p) in positions.iter().enumerate() {
        let _ = writeln!(poly, "{i} {:?} {:?} {:?}", p[0], p[1], p[2]);
    }
    let _ = writeln!(poly, "{} 0", triangles.len());
    for t in triangles {
        let _ = writeln!(poly, "1\n3 {} {} {}", t[0], t[1], t[2]);
    }
    poly.push_str("0\n0\n");
    let mesh = run_poly(program, poly.as_bytes(), "-pqzQAF")?;
    let mut rng = SplitMix::new(opts.seed);
    let map_of: Vec<[f64; 3]> = mesh
        .nodes
        .iter()
        .map(|p| {
            let d = rng.direction();
            let r = opts.noise * rng.unit();
            std::array::from_fn(|k| opts.scale * p[k] + opts.offset[k] + r * d[k])
        })
        .collect();
    let mut map = TetMap {
        positions: mesh.nodes.clone(),
        ..Default::default()
    };
    for t in &mesh.tets {
        let mut t = *t;
        if crate::chart::volume(&mesh.nodes, &t) < 0.0 {
            t.swap(0, 1);
        }
        map.simplices.push(t);
        map.coords.push(t.map(|v| map_of[v as usize]));
    }
    map.validate()?;
    Ok(map)
}

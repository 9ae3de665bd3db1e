//! Triangle-map and tet-map output, to any `Write` (exact round trip with
//! the readers of this crate).
//!
//! - tri map, OBJ: `v` per vertex, one `vt` per distinct (vertex, map
//!   coordinates) pair — corners of one vertex with bit-identical
//!   coordinates share their `vt`, as seamless-map writers do, so a map
//!   without seams has about one `vt` per vertex — numbered in order of
//!   first use, then `f v/vt v/vt v/vt`;
//! - tri map, PLY: double `x y z`, per face `vertex_indices` (uchar/int)
//!   and a `texcoord` list of 6 doubles, in the [`PlyFormat`] asked;
//! - tet map, `.hexex`: `n_v`, `x y z` lines, `n_t`, one line per tet with
//!   its 4 indices (0-based) and 12 map coordinates.
//!
//! Floats are printed in their shortest round-trip form (ryu, see [`crate::fmt`]), which
//! C's `strtod` and C++ streams read back exactly. The file writers validate
//! the map ([`dualex_map::SimplexMap::validate`]) before writing.

use crate::fmt::{float, floats_line, int, par_lines};
use crate::ply_out::PlyWriter;
use crate::PlyFormat;
use dualex_map::{TetMap, TriMap};
use std::io::{self, Write};

/// OBJ with one `vt` per distinct (vertex, coordinates) (see the module
/// docs).
pub fn tri_map_obj(w: &mut impl Write, map: &TriMap) -> io::Result<()> {
    writeln!(
        w,
        "# dualex triangle map: {} vertices, {} triangles",
        map.positions.len(),
        map.len()
    )?;
    par_lines(w, &map.positions, |out, p| floats_line(out, b"v", p, b""))?;
    let (uvs, corner_vt) = shared_uvs(map);
    par_lines(w, &uvs, |out, uv| floats_line(out, b"vt", uv, b""))?;
    let faces: Vec<(&[u32; 3], &[u32; 3])> = map.simplices.iter().zip(&corner_vt).collect();
    par_lines(w, &faces, |out, (t, vt)| {
        out.push(b'f');
        for (&v, &i) in t.iter().zip(vt.iter()) {
            out.push(b' ');
            int(out, u64::from(v) + 1);
            out.push(b'/');
            int(out, u64::from(i) + 1);
        }
        out.push(b'\n');
    })
}

/// The distinct (vertex, coordinate bits) pairs of `map`'s corners in order
/// of first use, and each corner's index among them.
fn shared_uvs(map: &TriMap) -> (Vec<[f64; 2]>, Vec<[u32; 3]>) {
    let mut index: std::collections::HashMap<(u32, [u64; 2]), u32> =
        std::collections::HashMap::with_capacity(map.positions.len());
    let mut uvs = Vec::with_capacity(map.positions.len());
    let corner_vt = map
        .simplices
        .iter()
        .zip(&map.coords)
        .map(|(t, c)| {
            std::array::from_fn(|k| {
                let key = (t[k], c[k].map(f64::to_bits));
                *index.entry(key).or_insert_with(|| {
                    uvs.push(c[k]);
                    (uvs.len() - 1) as u32
                })
            })
        })
        .collect();
    (uvs, corner_vt)
}

/// PLY with a per-face `texcoord` list, in `format`.
pub fn tri_map_ply(w: &mut impl Write, map: &TriMap, format: PlyFormat) -> io::Result<()> {
    let mut ply = PlyWriter::new(w, format);
    ply.header(&[
        &format!("element vertex {}", map.positions.len()),
        "property double x",
        "property double y",
        "property double z",
        &format!("element face {}", map.len()),
        "property list uchar int vertex_indices",
        "property list uchar double texcoord",
    ])?;
    for p in &map.positions {
        ply.doubles(p)?;
        ply.end_record()?;
    }
    for (t, uv) in map.simplices.iter().zip(&map.coords) {
        ply.index_list(t)?;
        ply.double_list(uv.as_flattened())?;
        ply.end_record()?;
    }
    Ok(())
}

/// HexEx `.hexex` (see the module docs).
pub fn tet_map_hexex(w: &mut impl Write, map: &TetMap) -> io::Result<()> {
    writeln!(w, "{}", map.positions.len())?;
    par_lines(w, &map.positions, |out, p| floats_line(out, b"", p, b""))?;
    writeln!(w, "{}", map.len())?;
    let tets: Vec<(&[u32; 4], &[[f64; 3]; 4])> = map.simplices.iter().zip(&map.coords).collect();
    par_lines(w, &tets, |out, (t, uvw)| {
        for (k, &v) in t.iter().enumerate() {
            if k > 0 {
                out.push(b' ');
            }
            int(out, u64::from(v));
        }
        for &x in uvw.as_flattened() {
            out.push(b' ');
            float(out, x);
        }
        out.push(b'\n');
    })
}

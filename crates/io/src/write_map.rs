//! Triangle-map and tet-map output, to any `Write` (exact round trip with
//! the readers of this crate).
//!
//! - tri map, OBJ: `v` per vertex, one `vt` per triangle corner (corner `c`
//!   of triangle `s` is `vt` number `3s + c + 1`), `f v/vt v/vt v/vt`;
//! - tri map, PLY: double `x y z`, per face `vertex_indices` (uchar/int)
//!   and a `texcoord` list of 6 doubles, in the [`PlyFormat`] asked;
//! - tet map, `.hexex`: `n_v`, `x y z` lines, `n_t`, one line per tet with
//!   its 4 indices (0-based) and 12 map coordinates.
//!
//! Floats are printed in Rust's shortest round-trip form (`{:?}`), which
//! C's `strtod` and C++ streams read back exactly. The file writers validate
//! the map ([`dualex_map::SimplexMap::validate`]) before writing.

use crate::ply_out::PlyWriter;
use crate::PlyFormat;
use dualex_map::{TetMap, TriMap};
use std::io::{self, Write};

/// OBJ with one `vt` per corner (see the module docs).
pub fn tri_map_obj(w: &mut impl Write, map: &TriMap) -> io::Result<()> {
    writeln!(
        w,
        "# dualex triangle map: {} vertices, {} triangles",
        map.positions.len(),
        map.len()
    )?;
    for p in &map.positions {
        writeln!(w, "v {:?} {:?} {:?}", p[0], p[1], p[2])?;
    }
    for corners in &map.coords {
        for uv in corners {
            writeln!(w, "vt {:?} {:?}", uv[0], uv[1])?;
        }
    }
    for (s, t) in map.simplices.iter().enumerate() {
        let vt = 3 * s as u64 + 1;
        let [a, b, c] = t.map(|v| u64::from(v) + 1);
        writeln!(w, "f {a}/{vt} {b}/{} {c}/{}", vt + 1, vt + 2)?;
    }
    Ok(())
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
    for p in &map.positions {
        writeln!(w, "{:?} {:?} {:?}", p[0], p[1], p[2])?;
    }
    writeln!(w, "{}", map.len())?;
    for (t, uvw) in map.simplices.iter().zip(&map.coords) {
        write!(w, "{} {} {} {}", t[0], t[1], t[2], t[3])?;
        for x in uvw.as_flattened() {
            write!(w, " {x:?}")?;
        }
        writeln!(w)?;
    }
    Ok(())
}

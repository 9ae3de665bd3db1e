//! OpenVolumeMesh ASCII `.ovm` output: tet maps (with HexHex's
//! `HexHex::Parametrization`) and hex meshes, as OpenVolumeMesh's
//! `FileManager` reads them (format in [`crate::ovm`]).
//!
//! Faces are shared: a face met again (same vertex set) is reused, by the
//! halfface of its orientation (`2f` as first listed, `2f+1` reversed).
//! Tets get their halffaces as OpenVolumeMesh's `add_cell(v0, v1, v2, v3)`
//! makes them — `(v0 v1 v2)`, `(v0 v2 v3)`, `(v0 v3 v1)`, `(v1 v3 v2)` —
//! each carrying the map value of the vertex opposite it (halffaces of no
//! cell carry `0 0 0`). Hexes (VTK order in) get their six halffaces in
//! `HexahedralMeshTopologyKernel`'s order (XF, XB, YF, YB, ZF, ZB), so
//! OpenVolumeMesh accepts them as hexahedra without reordering.

use crate::fmt::{float, floats_line, int};
use dualex_cells::HexMesh;
use dualex_map::TetMap;
use std::collections::HashMap;
use std::io::{self, Write};

/// The edges and faces met so far.
#[derive(Default)]
struct Builder {
    edges: Vec<[u32; 2]>,
    edge_of: HashMap<[u32; 2], usize>,
    /// Each face's halfedges, and its vertices as first listed.
    faces: Vec<(Vec<usize>, Vec<u32>)>,
    face_of: HashMap<Vec<u32>, usize>,
}

impl Builder {
    /// The halfedge `a → b` (edge `e`: `2e` from→to, `2e+1` back).
    fn halfedge(&mut self, a: u32, b: u32) -> usize {
        let key = [a.min(b), a.max(b)];
        let e = *self.edge_of.entry(key).or_insert_with(|| {
            self.edges.push([a, b]);
            self.edges.len() - 1
        });
        2 * e + usize::from(self.edges[e][0] != a)
    }

    /// The halfface through `vs` in this order (`2f` or `2f+1`).
    fn halfface(&mut self, vs: &[u32]) -> usize {
        let mut key = vs.to_vec();
        key.sort_unstable();
        if let Some(&f) = self.face_of.get(&key) {
            let first = &self.faces[f].1;
            let same =
                (0..vs.len()).any(|r| first.iter().cycle().skip(r).zip(vs).all(|(a, b)| a == b));
            return 2 * f + usize::from(!same);
        }
        let hes = (0..vs.len())
            .map(|i| self.halfedge(vs[i], vs[(i + 1) % vs.len()]))
            .collect();
        self.faces.push((hes, vs.to_vec()));
        self.face_of.insert(key, self.faces.len() - 1);
        2 * (self.faces.len() - 1)
    }

    /// Header, vertices, edges, faces and cells (`k hf…` per cell).
    fn write(
        &self,
        w: &mut impl Write,
        positions: &[[f64; 3]],
        cells: &[Vec<usize>],
    ) -> io::Result<()> {
        let mut out = Vec::with_capacity(64 * positions.len());
        out.extend_from_slice(b"OVM ASCII\nVertices\n");
        int(&mut out, positions.len() as u64);
        out.push(b'\n');
        for p in positions {
            floats_line(&mut out, b"", p, b"");
        }
        let list = |out: &mut Vec<u8>, xs: &[usize]| {
            int(out, xs.len() as u64);
            for &x in xs {
                out.push(b' ');
                int(out, x as u64);
            }
            out.push(b'\n');
        };
        out.extend_from_slice(format!("Edges\n{}\n", self.edges.len()).as_bytes());
        for [a, b] in &self.edges {
            out.extend_from_slice(format!("{a} {b}\n").as_bytes());
        }
        out.extend_from_slice(format!("Faces\n{}\n", self.faces.len()).as_bytes());
        for (hes, _) in &self.faces {
            list(&mut out, hes);
        }
        out.extend_from_slice(format!("Polyhedra\n{}\n", cells.len()).as_bytes());
        for hfs in cells {
            list(&mut out, hfs);
        }
        w.write_all(&out)
    }
}

/// A tet map as `.ovm` with the halfface property `HexHex::Parametrization`.
pub fn tet_map_ovm(w: &mut impl Write, map: &TetMap) -> io::Result<()> {
    let mut b = Builder::default();
    let mut cells = Vec::with_capacity(map.len());
    // per cell halfface: the corner opposite it
    const FACES: [([usize; 3], usize); 4] = [
        ([0, 1, 2], 3),
        ([0, 2, 3], 1),
        ([0, 3, 1], 2),
        ([1, 3, 2], 0),
    ];
    let mut param: HashMap<usize, [f64; 3]> = HashMap::with_capacity(4 * map.len());
    for (t, (tet, uvw)) in map.simplices.iter().zip(&map.coords).enumerate() {
        let mut hfs = Vec::with_capacity(4);
        for (corners, opposite) in FACES {
            let hf = b.halfface(&corners.map(|c| tet[c]));
            if param.insert(hf, uvw[opposite]).is_some() {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidData,
                    format!("tet {t}: a face already used with this orientation by another tet (inconsistently oriented tets)"),
                ));
            }
            hfs.push(hf);
        }
        cells.push(hfs);
    }
    b.write(w, &map.positions, &cells)?;
    let mut out = Vec::with_capacity(64 * b.faces.len());
    out.extend_from_slice(format!("HFProp vec3d \"{}\"\n", crate::ovm::HEXHEX_PARAM).as_bytes());
    for hf in 0..2 * b.faces.len() {
        let p = param.get(&hf).copied().unwrap_or_default();
        for (k, &x) in p.iter().enumerate() {
            if k > 0 {
                out.push(b' ');
            }
            float(&mut out, x);
        }
        out.push(b'\n');
    }
    w.write_all(&out)
}

/// A hex mesh (VTK corner order) as `.ovm`.
pub fn hex_ovm(w: &mut impl Write, mesh: &HexMesh) -> io::Result<()> {
    // OpenVolumeMesh's add_cell(8 vertices) faces, in VTK corner numbers
    // (OVM's vertices are VTK's 0 1 2 3 4 7 6 5):
    const FACES: [[usize; 4]; 6] = [
        [3, 2, 1, 0], // XF
        [5, 6, 7, 4], // XB
        [1, 2, 6, 5], // YF
        [4, 7, 3, 0], // YB
        [1, 5, 4, 0], // ZF
        [2, 3, 7, 6], // ZB
    ];
    let mut b = Builder::default();
    let cells: Vec<Vec<usize>> = mesh
        .cells
        .iter()
        .map(|h| FACES.iter().map(|f| b.halfface(&f.map(|c| h[c]))).collect())
        .collect();
    b.write(w, &mesh.positions, &cells)
}

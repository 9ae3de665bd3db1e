//! Meshes for `dualex inspect` and `dualex view`: reading a quad or hex
//! mesh, and the scaled Jacobian of each element ([`dualex::geom::quality`]).
//!
//! Input: a path (`.obj`/`.ply` whose faces are all quads, `.vtk` of
//! quads or hexes, MEDIT `.mesh` of hexes) and, for quads, optionally the
//! surface they lie on (`.obj`/`.ply` triangles; a map's coordinates are
//! ignored). Output: the mesh, one value per element, and where the quad
//! normals came from ([`Normals`]).
//!
//! A quad's value is taken against the unit normal of the surface
//! triangle nearest its centre (the quad's Newell normal as the hint, so
//! that the far side of a thin part is not taken); without a surface,
//! against the normalised sum of the unit Newell normals of the quad and
//! of the quads sharing an edge with it (the mesh's own normals: an
//! inverted quad among good ones still counts as inverted, but a region
//! of inverted quads can pass for good). Errors are one line naming the
//! file and the element; nothing here panics on bad input.

use std::collections::HashMap;
use std::path::Path;

use dualex::geom::quality::{corners, cross, hex_values, quad_values, sub, unit};
use dualex::geom::Reference;
use dualex::{HexMesh, QuadMesh};
use rayon::prelude::*;

use crate::error::{CliError, Need};
use dualex::render::valence::check_cells;
use dualex::render::RenderError;

/// A mesh read for its quality.
pub enum Mesh {
    /// A quad mesh.
    Quads(QuadMesh),
    /// A hex mesh.
    Hexes(HexMesh),
}

/// Where the quad normals come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Normals {
    /// The triangle of `--surface` nearest each quad.
    Surface,
    /// The mesh's own (each quad and its edge neighbours).
    Own,
}

impl Normals {
    /// Its name in `inspect --json`.
    pub fn key(self) -> &'static str {
        match self {
            Normals::Surface => "surface",
            Normals::Own => "mesh",
        }
    }

    /// A short note for the view page.
    pub fn short(self) -> &'static str {
        match self {
            Normals::Surface => "normals from the surface",
            Normals::Own => "normals: the mesh's own (less reliable than --surface)",
        }
    }

    /// A sentence for the reports.
    pub fn note(self) -> &'static str {
        match self {
            Normals::Surface => "quad normals from the surface",
            Normals::Own => {
                "quad normals are the mesh's own (each quad and its edge neighbours; less reliable than --surface)"
            }
        }
    }
}

/// Reads a quad or hex mesh; `what` (the subcommand) is named in the
/// errors. Errors: an unsupported extension, a face other than a quad,
/// an index out of range, a position not finite.
pub fn read_mesh(path: &Path, what: &'static str) -> Result<Mesh, CliError> {
    let name = path.display().to_string();
    let mesh = match dualex::io::lower_extension(path).as_str() {
        "mesh" => Mesh::Hexes(dualex::io::read_hex_mesh(path)?),
        "vtk" => match dualex::io::read_vtk(path)? {
            dualex::io::VtkMesh::Quads(m) => Mesh::Quads(m),
            dualex::io::VtkMesh::Hexes(m) => Mesh::Hexes(m),
        },
        "obj" | "ply" => {
            let poly = dualex::io::read_polygon_mesh(path)?;
            Mesh::Quads(quads_of(poly, &name, what)?)
        }
        ext => {
            return Err(CliError::NotAMesh {
                file: name,
                what,
                ext: ext.to_string(),
            })
        }
    };
    match &mesh {
        Mesh::Quads(m) => check_cells(&m.positions, &m.cells, "quad"),
        Mesh::Hexes(m) => check_cells(&m.positions, &m.cells, "hex"),
    }
    .map_err(|error| CliError::Mesh { file: name, error })?;
    Ok(mesh)
}

/// What `dualex inspect` reads at `path`: a mesh (`Some`), or a map
/// (`None`: `.hexex`/`.ovm`, an `.obj`/`.ply` of triangles, or one the
/// polygon reader refuses, whose error the map reader then gives).
pub fn inspected_mesh(path: &Path) -> Result<Option<Mesh>, CliError> {
    match dualex::io::lower_extension(path).as_str() {
        "mesh" | "vtk" => read_mesh(path, "inspect").map(Some),
        "obj" | "ply" => match dualex::io::read_polygon_mesh(path) {
            Ok(poly) if poly.faces.iter().any(|f| f.len() != 3) => {
                let name = path.display().to_string();
                let quads = quads_of(poly, &name, "inspect")?;
                check_cells(&quads.positions, &quads.cells, "quad")
                    .map_err(|error| CliError::Mesh { file: name, error })?;
                Ok(Some(Mesh::Quads(quads)))
            }
            _ => Ok(None),
        },
        _ => Ok(None),
    }
}

/// The quads of a polygon mesh whose faces all have 4 vertices.
fn quads_of(
    poly: dualex::io::PolyMesh,
    name: &str,
    what: &'static str,
) -> Result<QuadMesh, CliError> {
    let mut cells = Vec::with_capacity(poly.faces.len());
    for (i, f) in poly.faces.iter().enumerate() {
        let [a, b, c, d] = f[..] else {
            return Err(CliError::Face {
                file: name.to_string(),
                face: i,
                sides: f.len(),
                need: Need::Quads(what),
            });
        };
        cells.push([a, b, c, d]);
    }
    Ok(QuadMesh {
        positions: poly.positions,
        cells,
    })
}

/// The scaled Jacobian of every hex.
pub fn hex_quality(mesh: &HexMesh) -> Vec<f64> {
    hex_values(&mesh.positions, &mesh.cells)
}

/// The scaled Jacobian of every quad (see the module docs), against the
/// surface at `surface` when given. Errors: the surface cannot be read or
/// has a face other than a triangle.
pub fn quad_quality(
    mesh: &QuadMesh,
    surface: Option<&Path>,
) -> Result<(Vec<f64>, Normals), CliError> {
    let (normals, kind) = match surface {
        Some(path) => (surface_normals(mesh, path)?, Normals::Surface),
        None => (own_normals(mesh), Normals::Own),
    };
    Ok((quad_values(&mesh.positions, &mesh.cells, &normals), kind))
}

/// Per quad, the normal of the surface triangle nearest its centre.
fn surface_normals(mesh: &QuadMesh, path: &Path) -> Result<Vec<[f64; 3]>, CliError> {
    let name = path.display().to_string();
    let poly = dualex::io::read_polygon_mesh(path).map_err(CliError::SurfaceRead)?;
    let mut triangles = Vec::with_capacity(poly.faces.len());
    for (i, f) in poly.faces.iter().enumerate() {
        let [a, b, c] = f[..] else {
            return Err(CliError::Face {
                file: name,
                face: i,
                sides: f.len(),
                need: Need::SurfaceTriangles,
            });
        };
        triangles.push([a, b, c]);
    }
    if let Some(v) = poly
        .positions
        .iter()
        .position(|p| p.iter().any(|x| !x.is_finite()))
    {
        return Err(CliError::Surface {
            file: name,
            error: RenderError::VertexNotFinite { vertex: v },
        });
    }
    let reference = Reference::surface(&poly.positions, &triangles, 180.0);
    let normals = mesh
        .cells
        .par_iter()
        .map(|q| reference.quad_normal(&corners(&mesh.positions, q)));
    Ok(normals.collect())
}

/// Per quad, the normalised sum of the unit Newell normals of the quad
/// and of the quads sharing an edge with it.
fn own_normals(mesh: &QuadMesh) -> Vec<[f64; 3]> {
    let units: Vec<[f64; 3]> = mesh
        .cells
        .iter()
        .map(|q| {
            let p = corners(&mesh.positions, q);
            unit(cross(sub(p[2], p[0]), sub(p[3], p[1])))
        })
        .collect();
    let mut edges: HashMap<[u32; 2], Vec<u32>> = HashMap::new();
    for (i, q) in mesh.cells.iter().enumerate() {
        for k in 0..4 {
            let (a, b) = (q[k], q[(k + 1) % 4]);
            edges
                .entry([a.min(b), a.max(b)])
                .or_default()
                .push(i as u32);
        }
    }
    let mut around = Vec::new();
    mesh.cells
        .iter()
        .enumerate()
        .map(|(i, q)| {
            around.clear();
            around.push(i as u32);
            for k in 0..4 {
                let (a, b) = (q[k], q[(k + 1) % 4]);
                if let Some(on_edge) = edges.get(&[a.min(b), a.max(b)]) {
                    around.extend(on_edge.iter().copied());
                }
            }
            around.sort_unstable();
            around.dedup();
            let mut sum = [0.0; 3];
            for &j in &around {
                for (s, x) in sum.iter_mut().zip(units[j as usize]) {
                    *s += x;
                }
            }
            unit(sum)
        })
        .collect()
}

/// The quad count, the hex count: "9 quads", "1 hex".
pub fn elements(mesh: &Mesh) -> String {
    match mesh {
        Mesh::Quads(m) => crate::summary::count(m.cells.len(), "quad", "quads"),
        Mesh::Hexes(m) => crate::summary::count(m.cells.len(), "hex", "hexes"),
    }
}

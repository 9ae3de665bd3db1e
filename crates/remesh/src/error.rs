//! The remesher's errors: [`RemeshError`] for the pipeline's steps, and
//! [`SolveError`] for the sparse solves beneath them ([`crate::sparse`]).
//!
//! Input errors name the offending element (a vertex, a face, an edge, a
//! sparse entry) and the step that met it (`cross field:`, `cut:`,
//! `integrate:`), one line each; the facade (`dualex::remesh_map`) adds
//! the file.

use std::fmt;

/// Why a sparse factorisation or solve failed ([`crate::sparse`]).
#[derive(Clone, Debug, PartialEq)]
pub enum SolveError {
    /// The factorisation failed (the matrix is not positive definite):
    /// `faer`'s reason.
    Factorise {
        /// Complex Hermitian (`true`) or real symmetric.
        hermitian: bool,
        /// The matrix size.
        unknowns: usize,
        /// What `faer` said.
        reason: String,
    },
    /// A refactorisation was given another sparsity pattern.
    PatternDiffers,
    /// An entry outside the matrix.
    EntryOutside {
        /// Its row.
        row: usize,
        /// Its column.
        column: usize,
        /// The matrix size.
        size: usize,
    },
    /// An entry that is not a finite number.
    EntryNotFinite {
        /// Its row.
        row: usize,
        /// Its column.
        column: usize,
    },
    /// `faer` refused the triplets: its reason.
    Matrix(String),
    /// A right-hand side of the wrong length.
    RhsLength {
        /// Its length.
        len: usize,
        /// The matrix size.
        unknowns: usize,
    },
    /// The solution holds a non-finite number.
    NonFinite {
        /// The matrix size.
        unknowns: usize,
    },
}

impl fmt::Display for SolveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SolveError::Factorise {
                hermitian,
                unknowns,
                reason,
            } => {
                let kind = if *hermitian { " Hermitian" } else { "" };
                write!(f, "sparse{kind} Cholesky ({unknowns} unknowns): {reason}")
            }
            SolveError::PatternDiffers => write!(f, "sparse refactorisation: the pattern differs"),
            SolveError::EntryOutside { row, column, size } => write!(
                f,
                "sparse entry ({row}, {column}) outside a {size} × {size} matrix"
            ),
            SolveError::EntryNotFinite { row, column } => {
                write!(f, "sparse entry ({row}, {column}) is not finite")
            }
            SolveError::Matrix(reason) => write!(f, "sparse matrix: {reason}"),
            SolveError::RhsLength { len, unknowns } => {
                write!(f, "right-hand side of length {len} for {unknowns} unknowns")
            }
            SolveError::NonFinite { unknowns } => {
                write!(f, "sparse solve ({unknowns} unknowns): non-finite solution")
            }
        }
    }
}

impl std::error::Error for SolveError {}

/// Why the remesher could not make a map of a surface.
#[derive(Clone, Debug, PartialEq)]
pub enum RemeshError {
    /// Cross field: the surface has no triangle.
    NoTriangle,
    /// Cross field: the sharp angle is not a positive number of degrees.
    SharpAngle(f64),
    /// Cross field: the unit steps' shift is not a positive number.
    UnitShift(f64),
    /// Cross field: the triangles around a vertex form several fans.
    NonManifoldVertex {
        /// The vertex.
        vertex: u32,
    },
    /// Cross field: a solve failed.
    Field(SolveError),
    /// Cut: a singular vertex that is not a vertex of the surface.
    CutVertexOutOfRange {
        /// The vertex.
        vertex: u32,
        /// The surface's vertices.
        vertices: usize,
    },
    /// Cut: the field does not comb across an uncut edge.
    NotCombed {
        /// The edge.
        edge: u32,
        /// Its end vertices.
        ends: [u32; 2],
    },
    /// Cut check: a boundary edge is marked cut.
    BoundaryEdgeCut {
        /// The edge.
        edge: usize,
    },
    /// Cut check: a singular vertex is neither on the cut nor on the
    /// boundary.
    SingularOffCut {
        /// The vertex.
        vertex: u32,
    },
    /// Cut check: a component cut open is not a disk.
    ComponentNotDisk {
        /// The component.
        component: usize,
        /// Its Euler characteristic.
        euler: i64,
    },
    /// Integrate: the field's and the cut's sizes disagree with the
    /// surface's.
    Sizes {
        /// The field's angles.
        angles: usize,
        /// The field's matchings.
        matchings: usize,
        /// The cut's flags.
        cut_flags: usize,
        /// The surface's faces.
        faces: usize,
        /// The surface's edges.
        edges: usize,
    },
    /// Integrate: a face's field angle is not finite.
    FaceAngle {
        /// The face.
        face: usize,
        /// Its angle.
        angle: f64,
    },
    /// Integrate: an uncut edge keeps a matching after combing.
    CutMissesSingularity {
        /// The edge's end vertices.
        ends: [u32; 2],
        /// Its matching after combing.
        matching: u8,
    },
    /// Integrate: a piece of the cut-open surface is not a disk.
    NotDisks {
        /// Its Euler characteristic.
        euler: i64,
    },
    /// Integrate: a singular vertex that is not a vertex of the surface.
    SingularOutOfRange {
        /// The vertex.
        vertex: u32,
    },
    /// Integrate: the gauge offset is not finite.
    GaugeOffset([f64; 2]),
    /// Integrate: neither a scale nor a quad count.
    NoScale,
    /// Integrate: the scale is not a positive finite number.
    Scale(f64),
    /// Integrate: no rounding was made.
    NoSolve,
    /// Integrate: a solve failed.
    Solve(SolveError),
}

impl fmt::Display for RemeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use RemeshError as E;
        match self {
            E::NoTriangle => write!(f, "cross field: the surface has no triangle"),
            E::SharpAngle(a) => write!(
                f,
                "cross field: sharp angle {a} is not a positive number of degrees"
            ),
            E::UnitShift(s) => write!(
                f,
                "cross field: unit-step shift {s} is not a positive number"
            ),
            E::NonManifoldVertex { vertex } => write!(
                f,
                "cross field: vertex {vertex} is not manifold (its triangles form several fans)"
            ),
            E::Field(e) => write!(f, "cross field: {e}"),
            E::CutVertexOutOfRange { vertex, vertices } => write!(
                f,
                "cut: singular vertex {vertex} out of range ({vertices} vertices)"
            ),
            E::NotCombed { edge, ends: [a, b] } => write!(
                f,
                "the field does not comb across uncut edge {edge} ({a}–{b}): \
                 a singularity is not on the cut"
            ),
            E::BoundaryEdgeCut { edge } => write!(f, "boundary edge {edge} is marked cut"),
            E::SingularOffCut { vertex } => {
                write!(f, "singular vertex {vertex} is not on the cut")
            }
            E::ComponentNotDisk { component, euler } => write!(
                f,
                "component {component} cut open has Euler characteristic {euler} (a disk has 1)"
            ),
            E::Sizes {
                angles,
                matchings,
                cut_flags,
                faces,
                edges,
            } => write!(
                f,
                "integrate: {angles} angles, {matchings} matchings, {cut_flags} cut flags for {faces} faces and {edges} edges"
            ),
            E::FaceAngle { face, angle } => write!(f, "integrate: face {face} has angle {angle}"),
            E::CutMissesSingularity {
                ends: [a, b],
                matching,
            } => write!(
                f,
                "integrate: the cut misses a singularity (edge {a}–{b} keeps matching {matching} after combing)"
            ),
            E::NotDisks { euler } => write!(
                f,
                "integrate: the cut does not open the surface to disks (a piece has Euler characteristic {euler})"
            ),
            E::SingularOutOfRange { vertex } => {
                write!(f, "integrate: singular vertex {vertex} out of range")
            }
            E::GaugeOffset(o) => write!(f, "gauge offset {o:?} is not finite"),
            E::NoScale => write!(f, "integrate: neither a scale nor a quad count"),
            E::Scale(s) => write!(f, "integrate: scale {s} (needs a positive finite number)"),
            E::NoSolve => write!(f, "integrate: no solve"),
            E::Solve(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for RemeshError {}

impl From<SolveError> for RemeshError {
    /// A solve of the integration (the cross field's are
    /// [`RemeshError::Field`]).
    fn from(e: SolveError) -> Self {
        RemeshError::Solve(e)
    }
}

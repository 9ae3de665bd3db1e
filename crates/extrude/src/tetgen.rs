//! TetGen as an external program (Debian's `tetgen`, 1.5): write the
//! `.poly` into a fresh temporary directory, run `tetgen -pYzQFN` (then
//! `-pYzQAF` if needed, see [`run`]; `-pzQAFq` with quality), parse `.1.ele`
//! (and `.1.node`), remove the directory.
//!
//! Flags: `-p` tetrahedralize a PLC, `-Y` keep the input surface (every
//! input facet, so no Steiner point on a prism wall), `-z` number from 0,
//! `-Q` quiet, `-A` region attributes (the prism of each tet), `-F` no
//! `.face` / `.edge` files, `-N` no `.node` file (see [`run`]). Quality
//! (`-q`) is run *without* `-Y`: in a thin slab every bad tet's
//! circumcentre encroaches on a wall, so `-pYq` adds no point at all
//! (measured: 0 points on a 6 × 6 grid slab, 104 with `-pq`). Walls and
//! prism edges may then be split, but stay constraints: every tet still
//! lies in one prism. TetGen is AGPL: it is run, never linked.
//!
//! Quality is bounded: `-S` caps the Steiner points at
//! [`STEINER_PER_PRISM`] per prism (unbounded, TetGen ran 11 min at 9.5 GB
//! on 9 216 prisms); refinement stops there and the mesh is still valid,
//! only less refined ([`steiner_cap`] tells the caller to say so).

use crate::slab::Slab;
use crate::ExtrudeError;
use std::path::{Path, PathBuf};
use std::process::Command;

/// What TetGen returned.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TetgenMesh {
    /// Output nodes (the input points first, then Steiner points).
    pub nodes: Vec<[f64; 3]>,
    /// Tets as node ids.
    pub tets: Vec<[u32; 4]>,
    /// Region attribute per tet (`prism + 1`; 0 = no region).
    pub regions: Vec<u64>,
    /// The tets are already consistently oriented combinatorially (the
    /// built-in split); otherwise they are oriented by geometric volume.
    pub oriented: bool,
}

/// A temporary directory removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new() -> Result<TempDir, ExtrudeError> {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_nanos())
            .unwrap_or(0);
        let dir =
            std::env::temp_dir().join(format!("dualex-extrude-{}-{nanos}", std::process::id()));
        std::fs::create_dir_all(&dir)
            .map_err(|e| ExtrudeError::Io(format!("{}: {e}", dir.display())))?;
        Ok(TempDir(dir))
    }
}

impl TempDir {
    /// The text of TetGen's output file `slab.1.<ext>`.
    fn read(&self, ext: &str) -> Result<String, ExtrudeError> {
        let path = self.0.join(format!("slab.1.{ext}"));
        std::fs::read_to_string(&path)
            .map_err(|e| ExtrudeError::TetgenFailed(format!("{}: {e}", path.display())))
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Runs `program` on `poly`, the `.poly` of `slab` (see the module docs).
/// Without quality, TetGen is first asked for the `.ele` only: no `.node`
/// file (`-N`: ~6 % of its instructions on fandisk), whose points are then
/// the slab's (TetGen keeps them in order: `-z`, no `-j`), and no region
/// attributes (no `-A`: ~15 %), which [`crate::label`] derives from the
/// nodes. Only when a tet refers to a point past the slab's (a Steiner
/// point, which `-Y` does not rule out inside a prism) or cannot be
/// labelled is TetGen run again with both.
pub fn run(
    program: &Path,
    poly: &[u8],
    slab: &Slab,
    quality: bool,
) -> Result<TetgenMesh, ExtrudeError> {
    if quality {
        let cap = steiner_cap(slab.tris.len() * slab.layers);
        return run_poly(program, poly, &format!("-pzQAFqS{cap}"));
    }
    let dir = run_in_dir(program, poly, "-pYzQFN")?;
    let (tets, _) = parse_ele(&dir.read("ele")?, u32::MAX as usize, 0)?;
    let slab_points_only = tets
        .iter()
        .flatten()
        .all(|&v| (v as usize) < slab.points.len());
    match slab_points_only
        .then(|| crate::label::regions(slab, &tets))
        .flatten()
    {
        Some(regions) => Ok(TetgenMesh {
            nodes: slab.points.clone(),
            tets,
            regions,
            oriented: false,
        }),
        None => run_poly(program, poly, "-pYzQAF"),
    }
}

/// Steiner points `--quality` may add per prism (module docs).
pub const STEINER_PER_PRISM: usize = 8;

/// The cap on Steiner points of a quality run over `prisms` prisms.
pub fn steiner_cap(prisms: usize) -> usize {
    prisms.max(1) * STEINER_PER_PRISM
}

/// Runs TetGen with `flags` on the `.poly` text `poly` in a temporary
/// directory and reads its `.node` / `.ele` output.
pub fn run_poly(program: &Path, poly: &[u8], flags: &str) -> Result<TetgenMesh, ExtrudeError> {
    let dir = run_in_dir(program, poly, flags)?;
    let nodes = parse_node(&dir.read("node")?)?;
    let (tets, regions) = parse_ele(&dir.read("ele")?, nodes.len(), 1)?;
    Ok(TetgenMesh {
        nodes,
        tets,
        regions,
        oriented: false,
    })
}

/// The triangles (vertex ids) of the surface `.poly` text `poly` (see
/// [`crate::plc::surface_poly_text`]) that intersect another one, by
/// TetGen's check (`-d`: it writes them to `.1.face`, nothing when there
/// are none). Costs about half an aborted tetrahedralization (0.22 s on
/// duck_miq_4's 19 720 triangles).
pub fn intersecting_triangles(program: &Path, poly: &[u8]) -> Result<Vec<[u32; 3]>, ExtrudeError> {
    let (dir, out) = spawn(program, poly, "-dzQ")?;
    let path = dir.0.join("slab.1.face");
    if !out.status.success() {
        return Err(ExtrudeError::TetgenFailed(format!(
            "{} -dzQ exited with {}",
            program.display(),
            out.status
        )));
    }
    if !path.is_file() {
        return Ok(Vec::new());
    }
    let text = dir.read("face")?;
    let mut recs = records(&text);
    let head = recs.next().ok_or_else(|| bad("face", "empty".into()))?;
    let n: usize = head.reader("face").next()?;
    let mut out = Vec::with_capacity(n.min(1 << 20));
    for r in recs.take(n) {
        let mut f = r.reader("face");
        f.next::<u64>()?;
        out.push([f.next()?, f.next()?, f.next()?]);
    }
    Ok(out)
}

/// Writes `poly` to `slab.poly` in a fresh temporary directory and runs
/// TetGen there with `flags`.
fn spawn(
    program: &Path,
    poly: &[u8],
    flags: &str,
) -> Result<(TempDir, std::process::Output), ExtrudeError> {
    let dir = TempDir::new()?;
    let input = dir.0.join("slab.poly");
    std::fs::write(&input, poly)
        .map_err(|e| ExtrudeError::Io(format!("{}: {e}", input.display())))?;
    let out = Command::new(program)
        .arg(flags)
        .arg("slab.poly")
        .current_dir(&dir.0)
        .output()
        .map_err(|e| match e.kind() {
            std::io::ErrorKind::NotFound => ExtrudeError::TetgenMissing(program.into()),
            _ => ExtrudeError::Io(format!("cannot run {}: {e}", program.display())),
        })?;
    Ok((dir, out))
}

/// Runs TetGen with `flags` on `poly` written to `slab.poly` in a fresh
/// temporary directory, which holds its output files.
fn run_in_dir(program: &Path, poly: &[u8], flags: &str) -> Result<TempDir, ExtrudeError> {
    let (dir, out) = spawn(program, poly, flags)?;
    let written = |ext: &str| dir.0.join(format!("slab.1.{ext}")).is_file();
    let wants_node = !flags.contains('N');
    if out.status.success() && written("ele") && (written("node") || !wants_node) {
        return Ok(dir);
    }
    let all = format!(
        "{} {}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let tail: Vec<&str> = all.split_whitespace().collect();
    let tail = tail[tail.len().saturating_sub(40)..].join(" ");
    Err(ExtrudeError::TetgenFailed(format!(
        "{} {flags} exited with {}: {tail}",
        program.display(),
        out.status
    )))
}

/// The fields of the non-empty, non-comment lines (no allocation per
/// line).
fn records(text: &str) -> impl Iterator<Item = Fields<'_>> {
    text.lines()
        .map(|l| {
            Fields(
                l.as_bytes()
                    .iter()
                    .position(|&b| b == b'#')
                    .map_or(l, |i| &l[..i]),
            )
        })
        .filter(|f| f.0.split_ascii_whitespace().next().is_some())
}

/// One record's text (a line without its comment).
#[derive(Clone, Copy)]
struct Fields<'a>(&'a str);

impl<'a> Fields<'a> {
    /// A reader of the fields in order.
    fn reader(self, file: &'a str) -> FieldReader<'a> {
        FieldReader {
            rec: self.0,
            it: self.0.split_ascii_whitespace(),
            k: 0,
            file,
        }
    }
}

/// Reads one record's fields in order.
struct FieldReader<'a> {
    rec: &'a str,
    it: std::str::SplitAsciiWhitespace<'a>,
    k: usize,
    file: &'a str,
}

impl FieldReader<'_> {
    /// The next field as a region attribute: TetGen writes integers
    /// (read as such, the fast path) or reals; negative means none (0).
    fn region(&mut self) -> Result<u64, ExtrudeError> {
        let rest = self.it.clone().next();
        match rest.and_then(|x| x.parse::<u64>().ok()) {
            Some(a) => {
                self.it.next();
                self.k += 1;
                Ok(a)
            }
            None => {
                let a: f64 = self.next()?;
                Ok(if a >= 0.0 { a.round() as u64 } else { 0 })
            }
        }
    }

    /// The next field parsed as `T`.
    fn next<T: std::str::FromStr>(&mut self) -> Result<T, ExtrudeError> {
        let k = self.k;
        self.k += 1;
        self.it.next().and_then(|x| x.parse().ok()).ok_or_else(|| {
            bad(
                self.file,
                format!("record {:?}: field {k}", self.rec.trim()),
            )
        })
    }
}

fn bad(file: &str, what: String) -> ExtrudeError {
    ExtrudeError::TetgenFailed(format!("unreadable TetGen output .{file}: {what}"))
}

/// Parses a `.node` file (0-based, 3D).
pub fn parse_node(text: &str) -> Result<Vec<[f64; 3]>, ExtrudeError> {
    let mut recs = records(text);
    let head = recs.next().ok_or_else(|| bad("node", "empty".into()))?;
    let n: usize = head.reader("node").next()?;
    let mut out = Vec::with_capacity(n.min(1 << 24));
    for (i, r) in recs.take(n).enumerate() {
        let mut f = r.reader("node");
        if f.next::<usize>()? != i {
            return Err(bad("node", format!("node {i} is out of order")));
        }
        out.push([f.next()?, f.next()?, f.next()?]);
    }
    if out.len() != n {
        return Err(bad("node", format!("{} of {n} nodes", out.len())));
    }
    Ok(out)
}

/// Parses a `.ele` file of 4-node tets with `attributes` (0, or 1 with
/// `-A`) per tet; without attributes the regions are left empty.
pub fn parse_ele(
    text: &str,
    nodes: usize,
    attributes: usize,
) -> Result<(Vec<[u32; 4]>, Vec<u64>), ExtrudeError> {
    let mut recs = records(text);
    let head = recs.next().ok_or_else(|| bad("ele", "empty".into()))?;
    let mut h = head.reader("ele");
    let n: usize = h.next()?;
    if h.next::<usize>()? != 4 || h.next::<usize>()? != attributes {
        return Err(bad(
            "ele",
            format!(
                "header {:?}: want 4 nodes, {attributes} attribute(s)",
                head.0.trim()
            ),
        ));
    }
    let (mut tets, mut regions) = (Vec::with_capacity(n.min(1 << 24)), Vec::new());
    for r in recs.take(n) {
        let mut f = r.reader("ele");
        f.next::<u64>()?;
        let t: [u32; 4] = [f.next()?, f.next()?, f.next()?, f.next()?];
        if let Some(x) = t.iter().find(|&&x| x as usize >= nodes) {
            return Err(bad("ele", format!("node {x} of {nodes}")));
        }
        tets.push(t);
        if attributes > 0 {
            regions.push(f.region()?);
        }
    }
    if tets.len() != n {
        return Err(bad("ele", format!("{} of {n} tets", tets.len())));
    }
    Ok((tets, regions))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_tetgen_files() {
        let node = "3 3 0 0\n 0 0 0 0\n 1 1 0 0\n 2 0 1 1.5e0\n# Generated by tetgen\n";
        assert_eq!(parse_node(node).expect("ok")[2], [0.0, 1.0, 1.5]);
        let ele = "2 4 1\n 0 0 1 2 0 7\n 1 2 1 0 0 3\n";
        let (t, r) = parse_ele(ele, 3, 1).expect("ok");
        assert_eq!((t[1], r), ([2, 1, 0, 0], vec![7, 3]));
        assert!(parse_ele(ele, 2, 1).is_err());
        assert!(parse_ele(ele, 3, 0).is_err());
        assert!(parse_ele("1 4 0\n0 0 1 2 0\n", 3, 1).is_err());
        let (t, r) = parse_ele("1 4 0\n0 0 1 2 0\n", 3, 0).expect("ok");
        assert_eq!((t, r), (vec![[0, 1, 2, 0]], vec![]));
        assert!(parse_node("2 3 0 0\n0 0 0 0\n").is_err());
        assert!(parse_node("1 3 0 0\n1 0 0 0\n").is_err());
    }

    /// A stand-in for TetGen that adds a Steiner point (node 6 of a
    /// one-prism slab): with `-N` it writes only the `.ele` (no attribute),
    /// else the `.ele` with attributes and the `.node`.
    #[cfg(unix)]
    #[test]
    fn a_steiner_point_without_node_file_reruns_with_it() {
        use std::os::unix::fs::PermissionsExt;
        let dir = TempDir::new().expect("temp dir");
        let fake = dir.0.join("fake-tetgen");
        let script = r#"#!/bin/sh
case "$1" in *N*) printf '1 4 0\n0 0 1 2 6\n' > slab.1.ele; exit 0;; esac
printf '2 4 1\n0 0 1 2 6 1\n1 0 1 3 6 1\n' > slab.1.ele
printf '7 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 1 0 1\n5 0 1 1\n6 0.2 0.2 0.5\n' > slab.1.node
"#;
        std::fs::write(&fake, script).expect("script");
        std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).expect("chmod");
        let slab = one_prism();
        let m = run(&fake, b"", &slab, false).expect("ran");
        assert_eq!(m.nodes.len(), 7);
        assert_eq!(m.nodes[6], [0.2, 0.2, 0.5]);
        assert_eq!((m.tets[1], m.regions[1]), ([0, 1, 3, 6], 1));
    }

    fn one_prism() -> Slab {
        let map = dualex_map::TriMap {
            positions: vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.]],
            simplices: vec![[0, 1, 2]],
            coords: vec![[[0., 0.], [1., 0.], [0., 1.]]],
        };
        Slab::new(&map, 1, Some(1.0)).expect("valid")
    }

    #[test]
    fn a_missing_program_is_named() {
        let e =
            run(Path::new("/nonexistent/tetgen"), b"", &one_prism(), false).expect_err("missing");
        assert!(matches!(e, ExtrudeError::TetgenMissing(_)), "{e}");
        assert!(e.to_string().contains("apt-get install tetgen"), "{e}");
    }
}

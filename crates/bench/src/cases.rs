//! The benchmark cases and how one of them runs (in a child process).
//!
//! A case is named `KIND:SIZE` (a generated map: `square`, `square_noise`
//! of `2·r²` triangles, `torus`, `torus_fold` of `r²` triangles, `r` the
//! grid resolution; `block`, `block_noise` of `6·n³` tets; about 8
//! triangles per quad, 48 tets per hex) or `file:PATH` (a `.obj` triangle map or `.hexex` tet
//! map). [`run`] builds the input, extracts, and returns one [`Record`]:
//! input size, per-stage times from the extraction stats, output size and
//! hash (to check that optimisations keep the output byte-identical), and
//! the process's peak resident set (`VmHWM` of `/proc/self/status`) after
//! building the input and after extraction.

use dualex_gen::{Diagonal, Perturb};
use dualex_map::{InputError, TetMap, TriMap};
use serde_json::{json, Value};
use std::path::Path;
use std::time::Instant;

/// The input of one case.
pub enum Input {
    /// A triangle map.
    Tri(TriMap),
    /// A tet map.
    Tet(TetMap),
}

/// Builds the input of case `name`.
pub fn build(name: &str) -> Result<Input, String> {
    let (kind, arg) = name
        .split_once(':')
        .ok_or_else(|| format!("case {name:?}: expected KIND:SIZE or file:PATH"))?;
    if kind == "file" {
        return read(Path::new(arg)).map_err(|e| e.to_string());
    }
    let size: usize = arg
        .parse()
        .map_err(|_| format!("case {name:?}: SIZE must be a positive integer"))?;
    if size < 2 {
        return Err(format!("case {name:?}: SIZE must be at least 2"));
    }
    generate(kind, size).ok_or_else(|| format!("case {name:?}: unknown kind {kind:?}"))
}

fn read(path: &Path) -> Result<Input, InputError> {
    if path.extension().is_some_and(|e| e == "hexex") {
        Ok(Input::Tet(dualex_io::read_tet_map(path)?))
    } else {
        let map = dualex_io::read_tri_map(path)?;
        Ok(Input::Tri(dualex_map::weld::weld(&map).0))
    }
}

/// Map units spanned by a grid of resolution `r`: half a unit per cell
/// edge, so the quad count grows as the triangle count.
fn span(r: usize) -> f64 {
    r as f64 / 2.0
}

fn generate(kind: &str, r: usize) -> Option<Input> {
    const LO: f64 = 0.2;
    let alt = Diagonal::Alternating;
    let hi = LO + span(r);
    // the torus: res_u = 2·res_v, n·m quads with n = res_u/2, m = res_v/2
    let (ru, rv) = (r, (r / 2).max(3));
    let (n, m) = ((ru / 2).max(1) as u32, (rv / 2).max(1) as u32);
    Some(match kind {
        "square" => Input::Tri(dualex_gen::square_identity(r, LO, hi, alt).0),
        "square_noise" => Input::Tri(dualex_gen::square_noise(r, LO, hi, 0.3, 7, alt).0),
        "torus" => Input::Tri(dualex_gen::torus(n, m, ru, rv, Perturb::None, alt).0),
        "torus_fold" => {
            let fold = Perturb::Fold { strength: 1.5 };
            Input::Tri(dualex_gen::torus(n, m, ru, rv, fold, alt).0)
        }
        "block" => Input::Tet(dualex_gen::block::block(r, r, r, LO, hi).0),
        "block_noise" => Input::Tet(dualex_gen::block::block_noise(r, LO, hi, 0.3, 7).0),
        _ => return None,
    })
}

/// Peak resident set of this process so far, in KiB (`VmHWM`), 0 if unknown.
pub fn peak_rss_kib() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmHWM:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
        .unwrap_or(0)
}

/// FNV-1a over 64-bit words.
#[derive(Clone, Copy)]
struct Fnv(u64);

impl Fnv {
    fn new() -> Self {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
    fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
        }
    }
}

/// Hash of a cell mesh: every cell's vertex ids, then every position's bits.
pub fn mesh_hash<const K: usize>(mesh: &dualex_cells::CellMesh<K>) -> u64 {
    let mut h = Fnv::new();
    for c in &mesh.cells {
        for &v in c {
            h.word(u64::from(v));
        }
    }
    for p in &mesh.positions {
        for x in p {
            h.word(x.to_bits());
        }
    }
    h.0
}

/// Builds and extracts case `name`; the record as one JSON object.
pub fn run(name: &str) -> Result<Value, String> {
    let t0 = Instant::now();
    let input = build(name)?;
    let input_ms = t0.elapsed().as_secs_f64() * 1e3;
    let hwm_input = peak_rss_kib();
    let t1 = Instant::now();
    let (dim, simplices, cells, hash, stats) = match &input {
        Input::Tri(map) => {
            let (mesh, st) = dualex_quad::extract(map, &dualex_quad::QuadOptions::default())
                .map_err(|e| e.to_string())?;
            (
                2,
                map.len(),
                mesh.cells.len(),
                mesh_hash(&mesh),
                st.to_json(),
            )
        }
        Input::Tet(map) => {
            let (mesh, st) = dualex_hex::extract(map, &dualex_hex::HexOptions::default())
                .map_err(|e| e.to_string())?;
            (
                3,
                map.len(),
                mesh.cells.len(),
                mesh_hash(&mesh),
                st.to_json(),
            )
        }
    };
    let extract_ms = t1.elapsed().as_secs_f64() * 1e3;
    Ok(json!({
        "case": name,
        "dim": dim,
        "simplices": simplices,
        "input_ms": input_ms,
        "extract_ms": extract_ms,
        "stats": stats,
        "cells": cells,
        "hash": format!("{hash:016x}"),
        "hwm_input_kib": hwm_input,
        "hwm_kib": peak_rss_kib(),
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generated_sizes_follow_the_documented_formulas() {
        for (kind, r, want) in [("square", 10, 200), ("torus", 10, 100), ("block", 3, 162)] {
            let got = match build(&format!("{kind}:{r}")) {
                Ok(Input::Tri(m)) => m.len(),
                Ok(Input::Tet(m)) => m.len(),
                Err(e) => panic!("{e}"),
            };
            assert_eq!(got, want, "{kind}:{r}");
        }
    }

    #[test]
    fn bad_case_names_are_refused() {
        for bad in [
            "square",
            "square:x",
            "square:1",
            "nope:10",
            "file:/nonexistent.obj",
        ] {
            assert!(build(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn a_small_case_runs_and_reports_its_counts() {
        let r = run("square:8").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(r["simplices"], 128);
        // [0.2, 4.2]² holds the grid points 1..=4 squared, one (dual) quad each
        assert_eq!(r["cells"], 16);
        assert_eq!(r["stats"]["nodes"], 16);
        assert!(r["hwm_kib"].as_u64().unwrap_or(0) >= r["hwm_input_kib"].as_u64().unwrap_or(1));
    }

    #[test]
    fn the_hash_sees_a_changed_position() {
        let mut m = dualex_cells::QuadMesh {
            positions: vec![[0.0; 3]; 4],
            cells: vec![[0, 1, 2, 3]],
        };
        let a = mesh_hash(&m);
        m.positions[2][1] = 1.0;
        assert_ne!(a, mesh_hash(&m));
    }
}

//! Noisy copies of exact shared maps (independent uniform noise of
//! amplitude 1e-3 and 2e-3 on every corner coordinate, so every transition
//! translation is off by up to a few 1e-3) extract by default (transitions
//! rounded, and reported) to exactly the clean map's mesh: same cell count,
//! vertex count, boundary face/edge count and valence histograms.
//!
//! Cases in [`KNOWN_FAILING`] do not reach that yet; they are run and their
//! numbers printed all the same (not hidden), and a known failure that
//! starts passing is reported too. Skipped with a notice when
//! `../shared/data` is absent.

mod common;
use common::*;
use std::collections::BTreeMap;

/// Amplitudes of the noise (map units).
const AMPLITUDES: [f64; 2] = [1e-3, 2e-3];

/// `(file, amplitude)` pairs that do not give the clean mesh yet (none
/// since singular vertices are snapped onto their fixed sets; the list
/// stays for the next map that breaks).
const KNOWN_FAILING: &[(&str, f64)] = &[];

/// splitmix64: a deterministic noise source.
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn add_noise<const N: usize, const D: usize>(map: &mut dualex_map::SimplexMap<N, D>, amp: f64) {
    let mut rng = Rng(0x5EED);
    for x in map.coords.iter_mut().flatten().flatten() {
        *x += (2.0 * rng.unit() - 1.0) * amp;
    }
}

/// What must agree between the clean and the noisy extraction.
#[derive(Debug, PartialEq)]
struct Summary {
    cells: usize,
    vertices: usize,
    boundary: usize,
    valence: BTreeMap<u32, usize>,
    boundary_valence: BTreeMap<u32, usize>,
}

/// One extraction: the summary, or the error; and (rounded transitions,
/// largest residual, open interior faces / holes).
type Outcome = (Result<Summary, String>, usize, f64, u64);

fn hex(map: &dualex_map::TetMap) -> Outcome {
    match dualex_hex::extract(map, &Default::default()) {
        Err(e) => (Err(e.to_string()), 0, 0.0, 0),
        Ok((mesh, st)) => {
            let c = dualex_check::check_hex_mesh(mesh.positions.len(), &mesh.cells, None);
            let s = Summary {
                cells: c.cells,
                vertices: c.vertices_used,
                boundary: c.boundary_faces,
                valence: c.interior_edge_valence.clone(),
                boundary_valence: c.boundary.interior_valence.clone(),
            };
            let ok = if c.is_valid() {
                Ok(s)
            } else {
                Err(c.errors().join("; "))
            };
            let j = st.to_json();
            let holes = j["output"]["holes"].as_u64().unwrap_or(u64::MAX);
            (
                ok,
                st.segment.snapped_transitions,
                st.segment.max_transition_residual,
                holes,
            )
        }
    }
}

fn quad(map: &dualex_map::TriMap) -> Outcome {
    match dualex_quad::extract(map, &Default::default()) {
        Err(e) => (Err(e.to_string()), 0, 0.0, 0),
        Ok((mesh, st)) => {
            let c = dualex_check::check_quad_mesh(mesh.positions.len(), &mesh.cells);
            let s = Summary {
                cells: c.faces,
                vertices: c.vertices_used,
                boundary: c.boundary_edges,
                valence: c.interior_valence.clone(),
                boundary_valence: c.boundary_valence.clone(),
            };
            let ok = if c.is_valid() {
                Ok(s)
            } else {
                Err(c.errors().join("; "))
            };
            (
                ok,
                st.segment.snapped_transitions,
                st.segment.max_transition_residual,
                st.holes_left_open as u64,
            )
        }
    }
}

/// Runs every case; prints one table line per case; returns the cases
/// whose noisy mesh differs from the clean one, with why.
fn run_all(root: &std::path::Path) -> Vec<((String, f64), String)> {
    let mut failed = Vec::new();
    let mut record = |file: &str, amp: f64, clean: &Outcome, noisy: &Outcome| {
        let line = format!(
            "{file} noise {amp:e}: clean {:?}; noisy {:?}, {} transitions rounded (largest residual {:.2e}), holes {}",
            clean.0, noisy.0, noisy.1, noisy.2, noisy.3
        );
        eprintln!("{line}");
        let clean_summary = clean.0.as_ref().expect("the clean map extracts");
        assert_eq!(
            (clean.1, clean.3),
            (0, 0),
            "{file}: clean map rounded or cracked"
        );
        let same = noisy.0.as_ref().is_ok_and(|s| s == clean_summary);
        if !same || noisy.1 == 0 || noisy.3 != 0 {
            failed.push(((file.to_string(), amp), line));
        }
    };
    for file in ["hand_q.hexex", "fancy_ring_q.hexex", "rockerarm_q.hexex"] {
        let path = root.join("hexex").join(file);
        let map = dualex_io::read_tet_map(&path).unwrap_or_else(|e| panic!("{e}"));
        let clean = hex(&map);
        for amp in AMPLITUDES {
            let mut noisy = map.clone();
            add_noise(&mut noisy, amp);
            record(file, amp, &clean, &hex(&noisy));
        }
    }
    for file in ["fandisk_param.obj"] {
        let path = root.join("qex").join(file);
        let map = dualex_io::read_tri_map(&path).unwrap_or_else(|e| panic!("{e}"));
        let (map, _) = dualex_map::weld::weld_owned(map);
        let clean = quad(&map);
        for amp in AMPLITUDES {
            let mut noisy = map.clone();
            add_noise(&mut noisy, amp);
            record(file, amp, &clean, &quad(&noisy));
        }
    }
    failed
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn noisy_shared_maps_extract_like_the_clean_ones() {
    let Some(root) = shared_data("") else {
        return;
    };
    let failed = run_all(&root);
    let known = |k: &(String, f64)| KNOWN_FAILING.iter().any(|(f, a)| *f == k.0 && *a == k.1);
    for (file, amp) in KNOWN_FAILING {
        let still = failed.iter().any(|(k, _)| k.0 == *file && k.1 == *amp);
        eprintln!(
            "KNOWN_FAILING {file} noise {amp:e}: {}",
            if still {
                "still fails"
            } else {
                "NOW PASSES: remove it from KNOWN_FAILING"
            }
        );
    }
    let unexpected: Vec<&String> = failed
        .iter()
        .filter(|(k, _)| !known(k))
        .map(|(_, l)| l)
        .collect();
    assert!(
        unexpected.is_empty(),
        "noisy maps unlike the clean ones:\n{}",
        unexpected
            .iter()
            .map(|s| s.as_str())
            .collect::<Vec<_>>()
            .join("\n")
    );
}

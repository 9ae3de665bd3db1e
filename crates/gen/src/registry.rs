//! Named test maps with default parameters (triangle maps: [`names`],
//! [`by_name`]; tet maps: [`names_3d`], [`by_name_3d`]), for the CLI (`dualex generate
//! NAME`) and the end-to-end tests. The seed only matters for maps with
//! noise; the others ignore it.
//!
//! Square maps use `[lo, hi] = [0.2, 7.2]` (7 × 7 quads); the disks use 16
//! rings, 48 sectors and a map radius of 6.3.

use crate::block::*;
use crate::closed::{cube_surface, torus, Perturb};
use crate::disk::{invalid_quantization, multi_boundary, singular_disk};
use crate::expected::Expected;
use crate::prism::wedge_singular_edge;
use crate::square::*;
use crate::Diagonal;
use dualex_map::{TetMap, TriMap};

const LO: f64 = 0.2;
const HI: f64 = 7.2;
const DISK_INDICES: [(&str, i32); 6] = [
    ("p1", 1),
    ("m1", -1),
    ("m2", -2),
    ("m3", -3),
    ("m4", -4),
    ("m5", -5),
];

/// Every name [`by_name`] accepts, in a stable order.
pub fn names() -> Vec<String> {
    let mut out: Vec<String> = [
        "square_identity",
        "square_identity_fixed",
        "square_fold",
        "square_noise",
        "square_collapsed",
        "square_half_rotated",
        "cube",
        "cube_fold",
        "cube_noise",
        "torus",
        "torus_fold",
        "torus_noise",
        "invalid_quantization",
        "multi_boundary",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    for (tag, _) in DISK_INDICES {
        out.push(format!("disk_{tag}"));
        out.push(format!("disk_{tag}_reverted"));
    }
    out
}

/// The map called `name` (see [`names`]) with its expected quad mesh.
pub fn by_name(name: &str, seed: u64) -> Option<(TriMap, Expected)> {
    let alt = Diagonal::Alternating;
    let noise = |amplitude: f64| Perturb::Noise { amplitude, seed };
    let fold = Perturb::Fold { strength: 1.5 };
    Some(match name {
        "square_identity" => square_identity(14, LO, HI, alt),
        "square_identity_fixed" => square_identity(14, LO, HI, Diagonal::Fixed),
        "square_fold" => square_fold(28, LO, HI, 1.5, alt),
        "square_noise" => square_noise(14, LO, HI, 1.0, seed, alt),
        "square_collapsed" => square_collapsed(14, LO, HI, alt),
        "square_half_rotated" => square_half_rotated(14, LO, HI, 0.5, seed, alt),
        "cube" => cube_surface(3, 6, Perturb::None, alt),
        "cube_fold" => cube_surface(4, 16, fold, alt),
        "cube_noise" => cube_surface(3, 6, noise(0.4), alt),
        "torus" => torus(8, 4, 16, 8, Perturb::None, alt),
        "torus_fold" => torus(8, 4, 32, 16, fold, alt),
        "torus_noise" => torus(8, 4, 16, 8, noise(0.4), alt),
        "invalid_quantization" => return invalid_quantization(-2, 16, 48, 6.3),
        "multi_boundary" => return multi_boundary(24, 48, 6.3),
        _ => return disk_by_name(name),
    })
}

fn disk_by_name(name: &str) -> Option<(TriMap, Expected)> {
    let rest = name.strip_prefix("disk_")?;
    let (tag, reverted) = match rest.strip_suffix("_reverted") {
        Some(tag) => (tag, true),
        None => (rest, false),
    };
    let &(_, k) = DISK_INDICES.iter().find(|(t, _)| *t == tag)?;
    singular_disk(k, reverted, 16, 48, 6.3)
}

/// Every name [`by_name_3d`] accepts (tet maps), in a stable order.
pub fn names_3d() -> Vec<String> {
    [
        "block",
        "block_noise",
        "block_fold",
        "block_half_rotated",
        "block_degenerate",
        "wedge_p1",
        "wedge_m1",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect()
}

/// The tet map called `name` (see [`names_3d`]) with its expected hex mesh.
/// Blocks map onto `[0.2, 4.2]³` (4³ hexes); wedges are the `disk_p1` /
/// `disk_m1` disks (10 rings, 32 sectors, radius 4.3) × 3 layers.
pub fn by_name_3d(name: &str, seed: u64) -> Option<(TetMap, ExpectedHex)> {
    const B: (f64, f64) = (0.2, 4.2);
    Some(match name {
        "block" => block(6, 6, 6, B.0, B.1),
        "block_noise" => block_noise(8, B.0, B.1, 0.5, seed),
        "block_fold" => block_fold(12, B.0, B.1, 1.5),
        "block_half_rotated" => block_half_rotated(8, B.0, B.1, 0.3, seed),
        "block_degenerate" => block_degenerate(8, B.0, B.1, 5, seed),
        "wedge_p1" => return wedge_singular_edge(1, 10, 32, 4.3, 3),
        "wedge_m1" => return wedge_singular_edge(-1, 10, 32, 4.3, 3),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_builds_a_valid_map() {
        let names = names();
        assert_eq!(names.len(), 14 + 12);
        for n in &names {
            let (m, e) = by_name(n, 1).unwrap_or_else(|| panic!("{n} not found"));
            assert!(m.validate().is_ok(), "{n}");
            assert_eq!(crate::testing::gp_residual(&m), 0.0, "{n}");
            assert!(e.euler.is_some(), "{n}");
        }
        assert!(by_name("nope", 1).is_none());
        assert!(by_name("disk_m7", 1).is_none());
    }

    #[test]
    fn seeds_change_only_noisy_maps() {
        for n in names() {
            let a = by_name(&n, 1).map(|x| x.0);
            let b = by_name(&n, 2).map(|x| x.0);
            assert_eq!(
                a == b,
                !n.contains("noise") && !n.contains("half_rotated"),
                "{n}"
            );
        }
    }

    /// Cross-check with dualex-map's own analysis: exact transitions and
    /// the singularities each map is built to have.
    #[test]
    fn dualex_map_sees_the_intended_singularities() {
        use dualex_map::report::{inspect, quarters, InspectOptions};
        let opts = InspectOptions {
            weld: false,
            ..InspectOptions::default()
        };
        for n in names() {
            let (m, _) = by_name(&n, 1).unwrap_or_else(|| panic!("{n}"));
            let r = inspect(&m, &opts).unwrap_or_else(|e| panic!("{n}: {e}"));
            assert_eq!(r.max_transition_residual, 0.0, "{n}");
            let expected: Vec<(String, usize)> = if n == "invalid_quantization" {
                // the two singular vertices merged (2b: fewest singular
                // ends); next to degenerate triangles only the half turn of
                // index −1/2 is known, reported as its fractional part
                vec![("1/2".to_string(), 1)]
            } else if n.starts_with("cube") {
                vec![("1/4".to_string(), 8)]
            } else if let Some(&(_, k)) = DISK_INDICES.iter().find(|(t, _)| n.contains(t)) {
                vec![(quarters(i64::from(k)), 1)]
            } else {
                vec![]
            };
            // near folds only the fractional part of an index is known
            let mut got = r.singularities.clone();
            for (k, c) in &r.singularities_integer_part_unknown {
                *got.entry(k.clone()).or_insert(0) += c;
            }
            let got: Vec<(String, usize)> = got.into_iter().collect();
            assert_eq!(got, expected, "{n}: {r:?}");
        }
    }

    #[test]
    fn every_3d_name_builds_a_valid_exact_map() {
        let opts = dualex_map::InspectOptions {
            weld: false,
            ..Default::default()
        };
        for n in names_3d() {
            let (m, e) = by_name_3d(&n, 1).unwrap_or_else(|| panic!("{n}"));
            assert!(m.validate().is_ok(), "{n}");
            let r = dualex_map::inspect(&m, &opts).unwrap_or_else(|e| panic!("{n}: {e}"));
            assert_eq!(r.max_transition_residual, 0.0, "{n}");
            let singular: usize = r.singular_edges.values().sum();
            assert_eq!(singular, if n.starts_with("wedge") { 3 } else { 0 }, "{n}");
            assert!(e.hexes.is_some(), "{n}");
        }
        assert!(by_name_3d("nope", 1).is_none());
    }
}

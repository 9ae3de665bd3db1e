//! The quad count lands within 10 % of the target (issue 15): the map's
//! area is fitted after the continuous solve and after the rounding
//! (`IntegrateOptions::fit_area`), and the real extraction (`dualex::quad`)
//! of the direct-rounded map counts the quads.

use dualex_remesh::{remesh, remesh_counted, shapes, Quantization, RemeshOptions, Target};

/// `(quads, map area)` of `dualex remesh` on a named surface.
fn count(name: &str, n: usize, seed: u64, quantization: Quantization) -> (usize, f64) {
    let s = shapes::by_name(name).unwrap_or_else(|| panic!("no surface {name}"));
    let opts = RemeshOptions {
        target: Target::Quads(n),
        quantization,
        seed,
        ..RemeshOptions::default()
    };
    let made = remesh(&s, &opts).unwrap_or_else(|e| panic!("{name}, {n}, seed {seed}: {e}"));
    let out = dualex::quad(&made.map, &dualex::Options::default())
        .unwrap_or_else(|e| panic!("{name}, {n}, seed {seed}: extraction: {e}"));
    (out.mesh.cells.len(), made.stats.map_area)
}

fn within(x: f64, n: usize, percent: f64) -> bool {
    (x - n as f64).abs() <= percent / 100.0 * n as f64
}

#[test]
fn quad_count_within_ten_percent_on_the_generated_surfaces() {
    for &(name, _) in shapes::NAMED {
        if name == "surface_torus_large" {
            continue; // the speed benchmark's surface: too slow for a test
        }
        if name.starts_with("surface_sweep_") {
            continue; // tests/remesh_sweep.rs runs them (through `dualex remesh`)
        }
        if name.starts_with("surface_cad_") {
            // fan caps: the map collapses today (issue 23); the loud
            // failure is asserted by tests/remesh_errors.rs
            continue;
        }
        for n in [500, 2000] {
            for seed in [1, 2] {
                let (quads, area) = count(name, n, seed, Quantization::Direct);
                assert!(
                    within(quads as f64, n, 10.0),
                    "{name}, {n}, seed {seed}: {quads} quads (map area {area})"
                );
            }
        }
    }
}

#[test]
fn map_area_is_fitted_with_singularities_off_the_grid() {
    // the extraction's repairs near off-grid singularities add quads of
    // their own; the map itself covers N cells
    for name in ["surface_torus", "surface_genus3", "surface_sphere"] {
        let (_, area) = count(name, 500, 1, Quantization::SingularitiesOff);
        assert!(within(area, 500, 10.0), "{name}: map area {area}");
    }
}

/// With singularities off the grid the extraction's repairs add quads
/// (110–119 for 100 on the torus with the map's area fitted alone);
/// [`remesh_counted`] with the extraction's count makes the map again for
/// the area that count asks: within 10 % of `N`.
#[test]
fn quad_count_within_ten_percent_off_the_grid_with_the_extractions_count() {
    let quads_of = |map: &dualex_map::TriMap| {
        dualex::quad(map, &dualex::Options::default())
            .ok()
            .map(|out| out.mesh.cells.len())
    };
    for name in ["surface_torus", "surface_sphere", "surface_genus3"] {
        let s = shapes::by_name(name).unwrap_or_else(|| panic!("no surface {name}"));
        for seed in 1..=5 {
            let opts = RemeshOptions {
                target: Target::Quads(100),
                quantization: Quantization::SingularitiesOff,
                seed,
                ..RemeshOptions::default()
            };
            let made = remesh_counted(&s, &opts, &mut |m| quads_of(m))
                .unwrap_or_else(|e| panic!("{name}, seed {seed}: {e}"));
            let quads = quads_of(&made.map)
                .unwrap_or_else(|| panic!("{name}, seed {seed}: the extraction refuses"));
            assert!(
                within(quads as f64, 100, 10.0),
                "{name}, seed {seed}: {quads} quads, counts {:?}",
                made.stats.counted
            );
            assert_eq!(
                made.stats
                    .counted
                    .iter()
                    .flatten()
                    .min_by_key(|q| q.abs_diff(100)),
                Some(&quads),
                "{name}, seed {seed}: the closer map is kept"
            );
        }
    }
}

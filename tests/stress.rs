//! Random stress (property test): random messy maps — generated bases
//! (squares, cubes, tori, singular disks, blocks, wedges) with random white
//! noise of growing amplitude carried consistently through the transitions,
//! random collapses, random global rotation of charts — go through the quad
//! and hex extraction in-process. For every input: a valid mesh (all quads /
//! hexes, manifold, oriented, no holes, one component) or a clean error;
//! never a panic, never an invalid mesh.
//!
//! `DUALEX_STRESS_CASES=N` sets the number of cases per dimension (default
//! 120, a few seconds); `DUALEX_STRESS_SEED=S` the first seed.

use dualex_map::{SimplexMap, Stars, Topology, TransitionOptions, Transitions};

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// Adds per-vertex noise of amplitude `amp` (a random vector in each
/// vertex's reference chart, carried to its corners by the star rotations:
/// the map stays GP), skipping singular vertices; with `collapse`, a random
/// set of vertices is moved onto one point of their own charts instead.
fn perturb<const N: usize, const D: usize>(
    map: &mut SimplexMap<N, D>,
    rng: &mut Rng,
    amp: f64,
    collapse: bool,
) -> bool {
    let Ok(topo) = Topology::build(map) else {
        return false;
    };
    let Ok((trans, _)) = Transitions::derive(map, &topo, &TransitionOptions::default()) else {
        return false;
    };
    let stars = Stars::build(map, &topo, &trans);
    let nv = map.positions.len();
    let centre = rng.below(nv.max(1));
    let radius = 0.1 + 0.3 * rng.unit();
    let p0 = map.positions[centre];
    for v in 0..nv {
        if stars.singular[v] || stars.boundary[v] {
            continue;
        }
        let star = stars.of(v);
        let Some(first) = star.first() else { continue };
        let d: [f64; D] = if collapse {
            let dist: f64 = (0..3)
                .map(|k| (map.positions[v][k] - p0[k]).powi(2))
                .sum::<f64>()
                .sqrt();
            if dist > radius {
                continue;
            }
            // move towards the collapse point, expressed in v's reference chart
            let x = map.coords[first.simplex as usize][first.corner as usize];
            std::array::from_fn(|k| x[k].floor() + 0.37 - x[k])
        } else {
            std::array::from_fn(|_| amp * (2.0 * rng.unit() - 1.0))
        };
        for e in star {
            let de = e.rot.apply(&d);
            let c = &mut map.coords[e.simplex as usize][e.corner as usize];
            for k in 0..D {
                c[k] += de[k];
            }
        }
    }
    true
}

fn cases() -> (u64, u64) {
    let n = std::env::var("DUALEX_STRESS_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(120);
    let s = std::env::var("DUALEX_STRESS_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1);
    (s, n)
}

#[test]
fn random_messy_2d_maps_give_valid_meshes_or_clean_errors() {
    let names = dualex_gen::names();
    let (first, n) = cases();
    let (mut ok, mut errors) = (0, 0);
    for seed in first..first + n {
        let mut rng = Rng(seed);
        let name = &names[rng.below(names.len())];
        let (mut map, _) = dualex_gen::by_name(name, seed).expect("generator");
        let amp = 1.5 * rng.unit() * rng.unit();
        let collapse = rng.below(5) == 0;
        let case = format!("seed {seed}: {name}, noise {amp:.3}, collapse {collapse}");
        if !perturb(&mut map, &mut rng, amp, collapse) {
            continue;
        }
        if (seed - first) % 5000 == 4999 {
            eprintln!(
                "2D stress progress: {} cases, {ok} valid, {errors} errors",
                seed - first + 1
            );
        }
        let opts = dualex_quad::QuadOptions {
            seed,
            ..Default::default()
        };
        let result = std::panic::catch_unwind(|| dualex_quad::extract(&map, &opts));
        match result {
            Err(_) => panic!("{case}: panicked"),
            Ok(Err(e)) => {
                let msg = e.to_string();
                assert!(
                    !msg.is_empty() && !msg.contains('\n'),
                    "{case}: error {msg:?}"
                );
                errors += 1;
            }
            Ok(Ok((mesh, st))) => {
                let rep = dualex_check::check_quad_mesh(mesh.positions.len(), &mesh.cells);
                assert!(
                    rep.is_valid(),
                    "{case}: invalid mesh {:?}; {}",
                    rep.errors(),
                    st.to_json()
                );
                assert_eq!(st.holes_left_open, 0, "{case}: {}", st.to_json());
                assert_eq!(rep.components, 1, "{case}: components; {}", st.to_json());
                assert!(!mesh.cells.is_empty(), "{case}: empty output");
                ok += 1;
            }
        }
    }
    eprintln!(
        "2D stress: {ok} valid meshes, {errors} clean errors, seeds {first}..{}",
        first + n
    );
    assert!(ok > 0);
}

#[test]
fn random_messy_3d_maps_give_valid_meshes_or_clean_errors() {
    let names = dualex_gen::names_3d();
    let (first, n) = cases();
    let n = n.div_ceil(4); // 3D maps are larger
    let (mut ok, mut errors) = (0, 0);
    for seed in first..first + n {
        let mut rng = Rng(seed ^ 0xABCD);
        let name = &names[rng.below(names.len())];
        let (mut map, _) = dualex_gen::by_name_3d(name, seed).expect("generator");
        let amp = 0.8 * rng.unit() * rng.unit();
        let case = format!("seed {seed}: {name}, noise {amp:.3}");
        if !perturb(&mut map, &mut rng, amp, false) {
            continue;
        }
        if (seed - first) % 1000 == 999 {
            eprintln!(
                "3D stress progress: {} cases, {ok} valid, {errors} errors",
                seed - first + 1
            );
        }
        let opts = dualex_hex::HexOptions {
            seed,
            ..Default::default()
        };
        match std::panic::catch_unwind(|| dualex_hex::extract(&map, &opts)) {
            Err(_) => panic!("{case}: panicked"),
            Ok(Err(e)) => {
                assert!(!e.to_string().contains('\n'), "{case}: {e}");
                errors += 1;
            }
            Ok(Ok((mesh, st))) => {
                let rep = dualex_check::check_hex_mesh(mesh.positions.len(), &mesh.cells, None);
                assert!(
                    rep.is_valid(),
                    "{case}: invalid hex mesh {:?}; {}",
                    rep.errors(),
                    st.to_json()
                );
                ok += 1;
            }
        }
    }
    eprintln!("3D stress: {ok} valid meshes, {errors} clean errors");
    assert!(ok > 0);
}

/// The shared real maps (`../shared/data`, skipped with a notice when
/// absent), with random noise of growing amplitude carried through their
/// transitions: `DUALEX_STRESS_CASES / 20` cases (at least 6).
#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn random_noise_on_real_maps_gives_valid_meshes_or_clean_errors() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data");
    if !root.is_dir() {
        eprintln!("NOTICE: ../shared/data is absent: skipping the real-map stress");
        return;
    }
    let files = [
        "qex/fandisk_param.obj",
        "qex/duck_miq_8_param.obj",
        "directional/spherer-param.obj",
        "directional/decimated-knight-param.obj",
        "directional/lilium-param.obj",
    ];
    let maps: Vec<_> = files
        .iter()
        .map(|f| {
            let m = dualex_io::read_tri_map(&root.join(f)).expect("shared map");
            (f, dualex_map::weld::weld(&m).0)
        })
        .collect();
    let (first, n) = cases();
    let n = (n / 20).max(6);
    let mut ok = 0;
    for seed in first..first + n {
        let mut rng = Rng(seed ^ 0x5EED);
        let (name, base) = &maps[rng.below(maps.len())];
        let mut map = base.clone();
        let amp = 0.6 * rng.unit();
        let case = format!("seed {seed}: {name}, noise {amp:.3}");
        if !perturb(&mut map, &mut rng, amp, false) {
            continue;
        }
        let opts = dualex_quad::QuadOptions {
            seed,
            ..Default::default()
        };
        match std::panic::catch_unwind(|| dualex_quad::extract(&map, &opts)) {
            Err(_) => panic!("{case}: panicked"),
            Ok(Err(e)) => assert!(!e.to_string().contains('\n'), "{case}: {e}"),
            Ok(Ok((mesh, st))) => {
                let rep = dualex_check::check_quad_mesh(mesh.positions.len(), &mesh.cells);
                assert!(
                    rep.is_valid(),
                    "{case}: invalid mesh {:?}; {}",
                    rep.errors(),
                    st.to_json()
                );
                assert_eq!(st.holes_left_open, 0, "{case}: {}", st.to_json());
                assert_eq!(rep.components, 1, "{case}");
                ok += 1;
            }
        }
    }
    eprintln!("real-map stress: {ok} valid meshes of {n} cases");
    assert!(ok > 0);
}

//! Per-stage benchmarks (divan): `cargo bench -p dualex-bench`.
//!
//! Each bench runs one stage on generated maps of two or three sizes
//! (`torus_fold:R`: R² triangles with a fold; `block_noise:N`: 6·N³ noisy
//! tets), reports throughput in simplices/s, so growth with size is
//! visible. Whole-process figures (reading, writing, peak memory) come
//! from `dualex-bench` and `tools/bench-cli`, see BENCHMARKS.md.

use divan::counter::ItemsCount;
use divan::Bencher;
use dualex_bench::cases::{build, Input};
use dualex_map::{Stars, TetMap, Topology, TransitionOptions, Transitions, TriMap};

fn main() {
    divan::main();
}

const SIZES_2D: [usize; 3] = [110, 280, 540];
const SIZES_3D: [usize; 2] = [14, 26];

fn tri(r: usize) -> TriMap {
    match build(&format!("torus_fold:{r}")) {
        Ok(Input::Tri(m)) => m,
        _ => panic!("torus_fold:{r} is a triangle map"),
    }
}

fn tet(n: usize) -> TetMap {
    match build(&format!("block_noise:{n}")) {
        Ok(Input::Tet(m)) => m,
        _ => panic!("block_noise:{n} is a tet map"),
    }
}

#[divan::bench(args = SIZES_2D, sample_count = 10)]
fn read_obj(b: Bencher, r: usize) {
    let map = tri(r);
    let mut bytes = Vec::new();
    dualex_io::write_map::tri_map_obj(&mut bytes, &map).expect("write");
    b.counter(ItemsCount::new(map.len()))
        .bench(|| dualex_io::parse_obj(&bytes).expect("read"));
}

#[divan::bench(args = SIZES_3D, sample_count = 10)]
fn read_hexex(b: Bencher, n: usize) {
    let map = tet(n);
    let mut bytes = Vec::new();
    dualex_io::write_map::tet_map_hexex(&mut bytes, &map).expect("write");
    b.counter(ItemsCount::new(map.len()))
        .bench(|| dualex_io::parse_hexex(&bytes).expect("read"));
}

#[divan::bench(args = SIZES_2D, sample_count = 10)]
fn topology_2d(b: Bencher, r: usize) {
    let map = tri(r);
    b.counter(ItemsCount::new(map.len()))
        .bench(|| Topology::build(&map).expect("topology"));
}

#[divan::bench(args = SIZES_2D, sample_count = 10)]
fn transitions_2d(b: Bencher, r: usize) {
    let map = tri(r);
    let topo = Topology::build(&map).expect("topology");
    let opts = TransitionOptions::default();
    b.counter(ItemsCount::new(map.len()))
        .bench(|| Transitions::derive(&map, &topo, &opts).expect("transitions"));
}

#[divan::bench(args = SIZES_2D, sample_count = 10)]
fn stars_2d(b: Bencher, r: usize) {
    let map = tri(r);
    let topo = Topology::build(&map).expect("topology");
    let (trans, _) = Transitions::derive(&map, &topo, &Default::default()).expect("transitions");
    b.counter(ItemsCount::new(map.len()))
        .bench(|| Stars::build(&map, &topo, &trans));
}

#[divan::bench(args = SIZES_2D, sample_count = 10)]
fn extract_quad(b: Bencher, r: usize) {
    let map = tri(r);
    let opts = dualex_quad::QuadOptions::default();
    b.counter(ItemsCount::new(map.len()))
        .bench(|| dualex_quad::extract(&map, &opts).expect("quads"));
}

#[divan::bench(args = SIZES_3D, sample_count = 10)]
fn topology_3d(b: Bencher, n: usize) {
    let map = tet(n);
    b.counter(ItemsCount::new(map.len()))
        .bench(|| Topology::build(&map).expect("topology"));
}

#[divan::bench(args = SIZES_3D, sample_count = 10)]
fn transitions_3d(b: Bencher, n: usize) {
    let map = tet(n);
    let topo = Topology::build(&map).expect("topology");
    let opts = TransitionOptions::default();
    b.counter(ItemsCount::new(map.len()))
        .bench(|| Transitions::derive(&map, &topo, &opts).expect("transitions"));
}

#[divan::bench(args = SIZES_3D, sample_count = 10)]
fn extract_hex(b: Bencher, n: usize) {
    let map = tet(n);
    let opts = dualex_hex::HexOptions::default();
    b.counter(ItemsCount::new(map.len()))
        .bench(|| dualex_hex::extract(&map, &opts).expect("hexes"));
}

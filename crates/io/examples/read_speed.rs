//! Measures read time: `cargo run --release -p dualex-io --example read_speed -- FILE…`
//! (`.obj`/`.ply` as triangle maps, `.hexex` as tet maps; best of 5 runs).

use std::path::Path;
use std::time::Instant;

fn main() {
    for arg in std::env::args().skip(1) {
        let path = Path::new(&arg);
        let mut best = f64::INFINITY;
        let mut what = String::new();
        for _ in 0..5 {
            let t = Instant::now();
            let r = if arg.ends_with(".hexex") {
                dualex_io::read_tet_map(path)
                    .map(|m| format!("{} v, {} tets", m.positions.len(), m.len()))
            } else {
                dualex_io::read_tri_map(path)
                    .map(|m| format!("{} v, {} triangles", m.positions.len(), m.len()))
            };
            best = best.min(t.elapsed().as_secs_f64() * 1e3);
            what = r.unwrap_or_else(|e| e.to_string());
        }
        let mb = std::fs::metadata(path)
            .map(|m| m.len() as f64 / 1e6)
            .unwrap_or(0.0);
        println!(
            "{arg}: {what}; {mb:.1} MB in {best:.1} ms ({:.0} MB/s)",
            mb / best * 1e3
        );
    }
}

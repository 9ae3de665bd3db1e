//! `cargo run -p dualex --example quad [MAP.obj [OUT.obj]]`: the quad mesh
//! of a map file, or of a small map built from slices.

fn main() -> Result<(), dualex::Error> {
    let mut args = std::env::args().skip(1);
    let map = match args.next() {
        Some(path) => dualex::read_tri_map(path)?,
        None => {
            // a unit square of two triangles, mapped onto [0, 4]²
            let positions = [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]];
            let triangles = [[0, 1, 2], [0, 2, 3]];
            let uv = [
                [[0., 0.], [4., 0.], [4., 4.]],
                [[0., 0.], [4., 4.], [0., 4.]],
            ];
            dualex::tri_map_from_slices(&positions, &triangles, &uv)?
        }
    };
    // cut meshes are welded first; `weld: false` keeps their seams apart
    let out = dualex::quad(&map, &dualex::Options::default())?;
    let s = &out.stats;
    println!(
        "{} quads, {} vertices, {} components, Euler characteristic {}",
        s.cells, s.vertices, s.components, s.euler
    );
    println!("interior valences: {:?}", s.valence_interior);
    // the geometric stage (default: untangle inverted quads only)
    let g = &s.geometry;
    println!(
        "scaled Jacobian min {:.2}, {} inverted before the geometric stage, {} after",
        g.after.min, g.before.inverted, g.after.inverted
    );
    if let Some(obj) = args.next() {
        dualex::write_quad_mesh(obj, &out.mesh)?;
    }
    Ok(())
}

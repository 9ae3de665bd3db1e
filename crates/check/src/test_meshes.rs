//! Small quad meshes for the tests: grids, a cube surface, a torus.

/// An `nx × ny` grid of quads, CCW, vertex `(i, j)` at index `j·(nx+1) + i`.
pub(crate) fn grid(nx: u32, ny: u32) -> (usize, Vec<[u32; 4]>) {
    let id = |i: u32, j: u32| j * (nx + 1) + i;
    let mut quads = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            quads.push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    (((nx + 1) * (ny + 1)) as usize, quads)
}

/// An `n × m` periodic grid (a torus), CCW.
pub(crate) fn torus(n: u32, m: u32) -> (usize, Vec<[u32; 4]>) {
    let id = |i: u32, j: u32| (j % m) * n + (i % n);
    let mut quads = Vec::new();
    for j in 0..m {
        for i in 0..n {
            quads.push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    ((n * m) as usize, quads)
}

/// The surface of the cube `[0, n]³` split into `6n²` unit quads, oriented
/// outwards, with vertex positions.
pub(crate) fn cube(n: u32) -> (Vec<[f64; 3]>, Vec<[u32; 4]>) {
    let mut index = std::collections::HashMap::new();
    let mut positions = Vec::new();
    let mut id = |p: [u32; 3]| -> u32 {
        *index.entry(p).or_insert_with(|| {
            positions.push(p.map(f64::from));
            (positions.len() - 1) as u32
        })
    };
    let mut quads = Vec::new();
    // (normal axis, side): face axes (a, b) with a × b = outward normal
    for axis in 0..3 {
        for side in 0..2u32 {
            let (mut a, mut b) = ((axis + 1) % 3, (axis + 2) % 3);
            if side == 0 {
                std::mem::swap(&mut a, &mut b);
            }
            for j in 0..n {
                for i in 0..n {
                    let mut q = [0u32; 4];
                    for (k, (di, dj)) in [(0, 0), (1, 0), (1, 1), (0, 1)].into_iter().enumerate() {
                        let mut p = [0u32; 3];
                        p[axis] = side * n;
                        p[a] = i + di;
                        p[b] = j + dj;
                        q[k] = id(p);
                    }
                    quads.push(q);
                }
            }
        }
    }
    (positions, quads)
}

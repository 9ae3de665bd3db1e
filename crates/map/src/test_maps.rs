//! Small maps built for the tests of this crate, and tiny readers of the
//! shared data files (the I/O crate is a separate layer).

use std::collections::HashMap;

use crate::{Rot, SimplexMap, TetMap, TriMap};

/// Deterministic pseudo-random numbers (64-bit LCG, high bits).
pub struct Lcg(pub u64);

impl Lcg {
    /// Next value in `0..n`.
    pub fn below(&mut self, n: u64) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 33) % n
    }
}

/// An `n × n` grid of unit squares split into triangles, map = position.
pub fn grid(n: u32) -> TriMap {
    let mut m = TriMap::default();
    for j in 0..=n {
        for i in 0..=n {
            m.positions.push([i as f64, j as f64, 0.0]);
        }
    }
    for j in 0..n {
        for i in 0..n {
            let v = |a: u32, b: u32| (j + b) * (n + 1) + i + a;
            m.simplices.push([v(0, 0), v(1, 0), v(1, 1)]);
            m.simplices.push([v(0, 0), v(1, 1), v(0, 1)]);
        }
    }
    m.coords = m
        .simplices
        .iter()
        .map(|s| s.map(|v| [m.positions[v as usize][0], m.positions[v as usize][1]]))
        .collect();
    m
}

/// A cube `[0, n]³` split into `6·n³` tets (Kuhn), map = position.
pub fn tet_cube(n: u32) -> TetMap {
    let mut m = TetMap::default();
    let id = |i: u32, j: u32, k: u32| (k * (n + 1) + j) * (n + 1) + i;
    for k in 0..=n {
        for j in 0..=n {
            for i in 0..=n {
                m.positions.push([i as f64, j as f64, k as f64]);
            }
        }
    }
    const PERMS: [[usize; 3]; 6] = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                for p in PERMS {
                    let mut c = [i, j, k];
                    let mut t = [id(c[0], c[1], c[2]); 4];
                    for (step, &axis) in p.iter().enumerate() {
                        c[axis] += 1;
                        t[step + 1] = id(c[0], c[1], c[2]);
                    }
                    m.simplices.push(t);
                }
            }
        }
    }
    m.coords = m
        .simplices
        .iter()
        .map(|s| s.map(|v| m.positions[v as usize]))
        .collect();
    // orient every tet positively
    for s in 0..m.len() {
        if m.map_det(s) < 0.0 {
            m.simplices[s].swap(2, 3);
            m.coords[s].swap(2, 3);
        }
    }
    m
}

/// Re-expresses every simplex's chart through a pseudo-random rotation and
/// integer translation.
/// Returns the per-simplex `(rotation, translation)`.
pub fn rechart<const N: usize, const D: usize>(
    map: &mut SimplexMap<N, D>,
    seed: u64,
) -> Vec<(Rot<D>, [i64; D])> {
    let all = Rot::<D>::all();
    let mut rng = Lcg(seed);
    let mut out = Vec::new();
    for coords in map.coords.iter_mut() {
        let r = all[rng.below(all.len() as u64) as usize];
        let t: [i64; D] = std::array::from_fn(|_| rng.below(21) as i64 - 10);
        for p in coords.iter_mut() {
            let q = r.apply(p);
            *p = std::array::from_fn(|k| q[k] + t[k] as f64);
        }
        out.push((r, t));
    }
    out
}

/// Surface of the cube `[0, n]³`, each face an `n × n` grid in its own
/// chart (integer coordinates), oriented outwards.
pub fn cube_surface(n: i64) -> TriMap {
    // (origin, U, V) with U × V = outward normal
    let faces: [([i64; 3], [i64; 3], [i64; 3]); 6] = [
        ([0, 0, 0], [0, 1, 0], [1, 0, 0]),
        ([0, 0, n], [1, 0, 0], [0, 1, 0]),
        ([0, 0, 0], [0, 0, 1], [0, 1, 0]),
        ([n, 0, 0], [0, 1, 0], [0, 0, 1]),
        ([0, 0, 0], [1, 0, 0], [0, 0, 1]),
        ([0, n, 0], [0, 0, 1], [1, 0, 0]),
    ];
    let mut m = TriMap::default();
    let mut ids: HashMap<[i64; 3], u32> = HashMap::new();
    for (o, u, v) in faces {
        let mut vid = |i: i64, j: i64| {
            let p: [i64; 3] = std::array::from_fn(|k| o[k] + i * u[k] + j * v[k]);
            *ids.entry(p).or_insert_with(|| {
                m.positions.push(p.map(|x| x as f64));
                m.positions.len() as u32 - 1
            })
        };
        for j in 0..n {
            for i in 0..n {
                let c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
                let q = c.map(|(a, b)| vid(a, b));
                let uv = c.map(|(a, b)| [a as f64, b as f64]);
                m.simplices.push([q[0], q[1], q[2]]);
                m.coords.push([uv[0], uv[1], uv[2]]);
                m.simplices.push([q[0], q[2], q[3]]);
                m.coords.push([uv[0], uv[2], uv[3]]);
            }
        }
    }
    m
}

/// A flat `n × n` torus: the grid with opposite sides identified, map =
/// unwrapped coordinates (transitions are translations by `n`).
pub fn flat_torus(n: u32) -> TriMap {
    let g = grid(n);
    let wrap = |v: u32| {
        let (i, j) = (v % (n + 1) % n, v / (n + 1) % n);
        j * n + i
    };
    let mut m = TriMap {
        simplices: g.simplices.iter().map(|s| s.map(wrap)).collect(),
        coords: g.coords,
        ..Default::default()
    };
    let tau = std::f64::consts::TAU;
    for j in 0..n {
        for i in 0..n {
            let (a, b) = (tau * i as f64 / n as f64, tau * j as f64 / n as f64);
            m.positions.push([
                (2.0 + b.cos()) * a.cos(),
                (2.0 + b.cos()) * a.sin(),
                b.sin(),
            ]);
        }
    }
    m
}

/// A fan of `k` triangles around vertex 0, each right-angled at the centre
/// in its own chart: a cone of index `(4 − k)/4`.
pub fn cone(k: u32) -> TriMap {
    let mut m = TriMap::default();
    m.positions.push([0.0, 0.0, 1.0]);
    for i in 0..k {
        let a = std::f64::consts::TAU * i as f64 / k as f64;
        m.positions.push([a.cos(), a.sin(), 0.0]);
    }
    for i in 0..k {
        m.simplices.push([0, i + 1, (i + 1) % k + 1]);
        m.coords.push([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    }
    m
}

/// `k` tets around the edge 0→1, each right-angled at the edge in its own
/// chart (edge along +w): a singular edge unless `k = 4`.
pub fn edge_fan(k: u32) -> TetMap {
    let mut m = TetMap::default();
    m.positions.push([0.0, 0.0, 0.0]);
    m.positions.push([0.0, 0.0, 1.0]);
    for i in 0..k {
        let a = std::f64::consts::TAU * i as f64 / k as f64;
        m.positions.push([a.cos(), a.sin(), 0.5]);
    }
    for i in 0..k {
        m.simplices.push([0, 1, i + 2, (i + 1) % k + 2]);
        m.coords.push([
            [0.0, 0.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
        ]);
    }
    m
}

/// Path of a shared data file, or `None` (with a notice) when absent.
pub fn data_file(rel: &str) -> Option<String> {
    let p = format!("/work/shared/data/{rel}");
    if std::path::Path::new(&p).exists() {
        Some(p)
    } else {
        eprintln!("notice: {p} absent, test skipped");
        None
    }
}

/// Minimal OBJ reader (`v`, `vt`, triangles `f v/vt`), for tests only.
pub fn read_obj(path: &str) -> TriMap {
    let text = std::fs::read_to_string(path).expect("test data readable");
    let (mut pos, mut vt, mut tris) = (Vec::new(), Vec::new(), Vec::new());
    for line in text.lines() {
        let mut it = line.split_whitespace();
        let nums = |it: std::str::SplitWhitespace| -> Vec<f64> {
            it.map(|x| x.parse().expect("number")).collect()
        };
        match it.next() {
            Some("v") => {
                let p = nums(it);
                pos.push([p[0], p[1], p[2]]);
            }
            Some("vt") => {
                let p = nums(it);
                vt.push([p[0], p[1]]);
            }
            Some("f") => {
                let c: Vec<(u32, usize)> = it
                    .map(|tok| {
                        let mut parts = tok.split('/');
                        let v: u32 = parts.next().and_then(|x| x.parse().ok()).expect("v");
                        let t: usize = parts.next().and_then(|x| x.parse().ok()).expect("vt");
                        (v - 1, t - 1)
                    })
                    .collect();
                tris.push(c);
            }
            _ => {}
        }
    }
    TriMap {
        positions: pos,
        simplices: tris.iter().map(|c| [c[0].0, c[1].0, c[2].0]).collect(),
        coords: tris
            .iter()
            .map(|c| [vt[c[0].1], vt[c[1].1], vt[c[2].1]])
            .collect(),
    }
}

/// Minimal `.hexex` reader, for tests only.
pub fn read_hexex(path: &str) -> TetMap {
    let text = std::fs::read_to_string(path).expect("test data readable");
    let mut it = text.split_whitespace();
    let mut next = || it.next().expect("token");
    let nv: usize = next().parse().expect("count");
    let mut m = TetMap::default();
    for _ in 0..nv {
        let p: [f64; 3] = std::array::from_fn(|_| next().parse().expect("x"));
        m.positions.push(p);
    }
    let nt: usize = next().parse().expect("count");
    for _ in 0..nt {
        let t: [u32; 4] = std::array::from_fn(|_| next().parse().expect("v"));
        let c: [[f64; 3]; 4] =
            std::array::from_fn(|_| std::array::from_fn(|_| next().parse().expect("u")));
        m.simplices.push(t);
        m.coords.push(c);
    }
    m
}

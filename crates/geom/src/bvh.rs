//! A bounding-volume hierarchy over boxes (triangles, segments), for
//! closest-point queries with a filter.
//!
//! Input: one axis-aligned box per primitive. Output: the primitive nearest
//! a point among those a filter accepts, by a caller's distance function.
//! Invariants: every node's box holds its primitives' boxes; leaves hold
//! at most [`LEAF`] primitives; the build is deterministic (median splits
//! on the longest axis of the centroids, ties by index).

/// Most primitives in a leaf.
const LEAF: usize = 4;

/// An axis-aligned box.
#[derive(Clone, Copy, Debug)]
pub struct Aabb {
    /// Least corner.
    pub min: [f64; 3],
    /// Greatest corner.
    pub max: [f64; 3],
}

impl Aabb {
    /// The box of some points.
    pub fn of(points: &[[f64; 3]]) -> Aabb {
        let mut b = Aabb {
            min: [f64::INFINITY; 3],
            max: [f64::NEG_INFINITY; 3],
        };
        for p in points {
            b.grow(&Aabb { min: *p, max: *p });
        }
        b
    }

    /// [`Aabb::of`] by chunks in parallel: the same box (a minimum or
    /// maximum is exact in any order; only the sign of a zero bound may
    /// differ, which no length or distance of the box sees).
    pub fn of_par(points: &[[f64; 3]]) -> Aabb {
        use rayon::prelude::*;
        points.par_chunks(1 << 14).map(Aabb::of).reduce(
            || Aabb::of(&[]),
            |mut a, b| {
                a.grow(&b);
                a
            },
        )
    }

    fn grow(&mut self, o: &Aabb) {
        for k in 0..3 {
            self.min[k] = self.min[k].min(o.min[k]);
            self.max[k] = self.max[k].max(o.max[k]);
        }
    }

    /// Squared distance from `p` to the box (0 inside).
    pub fn dist2(&self, p: [f64; 3]) -> f64 {
        (0..3)
            .map(|k| {
                let d = (self.min[k] - p[k]).max(p[k] - self.max[k]).max(0.0);
                d * d
            })
            .sum()
    }

    /// Length of the diagonal.
    pub fn diagonal(&self) -> f64 {
        if self.min[0] > self.max[0] {
            return 0.0;
        }
        (0..3)
            .map(|k| (self.max[k] - self.min[k]).powi(2))
            .sum::<f64>()
            .sqrt()
    }
}

#[derive(Clone, Copy, Debug)]
struct Node {
    bbox: Aabb,
    /// Leaf: first primitive in `order`; inner: the right child.
    first: u32,
    /// Leaf: primitive count; inner: 0 (the left child follows the node).
    count: u32,
}

/// The hierarchy.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    order: Vec<u32>,
}

impl Bvh {
    /// Builds the hierarchy over `boxes` (subtrees of large ranges in
    /// parallel; the same tree whatever the thread count).
    pub fn new(boxes: &[Aabb]) -> Bvh {
        let mut order: Vec<u32> = (0..boxes.len() as u32).collect();
        let nodes = if boxes.is_empty() {
            Vec::new()
        } else {
            use rayon::prelude::*;
            let centres: Vec<[f64; 3]> = boxes
                .par_iter()
                .map(|b| [0, 1, 2].map(|k| 0.5 * (b.min[k] + b.max[k])))
                .collect();
            let empty = Node {
                bbox: boxes[0],
                first: 0,
                count: 0,
            };
            let mut nodes = vec![empty; node_count(boxes.len())];
            build(boxes, &centres, &mut order, 0, &mut nodes, 0);
            nodes
        };
        Bvh { nodes, order }
    }

    /// The primitive nearest `p` by `dist2(primitive) -> Option<squared
    /// distance>` (`None`: filtered out), with its squared distance; ties
    /// go to the lower index.
    pub fn nearest(&self, p: [f64; 3], dist2: impl Fn(u32) -> Option<f64>) -> Option<(u32, f64)> {
        self.nearest_within(p, f64::INFINITY, dist2)
    }

    /// [`Bvh::nearest`] among the primitives within squared distance
    /// `max_d2` of `p` (the search prunes every box farther).
    pub fn nearest_within(
        &self,
        p: [f64; 3],
        max_d2: f64,
        dist2: impl Fn(u32) -> Option<f64>,
    ) -> Option<(u32, f64)> {
        self.nearest_seeded(p, max_d2, None, dist2)
    }

    /// [`Bvh::nearest_within`] with a first candidate `seed` (e.g. the
    /// answer for a nearby point): its distance bounds the search from the
    /// start. The answer does not depend on the seed (the least distance,
    /// ties to the lower index), only the work does.
    pub fn nearest_seeded(
        &self,
        p: [f64; 3],
        max_d2: f64,
        seed: Option<u32>,
        dist2: impl Fn(u32) -> Option<f64>,
    ) -> Option<(u32, f64)> {
        let seed = seed.filter(|&i| (i as usize) < self.order.len());
        let mut best: Option<(u32, f64)> =
            seed.and_then(|i| dist2(i).filter(|&d| d <= max_d2).map(|d| (i, d)));
        if self.nodes.is_empty() {
            return None;
        }
        // depth first, each node with its box's distance (taken once, when
        // its parent orders its children); the stack holds at most two
        // nodes a level: halving splits keep the depth under 32 (no
        // allocation)
        let mut stack = [(0u32, 0.0f64); STACK];
        stack[0] = (0, self.nodes[0].bbox.dist2(p));
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let (n, bound) = stack[top];
            if bound > max_d2 || best.is_some_and(|(_, d)| bound > d) {
                continue;
            }
            let node = &self.nodes[n as usize];
            if node.count > 0 {
                let first = node.first as usize;
                // the seed was weighed first: again it would change nothing
                for &i in &self.order[first..first + node.count as usize] {
                    if Some(i) == seed {
                        continue;
                    }
                    if let Some(d) = dist2(i).filter(|&d| d <= max_d2) {
                        let better = match best {
                            None => true,
                            Some((bi, bd)) => d < bd || (d == bd && i < bi),
                        };
                        if better {
                            best = Some((i, d));
                        }
                    }
                }
            } else {
                let (l, r) = (n + 1, node.first);
                let dl = self.nodes[l as usize].bbox.dist2(p);
                let dr = self.nodes[r as usize].bbox.dist2(p);
                // the nearer child is searched first (pushed last)
                let (first, second) = if dl <= dr {
                    ((r, dr), (l, dl))
                } else {
                    ((l, dl), (r, dr))
                };
                stack[top] = first;
                stack[top + 1] = second;
                top += 2;
            }
        }
        best
    }
}

/// The query stack's size: two slots a level of a tree over at most
/// `u32::MAX` primitives (halving splits: at most 31 levels under the
/// root).
const STACK: usize = 64;

/// Ranges at least this long build their two halves in parallel.
const PARALLEL: usize = 1 << 14;

/// Ranges at least this long are split on a copy of their keys (the
/// comparisons then read one array in order, not the centres by index).
const KEYED: usize = 64;

/// `order` split at its middle `n / 2` by the centres' coordinate `axis`,
/// ties by index (`f64::total_cmp`): the halves hold the same primitives
/// however it is done, only their order inside differs.
fn split_at_median(order: &mut [u32], centres: &[[f64; 3]], axis: usize) {
    let mid = order.len() / 2;
    if order.len() < KEYED {
        order.select_nth_unstable_by(mid, |&a, &b| {
            centres[a as usize][axis]
                .total_cmp(&centres[b as usize][axis])
                .then(a.cmp(&b))
        });
        return;
    }
    // the key of `f64::total_cmp`: its bits, the magnitude's flipped when
    // negative, as a signed integer
    let key = |x: f64| {
        let b = x.to_bits() as i64;
        b ^ (((b >> 63) as u64) >> 1) as i64
    };
    let mut keyed: Vec<(i64, u32)> = order
        .iter()
        .map(|&i| (key(centres[i as usize][axis]), i))
        .collect();
    keyed.select_nth_unstable(mid);
    for (o, k) in order.iter_mut().zip(&keyed) {
        *o = k.1;
    }
}

/// Nodes of the subtree over `n` primitives (a leaf at most [`LEAF`],
/// else this node and its two halves, the left one `n / 2`).
fn node_count(n: usize) -> usize {
    node_counts(n).0
}

/// [`node_count`] of `n` and of `n + 1`, from those of `n / 2` and
/// `n / 2 + 1` (the halves of `n` and `n + 1` are among them): one call a
/// level instead of one a node.
fn node_counts(n: usize) -> (usize, usize) {
    if n < LEAF {
        return (1, 1);
    }
    let (a, b) = node_counts(n / 2);
    let even = n.is_multiple_of(2);
    let here = match (n <= LEAF, even) {
        (true, _) => 1,
        (false, true) => 1 + 2 * a,
        (false, false) => 1 + a + b,
    };
    let next = if even { 1 + a + b } else { 1 + 2 * b };
    (here, next)
}

/// The subtree over `order` (the primitives at `offset..` of the whole
/// order) written to `nodes` (`node_count(order.len())` of them, the
/// first numbered `base`): this node, then the left subtree, then the
/// right one; an inner node's `first` is its right child's number, a
/// leaf's the position of its first primitive. `centres`: the boxes'
/// centres. Returns the subtree's box (an inner node's: the union of its
/// children's, the same as over its primitives: min and max are exact).
fn build(
    boxes: &[Aabb],
    centres: &[[f64; 3]],
    order: &mut [u32],
    offset: usize,
    nodes: &mut [Node],
    base: usize,
) -> Aabb {
    let n = order.len();
    if n <= LEAF {
        let mut bbox = boxes[order[0] as usize];
        for &i in &order[1..] {
            bbox.grow(&boxes[i as usize]);
        }
        nodes[0] = Node {
            bbox,
            first: offset as u32,
            count: n as u32,
        };
        return bbox;
    }
    // the centres' box (plain comparisons skip a NaN as f64::min does)
    let mut cb = Aabb {
        min: [f64::INFINITY; 3],
        max: [f64::NEG_INFINITY; 3],
    };
    for &i in order.iter() {
        for (k, &c) in centres[i as usize].iter().enumerate() {
            if c < cb.min[k] {
                cb.min[k] = c;
            }
            if c > cb.max[k] {
                cb.max[k] = c;
            }
        }
    }
    let axis = (0..3)
        .max_by(|&a, &b| (cb.max[a] - cb.min[a]).total_cmp(&(cb.max[b] - cb.min[b])))
        .unwrap_or(0);
    let mid = n / 2;
    split_at_median(order, centres, axis);
    let (lo, hi) = order.split_at_mut(mid);
    let right_at = 1 + node_count(mid);
    let (head, rest) = nodes.split_at_mut(1);
    let (left, right) = rest.split_at_mut(right_at - 1);
    let (mut bbox, b) = if n >= PARALLEL {
        rayon::join(
            || build(boxes, centres, lo, offset, left, base + 1),
            || build(boxes, centres, hi, offset + mid, right, base + right_at),
        )
    } else {
        (
            build(boxes, centres, lo, offset, left, base + 1),
            build(boxes, centres, hi, offset + mid, right, base + right_at),
        )
    };
    bbox.grow(&b);
    head[0] = Node {
        bbox,
        first: (base + right_at) as u32,
        count: 0,
    };
    bbox
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_splits_keyed_or_not() {
        let centres: Vec<[f64; 3]> = (0..300)
            .map(|i| [((i * 37) % 11) as f64 - 5.0, -0.0, f64::from(i % 3)])
            .collect();
        for n in [10, 63, 64, 65, 300] {
            for axis in 0..3 {
                let mut keyed: Vec<u32> = (0..n).rev().collect();
                split_at_median(&mut keyed, &centres, axis);
                let mut sorted: Vec<u32> = (0..n).collect();
                sorted.sort_by(|&a, &b| {
                    let (x, y) = (centres[a as usize][axis], centres[b as usize][axis]);
                    x.total_cmp(&y).then(a.cmp(&b))
                });
                let mid = n as usize / 2;
                let mut lo = keyed[..mid].to_vec();
                lo.sort_unstable();
                let mut want = sorted[..mid].to_vec();
                want.sort_unstable();
                assert_eq!(lo, want, "{n} primitives, axis {axis}");
            }
        }
    }

    #[test]
    fn node_counts_by_recursion() {
        fn by_nodes(n: usize) -> usize {
            if n <= LEAF {
                1
            } else {
                1 + by_nodes(n / 2) + by_nodes(n - n / 2)
            }
        }
        for n in (0..3000).chain([810_000, 1 << 20, (1 << 20) + 1]) {
            assert_eq!(node_count(n), by_nodes(n), "{n} primitives");
        }
    }

    #[test]
    fn nearest_point_by_brute_force() {
        let mut s = 12345u64;
        let mut rnd = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        let pts: Vec<[f64; 3]> = (0..500).map(|_| [rnd(), rnd(), rnd()]).collect();
        let boxes: Vec<Aabb> = pts.iter().map(|p| Aabb::of(&[*p])).collect();
        let bvh = Bvh::new(&boxes);
        let d2 = |a: [f64; 3], b: [f64; 3]| (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>();
        for _ in 0..200 {
            let q = [rnd(), rnd(), rnd()];
            let got = bvh.nearest(q, |i| Some(d2(q, pts[i as usize])));
            let want = (0..pts.len())
                .min_by(|&a, &b| d2(q, pts[a]).total_cmp(&d2(q, pts[b])))
                .map(|i| i as u32);
            assert_eq!(got.map(|g| g.0), want);
            // a filter: only even primitives
            let got = bvh.nearest(q, |i| (i % 2 == 0).then(|| d2(q, pts[i as usize])));
            let want = (0..pts.len())
                .filter(|i| i % 2 == 0)
                .min_by(|&a, &b| d2(q, pts[a]).total_cmp(&d2(q, pts[b])))
                .map(|i| i as u32);
            assert_eq!(got.map(|g| g.0), want);
            // from any seed: the same
            for seed in [0, 7, 250, 499] {
                let from = bvh.nearest_seeded(q, f64::INFINITY, Some(seed), |i| {
                    (i % 2 == 0).then(|| d2(q, pts[i as usize]))
                });
                assert_eq!(from.map(|g| g.0), want, "seed {seed}");
            }
        }
        assert!(Bvh::new(&[]).nearest([0.; 3], |_| Some(0.0)).is_none());
    }

    /// The box by chunks in parallel is the serial box (random points of
    /// many magnitudes and signs, across several chunks; none: empty).
    #[test]
    fn box_in_parallel_as_serial() {
        let mut rng = dualex_util::rng::SplitMix::new(3);
        for n in [0, 1, 2, 1000, (1 << 14) + 1, 3 << 14] {
            let points: Vec<[f64; 3]> = (0..n)
                .map(|_| [0; 3].map(|_| (rng.unit() - 0.5) * 10f64.powi(rng.below(9) as i32 - 4)))
                .collect();
            let (a, b) = (Aabb::of(&points), Aabb::of_par(&points));
            assert_eq!((a.min, a.max), (b.min, b.max), "{n} points");
            assert_eq!(a.diagonal().to_bits(), b.diagonal().to_bits());
        }
    }
}

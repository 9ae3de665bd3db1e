//! Doublet removal in the graph, one operation for both dimensions
//! (issue 12): a valence-2 interior vertex (2D) or a chain of valence-2
//! interior edges (3D) is dissolved by merging the node pairs around it.
//!
//! D = 2: nodes X and Y glued along two perpendicular sides of X, `d0`
//! and `d1`, that meet at a corner whose vertex has exactly those two
//! corners. Y dies; X takes over Y's two outer sides, relinked to their
//! partners, and its corner at `v` becomes Y's far corner `y`:
//!
//! ```text
//!   before:          b                after:          b
//!                  ╱ │ ╲                            ╱   ╲
//!                ╱   │d1 ╲                        ╱       ╲
//!              y   Y v  X  x                    y    X     x     (v gone)
//!                ╲   │d0 ╱                        ╲       ╱
//!                  ╲ │ ╱                            ╲   ╱
//!                    a                                a
//! ```
//! (X = [v, a, x, b] and Y = [v, b, y, a] share the edges v–a, X's side
//! d0, and v–b, X's side d1.)
//! The chart rotation σ from X to Y *through the merged cell* maps
//! `d0 → t1 ^ 1` and `d1 → t0 ^ 1` (tᵢ the side of Y glued to X.dᵢ): it is
//! the quarter turn τ about the corner (`d0 → d1 ^ 1`, `d1 → d0`) then ρ₀,
//! the rotation across X.d0, and equally τ⁻¹ then ρ₁ (the holonomy around a
//! valence-2 vertex is a half turn). X.dᵢ is glued to the partner P of Y's
//! side σ(dᵢ) with σ then rot(Y → P); the label rule carries over.
//!
//! D = 3: the same for every pair along a **chain**: X's edge between `d0`
//! and `d1` runs along the third axis; the pair continues through X's sides
//! on that axis to the next pair (its X is the node glued there, its Y the
//! node glued to Y there, glued alike), until both sides are unmatched
//! (boundary faces) or the chain closes on itself. All pairs are merged or
//! none.
//!
//! Preconditions, all read before anything is written ([`OpError`] and an
//! untouched graph otherwise): the sides exist, belong to an alive node and
//! are perpendicular; in every pair X ≠ Y are alive with the same
//! orientation, both glued pairs obey the label rule and close the corner
//! (ρ₀(d1) = t1, ρ₁(d0) = t0, τ then ρ₀ = τ⁻¹ then ρ₁); the chain is
//! consistent (module text above) and its nodes distinct; no outer side of
//! a Y is glued to a node of the chain; every vertex on the doublet corners
//! or edges has only corners of the chain's pairs there (so it disappears);
//! the merged cells have 2^D distinct vertices.
//!
//! Output: [`DoubletMerge`], what was taken over (for vertex placement and
//! per-side data, see [`Takeover`]). Invariants: [`NodeGraph::check`]
//! holds after, the vertex partition of the other corners is unchanged
//! (V − 1 per pair in 2D; E, F, C drop accordingly: Euler kept).

mod run;
#[cfg(test)]
mod tests;

pub use run::{DoubletStats, Takeover};

use crate::glue::{corner_across, corners_on, rotate_corner};
use crate::graph::NodeGraph;
use crate::ids::{axis, positive, Node, Side};
use crate::ops::OpError;
use dualex_map::Rot;
use std::collections::HashSet;

/// What one doublet merge did (moves in the order they were made).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DoubletMerge {
    /// (X, Y) per pair: X kept, Y deleted.
    pub pairs: Vec<(Node, Node)>,
    /// (Y's outer side, X's side that took it over).
    pub sides: Vec<(Side, Side)>,
    /// (Y's corner, X's corner that became it), as `node·2^D + code`: X's
    /// corners on the doublet corner (edge) become Y's far corners.
    pub corners: Vec<(u32, u32)>,
    /// (Y's corner, X's corner at the same vertex): the vertices X keeps
    /// that Y had too (placement may trace them from either node).
    pub shared: Vec<(u32, u32)>,
}

/// One pair of a doublet, as read before the merge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Pair<const D: usize> {
    x: Node,
    y: Node,
    /// X's sides glued to Y.
    d: [usize; 2],
    /// Y's sides glued to X.d[0], X.d[1].
    t: [usize; 2],
    /// Chart of X to chart of Y through the merged cell.
    sigma: Rot<D>,
    /// Rotations across X.d[0], X.d[1].
    r: [Rot<D>; 2],
}

impl<const D: usize> Pair<D> {
    /// Y's outer side that X.d[i] takes over.
    fn outer(&self, i: usize) -> usize {
        self.t[1 - i] ^ 1
    }
}

/// The rotation mapping `d0 → d1 ^ 1`, `d1 → d0`, fixing the other axes.
fn quarter<const D: usize>(d0: usize, d1: usize) -> Option<Rot<D>> {
    let image = |d: usize| match d {
        _ if d == d0 => d1 ^ 1,
        _ if d == d0 ^ 1 => d1,
        _ if d == d1 => d0,
        _ if d == d1 ^ 1 => d0 ^ 1,
        _ => d,
    };
    Rot::from_images(std::array::from_fn(|a| image(2 * a) as u8))
}

/// The corner codes of a node on both sides `d0` and `d1`.
fn codes_on<const D: usize>(d: [usize; 2]) -> impl Iterator<Item = usize> {
    (0..1usize << D).filter(move |&c| d.iter().all(|&di| (c >> axis(di) & 1 == 1) == positive(di)))
}

impl<const D: usize> NodeGraph<D> {
    /// The corner id `node·2^D + code`.
    fn corner_id(n: Node, code: usize) -> u32 {
        (n.idx() * (1 << D) + code) as u32
    }

    /// The corners glued to corner `code` of `n` (the vertex's corners, as
    /// [`Self::glue`] finds them), ids `node·2^D + code`, sorted.
    pub(crate) fn corner_class(&self, n: Node, code: usize) -> Vec<u32> {
        let k = 1usize << D;
        let mut seen = vec![Self::corner_id(n, code)];
        let mut i = 0;
        while i < seen.len() {
            let (m, c) = (Node(seen[i] / k as u32), seen[i] as usize % k);
            i += 1;
            for a in 0..D {
                let s = self.side(m, 2 * a + usize::from(c >> a & 1 == 0));
                let Some(t) = self.opposite(s) else { continue };
                let across = corner_across(self.dir_of(s), self.dir_of(t), &self.rot[s.idx()], c);
                if let Some(ct) = across {
                    let id = Self::corner_id(self.node_of(t), ct);
                    if !seen.contains(&id) {
                        seen.push(id);
                    }
                }
            }
        }
        seen.sort_unstable();
        seen
    }

    /// The pair at X's corner (edge) between sides `d` (checks of one pair).
    fn doublet_pair(&self, x: Node, d: [usize; 2]) -> Result<Pair<D>, OpError> {
        let s = d.map(|di| self.side(x, di));
        for si in s {
            self.usable(si)?;
        }
        if axis(d[0]) == axis(d[1]) {
            return Err(OpError::NotDoublet(x));
        }
        let t0 = self.opposite(s[0]).ok_or(OpError::Unmatched(s[0]))?;
        let t1 = self.opposite(s[1]).ok_or(OpError::Unmatched(s[1]))?;
        let y = self.node_of(t0);
        if y == x || self.node_of(t1) != y || self.is_reverted(x) != self.is_reverted(y) {
            return Err(OpError::NotDoublet(x));
        }
        if !self.label_ok(s[0]) || !self.label_ok(s[1]) {
            return Err(OpError::LabelRule(s[0]));
        }
        let t = [self.dir_of(t0), self.dir_of(t1)];
        let (r0, r1) = (self.rot[s[0].idx()], self.rot[s[1].idx()]);
        let tau = quarter::<D>(d[0], d[1]).ok_or(OpError::NotDoublet(x))?;
        let sigma = tau.then(&r0);
        let closes = r0.apply_dir(d[1]) == t[1] && r1.apply_dir(d[0]) == t[0];
        if !closes || tau.inverse().then(&r1) != sigma {
            return Err(OpError::NotDoublet(x));
        }
        Ok(Pair {
            x,
            y,
            d,
            t,
            sigma,
            r: [r0, r1],
        })
    }

    /// The pair after `p` along X's side `up`, and the side continuing the
    /// same way; `None` at a boundary end (both X and Y unmatched there).
    fn next_pair(&self, p: &Pair<D>, up: usize) -> Result<Option<(Pair<D>, usize)>, OpError> {
        let (sx, sy) = (self.side(p.x, up), self.side(p.y, p.sigma.apply_dir(up)));
        let (Some(tx), Some(ty)) = (self.opposite(sx), self.opposite(sy)) else {
            if self.opposite(sx).is_some() || self.opposite(sy).is_some() {
                return Err(OpError::NotDoublet(p.x));
            }
            return Ok(None);
        };
        let r = self.rot[sx.idx()];
        let x2 = self.node_of(tx);
        if !self.label_ok(sx) || self.is_reverted(x2) != self.is_reverted(p.x) {
            return Err(OpError::LabelRule(sx));
        }
        let q = self.doublet_pair(x2, p.d.map(|di| r.apply_dir(di)))?;
        let up2 = self.dir_of(tx) ^ 1;
        // Y's column glued like X's: the same side, the same rotation
        let down_y = self.side(q.y, q.sigma.apply_dir(up2 ^ 1));
        let same = p.sigma.inverse().then(&r).then(&q.sigma);
        if ty != down_y || self.rot[sy.idx()] != same {
            return Err(OpError::NotDoublet(p.x));
        }
        Ok(Some((q, up2)))
    }

    /// The whole chain through the pair at X's sides `d` (one pair in 2D),
    /// in order along the chain axis.
    fn doublet_chain(&self, x: Node, d: [usize; 2]) -> Result<Vec<Pair<D>>, OpError> {
        let first = self.doublet_pair(x, d)?;
        let Some(a) = (0..D).find(|&a| a != axis(d[0]) && a != axis(d[1])) else {
            return Ok(vec![first]);
        };
        let bound = self.n_nodes() + 1;
        // down to the bottom end (or once around a closed chain)
        let (mut bottom, mut down) = (first, 2 * a + 1);
        for _ in 0..bound {
            match self.next_pair(&bottom, down)? {
                Some((q, _)) if q.x == first.x => break,
                Some((q, dn)) => (bottom, down) = (q, dn),
                None => break,
            }
        }
        let (mut chain, mut up) = (vec![bottom], down ^ 1);
        for _ in 0..bound {
            let Some((q, u)) = self.next_pair(&chain[chain.len() - 1], up)? else {
                return Ok(chain);
            };
            if q.x == chain[0].x {
                // closed: it must come back as the same pair
                let same = q.y == chain[0].y && q.sigma == chain[0].sigma && u == down ^ 1;
                return if same {
                    Ok(chain)
                } else {
                    Err(OpError::NotDoublet(x))
                };
            }
            chain.push(q);
            up = u;
        }
        Err(OpError::NotDoublet(x))
    }

    /// The checks on the whole chain (see the module docs).
    fn check_chain(&self, chain: &[Pair<D>]) -> Result<(), OpError> {
        let x = chain[0].x;
        let nodes: HashSet<Node> = chain.iter().flat_map(|p| [p.x, p.y]).collect();
        if nodes.len() != 2 * chain.len() {
            return Err(OpError::NotDoublet(x));
        }
        for p in chain {
            for i in 0..2 {
                let partner = self.opposite(self.side(p.y, p.outer(i)));
                if partner.is_some_and(|o| nodes.contains(&self.node_of(o))) {
                    return Err(OpError::DoubletPartner(p.x));
                }
            }
        }
        // the vertices on the doublet corners (edges) are those corners only
        let on: HashSet<u32> = chain
            .iter()
            .flat_map(|p| {
                let xs = codes_on::<D>(p.d).map(move |c| Self::corner_id(p.x, c));
                xs.chain(codes_on::<D>(p.t).map(move |c| Self::corner_id(p.y, c)))
            })
            .collect();
        for &id in &on {
            let k = 1usize << D;
            let class = self.corner_class(Node(id / k as u32), id as usize % k);
            if !class.iter().all(|c| on.contains(c)) {
                return Err(OpError::NotDoublet(x));
            }
        }
        // the merged cells have distinct vertices
        for p in chain {
            let mut classes: Vec<Vec<u32>> = Vec::with_capacity(1 << D);
            for c in 0..1usize << D {
                let class = if codes_on::<D>(p.d).any(|e| e == c) {
                    self.corner_class(p.y, rotate_corner(&p.sigma, c))
                } else {
                    self.corner_class(p.x, c)
                };
                if classes.iter().any(|other| other[0] == class[0]) {
                    return Err(OpError::RepeatedCorner(p.x));
                }
                classes.push(class);
            }
        }
        Ok(())
    }

    /// Merges the doublet at X's corner (2D) or edge (3D) between the
    /// perpendicular sides `d0`, `d1` (module docs): every Y dies, every X
    /// takes over its Y's outer sides and far corners.
    pub fn merge_doublet(
        &mut self,
        x: Node,
        d0: usize,
        d1: usize,
    ) -> Result<DoubletMerge, OpError> {
        if d0 >= 2 * D || d1 >= 2 * D {
            return Err(OpError::NotDoublet(x));
        }
        let chain = self.doublet_chain(x, [d0, d1])?;
        self.check_chain(&chain)?;
        // partners of the outer sides of every Y (outside the chain)
        let partners: Vec<[Option<(Side, Rot<D>)>; 2]> = chain
            .iter()
            .map(|p| {
                [0, 1].map(|i| {
                    let o = self.side(p.y, p.outer(i));
                    self.opposite(o).map(|t| (t, self.rot[o.idx()]))
                })
            })
            .collect();
        // all read: write
        let mut out = DoubletMerge::default();
        for p in &chain {
            for d in 0..2 * D {
                let s = self.side(p.y, d);
                if let Some(t) = self.opposite(s) {
                    self.clear(t);
                    self.clear(s);
                }
            }
            self.alive[p.y.idx()] = false;
        }
        for (p, partner) in chain.iter().zip(&partners) {
            for (i, taken) in partner.iter().enumerate() {
                let sx = self.side(p.x, p.d[i]);
                out.sides.push((self.side(p.y, p.outer(i)), sx));
                if let Some((t, r)) = *taken {
                    self.set_pair(sx, t, p.sigma.then(&r));
                }
            }
            for c in codes_on::<D>(p.d) {
                let from = Self::corner_id(p.y, rotate_corner(&p.sigma, c));
                out.corners.push((from, Self::corner_id(p.x, c)));
            }
            for i in 0..2 {
                let only = |c: &usize| !codes_on::<D>(p.d).any(|e| e == *c);
                for c in corners_on::<D>(p.d[i]).filter(only) {
                    if let Some(cy) = corner_across(p.d[i], p.t[i], &p.r[i], c) {
                        let ids = (Self::corner_id(p.y, cy), Self::corner_id(p.x, c));
                        out.shared.push(ids);
                    }
                }
            }
            out.pairs.push((p.x, p.y));
        }
        let touched: Vec<Side> = out.sides.iter().map(|&(_, s)| s).collect();
        debug_assert!(
            self.check_sides(&touched).is_ok(),
            "bug: a doublet merge broke the graph"
        );
        Ok(out)
    }
}

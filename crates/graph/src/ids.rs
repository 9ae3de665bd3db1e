//! Typed ids of the node graph.
//!
//! ```text
//!   Node(n)            one future quad (D = 2) or hex (D = 3)
//!   Side(n·2D + dir)   dir = 2·axis + neg   0:+u 1:-u 2:+v 3:-v [4:+w 5:-w]
//!                      dir ^ 1 is the reverse direction, dir >> 1 the axis
//! ```
//!
//! Both are `u32` newtypes; `u32::MAX` is reserved as "none" in the flat
//! opposite array and never names a side.

/// A node of the graph (a future quad or hex).
#[repr(transparent)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Node(pub u32);

/// A side of a node: `node·2D + dir` (see the module docs).
#[repr(transparent)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Side(pub u32);

impl Node {
    /// The id as an index into per-node arrays.
    #[inline]
    pub fn idx(self) -> usize {
        self.0 as usize
    }

    /// Side `dir` of this node in a graph of dimension `D`.
    #[inline]
    pub fn side<const D: usize>(self, dir: usize) -> Side {
        debug_assert!(dir < 2 * D, "bug: direction {dir} out of range");
        Side(self.0 * (2 * D as u32) + dir as u32)
    }
}

impl Side {
    /// The id as an index into per-side arrays.
    #[inline]
    pub fn idx(self) -> usize {
        self.0 as usize
    }

    /// The node this side belongs to.
    #[inline]
    pub fn node<const D: usize>(self) -> Node {
        Node(self.0 / (2 * D as u32))
    }

    /// The direction of this side (`2·axis + neg`).
    #[inline]
    pub fn dir<const D: usize>(self) -> usize {
        (self.0 % (2 * D as u32)) as usize
    }
}

/// The axis of a direction.
#[inline]
pub fn axis(dir: usize) -> usize {
    dir >> 1
}

/// Whether a direction points towards the positive end of its axis.
#[inline]
pub fn positive(dir: usize) -> bool {
    dir & 1 == 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn side_roundtrip() {
        for n in 0..5u32 {
            for d in 0..6 {
                let s = Node(n).side::<3>(d);
                assert_eq!(s.node::<3>(), Node(n));
                assert_eq!(s.dir::<3>(), d);
            }
            for d in 0..4 {
                let s = Node(n).side::<2>(d);
                assert_eq!((s.node::<2>(), s.dir::<2>()), (Node(n), d));
            }
        }
        assert_eq!((axis(3), positive(3), positive(4)), (1, false, true));
    }
}

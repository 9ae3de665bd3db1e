//! # dualex-graph — the dimension-generic node graph
//!
//! Steps 7–9 of the pipeline (ARCHITECTURE.md), shared by quad (D = 2)
//! and hex (D = 3) extraction (DESIGN §3.4, §4): nodes (future
//! quads/hexes) with 2·D sides, the opposite relation with a chart
//! rotation per glued pair, and the operations that act on it, topology
//! only: 7. the opposite relation ([`walk`]) and untangling
//! ([`untangle`]); 8. fairing ([`fair`], [`columns`]) and the clean-up
//! before gluing ([`collapse`], [`pillow`], [`bubble`], [`doublet`]); 9.
//! gluing ([`glue`]) and the choice of each vertex's position among its
//! corners' candidates ([`place`]).
//!
//! - [`ids`]: [`Node`], [`Side`] (`side = node·2D + dir`);
//! - [`graph`]: [`NodeGraph`], storage, `link`/`unlink`, queries;
//! - [`check`]: invariants ([`GraphError`]), label-rule violations;
//! - [`ops`]: OP2, OP1, pleat removal ([`OpError`] = not applicable);
//! - [`untangle`]: the pleat worklist ([`UntangleStats`]);
//! - [`glue`]: union–find over corners into cells ([`Glued`]), boundary
//!   and components counted on the graph;
//! - [`fan`]: vertex fans (2D), read from the graph;
//! - [`fair`]: index fairing by saddle lifts (2D, [`FairingStats`]), its
//!   ties broken by `canon` (an order of the graph seen from one corner,
//!   free of node numbers);
//! - [`columns`]: the same on every layer of a 3D graph made of columns
//!   (an extruded map's), [`ColumnFairing`];
//! - [`doublet`]: doublet removal, one merge for both dimensions (a
//!   valence-2 vertex, a chain of valence-2 edges), [`Takeover`];
//! - [`collapse`], [`pillow`], [`bubble`]: folded corners, detached
//!   pillows and closed components, the last resorts before gluing;
//! - [`testgrid`]: regular, folded and singular-disk graphs for tests.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bubble;
mod canon;
pub mod check;
pub mod collapse;
pub mod columns;
pub mod doublet;
pub mod fair;
mod fair_local;
pub mod fan;
pub mod glue;
pub mod graph;
pub mod ids;
pub mod ops;
pub mod pillow;
pub mod place;
use dualex_util::rng;
pub mod testgrid;
pub mod untangle;
pub mod walk;

#[cfg(test)]
mod tests;

pub use check::GraphError;
pub use columns::ColumnFairing;
pub use doublet::{DoubletMerge, DoubletStats, Takeover};
pub use fair::{FairingStats, LiftUndo};
pub use glue::{cell_code, Glued, NO_VERTEX};
pub use graph::NodeGraph;
pub use ids::{Node, Side};
pub use ops::{Op2Outcome, OpError, PleatPreview, PleatRemoval};
pub use untangle::UntangleStats;

//! Step 0: the 2D map's grid kept in 3D.
//!
//! `dualex quad` chooses the grid offset of the map (`--grid-offset auto`:
//! the offset ½ or 0, whichever puts fewer singular vertices on nodes, then
//! on isos). `dualex hex` does the same on the extruded map, but there the
//! levels `w = 0..=L` are isos under the offset 0, so it always takes ½:
//! on a map whose 2D choice is 0 (Directional's horse: 18 singular
//! vertices on nodes under 0, 26 under ½) the 3D grid would not be the
//! extrusion of the 2D one. So when the 2D choice is 0, every chart is
//! shifted by (½, ½) before extruding: the 3D offset ½ is then the 2D
//! offset 0 in `u, v` and puts the nodes at `w = k + ½`. Transitions stay
//! integer (`s − R s` is integer for `s = (½, ½)` and every rotation by a
//! multiple of 90°).
//!
//! Input: a triangle map. Output: whether its charts are to be shifted,
//! and the shifted map. The choice is the one of `dualex quad`: on the
//! singular vertices snapped onto their fixed points in the chart ½
//! (`dualex_segment::grid_offset::choose_snapped`, without building the
//! local map).

use dualex_map::{InputError, Stars, Topology, TransitionOptions, Transitions, TriMap};
use dualex_segment::grid_offset::{choose_snapped, GridOffset};

/// Whether `dualex quad --grid-offset auto` takes the offset 0 on `map`.
pub fn zero_in_2d(map: &TriMap) -> Result<bool, InputError> {
    let topo = Topology::build(map)?;
    let (trans, _) = Transitions::derive(map, &topo, &TransitionOptions::default())?;
    let stars = Stars::build(map, &topo, &trans);
    let choice = choose_snapped(map, &topo, &trans, &stars, GridOffset::Auto);
    Ok(choice.offset == GridOffset::Zero)
}

/// `map` with every corner's coordinates shifted by (½, ½).
pub fn shifted(map: &TriMap) -> TriMap {
    let mut out = map.clone();
    for c in out.coords.iter_mut().flatten() {
        for x in c.iter_mut() {
            *x += 0.5;
        }
    }
    out
}

//! PNG picture of a triangle map in the `(u, v)` plane.
//!
//! Input: a [`TriMap`], an output path, a size in pixels; optionally the
//! marks to draw. Output: a `size × size` PNG, white background:
//! - every triangle at its `(u, v)` per corner (each in its own chart):
//!   light blue-grey `#e4eaf0`, reverted ones (`det < 0`) purple `#8e44ad`
//!   drawn on top and outlined (slivers stay visible), with thin edges
//!   `#9aa4b4` when triangles are at least 8 px wide;
//! - the integer grid lines faint grey (every 2nd, 5th, 10th, … line when
//!   there would be more than one line per 4 pixels), on top;
//! - singular vertices as dots at each of their corners, in the valence
//!   colour of the quad vertex they become (index +1/4: valence 3 blue,
//!   −1/4: valence 5 red, any other: green, see [`crate::valence`]), with
//!   a white ring; their radius is 0.7 % of the picture (at least 2.5 px),
//!   whatever the number of triangles;
//! - a legend in the emptiest corner: reverted triangles and singular
//!   vertices by index, with their counts ([`legend`]).
//!
//! [`map_png`] finds the singular vertices itself: it welds coincident
//! boundary vertices (cut meshes, [`weld`]; the triangles and their
//! coordinates are unchanged), then topology, transitions with rounding,
//! [`vertex_singularities`]; when the topology cannot be built
//! (non-manifold input) the map is drawn without marks.

use std::path::Path;

use dualex_map::singularity::{vertex_singularities, VertexSingularity};
use dualex_map::weld::weld;
use dualex_map::{Topology, TransitionOptions, Transitions, TriMap};
use tiny_skia::{FillRule, PathBuilder, Pixmap, Stroke, Transform};

use crate::canvas::{bbox, encode, paint, white, write_png, Fit};
use crate::error::RenderError;
use crate::valence::ValenceClass;

/// A vertex to mark, with the class of the quad vertex it becomes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MapMark {
    /// The vertex of the map.
    pub vertex: u32,
    /// Its colour class.
    pub class: ValenceClass,
}

impl MapMark {
    /// The mark of a singularity: valence `4 − index·4` when the index is
    /// known, else from the ring rotation (1 turn: 3, 3 turns: 5).
    pub fn of(s: &VertexSingularity) -> MapMark {
        let valence = match s.index_quarters {
            Some(q) => 4 - q,
            None => [4, 3, 0, 5][s.turns.rem_euclid(4) as usize],
        };
        let class = match valence {
            3 => ValenceClass::V3,
            5 => ValenceClass::V5,
            _ => ValenceClass::Other,
        };
        MapMark {
            vertex: s.vertex,
            class,
        }
    }
}

const LIGHT: [u8; 3] = [0xe4, 0xea, 0xf0];
const EDGE: [u8; 3] = [0x9a, 0xa4, 0xb4];
/// Fill of reverted triangles.
pub const PURPLE: [u8; 3] = [0x8e, 0x44, 0xad];

/// Renders `map` with its singular vertices marked (see the module docs).
pub fn map_png(map: &TriMap, path: &Path, size: u32) -> Result<(), RenderError> {
    map.validate()?;
    let (welded, _) = weld(map);
    let marks = singular_marks(&welded);
    map_png_marked(&welded, &marks, path, size)
}

/// The PNG bytes of [`map_png`], for the caller to write (errors name no
/// file).
pub fn map_png_bytes(map: &TriMap, size: u32) -> Result<Vec<u8>, RenderError> {
    map.validate()?;
    let (welded, _) = weld(map);
    let marks = singular_marks(&welded);
    encode(&draw_map(&welded, &marks, size)?)
}

/// The marks of [`map_png`] on a (welded) map; empty when its topology
/// cannot be built.
pub fn singular_marks(map: &TriMap) -> Vec<MapMark> {
    let Ok(topo) = Topology::build(map) else {
        return Vec::new();
    };
    let opts = TransitionOptions {
        round: true,
        ..TransitionOptions::default()
    };
    let Ok((trans, _)) = Transitions::derive(map, &topo, &opts) else {
        return Vec::new();
    };
    vertex_singularities(map, &topo, &trans)
        .iter()
        .map(MapMark::of)
        .collect()
}

/// Renders `map` with the given marks (see the module docs). Errors: an
/// invalid map, a mark naming a missing vertex, a bad size, an I/O error.
pub fn map_png_marked(
    map: &TriMap,
    marks: &[MapMark],
    path: &Path,
    size: u32,
) -> Result<(), RenderError> {
    let pix = draw_map(map, marks, size)?;
    write_png(&pix, path)
}

/// Draws the picture of [`map_png_marked`] into a pixmap.
pub(crate) fn draw_map(map: &TriMap, marks: &[MapMark], size: u32) -> Result<Pixmap, RenderError> {
    map.validate()?;
    let nv = map.positions.len();
    if let Some(m) = marks.iter().find(|m| m.vertex as usize >= nv) {
        return Err(RenderError::MarkOutOfRange {
            vertex: m.vertex,
            vertices: nv,
        });
    }
    let mut pix = white(size)?;
    let uv = map.coords.iter().flatten().copied();
    let (lo, hi) = bbox(uv).ok_or(RenderError::NoTriangles)?;
    let fit = Fit::new(lo, hi, size);
    draw_triangles(&mut pix, map, &fit);
    draw_grid(&mut pix, lo, hi, &fit);
    let mut is_marked = vec![None; nv];
    for m in marks {
        is_marked[m.vertex as usize] = m.class.rgb();
    }
    let r = mark_radius(size);
    let ring = (0.3 * r).max(1.0);
    let id = Transform::identity();
    for (s, tri) in map.simplices.iter().enumerate() {
        for (c, &v) in tri.iter().enumerate() {
            let Some(rgb) = is_marked[v as usize] else {
                continue;
            };
            let (x, y) = fit.px(map.coords[s][c]);
            // a white ring first, so the dot stands out on purple too
            if let Some(halo) = PathBuilder::from_circle(x, y, r + ring) {
                pix.fill_path(&halo, &paint([255; 3], 255), FillRule::Winding, id, None);
            }
            if let Some(dot) = PathBuilder::from_circle(x, y, r) {
                pix.fill_path(&dot, &paint(rgb, 255), FillRule::Winding, id, None);
            }
        }
    }
    let reverted = (0..map.len()).filter(|&s| map.map_det(s) < 0.0).count();
    legend::draw_legend(&mut pix, reverted, marks);
    Ok(pix)
}

/// Radius in pixels of a singularity dot: a fixed share of the picture,
/// whatever the number of triangles (at least 2.5 px).
pub(crate) fn mark_radius(size: u32) -> f32 {
    (0.007 * size as f32).max(2.5)
}

/// Fills all triangles (light, then reverted ones purple) and their edges.
fn draw_triangles(pix: &mut Pixmap, map: &TriMap, fit: &Fit) {
    let mut light = PathBuilder::new();
    let mut purple = PathBuilder::new();
    let mut edge_len = Vec::with_capacity(map.len());
    for (s, p) in map.coords.iter().enumerate() {
        let px = p.map(|q| fit.px(q));
        edge_len.push(f64::from((px[1].0 - px[0].0).hypot(px[1].1 - px[0].1)));
        // counter-clockwise on screen (y down) for every triangle, so that
        // the winding fill is their union
        let reverted = map.map_det(s) < 0.0;
        let order = if reverted { [0, 1, 2] } else { [0, 2, 1] };
        let pb = if reverted { &mut purple } else { &mut light };
        pb.move_to(px[order[0]].0, px[order[0]].1);
        pb.line_to(px[order[1]].0, px[order[1]].1);
        pb.line_to(px[order[2]].0, px[order[2]].1);
        pb.close();
    }
    let mid = edge_len.len() / 2;
    let typical = edge_len
        .select_nth_unstable_by(mid, f64::total_cmp)
        .1
        .to_owned();
    let show_edges = typical >= 8.0;
    let id = Transform::identity();
    if let Some(path) = light.finish() {
        pix.fill_path(&path, &paint(LIGHT, 255), FillRule::Winding, id, None);
        if show_edges {
            let stroke = Stroke {
                width: 0.5,
                ..Stroke::default()
            };
            pix.stroke_path(&path, &paint(EDGE, 255), &stroke, id, None);
        }
    }
    if let Some(path) = purple.finish() {
        // outlined too, so that a sliver fold stays visible
        pix.fill_path(&path, &paint(PURPLE, 255), FillRule::Winding, id, None);
        // thinner when the triangles are tiny, so a dense fold keeps its shape
        let stroke = Stroke {
            width: (0.25 * typical).clamp(0.6, 1.5) as f32,
            ..Stroke::default()
        };
        pix.stroke_path(&path, &paint(PURPLE, 255), &stroke, id, None);
    }
}

/// Faint integer grid lines over `lo..hi`.
fn draw_grid(pix: &mut Pixmap, lo: [f64; 2], hi: [f64; 2], fit: &Fit) {
    let span = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let max_lines = f64::from(pix.width()) / 4.0;
    let step = [1.0, 2.0, 5.0]
        .iter()
        .flat_map(|m| (0..20).map(move |e| m * 10f64.powi(e)))
        .filter(|&st| span / st <= max_lines)
        .fold(f64::INFINITY, f64::min);
    if !step.is_finite() {
        return;
    }
    let mut pb = PathBuilder::new();
    for k in 0..2 {
        let first = (lo[k] / step).ceil();
        // a counter, not `t += step`: far-off coordinates absorb the step
        let count = ((hi[k] - lo[k]) / step).floor() as u64 + 1;
        for i in 0..count {
            let t = (first + i as f64) * step;
            if t > hi[k] {
                break;
            }
            let (a, b) = if k == 0 {
                ([t, lo[1]], [t, hi[1]])
            } else {
                ([lo[0], t], [hi[0], t])
            };
            let (pa, pb2) = (fit.px(a), fit.px(b));
            pb.move_to(pa.0, pa.1);
            pb.line_to(pb2.0, pb2.1);
        }
    }
    if let Some(path) = pb.finish() {
        let stroke = Stroke {
            width: (pix.width() as f32 / 1000.0).clamp(0.8, 2.0),
            ..Stroke::default()
        };
        let grid = paint([0x50, 0x50, 0x50], 70);
        pix.stroke_path(&path, &grid, &stroke, Transform::identity(), None);
    }
}

mod legend;

#[cfg(test)]
mod tests;

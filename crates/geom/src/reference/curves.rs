//! The reference's curves: feature segments on too-short curves dropped
//! as noise, the corners where curves meet or turn, and the arcs between
//! corners.
//!
//! Input: the triangles, their normals and the positions. Output: the
//! segments (boundary and feature edges, sorted by their ends), those on
//! too-short feature curves dropped, per vertex a corner flag, per
//! segment its arc.

use super::Segment;
use crate::quality::{dot, norm, sub};
use dualex_util::bucket;
use dualex_util::union_find::UnionFind;
use rayon::prelude::*;

/// Feature curves (connected sets of feature segments) of fewer than this
/// many segments are noise (a coarse smooth surface), not features.
pub const MIN_FEATURE_SEGMENTS: usize = 4;

/// The boundary edges (one triangle) and feature edges (more than two
/// triangles, or two whose unit normals' dot product is below `cos`) of
/// `triangles` over `n` vertices, sorted by their ends (smaller first).
/// The edges are bucketed by their smaller end (a counting sort, in
/// triangle order), each bucket sorted by (other end, triangle): the order
/// of one sort of every (edge, triangle) pair, in linear time.
pub(super) fn curve_segments(
    n: usize,
    triangles: &[[u32; 3]],
    normals: &[[f64; 3]],
    cos: f64,
) -> Vec<Segment> {
    let edge = |t: &[u32; 3], k: usize| {
        let (a, b) = (t[k], t[(k + 1) % 3]);
        (a.min(b), a.max(b))
    };
    // per edge, in its smaller end's bucket: its larger end, its triangle
    let (start, other) = bucket::sorted(n, |emit| {
        for (i, t) in triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = edge(t, k);
                emit(a as usize, (b, i as u32));
            }
        }
    });
    // the buckets scanned by groups in parallel, the groups joined in order
    let scan = |a: usize| {
        other[start[a]..start[a + 1]]
            .chunk_by(|x, y| x.0 == y.0)
            .filter_map(move |ts| {
                let boundary = ts.len() == 1;
                let feature = ts.len() > 2
                    || (ts.len() == 2 && {
                        let (n0, n1) = (normals[ts[0].1 as usize], normals[ts[1].1 as usize]);
                        norm(n0) > 0.0 && norm(n1) > 0.0 && dot(n0, n1) < cos
                    });
                (boundary || feature).then_some(Segment {
                    ends: [a as u32, ts[0].0],
                    boundary,
                    arc: u32::MAX,
                })
            })
    };
    let groups: Vec<Vec<Segment>> = (0..n.div_ceil(SCAN_GROUP))
        .into_par_iter()
        .map(|g| {
            (g * SCAN_GROUP..n.min((g + 1) * SCAN_GROUP))
                .flat_map(scan)
                .collect()
        })
        .collect();
    groups.concat()
}

/// Vertices (buckets) per parallel task of [`curve_segments`]' scan.
const SCAN_GROUP: usize = 1 << 12;

/// Drops the feature segments of curves shorter than
/// [`MIN_FEATURE_SEGMENTS`]; boundary segments stay.
pub(super) fn drop_short_features(segments: &mut Vec<Segment>, n: usize) {
    let mut curves = UnionFind::new(n);
    for s in segments.iter().filter(|s| !s.boundary) {
        curves.union(s.ends[0] as usize, s.ends[1] as usize);
    }
    let mut size = vec![0usize; n];
    for s in segments.iter().filter(|s| !s.boundary) {
        size[curves.find(s.ends[0] as usize)] += 1;
    }
    segments
        .retain(|s| s.boundary || size[curves.find(s.ends[0] as usize)] >= MIN_FEATURE_SEGMENTS);
}

/// [`Segment::arc`] for every segment: a flood over segments through
/// vertices that are no corner.
pub(super) fn label_arcs(segments: &mut [Segment], corner: &[bool]) {
    let mut at: Vec<(u32, u32)> = segments
        .iter()
        .enumerate()
        .flat_map(|(i, s)| s.ends.map(|v| (v, i as u32)))
        .collect();
    at.sort_unstable();
    let mut next = 0;
    for first in 0..segments.len() {
        if segments[first].arc != u32::MAX {
            continue;
        }
        segments[first].arc = next;
        let mut stack = vec![first];
        while let Some(i) = stack.pop() {
            for v in segments[i].ends {
                if corner[v as usize] {
                    continue;
                }
                let lo = at.partition_point(|a| a.0 < v);
                for &(_, t) in at[lo..].iter().take_while(|a| a.0 == v) {
                    if segments[t as usize].arc == u32::MAX {
                        segments[t as usize].arc = next;
                        stack.push(t as usize);
                    }
                }
            }
        }
        next += 1;
    }
}

/// Per vertex: a corner of the curves (see the module docs), from the
/// segments' ends alone (a vertex on no segment is none).
pub(super) fn corners(positions: &[[f64; 3]], segments: &[Segment], cos: f64) -> Vec<bool> {
    let mut corner = vec![false; positions.len()];
    // (vertex, segment, other end): a vertex's neighbours in segment order
    let mut at: Vec<(u32, u32, u32)> = segments
        .iter()
        .enumerate()
        .flat_map(|(i, s)| {
            [
                (s.ends[0], i as u32, s.ends[1]),
                (s.ends[1], i as u32, s.ends[0]),
            ]
        })
        .collect();
    at.sort_unstable();
    for run in at.chunk_by(|a, b| a.0 == b.0) {
        let v = run[0].0 as usize;
        corner[v] = match run {
            // an end of a curve is where a ridge fades out, not a corner
            [_] => false,
            [(_, _, n0), (_, _, n1)] => {
                let p = positions[v];
                let a = sub(p, positions[*n0 as usize]);
                let b = sub(positions[*n1 as usize], p);
                let l = norm(a) * norm(b);
                l > 0.0 && dot(a, b) < cos * l
            }
            _ => true,
        };
    }
    corner
}

//! The reference's curves: feature segments on too-short curves dropped
//! as noise, the corners where curves meet or turn, and the arcs between
//! corners.
//!
//! Input: the segments found (boundary and feature edges) and the
//! positions. Output: segments kept, per vertex a corner flag, per
//! segment its arc.

use super::Segment;
use crate::quality::{dot, norm, sub};
use std::collections::HashMap;
/// Feature curves (connected sets of feature segments) of fewer than this
/// many segments are noise (a coarse smooth surface), not features.
pub const MIN_FEATURE_SEGMENTS: usize = 4;

/// Drops the feature segments of curves shorter than
/// [`MIN_FEATURE_SEGMENTS`]; boundary segments stay.
pub(super) fn drop_short_features(segments: &mut Vec<Segment>, n: usize) {
    let mut parent: Vec<u32> = (0..n as u32).collect();
    fn find(p: &mut [u32], mut v: u32) -> u32 {
        while p[v as usize] != v {
            p[v as usize] = p[p[v as usize] as usize];
            v = p[v as usize];
        }
        v
    }
    for s in segments.iter().filter(|s| !s.boundary) {
        let (a, b) = (find(&mut parent, s.ends[0]), find(&mut parent, s.ends[1]));
        parent[a.max(b) as usize] = a.min(b);
    }
    let mut size: HashMap<u32, usize> = HashMap::new();
    for s in segments.iter().filter(|s| !s.boundary) {
        *size.entry(find(&mut parent, s.ends[0])).or_default() += 1;
    }
    segments.retain(|s| s.boundary || size[&find(&mut parent, s.ends[0])] >= MIN_FEATURE_SEGMENTS);
}

/// Per vertex: a corner of the curves (see the module docs).
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

pub(super) fn corners(positions: &[[f64; 3]], segments: &[Segment], cos: f64) -> Vec<bool> {
    let mut around: Vec<Vec<u32>> = vec![Vec::new(); positions.len()];
    for s in segments {
        around[s.ends[0] as usize].push(s.ends[1]);
        around[s.ends[1] as usize].push(s.ends[0]);
    }
    around
        .iter()
        .enumerate()
        .map(|(v, n)| match n.len() {
            // an end of a curve is where a ridge fades out, not a corner
            0 | 1 => false,
            2 => {
                let p = positions[v];
                let a = sub(p, positions[n[0] as usize]);
                let b = sub(positions[n[1] as usize], p);
                let l = norm(a) * norm(b);
                l > 0.0 && dot(a, b) < cos * l
            }
            _ => true,
        })
        .collect()
}

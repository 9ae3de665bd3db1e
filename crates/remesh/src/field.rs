//! Cross fields: one direction per face, known up to quarter turns.
//!
//! Input: a [`Surface`]. Output: a [`CrossField`]: an angle per face in the
//! face's frame ([`Surface::frames`]) and the period jump (matching) of
//! every interior edge.
//!
//! Convention (used by the integration): across interior edge `e` with
//! faces `[f0, f1]` (see [`Surface::edge_faces`]), the direction `θ0` of
//! `f0` transported to `f1` is `θ0 − edge_angle(e, f0) + edge_angle(e, f1)`;
//! the matching `p ∈ 0..4` is the number of quarter turns from that
//! transported direction to `θ1`: `θ1 ≈ transported + p·π/2`.
//! Boundary edges have matching 0.

use crate::surface::{Surface, NO_FACE};
use std::f64::consts::{FRAC_PI_2, PI};

/// A cross field with its period jumps.
#[derive(Clone, Debug)]
pub struct CrossField {
    /// Per face: the angle of one of the four directions, in the face frame.
    pub angle: Vec<f64>,
    /// Per edge: the matching `0..4` (0 on the boundary).
    pub matching: Vec<u8>,
}

impl CrossField {
    /// A field from its angles, with the matchings that make each edge's
    /// jump the smallest (`|θ1 − transported − p·π/2| ≤ π/4`).
    pub fn from_angles(surface: &Surface, angle: Vec<f64>) -> Self {
        let matching = (0..surface.edges.len() as u32)
            .map(|e| {
                let [_, f1] = surface.edge_faces[e as usize];
                if f1 == NO_FACE {
                    return 0;
                }
                let t = transported(surface, &angle, e);
                let q = ((angle[f1 as usize] - t) / FRAC_PI_2).round();
                q.rem_euclid(4.0) as u8
            })
            .collect();
        CrossField { angle, matching }
    }

    /// The leftover rotation of edge `e` after its matching, in
    /// `(−π, π]`: `θ1 − transported − p·π/2`, wrapped. Zero on the boundary.
    pub fn jump(&self, surface: &Surface, e: u32) -> f64 {
        let [_, f1] = surface.edge_faces[e as usize];
        if f1 == NO_FACE {
            return 0.0;
        }
        let t = transported(surface, &self.angle, e);
        wrap(self.angle[f1 as usize] - t - f64::from(self.matching[e as usize]) * FRAC_PI_2)
    }
}

/// `θ0` of the edge's first face, transported across the edge to its
/// second face.
pub fn transported(surface: &Surface, angle: &[f64], e: u32) -> f64 {
    let [f0, f1] = surface.edge_faces[e as usize];
    angle[f0 as usize] - surface.edge_angle(e, f0) + surface.edge_angle(e, f1)
}

/// An angle wrapped to `(−π, π]`.
pub fn wrap(a: f64) -> f64 {
    let w = a.rem_euclid(2.0 * PI);
    if w > PI {
        w - 2.0 * PI
    } else {
        w
    }
}

//! What sanitization did, in both dimensions (the report of `quad` and
//! `hex`'s step 4), and its `sanitize` object in the stats JSON; the
//! perturbation schedule both use ([`amplitude`]); what it could not do
//! ([`SanitizeReport::leftovers`], which the CLI prints even with `-q`).

use serde_json::{json, Map, Value};
use std::collections::BTreeMap;

/// Initial perturbation amplitude (map units), doubled every 8 rounds.
pub const AMPLITUDE: f64 = 1e-5;
/// Perturbation rounds of the ordinary schedule.
pub const ROUNDS: usize = 40;
/// Largest amplitude of the extra rounds (map units, a tenth of a cell).
pub const MAX_AMPLITUDE: f64 = 0.1;
/// Extra rounds at [`MAX_AMPLITUDE`] before giving up on a vertex.
pub const ROUNDS_AT_MAX: usize = 8;

/// The amplitude of perturbation round `round`, `None` once every round
/// is spent:
/// - rounds `0 .. ROUNDS`: [`AMPLITUDE`] doubled every 8 rounds (up to
///   `16·AMPLITUDE`);
/// - extra rounds (a non-singular vertex still on the grid after
///   [`ROUNDS`]: it is in a collapsed cluster that could not move, or
///   unlucky): doubled every round up to [`MAX_AMPLITUDE`], then
///   [`ROUNDS_AT_MAX`] rounds at it.
pub fn amplitude(round: usize) -> Option<f64> {
    let doubled = |n: usize| AMPLITUDE * 2f64.powi(n as i32);
    if round < ROUNDS {
        return Some(doubled(round / 8));
    }
    // the ordinary schedule ends at doubled((ROUNDS - 1) / 8)
    let amp = doubled((ROUNDS - 1) / 8 + round + 1 - ROUNDS);
    if amp < MAX_AMPLITUDE {
        return Some(amp);
    }
    // rounds already spent at the cap
    let first_at_max =
        (ROUNDS..).find(|&r| doubled((ROUNDS - 1) / 8 + r + 1 - ROUNDS) >= MAX_AMPLITUDE);
    let spent = round - first_at_max.unwrap_or(round);
    (spent < ROUNDS_AT_MAX).then_some(MAX_AMPLITUDE)
}

/// What sanitization did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SanitizeReport {
    /// Vertices whose corners were snapped to one GP value.
    pub snapped_vertices: usize,
    /// Largest distance a snap moved a corner.
    pub max_snap: f64,
    /// Distinct vertices perturbed.
    pub perturbed_vertices: usize,
    /// Collapsed clusters (more than one vertex) found.
    pub clusters: usize,
    /// Distinct clusters that could not move as one (their rotations
    /// disagree: a holonomy around the collapsed region).
    pub stuck_clusters: usize,
    /// Stuck clusters whose members were moved one by one in the extra
    /// rounds (the last resort: each member is non-singular, so it moves
    /// consistently in its own charts; the collapsed region opens into
    /// slivers).
    pub clusters_moved_apart: usize,
    /// Rounds used.
    pub rounds: usize,
    /// Rounds beyond [`ROUNDS`] (see [`amplitude`]).
    pub extra_rounds: usize,
    /// 3D: singular vertices moved along their singular edge's axis.
    pub singular_moved: usize,
    /// 2D: singular vertices left on an iso, by kind (`"90_node"`,
    /// `"180_iso"`, `"90_edge"`: only an edge through a grid point, …).
    pub singular_kinds: BTreeMap<String, usize>,
    /// Singular vertices left on an iso (cannot be perturbed).
    pub singular_on_iso: Vec<u32>,
    /// Non-singular vertices still on an iso after all rounds (0 expected).
    pub unresolved: usize,
    /// Singular vertices put exactly on the fixed set of their holonomies
    /// ([`crate::singular_snap`]).
    pub singular_snap: crate::singular_snap::SingularSnap,
}

impl SanitizeReport {
    /// The counts both dimensions report; each adds its own keys.
    pub fn to_json(&self) -> Map<String, Value> {
        let v = json!({
            "snapped_vertices": self.snapped_vertices,
            "max_snap": self.max_snap,
            "perturbed_vertices": self.perturbed_vertices,
            "clusters": self.clusters,
            "stuck_clusters": self.stuck_clusters,
            "clusters_moved_apart": self.clusters_moved_apart,
            "rounds": self.rounds,
            "extra_rounds": self.extra_rounds,
            "singular_on_iso": self.singular_on_iso.len(),
            "unresolved": self.unresolved,
            "singular_snapped": self.singular_snap.snapped,
            "max_singular_snap": self.singular_snap.max_move,
            "singular_left_unsnapped": self.singular_snap.left,
        });
        match v {
            Value::Object(m) => m,
            _ => Map::new(),
        }
    }

    /// What sanitization left on the dual grid, as one phrase naming the
    /// counts (`None` when nothing): non-singular vertices still on an iso
    /// after every round, singular vertices on an iso (they cannot move),
    /// singular vertices not snapped onto their fixed set. The mesh near
    /// them may be wrong, so the CLI prints this even with `-q` and
    /// `--strict` refuses it.
    pub fn leftovers(&self) -> Option<String> {
        let mut parts = Vec::new();
        if self.unresolved > 0 {
            parts.push(format!(
                "{} non-singular on an iso after {} rounds",
                self.unresolved,
                ROUNDS + self.extra_rounds
            ));
        }
        if !self.singular_on_iso.is_empty() {
            parts.push(format!(
                "{} singular on an iso, which cannot move",
                self.singular_on_iso.len()
            ));
        }
        if self.singular_snap.left > 0 {
            parts.push(format!(
                "{} singular not snapped onto their fixed set",
                self.singular_snap.left
            ));
        }
        (!parts.is_empty()).then(|| parts.join(", "))
    }
}

/// A histogram (value → count) as a JSON object keyed by the value.
pub fn histogram_json(h: &BTreeMap<usize, usize>) -> Value {
    Value::Object(h.iter().map(|(k, v)| (k.to_string(), json!(v))).collect())
}

/// Stage timings (name, milliseconds) as a JSON object.
pub fn times_json(times: &[(String, f64)]) -> Value {
    Value::Object(times.iter().map(|(k, v)| (k.clone(), json!(v))).collect())
}

/// What the grid offset was chosen on: the singular vertices on a node and
/// on an iso under each offset (zeros when the offset was given).
pub fn offset_json(c: &crate::grid_offset::OffsetChoice) -> Value {
    let on = |g: &crate::grid_offset::OnGrid| json!({"on_node": g.on_node, "on_iso": g.on_iso, "boundary_facets_on_iso": g.boundary_on_iso});
    json!({"half": on(&c.half), "zero": on(&c.zero)})
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ordinary rounds double every 8; the extra rounds double every
    /// round up to the cap, spend [`ROUNDS_AT_MAX`] rounds there, and end.
    #[test]
    fn amplitude_schedule() {
        assert_eq!(amplitude(0), Some(AMPLITUDE));
        assert_eq!(amplitude(7), Some(AMPLITUDE));
        assert_eq!(amplitude(8), Some(2.0 * AMPLITUDE));
        assert_eq!(amplitude(ROUNDS - 1), Some(16.0 * AMPLITUDE));
        assert_eq!(amplitude(ROUNDS), Some(32.0 * AMPLITUDE));
        assert_eq!(amplitude(ROUNDS + 1), Some(64.0 * AMPLITUDE));
        let all: Vec<f64> = (0..).map_while(amplitude).collect();
        let extra = &all[ROUNDS..];
        // 3.2e-4 … 0.08192 (9 doublings below the cap), then the cap
        assert_eq!(extra.len(), 9 + ROUNDS_AT_MAX, "{extra:?}");
        assert!(extra.windows(2).all(|w| w[1] >= w[0]));
        assert_eq!(
            extra.iter().filter(|&&a| a == MAX_AMPLITUDE).count(),
            ROUNDS_AT_MAX
        );
        assert!(all.iter().all(|&a| a <= MAX_AMPLITUDE));
        assert_eq!(amplitude(all.len()), None);
        assert_eq!(amplitude(all.len() + 5), None);
    }

    #[test]
    fn leftovers_name_the_counts() {
        let mut rep = SanitizeReport::default();
        assert_eq!(rep.leftovers(), None);
        rep.stuck_clusters = 2;
        rep.clusters_moved_apart = 2;
        assert_eq!(rep.leftovers(), None, "handled, not left");
        rep.unresolved = 3;
        rep.extra_rounds = 16;
        assert_eq!(
            rep.leftovers().as_deref(),
            Some("3 non-singular on an iso after 56 rounds")
        );
    }
}

//! The cut the integration tests use: the real one ([`crate::cut`])
//! through the given singular vertices, as `is_cut` per edge.

use crate::surface::Surface;

/// The cut of `surface` through `singular_vertices`.
pub fn cut(surface: &Surface, singular_vertices: &[u32]) -> Vec<bool> {
    let pairs: Vec<(u32, i32)> = singular_vertices.iter().map(|&v| (v, 1)).collect();
    match crate::cut::cut_to_disk(surface, &pairs) {
        Ok(c) => c.is_cut,
        Err(e) => panic!("test cut: {e}"),
    }
}

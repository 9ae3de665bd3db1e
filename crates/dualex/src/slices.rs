//! Maps from plain slices.
//!
//! Input: vertex positions, simplices (vertex indices, 0-based) and the map
//! coordinates of each corner of each simplex, in that simplex's chart (a
//! cut mesh's seams may disagree: that is what transitions are). Output: a
//! validated [`TriMap`] / [`TetMap`], or an [`Error::Input`] naming the
//! offending element: lengths that differ, an index out of range, a vertex
//! twice in a simplex, a NaN or infinite coordinate, no simplex at all.
//! Nothing panics on bad input.

use crate::{Error, TetMap, TriMap};
use dualex_map::error::CountError;
use dualex_map::{InputError, SimplexMap};

/// A triangle mesh with a 2D map, from slices: `uv[t][c]` is the map
/// coordinate of corner `c` of triangle `t`.
///
/// ```
/// // one unit square of two triangles, mapped onto [0, 2]²
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
/// let triangles = [[0, 1, 2], [0, 2, 3]];
/// let uv = [
///     [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0]],
///     [[0.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
/// ];
/// let map = dualex::tri_map_from_slices(&positions, &triangles, &uv)?;
/// assert_eq!(map.len(), 2);
///
/// // a corner out of range is an error naming the triangle
/// let e = dualex::tri_map_from_slices(&positions, &[[0, 1, 7]], &uv[..1]).unwrap_err();
/// assert_eq!(e.to_string(), "triangle 0: corner 2 refers to vertex 7, but there are 4 vertices");
/// # Ok::<(), dualex::Error>(())
/// ```
pub fn tri_map_from_slices(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    uv: &[[[f64; 2]; 3]],
) -> Result<TriMap, Error> {
    map_from_slices(positions, triangles, uv)
}

/// A tet mesh with a 3D map, from slices: `uvw[t][c]` is the map
/// coordinate of corner `c` of tet `t`. Same checks as
/// [`tri_map_from_slices`]; a tet must be positively oriented in 3-space
/// for its map to be read as unreverted.
pub fn tet_map_from_slices(
    positions: &[[f64; 3]],
    tets: &[[u32; 4]],
    uvw: &[[[f64; 3]; 4]],
) -> Result<TetMap, Error> {
    map_from_slices(positions, tets, uvw)
}

/// [`tri_map_from_slices`] and [`tet_map_from_slices`] in one, generic
/// over the simplex (`N` corners) and the map's dimension `D`, for code
/// written once for both (the C API).
pub fn map_from_slices<const N: usize, const D: usize>(
    positions: &[[f64; 3]],
    simplices: &[[u32; N]],
    coords: &[[[f64; D]; N]],
) -> Result<SimplexMap<N, D>, Error> {
    if u32::try_from(positions.len()).is_err() {
        return Err(InputError::new(CountError::TooManyVertices(positions.len())).into());
    }
    let map = SimplexMap {
        positions: positions.to_vec(),
        simplices: simplices.to_vec(),
        coords: coords.to_vec(),
    };
    // lengths, indices, repeated vertices, non-finite values
    map.validate()?;
    Ok(map)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_slices_are_errors_naming_the_element() {
        let p = [[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let uv = [[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]];
        assert!(tri_map_from_slices(&p, &[[0, 1, 2]], &uv).is_ok());
        let msg = |r: Result<TriMap, Error>| r.unwrap_err().to_string();
        assert_eq!(
            msg(tri_map_from_slices(&p, &[[0, 1, 2], [0, 2, 1]], &uv)),
            "2 triangles but 1 sets of map coordinates"
        );
        assert_eq!(msg(tri_map_from_slices(&p, &[], &[])), "no triangles");
        assert_eq!(
            msg(tri_map_from_slices(&p, &[[0, 1, 1]], &uv)),
            "triangle 0: vertex 1 appears twice"
        );
        let nan = [[[0.0, 0.0], [f64::NAN, 0.0], [0.0, 1.0]]];
        assert_eq!(
            msg(tri_map_from_slices(&p, &[[0, 1, 2]], &nan)),
            "triangle 0: corner 1 has a non-finite map coordinate"
        );
        let mut q = p;
        q[2][2] = f64::INFINITY;
        assert!(msg(tri_map_from_slices(&q, &[[0, 1, 2]], &uv)).starts_with("vertex 2: position"));
        let t = [[0.0; 3]; 4];
        assert_eq!(
            msg_tet(tet_map_from_slices(&p, &[[0, 1, 2, 3]], &[t])),
            "tet 0: corner 3 refers to vertex 3, but there are 3 vertices"
        );
    }

    fn msg_tet(r: Result<TetMap, Error>) -> String {
        r.unwrap_err().to_string()
    }
}

/*
 * dualex.h — the C API of dualex: quad meshes from triangle meshes with a
 * grid-preserving 2D map, hex meshes from tet meshes with a 3D map.
 *
 * Written by hand to match crates/capi/src (the test crates/capi/tests/c_api.rs
 * compiles C programs against it and compares every struct offset).
 *
 * Shaped like HexHex's hexhex_extract_simple(): flat arrays in, a plain
 * struct out. After the extraction a geometric stage measures every
 * element's scaled Jacobian, puts boundary vertices on the input's
 * boundary and untangles inverted elements (DualexOptions.untangle), or
 * smooths the whole mesh (smooth_rounds); the outputs report the quality
 * before and after it. Every function returning int returns 0 on success and a
 * DUALEX_ERR_* code on error; dualex_last_error() then gives the one-line
 * message. Bad input (NULL pointers, indices out of range, NaN, invalid
 * maps) is an error, never a crash; no Rust panic crosses this boundary.
 *
 * Link: -ldualex_capi (shared), or libdualex_capi.a plus
 * -lpthread -ldl -lm (static); see crates/capi/cmake and dualex.pc.in.
 */
#ifndef DUALEX_H
#define DUALEX_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Return codes. */
#define DUALEX_OK 0
/** A NULL or misaligned pointer, or a size whose byte count overflows. */
#define DUALEX_ERR_INVALID_ARGUMENT 1
/** The map is invalid or refused (index out of range, NaN, no simplex, ...). */
#define DUALEX_ERR_INVALID_INPUT 2
/** No valid mesh could be made, or (strict) the topology changed or inverted elements remain. */
#define DUALEX_ERR_EXTRACTION_FAILED 3
/** A bug in dualex (a caught panic); the message starts "internal error (bug): ". */
#define DUALEX_ERR_INTERNAL 4

/* DualexOptions.grid_offset */
#define DUALEX_GRID_AUTO 0 /**< choose from the singular vertices (default) */
#define DUALEX_GRID_HALF 1 /**< nodes at the map's half-integers */
#define DUALEX_GRID_ZERO 2 /**< nodes at the map's integer points */

/** A `sources` entry of a quad that closes a hole (no input triangle). */
#define DUALEX_NO_SOURCE UINT32_MAX

/** Extraction options; fill with dualex_options_default() first. Flags are 0 or 1. */
typedef struct DualexOptions {
    int weld;              /**< merge coincident boundary vertices (cut meshes) first; default 1 */
    int fairing;           /**< index fairing after untangling (hexes: on columns); default 1 */
    int round_transitions; /**< round transition translations of any residual; default 0 */
    int grid_offset;       /**< DUALEX_GRID_AUTO (default), _HALF or _ZERO */
    int strict;            /**< an output whose topology differs from the input's, or with inverted
                                elements left after the geometric stage, is an error; default 0 */
    uint64_t seed;         /**< seed of the sanitization perturbations; default 1 */
    int untangle;          /**< 1 (default; any nonzero): boundary vertices onto the input's boundary, inverted
                                elements untangled (only vertices near them move); 0: keep the
                                map's positions (quality still measured) */
    int smooth_rounds;     /**< 0 (default): no smoothing; n > 0: optimise every element's shape
                                in at most n rounds (needs untangle 1; negative is an error) */
} DualexOptions;

/** A quad mesh and its main counts; owned by the library, free with dualex_quad_mesh_free(). */
typedef struct DualexQuadMesh {
    size_t n_vertices;          /**< output vertices */
    double* positions;          /**< 3*n_vertices coordinates, x y z per vertex */
    size_t n_cells;             /**< output quads */
    uint32_t* cells;            /**< 4*n_cells vertex indices (0-based), counter-clockwise */
    uint32_t* sources;          /**< n_cells input triangle indices (DUALEX_NO_SOURCE: closes a hole) */
    size_t n_components;        /**< connected components of the output */
    size_t n_boundary_loops;    /**< boundary loops of the output */
    int64_t euler;              /**< Euler characteristic V - E + F of the output */
    size_t n_singular_vertices; /**< singular vertices of the input map */
    size_t n_welded_vertices;   /**< boundary vertices welded before extraction */
    int topology_matches;       /**< 1 when the output's topology equals the input's */
    /* the geometric stage: scaled Jacobian of the elements, before it (as the
       map places the vertices) and after it (of positions); 1 for no element */
    double sj_min_before;       /**< least scaled Jacobian before */
    double sj_min_after;        /**< least scaled Jacobian after */
    double sj_p5_before;        /**< its 5th percentile before */
    double sj_p5_after;         /**< its 5th percentile after */
    size_t inverted_before;     /**< elements with scaled Jacobian <= 0 before */
    size_t inverted_after;      /**< elements with scaled Jacobian <= 0 after */
    size_t moved_vertices;      /**< vertices the stage moved */
} DualexQuadMesh;

/** A hex mesh and its main counts; owned by the library, free with dualex_hex_mesh_free(). */
typedef struct DualexHexMesh {
    size_t n_vertices;          /**< output vertices */
    double* positions;          /**< 3*n_vertices coordinates, x y z per vertex */
    size_t n_cells;             /**< output hexes */
    uint32_t* cells;            /**< 8*n_cells vertex indices (0-based), VTK hexahedron order */
    uint32_t* sources;          /**< n_cells input tet indices (the tet holding each hex's centre) */
    size_t n_components;        /**< connected components of the output */
    size_t n_boundary_surfaces; /**< boundary surfaces of the output */
    int64_t euler;              /**< Euler characteristic V - E + F - C of the output */
    size_t n_singular_edges;    /**< singular interior edges of the input map */
    size_t n_welded_vertices;   /**< boundary vertices welded before extraction */
    int topology_matches;       /**< 1 when the output's topology equals the input's */
    /* the geometric stage: scaled Jacobian of the elements, before it (as the
       map places the vertices) and after it (of positions); 1 for no element */
    double sj_min_before;       /**< least scaled Jacobian before */
    double sj_min_after;        /**< least scaled Jacobian after */
    double sj_p5_before;        /**< its 5th percentile before */
    double sj_p5_after;         /**< its 5th percentile after */
    size_t inverted_before;     /**< elements with scaled Jacobian <= 0 before */
    size_t inverted_after;      /**< elements with scaled Jacobian <= 0 after */
    size_t moved_vertices;      /**< vertices the stage moved */
} DualexHexMesh;

/** Fills *opts with the defaults (weld and fairing on, automatic grid offset, seed 1,
    untangle 1, no smoothing). NULL is ignored. */
void dualex_options_default(DualexOptions* opts);

/**
 * Extracts the quad mesh of a triangle mesh with a 2D map.
 *
 * vpos:         3*n_vertices doubles (x y z per vertex)
 * tri_vertices: 3*n_triangles vertex indices (0-based)
 * tri_param:    n_triangles*3*2 doubles: the map coordinate (u v) of each
 *               corner of each triangle, in that triangle's chart (cut
 *               meshes may disagree across seams)
 * opts:         NULL for the defaults
 * out:          filled on success; zeroed on error
 *
 * Returns DUALEX_OK or a DUALEX_ERR_* code (message: dualex_last_error()).
 */
int dualex_quad_extract(size_t n_vertices, const double* vpos,
                        size_t n_triangles, const uint32_t* tri_vertices,
                        const double* tri_param, const DualexOptions* opts,
                        DualexQuadMesh* out);

/**
 * Extracts the hex mesh of a tet mesh with a 3D map (as HexHex's
 * hexhex_extract_simple, with the parameters per tet corner).
 *
 * vpos:         3*n_vertices doubles (x y z per vertex)
 * tet_vertices: 4*n_tets vertex indices (0-based), positively oriented
 * tet_param:    n_tets*4*3 doubles: the map coordinate (u v w) of each
 *               corner of each tet, in that tet's chart
 * opts:         NULL for the defaults
 * out:          filled on success; zeroed on error
 *
 * Returns DUALEX_OK or a DUALEX_ERR_* code (message: dualex_last_error()).
 */
int dualex_hex_extract(size_t n_vertices, const double* vpos,
                       size_t n_tets, const uint32_t* tet_vertices,
                       const double* tet_param, const DualexOptions* opts,
                       DualexHexMesh* out);

/** Frees the arrays of *mesh and zeroes it; NULL and zeroed structs are ignored. */
void dualex_quad_mesh_free(DualexQuadMesh* mesh);

/** Frees the arrays of *mesh and zeroes it; NULL and zeroed structs are ignored. */
void dualex_hex_mesh_free(DualexHexMesh* mesh);

/**
 * The last error message of the calling thread ("" after a success);
 * valid until this thread's next call into the library. Never NULL.
 */
const char* dualex_last_error(void);

/** The library version, e.g. "0.1.0" (a static string). */
const char* dualex_version(void);

#ifdef __cplusplus
}
#endif

#endif /* DUALEX_H */

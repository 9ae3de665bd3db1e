/*
 * The C API from C: compiled with gcc against include/dualex.h and the
 * built library, and run, by crates/capi/tests/c_api.rs.
 *
 *   test_quad_hex                 small maps built here + error cases
 *   test_quad_hex --layout        prints each struct field's offset and size
 *   test_quad_hex MAP EXPECTED    extracts MAP, a plain-text dump
 *                                 ("tri"|"tet", n_v, x y z..., n_s, then
 *                                 per simplex its indices and its corners'
 *                                 map coordinates) and checks the number
 *                                 of cells
 *   test_quad_hex --messy MAP     extracts MAP (a dump whose map places
 *                                 some elements inverted) with and without
 *                                 untangling and checks the quality fields
 *
 * Exit 0 when every check passes; a failed check prints itself.
 */
#include "dualex.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures = 0;

#define CHECK(cond)                                                     \
    do {                                                                \
        if (!(cond)) {                                                  \
            fprintf(stderr, "%s:%d: check failed: %s (last error: %s)\n", \
                    __FILE__, __LINE__, #cond, dualex_last_error());    \
            failures++;                                                 \
        }                                                               \
    } while (0)

#define FIELD(T, f) printf(#T "." #f " %zu %zu\n", offsetof(T, f), sizeof(((T*)0)->f))

static void print_layout(void) {
    printf("DualexOptions %zu\n", sizeof(DualexOptions));
    FIELD(DualexOptions, weld);
    FIELD(DualexOptions, fairing);
    FIELD(DualexOptions, round_transitions);
    FIELD(DualexOptions, grid_offset);
    FIELD(DualexOptions, strict);
    FIELD(DualexOptions, seed);
    FIELD(DualexOptions, untangle);
    FIELD(DualexOptions, smooth_rounds);
    printf("DualexQuadMesh %zu\n", sizeof(DualexQuadMesh));
    FIELD(DualexQuadMesh, n_vertices);
    FIELD(DualexQuadMesh, positions);
    FIELD(DualexQuadMesh, n_cells);
    FIELD(DualexQuadMesh, cells);
    FIELD(DualexQuadMesh, sources);
    FIELD(DualexQuadMesh, n_components);
    FIELD(DualexQuadMesh, n_boundary_loops);
    FIELD(DualexQuadMesh, euler);
    FIELD(DualexQuadMesh, n_singular_vertices);
    FIELD(DualexQuadMesh, n_welded_vertices);
    FIELD(DualexQuadMesh, topology_matches);
    FIELD(DualexQuadMesh, sj_min_before);
    FIELD(DualexQuadMesh, sj_min_after);
    FIELD(DualexQuadMesh, sj_p5_before);
    FIELD(DualexQuadMesh, sj_p5_after);
    FIELD(DualexQuadMesh, inverted_before);
    FIELD(DualexQuadMesh, inverted_after);
    FIELD(DualexQuadMesh, moved_vertices);
    printf("DualexHexMesh %zu\n", sizeof(DualexHexMesh));
    FIELD(DualexHexMesh, n_vertices);
    FIELD(DualexHexMesh, positions);
    FIELD(DualexHexMesh, n_cells);
    FIELD(DualexHexMesh, cells);
    FIELD(DualexHexMesh, sources);
    FIELD(DualexHexMesh, n_components);
    FIELD(DualexHexMesh, n_boundary_surfaces);
    FIELD(DualexHexMesh, euler);
    FIELD(DualexHexMesh, n_singular_edges);
    FIELD(DualexHexMesh, n_welded_vertices);
    FIELD(DualexHexMesh, topology_matches);
    FIELD(DualexHexMesh, sj_min_before);
    FIELD(DualexHexMesh, sj_min_after);
    FIELD(DualexHexMesh, sj_p5_before);
    FIELD(DualexHexMesh, sj_p5_after);
    FIELD(DualexHexMesh, inverted_before);
    FIELD(DualexHexMesh, inverted_after);
    FIELD(DualexHexMesh, moved_vertices);
}

/* A unit square of 2 triangles mapped onto [0,k]^2: k*k quads. */
static void square(unsigned k) {
    const double vpos[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const uint32_t tris[] = {0, 1, 2, 0, 2, 3};
    double uv[2 * 3 * 2];
    for (int c = 0; c < 6; c++) {
        uint32_t v = tris[c];
        uv[2 * c] = k * vpos[3 * v];
        uv[2 * c + 1] = k * vpos[3 * v + 1];
    }
    DualexQuadMesh q;
    CHECK(dualex_quad_extract(4, vpos, 2, tris, uv, NULL, &q) == DUALEX_OK);
    CHECK(q.n_cells == (size_t)k * k);
    CHECK(q.n_vertices == (size_t)(k + 1) * (k + 1));
    CHECK(q.n_components == 1 && q.n_boundary_loops == 1 && q.euler == 1);
    CHECK(q.topology_matches == 1);
    CHECK(strcmp(dualex_last_error(), "") == 0);
    for (size_t i = 0; i < 4 * q.n_cells; i++) CHECK(q.cells[i] < q.n_vertices);
    for (size_t i = 0; i < q.n_cells; i++) CHECK(q.sources[i] < 2);
    for (size_t i = 0; i < 3 * q.n_vertices; i++)
        CHECK(q.positions[i] >= -1e-9 && q.positions[i] <= 1 + 1e-9);
    /* a clean grid: squares before and after, nothing moved */
    CHECK(q.inverted_before == 0 && q.inverted_after == 0 && q.moved_vertices == 0);
    CHECK(q.sj_min_before > 0.999 && q.sj_min_after == q.sj_min_before);
    CHECK(q.sj_p5_after >= q.sj_min_after && q.sj_p5_after <= 1 + 1e-12);
    dualex_quad_mesh_free(&q);
    CHECK(q.cells == NULL && q.n_cells == 0);
    dualex_quad_mesh_free(&q); /* twice is safe */

    /* the same with explicit options */
    DualexOptions o;
    dualex_options_default(&o);
    CHECK(o.weld == 1 && o.fairing == 1 && o.seed == 1 && o.grid_offset == DUALEX_GRID_AUTO);
    CHECK(o.untangle == 1 && o.smooth_rounds == 0);
    o.grid_offset = DUALEX_GRID_HALF;
    CHECK(dualex_quad_extract(4, vpos, 2, tris, uv, &o, &q) == DUALEX_OK);
    CHECK(q.n_cells == (size_t)k * k);
    dualex_quad_mesh_free(&q);
    o.smooth_rounds = 3; /* smoothing a grid of squares keeps it untangled */
    CHECK(dualex_quad_extract(4, vpos, 2, tris, uv, &o, &q) == DUALEX_OK);
    CHECK(q.n_cells == (size_t)k * k && q.inverted_after == 0 && q.sj_min_after > 0.9);
    dualex_quad_mesh_free(&q);
    o.smooth_rounds = 0;
    o.untangle = 0;
    CHECK(dualex_quad_extract(4, vpos, 2, tris, uv, &o, &q) == DUALEX_OK);
    CHECK(q.moved_vertices == 0 && q.sj_min_after == q.sj_min_before);
    dualex_quad_mesh_free(&q);
    o.smooth_rounds = 2; /* smoothing with untangling off */
    CHECK(dualex_quad_extract(4, vpos, 2, tris, uv, &o, &q) == DUALEX_ERR_INVALID_ARGUMENT);
    CHECK(strstr(dualex_last_error(), "smooth_rounds 2 with untangle 0") != NULL);
    o.untangle = 1;
    o.smooth_rounds = -1;
    CHECK(dualex_quad_extract(4, vpos, 2, tris, uv, &o, &q) == DUALEX_ERR_INVALID_ARGUMENT);
    CHECK(strstr(dualex_last_error(), "smooth_rounds -1 is negative") != NULL);
    CHECK(q.cells == NULL && q.n_cells == 0);
    o.smooth_rounds = 0;

    /* errors: each a code and a message, the output zeroed */
    o.grid_offset = 7;
    CHECK(dualex_quad_extract(4, vpos, 2, tris, uv, &o, &q) == DUALEX_ERR_INVALID_ARGUMENT);
    CHECK(strstr(dualex_last_error(), "grid_offset 7") != NULL);
    CHECK(q.cells == NULL && q.n_cells == 0);
    const uint32_t bad[] = {0, 1, 7, 0, 2, 3};
    CHECK(dualex_quad_extract(4, vpos, 2, bad, uv, NULL, &q) == DUALEX_ERR_INVALID_INPUT);
    CHECK(strcmp(dualex_last_error(),
                 "triangle 0: corner 2 refers to vertex 7, but there are 4 vertices") == 0);
    CHECK(dualex_quad_extract(4, NULL, 2, tris, uv, NULL, &q) == DUALEX_ERR_INVALID_ARGUMENT);
    CHECK(strcmp(dualex_last_error(), "vpos is NULL but 4 items are expected") == 0);
    CHECK(dualex_quad_extract(4, vpos, 2, tris, uv, NULL, NULL) == DUALEX_ERR_INVALID_ARGUMENT);
    CHECK(dualex_quad_extract(0, NULL, 0, NULL, NULL, NULL, &q) == DUALEX_ERR_INVALID_INPUT);
    CHECK(strcmp(dualex_last_error(), "no triangles") == 0);
    double nan_uv[12];
    memcpy(nan_uv, uv, sizeof uv);
    nan_uv[3] = NAN;
    CHECK(dualex_quad_extract(4, vpos, 2, tris, nan_uv, NULL, &q) == DUALEX_ERR_INVALID_INPUT);
    CHECK(strstr(dualex_last_error(), "non-finite") != NULL);
    dualex_quad_mesh_free(&q);
    dualex_quad_mesh_free(NULL);
}

/* A unit cube of 6 tets around the diagonal 0-7, mapped onto [0,2]^3: 8 hexes. */
static void cube(void) {
    double vpos[8 * 3];
    for (int i = 0; i < 8; i++) {
        vpos[3 * i] = i & 1;
        vpos[3 * i + 1] = (i >> 1) & 1;
        vpos[3 * i + 2] = (i >> 2) & 1;
    }
    const uint32_t tets[] = {0, 1, 3, 7, 0, 3, 2, 7, 0, 2, 6, 7,
                             0, 6, 4, 7, 0, 4, 5, 7, 0, 5, 1, 7};
    double uvw[6 * 4 * 3];
    for (int c = 0; c < 24; c++)
        for (int d = 0; d < 3; d++) uvw[3 * c + d] = 2 * vpos[3 * tets[c] + d];
    DualexHexMesh h;
    CHECK(dualex_hex_extract(8, vpos, 6, tets, uvw, NULL, &h) == DUALEX_OK);
    CHECK(h.n_cells == 8 && h.n_vertices == 27);
    CHECK(h.n_components == 1 && h.n_boundary_surfaces == 1 && h.topology_matches == 1);
    CHECK(h.inverted_before == 0 && h.inverted_after == 0 && h.moved_vertices == 0);
    CHECK(h.sj_min_before > 0.999 && h.sj_min_after == h.sj_min_before);
    for (size_t i = 0; i < 8 * h.n_cells; i++) CHECK(h.cells[i] < h.n_vertices);
    for (size_t i = 0; i < h.n_cells; i++) CHECK(h.sources[i] < 6);
    dualex_hex_mesh_free(&h);
    CHECK(h.cells == NULL);
    CHECK(dualex_hex_extract(8, vpos, 6, tets, NULL, NULL, &h) == DUALEX_ERR_INVALID_ARGUMENT);
    CHECK(strcmp(dualex_last_error(), "tet_param is NULL but 6 items are expected") == 0);
    dualex_hex_mesh_free(&h);
}

/* A map read from a plain-text dump. */
typedef struct Dump {
    int tet;
    size_t nv, ns;
    double* vpos;
    uint32_t* simplices;
    double* param;
} Dump;

/* Reads a plain-text dump; 0 when the file cannot be opened. */
static int read_dump(const char* path, Dump* m) {
    memset(m, 0, sizeof *m);
    FILE* f = fopen(path, "r");
    CHECK(f != NULL);
    if (!f) return 0;
    char kind[4] = {0};
    CHECK(fscanf(f, "%3s %zu", kind, &m->nv) == 2);
    m->tet = strcmp(kind, "tet") == 0;
    size_t n = m->tet ? 4 : 3, d = m->tet ? 3 : 2;
    m->vpos = malloc(sizeof(double) * 3 * m->nv);
    for (size_t i = 0; i < 3 * m->nv; i++) CHECK(fscanf(f, "%lf", &m->vpos[i]) == 1);
    CHECK(fscanf(f, "%zu", &m->ns) == 1);
    m->simplices = malloc(sizeof(uint32_t) * n * m->ns);
    m->param = malloc(sizeof(double) * n * d * m->ns);
    for (size_t s = 0; s < m->ns; s++) {
        for (size_t c = 0; c < n; c++) {
            unsigned v = 0;
            CHECK(fscanf(f, "%u", &v) == 1);
            m->simplices[n * s + c] = v;
        }
        for (size_t c = 0; c < n * d; c++) CHECK(fscanf(f, "%lf", &m->param[n * d * s + c]) == 1);
    }
    fclose(f);
    return 1;
}

static void free_dump(Dump* m) {
    free(m->vpos);
    free(m->simplices);
    free(m->param);
}

/* Reads a plain-text dump and checks the number of cells. */
static void dumped(const char* path, size_t expected) {
    Dump m;
    if (!read_dump(path, &m)) return;
    size_t nv = m.nv, ns = m.ns;
    const double *vpos = m.vpos, *param = m.param;
    const uint32_t* simplices = m.simplices;
    if (m.tet) {
        DualexHexMesh h;
        CHECK(dualex_hex_extract(nv, vpos, ns, simplices, param, NULL, &h) == DUALEX_OK);
        CHECK(h.n_cells == expected);
        printf("%s: %zu hexes, %zu vertices\n", path, h.n_cells, h.n_vertices);
        dualex_hex_mesh_free(&h);
    } else {
        DualexQuadMesh q;
        CHECK(dualex_quad_extract(nv, vpos, ns, simplices, param, NULL, &q) == DUALEX_OK);
        CHECK(q.n_cells == expected);
        printf("%s: %zu quads, %zu vertices\n", path, q.n_cells, q.n_vertices);
        dualex_quad_mesh_free(&q);
    }
    free_dump(&m);
}

/* The quality fields of one extraction of a messy map. */
typedef struct Quality {
    int status;
    size_t cells, inverted_before, inverted_after, moved;
    double min_before, min_after;
} Quality;

static Quality extract_quality(const Dump* m, const DualexOptions* o) {
    Quality r = {0};
    if (m->tet) {
        DualexHexMesh h;
        r.status = dualex_hex_extract(m->nv, m->vpos, m->ns, m->simplices, m->param, o, &h);
        r.cells = h.n_cells;
        r.inverted_before = h.inverted_before;
        r.inverted_after = h.inverted_after;
        r.moved = h.moved_vertices;
        r.min_before = h.sj_min_before;
        r.min_after = h.sj_min_after;
        dualex_hex_mesh_free(&h);
    } else {
        DualexQuadMesh q;
        r.status = dualex_quad_extract(m->nv, m->vpos, m->ns, m->simplices, m->param, o, &q);
        r.cells = q.n_cells;
        r.inverted_before = q.inverted_before;
        r.inverted_after = q.inverted_after;
        r.moved = q.moved_vertices;
        r.min_before = q.sj_min_before;
        r.min_after = q.sj_min_after;
        dualex_quad_mesh_free(&q);
    }
    return r;
}

/* A map whose extraction places some elements inverted: the default
   untangles them all; untangle 0 keeps them (and strict refuses them). */
static void messy(const char* path) {
    Dump m;
    if (!read_dump(path, &m)) return;
    Quality a = extract_quality(&m, NULL);
    CHECK(a.status == DUALEX_OK);
    CHECK(a.inverted_before > 0 && a.inverted_after == 0);
    CHECK(a.min_before <= 0 && a.min_after > 0 && a.moved > 0);
    DualexOptions o;
    dualex_options_default(&o);
    o.untangle = 0;
    Quality off = extract_quality(&m, &o);
    CHECK(off.status == DUALEX_OK && off.cells == a.cells);
    CHECK(off.inverted_before == a.inverted_before && off.inverted_after == a.inverted_before);
    CHECK(off.min_after == a.min_before && off.moved == 0);
    o.strict = 1;
    Quality strict = extract_quality(&m, &o);
    CHECK(strict.status == DUALEX_ERR_EXTRACTION_FAILED && strict.cells == 0);
    CHECK(strstr(dualex_last_error(), "inverted") != NULL);
    o.untangle = 1;
    Quality fixed = extract_quality(&m, &o);
    CHECK(fixed.status == DUALEX_OK && fixed.inverted_after == 0);
    printf("%s: %zu cells, %zu inverted before, %zu after\n", path, a.cells,
           a.inverted_before, a.inverted_after);
    free_dump(&m);
}

int main(int argc, char** argv) {
    if (argc == 2 && strcmp(argv[1], "--layout") == 0) {
        print_layout();
        return 0;
    }
    CHECK(strlen(dualex_version()) > 0);
    if (argc == 3 && strcmp(argv[1], "--messy") == 0) {
        messy(argv[2]);
    } else if (argc == 3) {
        dumped(argv[1], (size_t)strtoull(argv[2], NULL, 10));
    } else {
        square(3);
        square(5);
        cube();
    }
    if (failures) fprintf(stderr, "%d checks failed\n", failures);
    else printf("all checks passed\n");
    return failures ? 1 : 0;
}

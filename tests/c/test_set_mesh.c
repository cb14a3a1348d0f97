/* SPDX-License-Identifier: BSD-3-Clause */
/* sfa_set_mesh: what it accepts, what it rejects and how it says so, and that a rejected
 * mesh leaves the surface exactly as it was. */
#include "support/testing.h"

/* ------------------------------------------------------------------ helpers */

/* A surface holding the unit cube, with a non-default parameter and a field, so that a
 * rejected mesh has something to lose. */
static sfa_surface *loaded_cube(void)
{
    sfa_surface *s = make_cube_surface();
    assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.25), SFA_OK);
    double values[2 * 8];
    for (int i = 0; i < 16; ++i)
        values[i] = 0.5 * i - 3;
    int32_t id = -1;
    assert_int_equal(sfa_add_field(s, 2, values, &id), SFA_OK);
    assert_int_equal(id, 0);
    return s;
}

/* Sets (nverts, xyz, ntris, tris, base) on a loaded cube and expects `expected` with a
 * message containing each phrase, the cube untouched. Indices are passed as given. */
static void expect_rejected_(int32_t nverts, const double *xyz, int32_t ntris, const int32_t *tris, int32_t base,
                             int expected, const char *const *phrases, const char *file, int line)
{
    sfa_surface *s = loaded_cube();
    snapshot before, after;
    snapshot_take(s, &before);
    const int rc = sfa_set_mesh(s, nverts, xyz, ntris, tris, base);
    assert_error_(s, rc, expected, phrases, file, line);
    snapshot_take(s, &after);
    assert_same_snapshot(&before, &after);
    snapshot_free(&before);
    snapshot_free(&after);
    sfa_destroy(s);
}
#define expect_rejected(nverts, xyz, ntris, tris, base, expected, ...)                                                 \
    do {                                                                                                               \
        const char *const phrases_[] = {__VA_ARGS__, NULL};                                                            \
        expect_rejected_((nverts), (xyz), (ntris), (tris), (base), (expected), phrases_, __FILE__, __LINE__);          \
    } while (0)

/* The same for a mesh given 0-based, passed in `base` (indices shifted). */
static void expect_mesh_rejected_(const sfa_mesh_data *m, int32_t base, int expected, const char *const *phrases,
                                  const char *file, int line)
{
    int32_t *tris = malloc(sizeof(int32_t) * 3 * (size_t)(m->ntris ? m->ntris : 1));
    assert_non_null(tris);
    for (int32_t i = 0; i < 3 * m->ntris; ++i)
        tris[i] = m->tris[i] + base;
    expect_rejected_(m->nverts, m->xyz, m->ntris, tris, base, expected, phrases, file, line);
    free(tris);
}
#define expect_mesh_rejected(m, base, expected, ...)                                                                   \
    do {                                                                                                               \
        const char *const phrases_[] = {__VA_ARGS__, NULL};                                                            \
        expect_mesh_rejected_((m), (base), (expected), phrases_, __FILE__, __LINE__);                                  \
    } while (0)

/* The mesh read back from s (in `base`) is m, bit for bit. */
static void assert_holds(const sfa_surface *s, const sfa_mesh_data *m, int32_t base)
{
    int32_t nv = -1, nt = -1;
    assert_int_equal(sfa_get_counts(s, &nv, &nt), SFA_OK);
    assert_int_equal(nv, m->nverts);
    assert_int_equal(nt, m->ntris);
    double *xyz = malloc(sizeof(double) * 3 * (size_t)nv);
    int32_t *tris = malloc(sizeof(int32_t) * 3 * (size_t)nt);
    assert_non_null(xyz);
    assert_non_null(tris);
    assert_int_equal(sfa_get_mesh(s, nv, xyz, nt, tris, base), SFA_OK);
    assert_memory_equal(xyz, m->xyz, sizeof(double) * 3 * (size_t)nv);
    for (int32_t i = 0; i < 3 * nt; ++i)
        assert_int_equal(tris[i], m->tris[i] + base);
    free(xyz);
    free(tris);
}

/* A mesh from literal arrays. */
static sfa_mesh_data literal(int32_t nverts, const double *xyz, int32_t ntris, const int32_t *tris)
{
    sfa_mesh_data m = {nverts, ntris, malloc(sizeof(double) * 3 * (size_t)(nverts + 1)),
                       malloc(sizeof(int32_t) * 3 * (size_t)(ntris + 1))};
    assert_non_null(m.xyz);
    assert_non_null(m.tris);
    memcpy(m.xyz, xyz, sizeof(double) * 3 * (size_t)nverts);
    memcpy(m.tris, tris, sizeof(int32_t) * 3 * (size_t)ntris);
    return m;
}

/* A tetrahedron with apex at the origin and the other vertices at p[0..2], faces turned
 * outward; appended to m. Returns nothing: m grows by 3 vertices (the apex is vertex 0 of
 * m, shared) and 4 triangles. */
static void add_tetrahedron_at_origin(sfa_mesh_data *m, const double p[3][3])
{
    const int32_t base = m->nverts;
    double *xyz = realloc(m->xyz, sizeof(double) * 3 * (size_t)(m->nverts + 3));
    int32_t *tris = realloc(m->tris, sizeof(int32_t) * 3 * (size_t)(m->ntris + 4));
    assert_non_null(xyz);
    assert_non_null(tris);
    m->xyz = xyz;
    m->tris = tris;
    memcpy(m->xyz + 3 * base, p, sizeof(double) * 9);
    m->nverts += 3;
    const int32_t ids[4] = {0, base, base + 1, base + 2};
    const int faces[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
    double centre[3] = {0, 0, 0};
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c)
            centre[c] += m->xyz[3 * ids[k] + c] / 4;
    for (int f = 0; f < 4; ++f) {
        int32_t a = ids[faces[f][0]], b = ids[faces[f][1]], c = ids[faces[f][2]];
        const double *A = m->xyz + 3 * a, *B = m->xyz + 3 * b, *C = m->xyz + 3 * c;
        const double u[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]}, v[3] = {C[0] - A[0], C[1] - A[1], C[2] - A[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double out = n[0] * (A[0] - centre[0]) + n[1] * (A[1] - centre[1]) + n[2] * (A[2] - centre[2]);
        if (out < 0) {
            const int32_t swap = b;
            b = c;
            c = swap;
        }
        int32_t *t = m->tris + 3 * m->ntris++;
        t[0] = a;
        t[1] = b;
        t[2] = c;
    }
}

/* ------------------------------------------------------------------ accepted */

static void cube_round_trip_in_both_bases(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    for (int32_t in_base = 0; in_base <= 1; ++in_base) {
        sfa_surface *s = make_surface(&cube, in_base);
        assert_string_equal(sfa_last_error(s), "");
        for (int32_t out_base = 0; out_base <= 1; ++out_base)
            assert_holds(s, &cube, out_base);
        sfa_destroy(s);
    }
    mesh_free(&cube);
}

static void icosphere_round_trip(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_icosphere(3, 2.5);
    sfa_surface *s = make_surface(&sphere, 1);
    assert_holds(s, &sphere, 0);
    assert_holds(s, &sphere, 1);
    sfa_destroy(s);
    mesh_free(&sphere);
}

static void box_with_shared_vertices_accepted(void **state)
{
    (void)state;
    const double lo[3] = {-1, -2, -3}, hi[3] = {1, 2, 3};
    sfa_mesh_data box = shape_box(4, lo, hi);
    assert_int_equal(box.nverts, 6 * 16 + 2);
    assert_int_equal(box.ntris, 12 * 16);
    sfa_surface *s = make_surface(&box, 0);
    assert_holds(s, &box, 0);
    assert_near(measure(s, SFA_MEASURE_VOLUME), 2.0 * 4.0 * 6.0, 1e-12);
    sfa_destroy(s);
    mesh_free(&box);
}

static void open_patch_accepted(void **state)
{
    (void)state;
    sfa_mesh_data grid = shape_grid(5, 3, 0.5);
    sfa_surface *s = make_surface(&grid, 0);
    assert_holds(s, &grid, 0);
    assert_near(measure(s, SFA_MEASURE_AREA), 2.5 * 1.5, 1e-14);
    sfa_destroy(s);
    mesh_free(&grid);
}

static void two_components_accepted(void **state)
{
    (void)state;
    sfa_mesh_data two = shape_unit_cube();
    sfa_mesh_data other = shape_unit_cube();
    const double d[3] = {3, 0, 0};
    mesh_translate(&other, d);
    mesh_append(&two, &other);
    sfa_surface *s = make_surface(&two, 0);
    assert_holds(s, &two, 0);
    assert_near(measure(s, SFA_MEASURE_VOLUME), 2.0, 1e-12);
    sfa_destroy(s);
    mesh_free(&two);
    mesh_free(&other);
}

static void replacing_a_mesh(void **state)
{
    (void)state;
    sfa_surface *s = loaded_cube();
    sfa_mesh_data sphere = shape_icosphere(1, 1.0);
    assert_ok(s, sfa_set_mesh(s, sphere.nverts, sphere.xyz, sphere.ntris, sphere.tris, 0));
    assert_holds(s, &sphere, 0);
    /* Parameters stay; the cube's field is gone. */
    double l = 0;
    assert_int_equal(sfa_get_param(s, SFA_PARAM_EDGE_LENGTH, &l), SFA_OK);
    assert_true(l == 0.25);
    double values[8 * 42];
    assert_int_equal(sfa_get_field(s, 0, 8 * 42, values), SFA_ERR_ARGUMENT);
    sfa_destroy(s);
    mesh_free(&sphere);
}

/* ------------------------------------------------------------------ arguments */

static void null_pointers_and_bad_counts(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    assert_int_equal(sfa_set_mesh(NULL, 8, cube.xyz, 12, cube.tris, 0), SFA_ERR_ARGUMENT);
    expect_rejected(8, NULL, 12, cube.tris, 0, SFA_ERR_ARGUMENT, "");
    expect_rejected(8, cube.xyz, 12, NULL, 0, SFA_ERR_ARGUMENT, "");
    expect_rejected(-1, cube.xyz, 12, cube.tris, 0, SFA_ERR_ARGUMENT, "");
    expect_rejected(8, cube.xyz, -1, cube.tris, 0, SFA_ERR_ARGUMENT, "");
    expect_rejected(INT32_MIN, cube.xyz, INT32_MIN, cube.tris, 0, SFA_ERR_ARGUMENT, "");
    expect_rejected(8, cube.xyz, 12, cube.tris, 2, SFA_ERR_ARGUMENT, "");
    expect_rejected(8, cube.xyz, 12, cube.tris, -1, SFA_ERR_ARGUMENT, "");
    mesh_free(&cube);
}

static void failure_on_an_empty_surface_keeps_it_empty(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    sfa_mesh_data cube = shape_unit_cube();
    cube.tris[0] = 8;
    snapshot before, after;
    snapshot_take(s, &before);
    assert_error(s, sfa_set_mesh(s, 8, cube.xyz, 12, cube.tris, 0), SFA_ERR_MESH, "triangle 0", "vertex 8");
    snapshot_take(s, &after);
    assert_same_snapshot(&before, &after);
    int32_t nv = -1, nt = -1;
    assert_int_equal(sfa_get_counts(s, &nv, &nt), SFA_OK);
    assert_int_equal(nv, 0);
    assert_int_equal(nt, 0);
    snapshot_free(&before);
    snapshot_free(&after);
    mesh_free(&cube);
    sfa_destroy(s);
}

/* ------------------------------------------------------------------ rejected meshes */

static void no_triangles(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    expect_rejected(8, cube.xyz, 0, cube.tris, 0, SFA_ERR_MESH, "no triangles");
    expect_rejected(0, cube.xyz, 0, cube.tris, 0, SFA_ERR_MESH, "no triangles");
    expect_rejected(0, cube.xyz, 0, cube.tris, 1, SFA_ERR_MESH, "no triangles");
    mesh_free(&cube);
}

static void non_finite_coordinates(void **state)
{
    (void)state;
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (int b = 0; b < 3; ++b)
        for (int k = 0; k < 3; ++k) {
            sfa_mesh_data cube = shape_unit_cube();
            cube.xyz[3 * 5 + k] = bad[b];
            expect_mesh_rejected(&cube, 0, SFA_ERR_MESH, "vertex 5", "non-finite");
            expect_mesh_rejected(&cube, 1, SFA_ERR_MESH, "vertex 6", "non-finite");
            mesh_free(&cube);
        }
}

/* A tetrahedron with its apex at y = -1e300 over a base at 1e10: every coordinate is finite,
 * but the products of their differences overflow (infinity minus infinity makes the area
 * of each side NaN), and it used to be accepted, its measures NaN. */
static const double overflowing_tetrahedron[] = {1e10, 1e10, 1e10, -1e10, 1e10, 3e10, 0, 1e10, 1e10, 0, -1e300, 0};
static const int32_t tetrahedron_tris[] = {0, 1, 2, 3, 1, 0, 3, 2, 1, 3, 0, 2};

static void coordinates_outside_the_range(void **state)
{
    (void)state;
    sfa_mesh_data tetrahedron = literal(4, overflowing_tetrahedron, 4, tetrahedron_tris);
    expect_mesh_rejected(&tetrahedron, 0, SFA_ERR_MESH, "vertex 3", "outside the range the library computes in");
    expect_mesh_rejected(&tetrahedron, 1, SFA_ERR_MESH, "vertex 4", "outside the range the library computes in");
    /* Just over the largest coordinate, on each axis and with each sign. */
    for (int k = 0; k < 3; ++k)
        for (int sign = -1; sign <= 1; sign += 2) {
            sfa_mesh_data cube = shape_unit_cube();
            cube.xyz[3 * 5 + k] = sign * 1.0000001e50;
            expect_mesh_rejected(&cube, 0, SFA_ERR_MESH, "vertex 5", "outside the range");
            mesh_free(&cube);
        }
    /* A sphere of radius 1e120 (it was accepted, and reported thousands of
     * self-intersections). */
    sfa_mesh_data huge = shape_icosphere(2, 1e120);
    expect_mesh_rejected(&huge, 0, SFA_ERR_MESH, "vertex 0", "outside the range the library computes in");
    mesh_free(&huge);
    mesh_free(&tetrahedron);
}

/* A good sphere at scale 1e-100 is not flat: it is too small to compute with, and the
 * message says so (it used to say "zero area ... collinear or coincide"). */
static void mesh_smaller_than_the_range(void **state)
{
    (void)state;
    sfa_mesh_data tiny = shape_icosphere(2, 1e-100);
    expect_mesh_rejected(&tiny, 0, SFA_ERR_MESH, "spans only", "outside the range the library computes in");
    sfa_surface *s = loaded_cube();
    assert_int_equal(sfa_set_mesh(s, tiny.nverts, tiny.xyz, tiny.ntris, tiny.tris, 0), SFA_ERR_MESH);
    assert_null(strstr(sfa_last_error(s), "zero area"));
    sfa_destroy(s);
    mesh_free(&tiny);
}

/* At both ends of the range a sphere is accepted and measured as the unit sphere is, scaled,
 * and smoothing and adaptation keep its volume. */
static void ends_of_the_range_compute_as_the_unit_sphere(void **state)
{
    (void)state;
    sfa_mesh_data unit = shape_jittered_icosphere(2, 1.0, 0.2, 5);
    sfa_surface *reference = make_surface(&unit, 0);
    const double volume = measure(reference, SFA_MEASURE_VOLUME), area = measure(reference, SFA_MEASURE_AREA);
    sfa_destroy(reference);
    const double scales[] = {0.9e-50, 0.9e50}; /* the sphere spans 1.8e-50 and reaches 0.9e50 */
    for (int i = 0; i < 2; ++i) {
        const double r = scales[i];
        sfa_mesh_data m = mesh_copy(&unit);
        for (int32_t k = 0; k < 3 * m.nverts; ++k)
            m.xyz[k] *= r;
        sfa_surface *s = make_surface(&m, 0);
        assert_near(measure(s, SFA_MEASURE_VOLUME) / (r * r * r), volume, 1e-13 * volume);
        assert_near(measure(s, SFA_MEASURE_AREA) / (r * r), area, 1e-13 * area);
        assert_true(measure(s, SFA_MEASURE_SELF_INTERSECTIONS) == 0);
        assert_ok(s, sfa_smooth(s, 2));
        assert_near(measure(s, SFA_MEASURE_VOLUME) / (r * r * r), volume, 1e-12 * volume);
        assert_ok(s, sfa_adapt(s));
        assert_near(measure(s, SFA_MEASURE_VOLUME) / (r * r * r), volume, 1e-12 * volume);
        assert_true(measure(s, SFA_MEASURE_SELF_INTERSECTIONS) == 0);
        sfa_destroy(s);
        mesh_free(&m);
    }
    mesh_free(&unit);
}

static void index_out_of_range(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    int32_t tris[36];
    /* Base 0: 8 and -1 do not exist. */
    const int32_t base0_bad[2] = {8, -1};
    for (int i = 0; i < 2; ++i) {
        memcpy(tris, cube.tris, sizeof tris);
        tris[3 * 7 + 1] = base0_bad[i];
        char vertex[32];
        snprintf(vertex, sizeof vertex, "vertex %d", (int)base0_bad[i]);
        expect_rejected(8, cube.xyz, 12, tris, 0, SFA_ERR_MESH, "triangle 7", vertex, "8 vertices");
    }
    /* Base 1: 0 and 9 do not exist; triangle 7 (0-based) is the host's triangle 8. */
    const int32_t base1_bad[2] = {0, 9};
    for (int i = 0; i < 2; ++i) {
        for (int k = 0; k < 36; ++k)
            tris[k] = cube.tris[k] + 1;
        tris[3 * 7 + 2] = base1_bad[i];
        char vertex[32];
        snprintf(vertex, sizeof vertex, "vertex %d", (int)base1_bad[i]);
        expect_rejected(8, cube.xyz, 12, tris, 1, SFA_ERR_MESH, "triangle 8", vertex, "8 vertices");
    }
    /* No vertices at all. */
    expect_rejected(0, cube.xyz, 12, cube.tris, 0, SFA_ERR_MESH, "triangle 0", "0 vertices");
    /* Far out of range, both signs. */
    memcpy(tris, cube.tris, sizeof tris);
    tris[0] = INT32_MAX;
    expect_rejected(8, cube.xyz, 12, tris, 0, SFA_ERR_MESH, "triangle 0", "vertex 2147483647");
    tris[0] = INT32_MIN;
    expect_rejected(8, cube.xyz, 12, tris, 1, SFA_ERR_MESH, "triangle 1", "vertex -2147483648");
    mesh_free(&cube);
}

static void triangle_repeating_a_vertex(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    cube.tris[3 * 3 + 2] = cube.tris[3 * 3 + 0]; /* triangle 3 = (4, 6, 4) */
    expect_mesh_rejected(&cube, 0, SFA_ERR_MESH, "triangle 3", "vertex 4", "twice");
    expect_mesh_rejected(&cube, 1, SFA_ERR_MESH, "triangle 4", "vertex 5", "twice");
    mesh_free(&cube);
}

static void zero_area_triangle(void **state)
{
    (void)state;
    /* One collinear triangle alone. */
    const double line[] = {0, 0, 0, 1, 0, 0, 2, 0, 0};
    const int32_t one[] = {0, 1, 2};
    sfa_mesh_data m = literal(3, line, 1, one);
    expect_mesh_rejected(&m, 0, SFA_ERR_MESH, "triangle 0", "zero area");
    expect_mesh_rejected(&m, 1, SFA_ERR_MESH, "triangle 1", "zero area");
    mesh_free(&m);
    /* In a patch: vertex 2 of a 1x1 grid moved onto the diagonal 0-3 flattens triangle 1. */
    sfa_mesh_data grid = shape_grid(1, 1, 1.0);
    grid.xyz[3 * 2 + 0] = 2;
    grid.xyz[3 * 2 + 1] = 2;
    expect_mesh_rejected(&grid, 0, SFA_ERR_MESH, "triangle 1", "zero area");
    /* Two coincident vertices also make zero area. */
    grid.xyz[3 * 2 + 0] = 1;
    grid.xyz[3 * 2 + 1] = 1;
    expect_mesh_rejected(&grid, 0, SFA_ERR_MESH, "triangle 1", "zero area");
    mesh_free(&grid);
}

static void duplicate_triangles(void **state)
{
    (void)state;
    /* Triangle 4 of the cube is (0, 1, 5); a 13th triangle on the same three vertices,
     * in each rotation and reversed. */
    const int32_t copies[4][3] = {{0, 1, 5}, {1, 5, 0}, {5, 0, 1}, {0, 5, 1}};
    for (int c = 0; c < 4; ++c) {
        sfa_mesh_data cube = shape_unit_cube();
        int32_t tris[39];
        memcpy(tris, cube.tris, sizeof(int32_t) * 36);
        memcpy(tris + 36, copies[c], sizeof copies[c]);
        expect_rejected(8, cube.xyz, 13, tris, 0, SFA_ERR_MESH, "triangles 4 and 12", "same three vertices");
        for (int k = 0; k < 39; ++k)
            ++tris[k];
        expect_rejected(8, cube.xyz, 13, tris, 1, SFA_ERR_MESH, "triangles 5 and 13", "same three vertices");
        mesh_free(&cube);
    }
    /* Two triangles alone, opposite orientations: a closed "pillow" whose only fault is
     * the duplicate. */
    const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const int32_t pillow[] = {0, 1, 2, 0, 2, 1};
    expect_rejected(3, xyz, 2, pillow, 0, SFA_ERR_MESH, "triangles 0 and 1", "same three vertices");
}

static void edge_with_three_triangles(void **state)
{
    (void)state;
    /* A fin on the cube's edge (0, 1): triangles 0, 4 and the new 12 = (1, 0, 8). */
    sfa_mesh_data cube = shape_unit_cube();
    double xyz[27];
    int32_t tris[39];
    memcpy(xyz, cube.xyz, sizeof(double) * 24);
    xyz[24] = 0.5;
    xyz[25] = -0.5;
    xyz[26] = -0.5;
    memcpy(tris, cube.tris, sizeof(int32_t) * 36);
    tris[36] = 1;
    tris[37] = 0;
    tris[38] = 8;
    sfa_mesh_data fin = literal(9, xyz, 13, tris);
    expect_mesh_rejected(&fin, 0, SFA_ERR_MESH, "shared by 3", "0", "4", "12");
    expect_mesh_rejected(&fin, 1, SFA_ERR_MESH, "shared by 3", "1", "5", "13");
    mesh_free(&cube);
    mesh_free(&fin);
}

static void bow_tie_vertices(void **state)
{
    (void)state;
    /* Two triangles touching at vertex 0 only. */
    const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0.5, 0, -1, 0.5};
    const int32_t tris[] = {0, 1, 2, 0, 3, 4};
    expect_rejected(5, xyz, 2, tris, 0, SFA_ERR_MESH, "vertex 0", "bow-tie");
    const int32_t tris1[] = {1, 2, 3, 1, 4, 5};
    expect_rejected(5, xyz, 2, tris1, 1, SFA_ERR_MESH, "vertex 1", "bow-tie");

    /* Two closed tetrahedra sharing their apex: every edge has two triangles, but the apex
     * has two fans. */
    const double origin[3] = {0, 0, 0};
    const int32_t none[3] = {0, 0, 0};
    sfa_mesh_data m = literal(1, origin, 0, none);
    const double up[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double down[3][3] = {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    add_tetrahedron_at_origin(&m, up);
    add_tetrahedron_at_origin(&m, down);
    assert_int_equal(m.nverts, 7);
    assert_int_equal(m.ntris, 8);
    expect_mesh_rejected(&m, 0, SFA_ERR_MESH, "vertex 0", "bow-tie");
    expect_mesh_rejected(&m, 1, SFA_ERR_MESH, "vertex 1", "bow-tie");
    /* Each tetrahedron alone is fine. */
    sfa_mesh_data one = mesh_copy(&m);
    one.nverts = 4;
    one.ntris = 4;
    sfa_surface *s = make_surface(&one, 0);
    assert_near(measure(s, SFA_MEASURE_VOLUME), 1.0 / 6.0, 1e-15);
    sfa_destroy(s);
    mesh_free(&one);
    mesh_free(&m);
}

static void inconsistent_orientation(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    const int32_t swap = cube.tris[3 * 5 + 1];
    cube.tris[3 * 5 + 1] = cube.tris[3 * 5 + 2];
    cube.tris[3 * 5 + 2] = swap;
    /* Whichever neighbour is named with it, the reversed triangle 5 is one of the two. */
    expect_mesh_rejected(&cube, 0, SFA_ERR_MESH, "orientation", "5");
    expect_mesh_rejected(&cube, 1, SFA_ERR_MESH, "orientation", "6");
    mesh_free(&cube);
    /* The whole cube reversed is consistent (inward normals): accepted, volume -1. */
    sfa_mesh_data inside_out = shape_unit_cube();
    mesh_reverse(&inside_out);
    sfa_surface *s = make_surface(&inside_out, 0);
    assert_near(measure(s, SFA_MEASURE_VOLUME), -1.0, 1e-15);
    sfa_destroy(s);
    mesh_free(&inside_out);
}

/* The cube with an extra vertex inserted at position 3 that no triangle uses. */
static sfa_mesh_data cube_with_unreferenced_vertex(void)
{
    sfa_mesh_data cube = shape_unit_cube();
    sfa_mesh_data m = {9, 12, malloc(sizeof(double) * 27), malloc(sizeof(int32_t) * 36)};
    assert_non_null(m.xyz);
    assert_non_null(m.tris);
    memcpy(m.xyz, cube.xyz, sizeof(double) * 9);
    m.xyz[9] = 0.5;
    m.xyz[10] = 0.5;
    m.xyz[11] = 7;
    memcpy(m.xyz + 12, cube.xyz + 9, sizeof(double) * 15);
    for (int i = 0; i < 36; ++i)
        m.tris[i] = cube.tris[i] >= 3 ? cube.tris[i] + 1 : cube.tris[i];
    mesh_free(&cube);
    return m;
}

static void unreferenced_vertex_rejected_by_default(void **state)
{
    (void)state;
    sfa_mesh_data m = cube_with_unreferenced_vertex();
    expect_mesh_rejected(&m, 0, SFA_ERR_MESH, "vertex 3", "unreferenced");
    expect_mesh_rejected(&m, 1, SFA_ERR_MESH, "vertex 4", "unreferenced");
    /* Unreferenced at the end too. */
    sfa_mesh_data tail = shape_unit_cube();
    const double far[3] = {9, 9, 9};
    const int32_t none[3] = {0, 0, 0};
    sfa_mesh_data lone = literal(1, far, 0, none);
    mesh_append(&tail, &lone);
    expect_mesh_rejected(&tail, 0, SFA_ERR_MESH, "vertex 8", "unreferenced");
    mesh_free(&lone);
    mesh_free(&tail);
    mesh_free(&m);
}

static void unreferenced_vertex_dropped_on_request(void **state)
{
    (void)state;
    sfa_mesh_data m = cube_with_unreferenced_vertex();
    sfa_mesh_data cube = shape_unit_cube();
    for (int32_t base = 0; base <= 1; ++base) {
        sfa_surface *s = NULL;
        assert_int_equal(sfa_create(&s), SFA_OK);
        assert_int_equal(sfa_set_param(s, SFA_PARAM_DROP_UNREFERENCED, 1), SFA_OK);
        int32_t tris[36];
        for (int i = 0; i < 36; ++i)
            tris[i] = m.tris[i] + base;
        assert_ok(s, sfa_set_mesh(s, 9, m.xyz, 12, tris, base));
        /* The kept vertices keep their order: what is left is exactly the cube. */
        assert_holds(s, &cube, 0);
        assert_holds(s, &cube, 1);
        sfa_destroy(s);
    }
    mesh_free(&cube);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cube_round_trip_in_both_bases),
        cmocka_unit_test(icosphere_round_trip),
        cmocka_unit_test(box_with_shared_vertices_accepted),
        cmocka_unit_test(open_patch_accepted),
        cmocka_unit_test(two_components_accepted),
        cmocka_unit_test(replacing_a_mesh),
        cmocka_unit_test(null_pointers_and_bad_counts),
        cmocka_unit_test(failure_on_an_empty_surface_keeps_it_empty),
        cmocka_unit_test(no_triangles),
        cmocka_unit_test(non_finite_coordinates),
        cmocka_unit_test(coordinates_outside_the_range),
        cmocka_unit_test(mesh_smaller_than_the_range),
        cmocka_unit_test(ends_of_the_range_compute_as_the_unit_sphere),
        cmocka_unit_test(index_out_of_range),
        cmocka_unit_test(triangle_repeating_a_vertex),
        cmocka_unit_test(zero_area_triangle),
        cmocka_unit_test(duplicate_triangles),
        cmocka_unit_test(edge_with_three_triangles),
        cmocka_unit_test(bow_tie_vertices),
        cmocka_unit_test(inconsistent_orientation),
        cmocka_unit_test(unreferenced_vertex_rejected_by_default),
        cmocka_unit_test(unreferenced_vertex_dropped_on_request),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

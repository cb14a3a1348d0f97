/* SPDX-License-Identifier: BSD-3-Clause */
/* sfa_measure on shapes whose answers are known in closed form. */
#include "support/testing.h"

#include "icosphere.h"

static const double pi = 3.14159265358979323846;

static void unit_cube(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    /* Integer coordinates make every triple product an integer: the sum is exact. */
    assert_true(measure(s, SFA_MEASURE_VOLUME) == 1.0);
    assert_near(measure(s, SFA_MEASURE_AREA), 6.0, 1e-15);
    assert_near(measure(s, SFA_MEASURE_MIN_ANGLE), 45.0, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MAX_ANGLE), 90.0, 1e-12);
    /* 18 edges: the 12 of the cube and the 6 face diagonals. */
    assert_near(measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH), (12 + 6 * sqrt(2.0)) / 18, 1e-15);
    assert_near(measure(s, SFA_MEASURE_MIN_EDGE_LENGTH), 1.0, 1e-15);
    assert_near(measure(s, SFA_MEASURE_MAX_EDGE_LENGTH), sqrt(2.0), 1e-15);
    /* Right isosceles triangle with legs 1: R = sqrt(2)/2, r = (2 - sqrt(2))/2,
     * R / (2 r) = (1 + sqrt(2)) / 2. */
    assert_near(measure(s, SFA_MEASURE_MAX_ASPECT_RATIO), (1 + sqrt(2.0)) / 2, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MAX_NORMAL_TURN), 90.0, 1e-12);
    assert_true(measure(s, SFA_MEASURE_SELF_INTERSECTIONS) == 0);
    sfa_destroy(s);
}

static void icosahedron(void **state)
{
    (void)state;
    sfa_mesh_data ico = shape_icosahedron(1.0);
    sfa_surface *s = make_surface(&ico, 0);
    const double a = 1 / sin(2 * pi / 5); /* edge of the icosahedron of circumradius 1 */
    const double volume = 5.0 / 12.0 * (3 + sqrt(5.0)) * a * a * a;
    assert_near(measure(s, SFA_MEASURE_VOLUME), volume, 1e-12 * volume);
    assert_near(measure(s, SFA_MEASURE_AREA), 5 * sqrt(3.0) * a * a, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MIN_ANGLE), 60.0, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MAX_ANGLE), 60.0, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH), a, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MIN_EDGE_LENGTH), a, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MAX_EDGE_LENGTH), a, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MAX_ASPECT_RATIO), 1.0, 1e-12);
    sfa_destroy(s);
    mesh_free(&ico);
}

static void translated_cube(void **state)
{
    (void)state;
    const double shifts[2][3] = {{10.5, -20.25, 3.125}, {0.1, 0.2, 0.3}};
    for (int i = 0; i < 2; ++i) {
        sfa_mesh_data cube = shape_unit_cube();
        mesh_translate(&cube, shifts[i]);
        sfa_surface *s = make_surface(&cube, 0);
        assert_near(measure(s, SFA_MEASURE_VOLUME), 1.0, 1e-12);
        assert_near(measure(s, SFA_MEASURE_AREA), 6.0, 1e-12);
        sfa_destroy(s);
        mesh_free(&cube);
    }
}

static void reversed_cube(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    mesh_reverse(&cube);
    sfa_surface *s = make_surface(&cube, 0);
    assert_true(measure(s, SFA_MEASURE_VOLUME) == -1.0);
    assert_near(measure(s, SFA_MEASURE_AREA), 6.0, 1e-15);
    sfa_destroy(s);
    mesh_free(&cube);
}

static void icosphere_matches_tetrahedra(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_icosphere(3, 1.7);
    sfa_surface *s = make_surface(&sphere, 0);
    double volume = 0, area = 0;
    for (int32_t t = 0; t < sphere.ntris; ++t) {
        const double *a = sphere.xyz + 3 * sphere.tris[3 * t], *b = sphere.xyz + 3 * sphere.tris[3 * t + 1],
                     *c = sphere.xyz + 3 * sphere.tris[3 * t + 2];
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        area += sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
    }
    assert_near(measure(s, SFA_MEASURE_VOLUME), volume, 1e-12 * volume);
    assert_near(measure(s, SFA_MEASURE_AREA), area, 1e-12 * area);
    /* Inscribed in the sphere: a little less than its volume and area. */
    const double r = 1.7;
    assert_true(volume < 4.0 / 3.0 * pi * r * r * r && volume > 0.98 * 4.0 / 3.0 * pi * r * r * r);
    assert_true(area < 4 * pi * r * r && area > 0.98 * 4 * pi * r * r);
    sfa_destroy(s);
    mesh_free(&sphere);
}

/* Geodesic spheres of any frequency are valid closed meshes (sfa_set_mesh checks manifold
 * and orientation) with the documented counts; frequency 2^k has the icosphere's volume. */
static void geodesic_spheres_are_valid_at_any_frequency(void **state)
{
    (void)state;
    const double center[3] = {0, 0, 0};
    const int frequencies[] = {1, 2, 3, 5, 8, 48};
    for (size_t k = 0; k < sizeof frequencies / sizeof frequencies[0]; ++k) {
        const int n = frequencies[k];
        sfa_mesh_data m;
        assert_int_equal(geodesic_sphere(n, 1.0, center, &m.nverts, &m.xyz, &m.ntris, &m.tris), 0);
        assert_int_equal(m.nverts, 10 * n * n + 2);
        assert_int_equal(m.ntris, 20 * n * n);
        sfa_surface *s = make_surface(&m, 0);
        const double volume = measure(s, SFA_MEASURE_VOLUME);
        assert_true(volume > 0 && volume < 4.0 / 3.0 * pi);
        if (n == 1 || n == 2 || n == 8) {
            sfa_mesh_data ico = shape_icosphere(n == 1 ? 0 : n == 2 ? 1 : 3, 1.0);
            sfa_surface *t = make_surface(&ico, 0);
            assert_near(volume, measure(t, SFA_MEASURE_VOLUME), 1e-12);
            sfa_destroy(t);
            mesh_free(&ico);
        }
        sfa_destroy(s);
        mesh_free(&m);
    }
}

/* A fold: a flat patch whose middle vertex is pulled through to the other side, so that
 * its triangles face down while the others face up. */
static void folded_patch_turns_by_almost_180_degrees(void **state)
{
    (void)state;
    sfa_mesh_data grid = shape_grid(2, 2, 1.0);
    grid.xyz[3 * 4] = 2.5; /* vertex (1, 1) moved past (2, 1): its fan turns over */
    sfa_surface *s = make_surface(&grid, 0);
    assert_true(measure(s, SFA_MEASURE_MAX_NORMAL_TURN) > 179);
    sfa_destroy(s);
    mesh_free(&grid);
}

/* A cusp: a patch hinged along its middle line until its halves are 4 degrees apart, like
 * the rim of a sheet thinner than an edge. Its normals turn by 176 degrees, but it does
 * not pass through itself. Pulling one vertex across its neighbours in the plane makes
 * its fan overlap triangles it shares no vertex with: that does. */
static void a_cusp_is_no_self_intersection_but_an_overlap_is(void **state)
{
    (void)state;
    const double opening = 176 * acos(-1.0) / 180;
    sfa_mesh_data grid = shape_grid(4, 4, 0.25);
    for (int32_t v = 0; v < grid.nverts; ++v) {
        double *p = grid.xyz + 3 * v;
        if (p[0] > 0.5 + 1e-9) { /* the right half turns about the line x = 0.5 */
            const double r = p[0] - 0.5;
            p[0] = 0.5 + r * cos(opening);
            p[2] = r * sin(opening);
        }
    }
    sfa_surface *s = make_surface(&grid, 0);
    assert_near(measure(s, SFA_MEASURE_MAX_NORMAL_TURN), 176.0, 1e-9);
    assert_true(measure(s, SFA_MEASURE_SELF_INTERSECTIONS) == 0);
    sfa_destroy(s);
    mesh_free(&grid);

    grid = shape_grid(4, 4, 0.25);
    grid.xyz[3 * 6] += 0.6; /* vertex (1, 1), at (0.25, 0.25), pulled to x = 0.85 */
    s = make_surface(&grid, 0);
    assert_true(measure(s, SFA_MEASURE_SELF_INTERSECTIONS) > 0);
    sfa_destroy(s);
    mesh_free(&grid);
}

/* Two spheres in one mesh: apart they do not intersect; overlapping, they do. */
static void overlapping_spheres_intersect(void **state)
{
    (void)state;
    const double shifts[] = {2.5, 1.5};
    for (int k = 0; k < 2; ++k) {
        sfa_mesh_data a = shape_icosphere(3, 1.0), both;
        both.nverts = 2 * a.nverts;
        both.ntris = 2 * a.ntris;
        both.xyz = malloc(sizeof(double) * 3 * (size_t)both.nverts);
        both.tris = malloc(sizeof(int32_t) * 3 * (size_t)both.ntris);
        assert_non_null(both.xyz);
        assert_non_null(both.tris);
        for (int32_t i = 0; i < 3 * a.nverts; ++i) {
            both.xyz[i] = a.xyz[i];
            both.xyz[3 * a.nverts + i] = a.xyz[i] + (i % 3 == 0 ? shifts[k] : 0);
        }
        for (int32_t i = 0; i < 3 * a.ntris; ++i) {
            both.tris[i] = a.tris[i];
            both.tris[3 * a.ntris + i] = a.tris[i] + a.nverts;
        }
        sfa_surface *s = make_surface(&both, 0);
        const double crossings = measure(s, SFA_MEASURE_SELF_INTERSECTIONS);
        if (k == 0)
            assert_true(crossings == 0);
        else
            assert_true(crossings > 0);
        sfa_destroy(s);
        mesh_free(&a);
        mesh_free(&both);
    }
}

static void open_flat_patch(void **state)
{
    (void)state;
    sfa_mesh_data grid = shape_grid(4, 2, 0.25);
    sfa_surface *s = make_surface(&grid, 0);
    assert_true(measure(s, SFA_MEASURE_VOLUME) == 0.0); /* every vertex has z = 0 */
    assert_near(measure(s, SFA_MEASURE_AREA), 0.5, 1e-15);
    assert_near(measure(s, SFA_MEASURE_MIN_ANGLE), 45.0, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MAX_ANGLE), 90.0, 1e-12);
    assert_near(measure(s, SFA_MEASURE_MIN_EDGE_LENGTH), 0.25, 1e-15);
    assert_near(measure(s, SFA_MEASURE_MAX_EDGE_LENGTH), 0.25 * sqrt(2.0), 1e-15);
    /* 4x2 cells: 5*2 + 3*4 = 22 axis edges and 8 diagonals. */
    assert_near(measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH), 0.25 * (22 + 8 * sqrt(2.0)) / 30, 1e-15);
    assert_true(measure(s, SFA_MEASURE_MAX_NORMAL_TURN) == 0.0);
    sfa_destroy(s);
    mesh_free(&grid);
}

/* Where the mesh does not resolve its surface: the surface turns by more than a right
 * angle within a triangle's own size. A fine sphere turns by a few degrees an edge and a
 * finely meshed cube by exactly a right angle at its creases: nothing is left out. A
 * tetrahedron's faces are 109 degrees apart at every edge: everything is. A lens a
 * hundredth as thick as it is wide folds round its rim within a triangle: its rim is left
 * out, and its two faces, each meshed well, are not, for the walk from a face does not
 * cross to the other. */
static void unresolved_area_is_where_the_surface_turns_within_a_triangle(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_icosphere(3, 1.0); /* about 40 edges round */
    sfa_surface *s = make_surface(&sphere, 0);
    assert_true(measure(s, SFA_MEASURE_UNRESOLVED_AREA) == 0);
    assert_true(measure(s, SFA_MEASURE_MIN_ANGLE_RESOLVED) == measure(s, SFA_MEASURE_MIN_ANGLE));
    sfa_destroy(s);

    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    sfa_mesh_data box = shape_box(8, lo, hi);
    s = make_surface(&box, 0);
    assert_true(measure(s, SFA_MEASURE_UNRESOLVED_AREA) == 0);
    assert_near(measure(s, SFA_MEASURE_MIN_ANGLE_RESOLVED), 45.0, 1e-12);
    sfa_destroy(s);
    mesh_free(&box);
    /* The cube of 12 triangles is as thick as its triangles: from each, the opposite face
     * lies within its size. */
    s = make_cube_surface();
    assert_true(measure(s, SFA_MEASURE_UNRESOLVED_AREA) == 1);
    sfa_destroy(s);

    double corners[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    int32_t faces[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    const sfa_mesh_data tetrahedron = {.nverts = 4, .ntris = 4, .xyz = corners, .tris = faces};
    s = make_surface(&tetrahedron, 0);
    assert_true(measure(s, SFA_MEASURE_UNRESOLVED_AREA) == 1);
    assert_true(measure(s, SFA_MEASURE_MIN_ANGLE_RESOLVED) == 180);
    sfa_destroy(s);

    sfa_mesh_data lens = shape_ellipsoid(4, 1.0, 1.0, 0.01);
    s = make_surface(&lens, 0);
    const double rim = measure(s, SFA_MEASURE_UNRESOLVED_AREA);
    print_message("lens: %.3f of the area left out, smallest angle %.2f there and %.2f elsewhere\n", rim,
                  measure(s, SFA_MEASURE_MIN_ANGLE), measure(s, SFA_MEASURE_MIN_ANGLE_RESOLVED));
    assert_true(rim > 0.05 && rim < 0.5);
    assert_true(measure(s, SFA_MEASURE_MIN_ANGLE_RESOLVED) > measure(s, SFA_MEASURE_MIN_ANGLE));
    sfa_destroy(s);
    /* The rule has no length in it: the same lens 2^-40 and 2^40 times as large (scaled
     * exactly) gives the same share to the bit, and 1e5 from the origin nearly so. */
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, far[3] = {1e5, -1e5, 1e5};
    for (int k = 0; k < 3; ++k) {
        sfa_mesh_data moved = mesh_copy(&lens);
        if (k < 2)
            mesh_rotate_scale(&moved, identity, ldexp(1.0, k ? 40 : -40));
        else
            mesh_translate(&moved, far);
        s = make_surface(&moved, 0);
        assert_near(measure(s, SFA_MEASURE_UNRESOLVED_AREA), rim, k < 2 ? 0 : 1e-6);
        sfa_destroy(s);
        mesh_free(&moved);
    }

    /* Each component on its own: the sphere's nothing, the lens's rim. */
    const double away[3] = {3, 0, 0};
    mesh_translate(&lens, away);
    mesh_append(&sphere, &lens);
    s = make_surface(&sphere, 0);
    int32_t *component = malloc(sizeof(int32_t) * (size_t)sphere.nverts);
    assert_int_equal(sfa_get_components(s, sphere.nverts, component), SFA_OK);
    const int32_t of_sphere = component[0], of_lens = component[sphere.nverts - 1];
    double value = -1;
    assert_int_equal(sfa_measure_component(s, of_sphere, SFA_MEASURE_UNRESOLVED_AREA, &value), SFA_OK);
    assert_true(value == 0);
    assert_int_equal(sfa_measure_component(s, of_lens, SFA_MEASURE_UNRESOLVED_AREA, &value), SFA_OK);
    assert_near(value, rim, 1e-12);
    const double whole = measure(s, SFA_MEASURE_UNRESOLVED_AREA);
    assert_true(whole > 0 && whole < rim);
    free(component);
    sfa_destroy(s);
    mesh_free(&lens);
    mesh_free(&sphere);
}

static void bad_arguments_and_state(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    double v = 77;
    const int unknown[] = {-1, SFA_MEASURE_MIN_ANGLE_RESOLVED + 1, 1000, INT32_MIN};
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; ++i) {
        assert_error(s, sfa_measure(s, unknown[i], &v), SFA_ERR_ARGUMENT, "");
        assert_true(v == 77);
    }
    assert_error(s, sfa_measure(s, SFA_MEASURE_VOLUME, NULL), SFA_ERR_ARGUMENT, "");
    assert_int_equal(sfa_measure(NULL, SFA_MEASURE_VOLUME, &v), SFA_ERR_ARGUMENT);
    sfa_destroy(s);

    assert_int_equal(sfa_create(&s), SFA_OK);
    for (int q = SFA_MEASURE_VOLUME; q <= SFA_MEASURE_SELF_INTERSECTIONS; ++q) {
        if (q >= SFA_MEASURE_SECONDS_ANALYSIS && q <= SFA_MEASURE_SECONDS_REPAIR)
            continue; /* the phase clocks need no mesh */
        assert_error(s, sfa_measure(s, q, &v), SFA_ERR_STATE, "");
        assert_true(v == 77);
    }
    sfa_destroy(s);
}

static double phase_seconds(const sfa_surface *s)
{
    double total = 0;
    for (int q = SFA_MEASURE_SECONDS_ANALYSIS; q <= SFA_MEASURE_SECONDS_REPAIR; ++q) {
        double seconds = -1;
        assert_int_equal(sfa_measure(s, q, &seconds), SFA_OK);
        assert_true(seconds >= 0);
        total += seconds;
    }
    return total;
}

// The phase clocks start at zero, need no mesh, and grow with every successful call.
static void phase_seconds_accumulate(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    assert_true(phase_seconds(s) == 0);
    sfa_destroy(s);

    sfa_mesh_data sphere = shape_icosphere(3, 1.0);
    s = make_surface(&sphere, 0);
    mesh_free(&sphere);
    double repair = 0, analysis = 0;
    assert_int_equal(sfa_smooth(s, 2), SFA_OK);
    assert_int_equal(sfa_measure(s, SFA_MEASURE_SECONDS_REPAIR, &repair), SFA_OK);
    assert_true(repair == 0); // smoothing repairs nothing
    const double after_smooth = phase_seconds(s);
    assert_true(after_smooth > 0);
    assert_int_equal(sfa_adapt(s), SFA_OK);
    assert_int_equal(sfa_measure(s, SFA_MEASURE_SECONDS_REPAIR, &repair), SFA_OK);
    assert_int_equal(sfa_measure(s, SFA_MEASURE_SECONDS_ANALYSIS, &analysis), SFA_OK);
    assert_true(repair > 0 && analysis > 0);
    assert_true(phase_seconds(s) > after_smooth);
    sfa_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(unit_cube),
        cmocka_unit_test(icosahedron),
        cmocka_unit_test(translated_cube),
        cmocka_unit_test(reversed_cube),
        cmocka_unit_test(icosphere_matches_tetrahedra),
        cmocka_unit_test(geodesic_spheres_are_valid_at_any_frequency),
        cmocka_unit_test(open_flat_patch),
        cmocka_unit_test(folded_patch_turns_by_almost_180_degrees),
        cmocka_unit_test(a_cusp_is_no_self_intersection_but_an_overlap_is),
        cmocka_unit_test(overlapping_spheres_intersect),
        cmocka_unit_test(unresolved_area_is_where_the_surface_turns_within_a_triangle),
        cmocka_unit_test(bad_arguments_and_state),
        cmocka_unit_test(phase_seconds_accumulate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* SPDX-License-Identifier: BSD-3-Clause */
/* Parameters: defaults (the paper's), round trips, range checks, their bounds, survival across meshes. */
#include "support/testing.h"

static const double pi = 3.14159265358979323846;

/* The default of every key, in key order. */
static double expected_default(int key)
{
    switch (key) {
    case SFA_PARAM_EDGE_LENGTH: return 0;
    case SFA_PARAM_ANISOTROPIC: return 1;
    case SFA_PARAM_RIDGE_ANGLE: return 45;
    case SFA_PARAM_CORNER_ANGLE: return 20;
    case SFA_PARAM_METRIC_MIN_ANGLE: return 8;
    case SFA_PARAM_METRIC_MAX_ANGLE: return 30;
    case SFA_PARAM_SPLIT_LENGTH_RATIO: return 1.5;
    case SFA_PARAM_SPLIT_SHORTEST_RATIO: return tan(4 * pi / 180) / tan(15 * pi / 180);
    case SFA_PARAM_CONTRACT_LENGTH_RATIO: return 0.5;
    case SFA_PARAM_CONTRACT_SHORT_RATIO: return 0.1;
    case SFA_PARAM_CONTRACT_SMALL_RATIO: return 0.5;
    case SFA_PARAM_SMALL_ANGLE: return 15;
    case SFA_PARAM_LARGE_ANGLE: return 160;
    case SFA_PARAM_FOLD_SAFETY: return 0.5;
    case SFA_PARAM_DROP_UNREFERENCED: return 0;
    case SFA_PARAM_RIDGE_TURN_ANGLE: return 40;
    case SFA_PARAM_FLIP_DIHEDRAL_ANGLE: return 20;
    case SFA_PARAM_THREADS: return 0;
    case SFA_PARAM_DENOISE: return 0;
    case SFA_PARAM_ADAPT_PASSES: return 8;
    case SFA_PARAM_CROSSING_GUARD: return 1;
    case SFA_PARAM_COLLISION_SAFE_MOTION: return 0;
    case SFA_PARAM_TOPOLOGY_CHANGE: return 0;
    case SFA_PARAM_MERGE_DISTANCE: return 0.5;
    case SFA_PARAM_THIN_SHEET_EDGE_RATIO: return 1;
    case SFA_PARAM_VOLUME_CORRECTION: return 1;
    case SFA_PARAM_SIZE_GRADATION: return 1.5;
    case SFA_PARAM_SHORT_EDGE_RATIO: return 0.6;
    default: return NAN;
    }
}

/* A value inside the documented range of each key, different from the default. */
static double valid_value(int key)
{
    switch (key) {
    case SFA_PARAM_EDGE_LENGTH: return 0.125;
    case SFA_PARAM_ANISOTROPIC: return 0;
    case SFA_PARAM_RIDGE_ANGLE: return 30;
    case SFA_PARAM_CORNER_ANGLE: return 10;
    case SFA_PARAM_METRIC_MIN_ANGLE: return 6;
    case SFA_PARAM_METRIC_MAX_ANGLE: return 40;
    case SFA_PARAM_SPLIT_LENGTH_RATIO: return 1.25;
    case SFA_PARAM_SPLIT_SHORTEST_RATIO: return 0.3;
    case SFA_PARAM_CONTRACT_LENGTH_RATIO: return 0.4;
    case SFA_PARAM_CONTRACT_SHORT_RATIO: return 0.2;
    case SFA_PARAM_CONTRACT_SMALL_RATIO: return 0.25;
    case SFA_PARAM_SMALL_ANGLE: return 20;
    case SFA_PARAM_LARGE_ANGLE: return 150;
    case SFA_PARAM_FOLD_SAFETY: return 1;
    case SFA_PARAM_DROP_UNREFERENCED: return 1;
    case SFA_PARAM_RIDGE_TURN_ANGLE: return 60;
    case SFA_PARAM_FLIP_DIHEDRAL_ANGLE: return 10;
    case SFA_PARAM_THREADS: return 1;
    case SFA_PARAM_DENOISE: return 1;
    case SFA_PARAM_ADAPT_PASSES: return 1;
    case SFA_PARAM_CROSSING_GUARD: return 0;
    case SFA_PARAM_COLLISION_SAFE_MOTION: return 1;
    case SFA_PARAM_TOPOLOGY_CHANGE: return 1;
    case SFA_PARAM_MERGE_DISTANCE: return 10;
    case SFA_PARAM_THIN_SHEET_EDGE_RATIO: return 1;
    case SFA_PARAM_VOLUME_CORRECTION: return 0;
    case SFA_PARAM_SIZE_GRADATION: return 3;
    case SFA_PARAM_SHORT_EDGE_RATIO: return 0;
    default: return NAN;
    }
}

/* Values outside each key's documented range (NaN and infinities are tried for all). */
static int invalid_values(int key, double out[4])
{
    switch (key) {
    case SFA_PARAM_EDGE_LENGTH: out[0] = -1e-300; out[1] = -1; return 2;
    case SFA_PARAM_ANISOTROPIC: out[0] = 0.5; out[1] = 2; out[2] = -1; return 3;
    case SFA_PARAM_RIDGE_ANGLE:
    case SFA_PARAM_CORNER_ANGLE:
    case SFA_PARAM_METRIC_MIN_ANGLE:
    case SFA_PARAM_METRIC_MAX_ANGLE:
    case SFA_PARAM_RIDGE_TURN_ANGLE:
    case SFA_PARAM_FLIP_DIHEDRAL_ANGLE: out[0] = 0; out[1] = 180; out[2] = -10; out[3] = 200; return 4;
    case SFA_PARAM_SPLIT_LENGTH_RATIO:
    case SFA_PARAM_SPLIT_SHORTEST_RATIO:
    case SFA_PARAM_CONTRACT_LENGTH_RATIO: out[0] = 0; out[1] = -0.5; return 2;
    case SFA_PARAM_CONTRACT_SHORT_RATIO:
    case SFA_PARAM_CONTRACT_SMALL_RATIO: out[0] = 0; out[1] = 1; out[2] = -0.1; out[3] = 1.5; return 4;
    case SFA_PARAM_SMALL_ANGLE: out[0] = 0; out[1] = 60.5; out[2] = -1; return 3;
    case SFA_PARAM_LARGE_ANGLE: out[0] = 59.5; out[1] = 180; out[2] = 200; return 3;
    case SFA_PARAM_FOLD_SAFETY: out[0] = 0; out[1] = 1.0000001; out[2] = -0.5; return 3;
    case SFA_PARAM_DROP_UNREFERENCED: out[0] = 0.5; out[1] = 2; out[2] = -1; return 3;
    case SFA_PARAM_THREADS: out[0] = -1; out[1] = 1.5; out[2] = 5000; return 3;
    case SFA_PARAM_DENOISE: out[0] = -1e-9; out[1] = 1.0000001; return 2;
    case SFA_PARAM_ADAPT_PASSES: out[0] = 0; out[1] = 2.5; out[2] = 101; return 3;
    case SFA_PARAM_CROSSING_GUARD: out[0] = 0.5; out[1] = 2; out[2] = -1; return 3;
    case SFA_PARAM_COLLISION_SAFE_MOTION: out[0] = 0.5; out[1] = 2; out[2] = -1; return 3;
    case SFA_PARAM_TOPOLOGY_CHANGE: out[0] = 0.5; out[1] = 2; out[2] = -1; return 3;
    case SFA_PARAM_MERGE_DISTANCE: out[0] = 0; out[1] = 10.000001; out[2] = -0.5; return 3;
    case SFA_PARAM_THIN_SHEET_EDGE_RATIO: out[0] = 0; out[1] = 1.000001; out[2] = -0.5; return 3;
    case SFA_PARAM_VOLUME_CORRECTION: out[0] = 0.5; out[1] = 2; out[2] = -1; return 3;
    case SFA_PARAM_SIZE_GRADATION: out[0] = 1; out[1] = 0.5; out[2] = -2; return 3;
    case SFA_PARAM_SHORT_EDGE_RATIO: out[0] = 1; out[1] = -0.1; out[2] = 1.5; return 3;
    default: return 0;
    }
}

/* The documented range of each key: its ends and whether each end is itself accepted. */
typedef struct documented_range {
    double lowest, highest;
    int lowest_accepted, highest_accepted;
} documented_range;

static documented_range range_of(int key)
{
    switch (key) {
    case SFA_PARAM_EDGE_LENGTH: return (documented_range){0, INFINITY, 1, 0};
    case SFA_PARAM_ANISOTROPIC:
    case SFA_PARAM_DROP_UNREFERENCED:
    case SFA_PARAM_CROSSING_GUARD: return (documented_range){0, 1, 1, 1};
    case SFA_PARAM_COLLISION_SAFE_MOTION: return (documented_range){0, 1, 1, 1};
    case SFA_PARAM_TOPOLOGY_CHANGE: return (documented_range){0, 1, 1, 1};
    case SFA_PARAM_MERGE_DISTANCE: return (documented_range){0, 10, 0, 1};
    case SFA_PARAM_THIN_SHEET_EDGE_RATIO: return (documented_range){0, 1, 0, 1};
    case SFA_PARAM_VOLUME_CORRECTION: return (documented_range){0, 1, 1, 1};
    case SFA_PARAM_SIZE_GRADATION: return (documented_range){1, INFINITY, 0, 0};
    case SFA_PARAM_SHORT_EDGE_RATIO: return (documented_range){0, 1, 1, 0};
    case SFA_PARAM_RIDGE_ANGLE:
    case SFA_PARAM_CORNER_ANGLE:
    case SFA_PARAM_METRIC_MIN_ANGLE:
    case SFA_PARAM_METRIC_MAX_ANGLE:
    case SFA_PARAM_RIDGE_TURN_ANGLE:
    case SFA_PARAM_FLIP_DIHEDRAL_ANGLE: return (documented_range){0, 180, 0, 0};
    case SFA_PARAM_SPLIT_LENGTH_RATIO:
    case SFA_PARAM_SPLIT_SHORTEST_RATIO:
    case SFA_PARAM_CONTRACT_LENGTH_RATIO: return (documented_range){0, INFINITY, 0, 0};
    case SFA_PARAM_CONTRACT_SHORT_RATIO:
    case SFA_PARAM_CONTRACT_SMALL_RATIO: return (documented_range){0, 1, 0, 0};
    case SFA_PARAM_SMALL_ANGLE: return (documented_range){0, 60, 0, 1};
    case SFA_PARAM_LARGE_ANGLE: return (documented_range){60, 180, 1, 0};
    case SFA_PARAM_FOLD_SAFETY: return (documented_range){0, 1, 0, 1};
    case SFA_PARAM_THREADS: return (documented_range){0, 4096, 1, 1};
    case SFA_PARAM_DENOISE: return (documented_range){0, 1, 1, 1};
    case SFA_PARAM_ADAPT_PASSES: return (documented_range){1, 100, 1, 1};
    default: return (documented_range){NAN, NAN, 0, 0};
    }
}

static void defaults(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    for (int key = 0; key < SHAPES_NPARAMS; ++key) {
        double v = NAN;
        assert_ok(s, sfa_get_param(s, key, &v));
        if (key == SFA_PARAM_SPLIT_SHORTEST_RATIO)
            assert_near(v, expected_default(key), 1e-12);
        else if (v != expected_default(key))
            fail_msg("parameter %d defaults to %.17g, expected %.17g", key, v, expected_default(key));
    }
    sfa_destroy(s);
}

static void round_trip(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    for (int key = 0; key < SHAPES_NPARAMS; ++key) {
        double v = NAN;
        assert_ok(s, sfa_set_param(s, key, valid_value(key)));
        assert_ok(s, sfa_get_param(s, key, &v));
        assert_memory_equal(&v, &(double){valid_value(key)}, sizeof v);
    }
    /* The others did not move when one was set. */
    for (int key = 0; key < SHAPES_NPARAMS; ++key) {
        double v = NAN;
        assert_int_equal(sfa_get_param(s, key, &v), SFA_OK);
        assert_true(v == valid_value(key));
    }
    /* Documented range ends that are included. */
    assert_ok(s, sfa_set_param(s, SFA_PARAM_SMALL_ANGLE, 60));
    assert_ok(s, sfa_set_param(s, SFA_PARAM_LARGE_ANGLE, 60));
    assert_ok(s, sfa_set_param(s, SFA_PARAM_FOLD_SAFETY, 1));
    assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0));
    /* Open angle ranges: just inside both ends. */
    assert_ok(s, sfa_set_param(s, SFA_PARAM_RIDGE_TURN_ANGLE, 1e-9));
    assert_ok(s, sfa_set_param(s, SFA_PARAM_RIDGE_TURN_ANGLE, 179.999));
    sfa_destroy(s);
}

static void out_of_range_values_rejected(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    for (int key = 0; key < SHAPES_NPARAMS; ++key) {
        double bad[4 + 3];
        const int n = invalid_values(key, bad);
        bad[n] = NAN;
        bad[n + 1] = INFINITY;
        bad[n + 2] = -INFINITY;
        for (int i = 0; i < n + 3; ++i) {
            double before = NAN, after = NAN;
            assert_int_equal(sfa_get_param(s, key, &before), SFA_OK);
            const int rc = sfa_set_param(s, key, bad[i]);
            if (rc != SFA_ERR_ARGUMENT)
                fail_msg("parameter %d = %g: status %d, expected SFA_ERR_ARGUMENT", key, bad[i], rc);
            assert_true(strlen(sfa_last_error(s)) > 0);
            assert_int_equal(sfa_get_param(s, key, &after), SFA_OK);
            assert_memory_equal(&before, &after, sizeof before);
        }
    }
    sfa_destroy(s);
}

static void unknown_keys_rejected(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    snapshot before, after;
    snapshot_take(s, &before);
    const int keys[] = {-1, SHAPES_NPARAMS, SHAPES_NPARAMS + 1, 1000, INT32_MIN, INT32_MAX};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; ++i) {
        double v = 12345;
        assert_error(s, sfa_set_param(s, keys[i], 1.0), SFA_ERR_ARGUMENT, "");
        assert_error(s, sfa_get_param(s, keys[i], &v), SFA_ERR_ARGUMENT, "");
        assert_true(v == 12345);
    }
    snapshot_take(s, &after);
    assert_same_snapshot(&before, &after);
    snapshot_free(&before);
    snapshot_free(&after);
    sfa_destroy(s);
}

static void null_arguments(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    double v;
    assert_int_equal(sfa_set_param(NULL, SFA_PARAM_EDGE_LENGTH, 1), SFA_ERR_ARGUMENT);
    assert_int_equal(sfa_get_param(NULL, SFA_PARAM_EDGE_LENGTH, &v), SFA_ERR_ARGUMENT);
    assert_error(s, sfa_get_param(s, SFA_PARAM_EDGE_LENGTH, NULL), SFA_ERR_ARGUMENT, "");
    sfa_destroy(s);
}

static void kept_across_set_mesh(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    /* Set before any mesh, then two meshes in a row. */
    for (int key = 0; key < SHAPES_NPARAMS; ++key)
        if (key != SFA_PARAM_DROP_UNREFERENCED)
            assert_int_equal(sfa_set_param(s, key, valid_value(key)), SFA_OK);
    sfa_mesh_data cube = shape_unit_cube(), sphere = shape_icosphere(1, 3.0);
    assert_ok(s, sfa_set_mesh(s, cube.nverts, cube.xyz, cube.ntris, cube.tris, 0));
    assert_ok(s, sfa_set_mesh(s, sphere.nverts, sphere.xyz, sphere.ntris, sphere.tris, 0));
    for (int key = 0; key < SHAPES_NPARAMS; ++key) {
        double v = NAN;
        assert_int_equal(sfa_get_param(s, key, &v), SFA_OK);
        assert_true(v == (key == SFA_PARAM_DROP_UNREFERENCED ? 0 : valid_value(key)));
    }
    /* EDGE_LENGTH 0 stays 0 (it means "the mean edge length", not a stored number). */
    assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0), SFA_OK);
    assert_ok(s, sfa_set_mesh(s, cube.nverts, cube.xyz, cube.ntris, cube.tris, 0));
    double l = -1;
    assert_int_equal(sfa_get_param(s, SFA_PARAM_EDGE_LENGTH, &l), SFA_OK);
    assert_true(l == 0);
    mesh_free(&cube);
    mesh_free(&sphere);
    sfa_destroy(s);
}

static void bounds_are_the_ends_of_the_documented_range(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    for (int key = 0; key < SHAPES_NPARAMS; ++key) {
        const documented_range want = range_of(key);
        double lowest = NAN, highest = NAN;
        assert_int_equal(sfa_get_param_bounds(key, &lowest, &highest), SFA_OK);
        if (lowest != want.lowest || highest != want.highest)
            fail_msg("parameter %d: bounds [%.17g, %.17g], documented [%.17g, %.17g]", key, lowest, highest,
                     want.lowest, want.highest);
        /* Each end is accepted exactly where the documentation has a bracket, and nothing
           beyond the ends is. */
        if ((sfa_set_param(s, key, lowest) == SFA_OK) != want.lowest_accepted)
            fail_msg("parameter %d: sfa_set_param(lowest = %g) disagrees with the documented range", key, lowest);
        assert_int_equal(sfa_set_param(s, key, nextafter(lowest, -INFINITY)), SFA_ERR_ARGUMENT);
        if (isfinite(highest)) {
            if ((sfa_set_param(s, key, highest) == SFA_OK) != want.highest_accepted)
                fail_msg("parameter %d: sfa_set_param(highest = %g) disagrees with the documented range", key,
                         highest);
            assert_int_equal(sfa_set_param(s, key, nextafter(highest, INFINITY)), SFA_ERR_ARGUMENT);
        }
        /* The default lies within the bounds. */
        sfa_surface *fresh = NULL;
        double v = NAN;
        assert_int_equal(sfa_create(&fresh), SFA_OK);
        assert_int_equal(sfa_get_param(fresh, key, &v), SFA_OK);
        assert_true(v >= lowest && v <= highest);
        sfa_destroy(fresh);
    }
    sfa_destroy(s);
}

static void bounds_of_unknown_keys_and_null_pointers(void **state)
{
    (void)state;
    const int keys[] = {-1, SHAPES_NPARAMS, SHAPES_NPARAMS + 1, 1000, INT32_MIN, INT32_MAX};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; ++i) {
        double lowest = 12345, highest = 54321;
        assert_int_equal(sfa_get_param_bounds(keys[i], &lowest, &highest), SFA_ERR_ARGUMENT);
        /* Nothing written on failure. */
        assert_true(lowest == 12345 && highest == 54321);
    }
    double end = 12345;
    assert_int_equal(sfa_get_param_bounds(SFA_PARAM_RIDGE_ANGLE, NULL, &end), SFA_ERR_ARGUMENT);
    assert_true(end == 12345);
    assert_int_equal(sfa_get_param_bounds(SFA_PARAM_RIDGE_ANGLE, &end, NULL), SFA_ERR_ARGUMENT);
    assert_true(end == 12345);
    assert_int_equal(sfa_get_param_bounds(SFA_PARAM_RIDGE_ANGLE, NULL, NULL), SFA_ERR_ARGUMENT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(defaults),
        cmocka_unit_test(round_trip),
        cmocka_unit_test(out_of_range_values_rejected),
        cmocka_unit_test(unknown_keys_rejected),
        cmocka_unit_test(null_arguments),
        cmocka_unit_test(kept_across_set_mesh),
        cmocka_unit_test(bounds_are_the_ends_of_the_documented_range),
        cmocka_unit_test(bounds_of_unknown_keys_and_null_pointers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

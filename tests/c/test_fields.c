/* SPDX-License-Identifier: BSD-3-Clause */
/* Vertex fields: attach, read back, replace, bad input, and what other calls do to them. */
#include "support/testing.h"

#define SENTINEL_BYTE 0x5A

static void values_for(int32_t nverts, int32_t ncomp, double seed, double *out)
{
    for (int32_t i = 0; i < nverts * ncomp; ++i)
        out[i] = seed + 0.1 * i - 1.0 / (i + 3);
}

static void round_trip_and_ids(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    double scalar[8], vector[24], back[24];
    values_for(8, 1, 1.5, scalar);
    values_for(8, 3, -7.25, vector);
    int32_t id = -1;
    assert_ok(s, sfa_add_field(s, 1, scalar, &id));
    assert_int_equal(id, 0);
    assert_ok(s, sfa_add_field(s, 3, vector, &id));
    assert_int_equal(id, 1);
    assert_ok(s, sfa_add_field(s, 1, scalar, &id));
    assert_int_equal(id, 2);
    assert_ok(s, sfa_get_field(s, 0, 8, back));
    assert_memory_equal(back, scalar, sizeof scalar);
    assert_ok(s, sfa_get_field(s, 1, 24, back));
    assert_memory_equal(back, vector, sizeof vector);
    assert_ok(s, sfa_get_field(s, 2, 24, back)); /* more room than needed is fine */
    assert_memory_equal(back, scalar, sizeof scalar);
    sfa_destroy(s);
}

static void capacity_too_small_writes_nothing(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    double vector[24], back[25];
    values_for(8, 3, 2, vector);
    int32_t id = -1;
    assert_int_equal(sfa_add_field(s, 3, vector, &id), SFA_OK);
    const int32_t caps[] = {23, 8, 0, -1};
    for (size_t i = 0; i < sizeof caps / sizeof caps[0]; ++i) {
        memset(back, SENTINEL_BYTE, sizeof back);
        assert_error(s, sfa_get_field(s, id, caps[i], back), SFA_ERR_ARGUMENT, "");
        for (size_t b = 0; b < sizeof back; ++b)
            assert_int_equal(((unsigned char *)back)[b], SENTINEL_BYTE);
    }
    /* Exactly enough writes exactly that much. */
    memset(back, SENTINEL_BYTE, sizeof back);
    assert_ok(s, sfa_get_field(s, id, 24, back));
    assert_memory_equal(back, vector, sizeof vector);
    for (size_t b = sizeof vector; b < sizeof back; ++b)
        assert_int_equal(((unsigned char *)back)[b], SENTINEL_BYTE);
    sfa_destroy(s);
}

static void unknown_ids(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    double values[8], back[64];
    values_for(8, 1, 0, values);
    int32_t id = -1;
    assert_int_equal(sfa_add_field(s, 1, values, &id), SFA_OK);
    const int32_t ids[] = {-1, 1, 2, 100, INT32_MAX, INT32_MIN};
    for (size_t i = 0; i < sizeof ids / sizeof ids[0]; ++i) {
        memset(back, SENTINEL_BYTE, sizeof back);
        assert_error(s, sfa_get_field(s, ids[i], 64, back), SFA_ERR_ARGUMENT, "");
        for (size_t b = 0; b < sizeof back; ++b)
            assert_int_equal(((unsigned char *)back)[b], SENTINEL_BYTE);
    }
    sfa_destroy(s);
}

static void bad_arguments(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    double values[24], back[24];
    values_for(8, 3, 0, values);
    int32_t id = 99;
    snapshot before, after;
    snapshot_take(s, &before);
    assert_int_equal(sfa_add_field(NULL, 1, values, &id), SFA_ERR_ARGUMENT);
    assert_error(s, sfa_add_field(s, 1, NULL, &id), SFA_ERR_ARGUMENT, "");
    assert_error(s, sfa_add_field(s, 1, values, NULL), SFA_ERR_ARGUMENT, "");
    assert_error(s, sfa_add_field(s, 0, values, &id), SFA_ERR_ARGUMENT, "");
    assert_error(s, sfa_add_field(s, -3, values, &id), SFA_ERR_ARGUMENT, "");
    assert_int_equal(id, 99);
    snapshot_take(s, &after);
    assert_same_snapshot(&before, &after);
    assert_int_equal(sfa_add_field(s, 1, values, &id), SFA_OK);
    assert_int_equal(id, 0); /* the failed calls used up no id */
    assert_int_equal(sfa_get_field(NULL, 0, 24, back), SFA_ERR_ARGUMENT);
    assert_error(s, sfa_get_field(s, 0, 24, NULL), SFA_ERR_ARGUMENT, "");
    snapshot_free(&before);
    snapshot_free(&after);
    sfa_destroy(s);
}

static void non_finite_value_rejected(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    const double nonfinite[] = {NAN, INFINITY, -INFINITY};
    for (int32_t base = 0; base <= 1; ++base)
        for (int k = 0; k < 3; ++k) {
            sfa_surface *s = make_surface(&cube, base);
            double first[8], values[24];
            values_for(8, 1, 3, first);
            int32_t id = -1;
            assert_int_equal(sfa_add_field(s, 1, first, &id), SFA_OK);
            snapshot before, after;
            snapshot_take(s, &before);
            values_for(8, 3, 0, values);
            values[3 * 6 + 2] = nonfinite[k]; /* vertex 6, third component */
            id = 99;
            assert_error(s, sfa_add_field(s, 3, values, &id), SFA_ERR_NUMERIC, base ? "vertex 7" : "vertex 6",
                         "non-finite");
            assert_int_equal(id, 99);
            snapshot_take(s, &after);
            assert_same_snapshot(&before, &after);
            assert_int_equal(sfa_add_field(s, 1, first, &id), SFA_OK);
            assert_int_equal(id, 1);
            snapshot_free(&before);
            snapshot_free(&after);
            sfa_destroy(s);
        }
    mesh_free(&cube);
}

static void no_mesh_is_state_error(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    double values[8] = {0};
    int32_t id = 99;
    assert_error(s, sfa_add_field(s, 1, values, &id), SFA_ERR_STATE, "");
    assert_int_equal(id, 99);
    assert_error(s, sfa_get_field(s, 0, 8, values), SFA_ERR_STATE, "");
    sfa_destroy(s);
}

static void dropped_by_set_mesh(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    double values[8], back[8];
    values_for(8, 1, 0, values);
    int32_t id = -1;
    assert_int_equal(sfa_add_field(s, 1, values, &id), SFA_OK);
    assert_int_equal(sfa_add_field(s, 1, values, &id), SFA_OK);
    sfa_mesh_data cube = shape_unit_cube();
    assert_ok(s, sfa_set_mesh(s, 8, cube.xyz, 12, cube.tris, 0));
    assert_error(s, sfa_get_field(s, 0, 8, back), SFA_ERR_ARGUMENT, "");
    assert_error(s, sfa_get_field(s, 1, 8, back), SFA_ERR_ARGUMENT, "");
    /* Numbering starts again for the new mesh. */
    assert_int_equal(sfa_add_field(s, 1, values, &id), SFA_OK);
    assert_int_equal(id, 0);
    mesh_free(&cube);
    sfa_destroy(s);
}

static void unchanged_by_motion(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_icosphere(2, 1.0);
    sfa_surface *s = make_surface(&sphere, 0);
    const int32_t n = sphere.nverts;
    double *values = malloc(sizeof(double) * 2 * (size_t)n), *back = malloc(sizeof(double) * 2 * (size_t)n),
           *vel = malloc(sizeof(double) * 3 * (size_t)n);
    assert_non_null(values);
    assert_non_null(back);
    assert_non_null(vel);
    values_for(n, 2, 4, values);
    for (int32_t i = 0; i < 3 * n; ++i)
        vel[i] = 0.1 * sphere.xyz[i]; /* uniform expansion */
    int32_t id = -1;
    assert_int_equal(sfa_add_field(s, 2, values, &id), SFA_OK);
    assert_int_equal(sfa_set_velocities(s, vel), SFA_OK);
    double taken = 0;
    assert_ok(s, sfa_move(s, 0.5, &taken));
    assert_true(taken == 0.5);
    assert_ok(s, sfa_get_field(s, id, 2 * n, back));
    assert_memory_equal(back, values, sizeof(double) * 2 * (size_t)n);
    free(values);
    free(back);
    free(vel);
    sfa_destroy(s);
    mesh_free(&sphere);
}

/* sfa_set_field: a host replaces a field's values after it has advanced them over a step.
 * The new values are what it reads back and what sfa_adapt() carries: a constant set
 * over a field that held something else stays that constant at every vertex a refinement
 * makes. */
static void set_field_replaces_what_is_carried(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_icosphere(2, 1.0);
    sfa_surface *s = make_surface(&sphere, 0);
    int32_t n = sphere.nverts;
    double *values = malloc(sizeof(double) * 2 * (size_t)n), *back = malloc(sizeof(double) * 2 * (size_t)n);
    assert_non_null(values);
    assert_non_null(back);
    values_for(n, 2, 4, values);
    int32_t id = -1;
    assert_ok(s, sfa_add_field(s, 2, values, &id));
    for (int32_t v = 0; v < n; ++v) {
        values[2 * v] = 7;
        values[2 * v + 1] = -3;
    }
    assert_ok(s, sfa_set_field(s, id, n, values));
    assert_ok(s, sfa_get_field(s, id, 2 * n, back));
    assert_memory_equal(back, values, sizeof(double) * 2 * (size_t)n);

    assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.1));
    assert_ok(s, sfa_adapt(s));
    int32_t after = 0;
    assert_ok(s, sfa_get_counts(s, &after, NULL));
    assert_true(after > 2 * n);
    back = realloc(back, sizeof(double) * 2 * (size_t)after);
    assert_non_null(back);
    assert_ok(s, sfa_get_field(s, id, 2 * after, back));
    for (int32_t v = 0; v < after; ++v)
        if (!(fabs(back[2 * v] - 7) <= 1e-12 && fabs(back[2 * v + 1] + 3) <= 1e-12))
            fail_msg("vertex %d carries (%.17g, %.17g), not (7, -3)", (int)v, back[2 * v], back[2 * v + 1]);
    free(values);
    free(back);
    sfa_destroy(s);
    mesh_free(&sphere);
}

/* A bad replacement names what is wrong and changes nothing, the field included. */
static void bad_set_field_changes_nothing(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    sfa_surface *s = make_surface(&cube, 1);
    double values[24];
    values_for(8, 3, 2, values);
    int32_t id = -1;
    assert_ok(s, sfa_add_field(s, 3, values, &id));
    values_for(8, 3, -1, values);
    values[3 * 5 + 1] = NAN;
    expect_unchanged(s, sfa_set_field(s, id, 8, values), SFA_ERR_NUMERIC, "vertex 6", "non-finite");
    values[3 * 5 + 1] = 0;
    expect_unchanged(s, sfa_set_field(s, id, 7, values), SFA_ERR_ARGUMENT,
                     "the mesh has 8 vertices since the last sfa_set_mesh", "the array given has 7");
    expect_unchanged(s, sfa_set_field(s, id + 1, 8, values), SFA_ERR_ARGUMENT, "unknown field id 1");
    expect_unchanged(s, sfa_set_field(s, -1, 8, values), SFA_ERR_ARGUMENT, "unknown field id -1");
    expect_unchanged(s, sfa_set_field(s, id, 8, NULL), SFA_ERR_ARGUMENT, "values is NULL");
    assert_int_equal(sfa_set_field(NULL, id, 8, values), SFA_ERR_ARGUMENT);
    sfa_destroy(s);
    mesh_free(&cube);

    assert_int_equal(sfa_create(&s), SFA_OK);
    assert_error(s, sfa_set_field(s, 0, 8, values), SFA_ERR_STATE, "no mesh");
    sfa_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(round_trip_and_ids),
        cmocka_unit_test(capacity_too_small_writes_nothing),
        cmocka_unit_test(unknown_ids),
        cmocka_unit_test(bad_arguments),
        cmocka_unit_test(non_finite_value_rejected),
        cmocka_unit_test(no_mesh_is_state_error),
        cmocka_unit_test(dropped_by_set_mesh),
        cmocka_unit_test(unchanged_by_motion),
        cmocka_unit_test(set_field_replaces_what_is_carried),
        cmocka_unit_test(bad_set_field_changes_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

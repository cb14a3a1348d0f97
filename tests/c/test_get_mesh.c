/* SPDX-License-Identifier: BSD-3-Clause */
/* sfa_get_counts and sfa_get_mesh: capacities, bases, state. */
#include "support/testing.h"

#define SENTINEL_BYTE 0x5A

static void counts_without_mesh(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    int32_t nv = -1, nt = -1;
    assert_ok(s, sfa_get_counts(s, &nv, &nt));
    assert_int_equal(nv, 0);
    assert_int_equal(nt, 0);
    /* Either output may be left out. */
    assert_int_equal(sfa_get_counts(s, NULL, &nt), SFA_OK);
    assert_int_equal(sfa_get_counts(s, &nv, NULL), SFA_OK);
    assert_int_equal(sfa_get_counts(s, NULL, NULL), SFA_OK);
    assert_int_equal(sfa_get_counts(NULL, &nv, &nt), SFA_ERR_ARGUMENT);
    sfa_destroy(s);
}

static void counts_with_mesh(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_icosphere(2, 1.0);
    sfa_surface *s = make_surface(&sphere, 0);
    int32_t nv = -1, nt = -1;
    assert_ok(s, sfa_get_counts(s, &nv, &nt));
    assert_int_equal(nv, 162);
    assert_int_equal(nt, 320);
    nv = -1;
    assert_int_equal(sfa_get_counts(s, &nv, NULL), SFA_OK);
    assert_int_equal(nv, 162);
    nt = -1;
    assert_int_equal(sfa_get_counts(s, NULL, &nt), SFA_OK);
    assert_int_equal(nt, 320);
    sfa_destroy(s);
    mesh_free(&sphere);
}

static void mesh_without_mesh_is_state_error(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    double xyz[24];
    int32_t tris[36];
    memset(xyz, SENTINEL_BYTE, sizeof xyz);
    memset(tris, SENTINEL_BYTE, sizeof tris);
    assert_error(s, sfa_get_mesh(s, 8, xyz, 12, tris, 0), SFA_ERR_STATE, "");
    for (size_t i = 0; i < sizeof xyz; ++i)
        assert_int_equal(((unsigned char *)xyz)[i], SENTINEL_BYTE);
    for (size_t i = 0; i < sizeof tris; ++i)
        assert_int_equal(((unsigned char *)tris)[i], SENTINEL_BYTE);
    sfa_destroy(s);
}

/* Calls sfa_get_mesh with the given capacities on buffers one element larger than the
 * mesh, prefilled with a sentinel; returns the status and whether anything was written. */
static int get_into_sentinels(const sfa_surface *s, int32_t vcap, int32_t tcap, int32_t base, int *written)
{
    double xyz[3 * 9];
    int32_t tris[3 * 13];
    memset(xyz, SENTINEL_BYTE, sizeof xyz);
    memset(tris, SENTINEL_BYTE, sizeof tris);
    const int rc = sfa_get_mesh(s, vcap, xyz, tcap, tris, base);
    *written = 0;
    for (size_t i = 0; i < sizeof xyz; ++i)
        *written |= ((unsigned char *)xyz)[i] != SENTINEL_BYTE;
    for (size_t i = 0; i < sizeof tris; ++i)
        *written |= ((unsigned char *)tris)[i] != SENTINEL_BYTE;
    return rc;
}

static void capacity_too_small_writes_nothing(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    int written;
    assert_error(s, get_into_sentinels(s, 7, 12, 0, &written), SFA_ERR_ARGUMENT, "");
    assert_false(written);
    assert_error(s, get_into_sentinels(s, 8, 11, 0, &written), SFA_ERR_ARGUMENT, "");
    assert_false(written);
    assert_error(s, get_into_sentinels(s, 0, 0, 1, &written), SFA_ERR_ARGUMENT, "");
    assert_false(written);
    assert_error(s, get_into_sentinels(s, -1, -1, 0, &written), SFA_ERR_ARGUMENT, "");
    assert_false(written);
    /* Exactly enough, and more than enough, both work. */
    assert_ok(s, get_into_sentinels(s, 8, 12, 0, &written));
    assert_true(written);
    assert_ok(s, get_into_sentinels(s, 9, 13, 0, &written));
    sfa_destroy(s);
}

static void extra_capacity_is_left_alone(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    double xyz[3 * 9];
    int32_t tris[3 * 13];
    memset(xyz, SENTINEL_BYTE, sizeof xyz);
    memset(tris, SENTINEL_BYTE, sizeof tris);
    assert_ok(s, sfa_get_mesh(s, 9, xyz, 13, tris, 0));
    for (size_t i = 24 * sizeof(double); i < sizeof xyz; ++i)
        assert_int_equal(((unsigned char *)xyz)[i], SENTINEL_BYTE);
    for (size_t i = 36 * sizeof(int32_t); i < sizeof tris; ++i)
        assert_int_equal(((unsigned char *)tris)[i], SENTINEL_BYTE);
    sfa_destroy(s);
}

static void bad_arguments(void **state)
{
    (void)state;
    sfa_surface *s = make_cube_surface();
    double xyz[24];
    int32_t tris[36];
    assert_int_equal(sfa_get_mesh(NULL, 8, xyz, 12, tris, 0), SFA_ERR_ARGUMENT);
    assert_error(s, sfa_get_mesh(s, 8, NULL, 12, tris, 0), SFA_ERR_ARGUMENT, "");
    assert_error(s, sfa_get_mesh(s, 8, xyz, 12, NULL, 0), SFA_ERR_ARGUMENT, "");
    assert_error(s, sfa_get_mesh(s, 8, xyz, 12, tris, 2), SFA_ERR_ARGUMENT, "");
    assert_error(s, sfa_get_mesh(s, 8, xyz, 12, tris, -1), SFA_ERR_ARGUMENT, "");
    sfa_destroy(s);
}

static void bases_differ_by_one(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    sfa_surface *s = make_surface(&cube, 1);
    double xyz0[24], xyz1[24];
    int32_t tris0[36], tris1[36];
    assert_ok(s, sfa_get_mesh(s, 8, xyz0, 12, tris0, 0));
    assert_ok(s, sfa_get_mesh(s, 8, xyz1, 12, tris1, 1));
    assert_memory_equal(xyz0, cube.xyz, sizeof xyz0);
    assert_memory_equal(xyz1, cube.xyz, sizeof xyz1);
    for (int i = 0; i < 36; ++i) {
        assert_int_equal(tris0[i], cube.tris[i]);
        assert_int_equal(tris1[i], cube.tris[i] + 1);
    }
    sfa_destroy(s);
    mesh_free(&cube);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(counts_without_mesh),
        cmocka_unit_test(counts_with_mesh),
        cmocka_unit_test(mesh_without_mesh_is_state_error),
        cmocka_unit_test(capacity_too_small_writes_nothing),
        cmocka_unit_test(extra_capacity_is_left_alone),
        cmocka_unit_test(bad_arguments),
        cmocka_unit_test(bases_differ_by_one),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

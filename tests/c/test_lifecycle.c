/* SPDX-License-Identifier: BSD-3-Clause */
/* Library identity, handle lifecycle, error strings and the plugin function table. */
#include "support/testing.h"

static void version_matches_macros(void **state)
{
    (void)state;
    char expected[64];
    snprintf(expected, sizeof expected, "%d.%d.%d", SFA_VERSION_MAJOR, SFA_VERSION_MINOR, SFA_VERSION_PATCH);
    assert_non_null(sfa_version_string());
    assert_string_equal(sfa_version_string(), expected);
    assert_string_equal(sfa_version_string(), "1.1.0");
    assert_int_equal(sfa_abi_version(), SFA_ABI_VERSION);
    assert_int_equal(sfa_abi_version(), 1);
}

static void version_number_is_the_version_string_as_one_number(void **state)
{
    (void)state;
    assert_int_equal(sfa_version_number(), SFA_VERSION_MAJOR * 10000 + SFA_VERSION_MINOR * 100 + SFA_VERSION_PATCH);
    int major = -1, minor = -1, patch = -1;
    assert_int_equal(sscanf(sfa_version_string(), "%d.%d.%d", &major, &minor, &patch), 3);
    assert_int_equal(sfa_version_number(), major * 10000 + minor * 100 + patch);
}

static void status_strings_never_null(void **state)
{
    (void)state;
    /* Every known code has its own description; unknown codes get one too. */
    for (int code = SFA_OK; code <= SFA_ERR_INTERNAL; ++code) {
        const char *text = sfa_status_string(code);
        assert_non_null(text);
        assert_true(strlen(text) > 0);
        for (int other = SFA_OK; other < code; ++other)
            assert_string_not_equal(text, sfa_status_string(other));
    }
    assert_non_null(strstr(sfa_status_string(SFA_ERR_MESH), "SFA_ERR_MESH"));
    const int unknown[] = {-1, 7, 42, 1000, INT32_MIN, INT32_MAX};
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; ++i) {
        assert_non_null(sfa_status_string(unknown[i]));
        assert_non_null(strstr(sfa_status_string(unknown[i]), "unknown"));
    }
}

static void create_and_destroy(void **state)
{
    (void)state;
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    assert_non_null(s);
    assert_string_equal(sfa_last_error(s), "");
    int32_t nv = -7, nt = -7;
    assert_int_equal(sfa_get_counts(s, &nv, &nt), SFA_OK);
    assert_int_equal(nv, 0);
    assert_int_equal(nt, 0);
    sfa_destroy(s);

    /* Many handles at once are independent. */
    sfa_surface *many[16];
    for (int i = 0; i < 16; ++i)
        assert_int_equal(sfa_create(&many[i]), SFA_OK);
    for (int i = 0; i < 16; ++i)
        for (int j = 0; j < i; ++j)
            assert_ptr_not_equal(many[i], many[j]);
    for (int i = 0; i < 16; ++i)
        sfa_destroy(many[i]);
}

static void destroy_null_is_a_noop(void **state)
{
    (void)state;
    sfa_destroy(NULL);
}

static void create_null_out(void **state)
{
    (void)state;
    assert_int_equal(sfa_create(NULL), SFA_ERR_ARGUMENT);
}

static void last_error_lifecycle(void **state)
{
    (void)state;
    assert_non_null(sfa_last_error(NULL));
    sfa_surface *s = make_cube_surface();
    assert_string_equal(sfa_last_error(s), "");
    double v;
    assert_int_equal(sfa_get_param(s, 1000, &v), SFA_ERR_ARGUMENT);
    assert_true(strlen(sfa_last_error(s)) > 0);
    /* The next successful call clears it. */
    assert_int_equal(sfa_get_param(s, SFA_PARAM_EDGE_LENGTH, &v), SFA_OK);
    assert_string_equal(sfa_last_error(s), "");
    assert_int_equal(sfa_set_param(s, 1000, 1.0), SFA_ERR_ARGUMENT);
    assert_true(strlen(sfa_last_error(s)) > 0);
    assert_int_equal(sfa_measure(s, SFA_MEASURE_AREA, &v), SFA_OK);
    assert_string_equal(sfa_last_error(s), "");
    sfa_destroy(s);
}

static void api_table_is_complete(void **state)
{
    (void)state;
    const sfa_api *api = sfa_get_api(1);
    assert_non_null(api);
    assert_ptr_equal(sfa_get_api(SFA_ABI_VERSION), api);
    assert_int_equal(api->struct_size, sizeof(sfa_api));
    assert_int_equal(api->abi, 1);
    /* Each member is the exported function itself, in the header's order. */
    assert_true(api->version_string == sfa_version_string);
    assert_true(api->abi_version == sfa_abi_version);
    assert_true(api->status_string == sfa_status_string);
    assert_true(api->create == sfa_create);
    assert_true(api->destroy == sfa_destroy);
    assert_true(api->last_error == sfa_last_error);
    assert_true(api->set_mesh == sfa_set_mesh);
    assert_true(api->get_counts == sfa_get_counts);
    assert_true(api->get_mesh == sfa_get_mesh);
    assert_true(api->set_param == sfa_set_param);
    assert_true(api->get_param == sfa_get_param);
    assert_true(api->set_velocities == sfa_set_velocities);
    assert_true(api->move == sfa_move);
    assert_true(api->advect == sfa_advect);
    assert_true(api->smooth == sfa_smooth);
    assert_true(api->adapt == sfa_adapt);
    assert_true(api->get_feature_ranks == sfa_get_feature_ranks);
    assert_true(api->measure == sfa_measure);
    assert_true(api->add_field == sfa_add_field);
    assert_true(api->get_field == sfa_get_field);
    assert_true(api->get_vertex_frames == sfa_get_vertex_frames);
    assert_true(api->get_ridge_edges == sfa_get_ridge_edges);
    assert_true(api->get_param_bounds == sfa_get_param_bounds);
    assert_true(api->version_number == sfa_version_number);
    /* No member left NULL, whatever was added after the ones listed above. */
    const unsigned char *bytes = (const unsigned char *)api;
    for (size_t off = offsetof(sfa_api, version_string); off + sizeof(void (*)(void)) <= api->struct_size;
         off += sizeof(void (*)(void))) {
        void (*fn)(void);
        memcpy(&fn, bytes + off, sizeof fn);
        assert_true(fn != NULL);
    }
    /* The table works: a whole round through it. */
    sfa_surface *s = NULL;
    assert_int_equal(api->create(&s), SFA_OK);
    assert_string_equal(api->version_string(), "1.1.0");
    api->destroy(s);
}

static void api_other_versions_absent(void **state)
{
    (void)state;
    assert_null(sfa_get_api(0));
    assert_null(sfa_get_api(2));
    assert_null(sfa_get_api(UINT32_MAX));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(version_matches_macros),
        cmocka_unit_test(version_number_is_the_version_string_as_one_number),
        cmocka_unit_test(status_strings_never_null),
        cmocka_unit_test(create_and_destroy),
        cmocka_unit_test(destroy_null_is_a_noop),
        cmocka_unit_test(create_null_out),
        cmocka_unit_test(last_error_lifecycle),
        cmocka_unit_test(api_table_is_complete),
        cmocka_unit_test(api_other_versions_absent),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* SPDX-License-Identifier: BSD-3-Clause */
/* Argument and state checks of sfa_smooth and sfa_adapt. Smoothing a cube succeeds and
 * changes nothing: every vertex is a corner, and corners never move. Adapting it at its
 * own mean edge length changes nothing either: no edge is long enough to split, and
 * corners are never contracted. Bad metric angles are refused before anything changes.
 * (The operations themselves are tested in test_smooth.c and test_adapt.c.) */
#include "support/testing.h"

/* Calls `call` on a loaded cube and checks the outcome and that nothing changed. */
#define expect_on_cube(call, expected, ...)                                                                            \
    do {                                                                                                               \
        sfa_surface *s = make_cube_surface();                                                                          \
        double f_[8] = {1, 2, 3, 4, 5, 6, 7, 8};                                                                       \
        int32_t id_;                                                                                                   \
        assert_int_equal(sfa_add_field(s, 1, f_, &id_), SFA_OK);                                                       \
        expect_unchanged(s, call, expected, __VA_ARGS__);                                                              \
        sfa_destroy(s);                                                                                                \
    } while (0)

static void smooth(void **state)
{
    (void)state;
    assert_int_equal(sfa_smooth(NULL, 1), SFA_ERR_ARGUMENT);
    expect_on_cube(sfa_smooth(s, -1), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_smooth(s, INT32_MIN), SFA_ERR_ARGUMENT, "");
    sfa_surface *empty = NULL;
    assert_int_equal(sfa_create(&empty), SFA_OK);
    assert_error(empty, sfa_smooth(empty, 1), SFA_ERR_STATE, "");
    sfa_destroy(empty);
    expect_on_cube(sfa_smooth(s, 0), SFA_OK, "");
    expect_on_cube(sfa_smooth(s, 5), SFA_OK, "");
}

static void adapt(void **state)
{
    (void)state;
    assert_int_equal(sfa_adapt(NULL), SFA_ERR_ARGUMENT);
    sfa_surface *empty = NULL;
    assert_int_equal(sfa_create(&empty), SFA_OK);
    assert_error(empty, sfa_adapt(empty), SFA_ERR_STATE, "");
    sfa_destroy(empty);
    expect_on_cube(sfa_adapt(s), SFA_OK, "");
    sfa_surface *s = make_cube_surface();
    assert_int_equal(sfa_set_param(s, SFA_PARAM_METRIC_MIN_ANGLE, 40), SFA_OK);
    expect_unchanged(s, sfa_adapt(s), SFA_ERR_ARGUMENT, "SFA_PARAM_METRIC_MIN_ANGLE");
    sfa_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(smooth),
        cmocka_unit_test(adapt),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

/* SPDX-License-Identifier: BSD-3-Clause */
/* CMocka helpers for the C tests. Header-only (static inline) because the objects in
 * support/ are also linked into the benchmarks, which do not link CMocka. */
#ifndef SURFADAPT_TEST_TESTING_H
#define SURFADAPT_TEST_TESTING_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support/shapes.h"
#include "surfadapt.h"

/* A surface holding m (in index base `base`); fails the test if the library refuses it. */
static inline sfa_surface *make_surface(const sfa_mesh_data *m, int base)
{
    char err[512];
    sfa_surface *s = surface_from(m, base, err, sizeof err);
    if (!s)
        fail_msg("the library refused a generated mesh: %s", err);
    return s;
}

/* A surface holding the unit cube. */
static inline sfa_surface *make_cube_surface(void)
{
    sfa_mesh_data cube = shape_unit_cube();
    sfa_surface *s = make_surface(&cube, 0);
    mesh_free(&cube);
    return s;
}

static inline void assert_same_snapshot(const snapshot *before, const snapshot *after)
{
    char why[256];
    if (!snapshot_equal(before, after, why, sizeof why))
        fail_msg("the surface changed: %s", why);
}

/* Whether `text` contains `phrase` as whole numbers: a phrase ending (starting) in a digit
 * must not be followed (preceded) by another digit there ("vertex 5" is not found in
 * "vertex 51", "12" not in "112"). */
static inline int contains_phrase(const char *text, const char *phrase)
{
#define IS_DIGIT_(c) ((c) >= '0' && (c) <= '9')
    const size_t n = strlen(phrase);
    if (n == 0)
        return 1;
    for (const char *p = strstr(text, phrase); p; p = strstr(p + 1, phrase))
        if (!(IS_DIGIT_(phrase[n - 1]) && IS_DIGIT_(p[n])) && !(IS_DIGIT_(phrase[0]) && p > text && IS_DIGIT_(p[-1])))
            return 1;
    return 0;
#undef IS_DIGIT_
}

/* The status is `expected` and sfa_last_error() contains every one of the NULL-terminated
 * phrases (so a test asserts the stable parts of a message, not its wording). */
static inline void assert_error_(const sfa_surface *s, int rc, int expected, const char *const *phrases,
                                 const char *file, int line)
{
    const char *msg = sfa_last_error(s);
    if (!msg)
        fail_msg("%s:%d: sfa_last_error returned NULL", file, line);
    if (rc != expected)
        fail_msg("%s:%d: status %d (%s), expected %d (%s); message: \"%s\"", file, line, rc, sfa_status_string(rc),
                 expected, sfa_status_string(expected), msg);
    for (const char *const *p = phrases; *p; ++p)
        if (!contains_phrase(msg, *p))
            fail_msg("%s:%d: the message \"%s\" does not contain \"%s\"", file, line, msg, *p);
    if (expected != SFA_OK && msg[0] == '\0')
        fail_msg("%s:%d: status %d with an empty message", file, line, rc);
}
#define assert_error(s, rc, expected, ...)                                                                            \
    do {                                                                                                               \
        const char *const phrases_[] = {__VA_ARGS__, NULL};                                                            \
        assert_error_((s), (rc), (expected), phrases_, __FILE__, __LINE__);                                            \
    } while (0)

/* Runs `call` on the surface `s`, checks its status and message as assert_error does, and
 * that the surface (mesh, parameters, fields) is bit-for-bit as before. */
#define expect_unchanged(s, call, expected, ...)                                                                       \
    do {                                                                                                               \
        snapshot before_, after_;                                                                                      \
        snapshot_take((s), &before_);                                                                                  \
        const int rc_ = (call);                                                                                        \
        assert_error((s), rc_, (expected), __VA_ARGS__);                                                               \
        snapshot_take((s), &after_);                                                                                   \
        assert_same_snapshot(&before_, &after_);                                                                       \
        snapshot_free(&before_);                                                                                       \
        snapshot_free(&after_);                                                                                        \
    } while (0)

/* SFA_OK, and the message is then "". */
#define assert_ok(s, rc)                                                                                               \
    do {                                                                                                               \
        const int rc_ = (rc);                                                                                          \
        if (rc_ != SFA_OK)                                                                                             \
            fail_msg("%s:%d: status %d (%s): \"%s\"", __FILE__, __LINE__, rc_, sfa_status_string(rc_),                 \
                     sfa_last_error(s));                                                                               \
        assert_string_equal(sfa_last_error(s), "");                                                                    \
    } while (0)

/* |a - b| <= tol, with both values in the failure message. */
#define assert_near(a, b, tol)                                                                                         \
    do {                                                                                                               \
        const double a_ = (a), b_ = (b), t_ = (tol);                                                                   \
        if (!(fabs(a_ - b_) <= t_))                                                                                    \
            fail_msg("%s:%d: %s = %.17g, expected %.17g within %.3g (off by %.3g)", __FILE__, __LINE__, #a, a_, b_,     \
                     t_, a_ - b_);                                                                                     \
    } while (0)

/* Reads a real mesh from the data directory, or skips the test, saying why in one line, if
 * it is not there. */
static inline void read_data_or_skip(const char *name, sfa_mesh_data *m)
{
    char path[1024], err[1024];
    if (!data_file(name, path, sizeof path)) {
        print_data_skip(path);
        skip();
    }
    if (mesh_read(path, m, err, sizeof err) != 0)
        fail_msg("cannot read %s: %s", path, err);
}

static inline double measure(const sfa_surface *s, int quantity)
{
    double value = NAN;
    const int rc = sfa_measure(s, quantity, &value);
    if (rc != SFA_OK)
        fail_msg("sfa_measure(%d): status %d: %s", quantity, rc, sfa_last_error(s));
    return value;
}

/* The current mesh, 0-based. */
static inline sfa_mesh_data read_back(const sfa_surface *s)
{
    sfa_mesh_data m;
    assert_int_equal(sfa_get_counts(s, &m.nverts, &m.ntris), SFA_OK);
    m.xyz = malloc(sizeof(double) * 3 * (size_t)(m.nverts ? m.nverts : 1));
    m.tris = malloc(sizeof(int32_t) * 3 * (size_t)(m.ntris ? m.ntris : 1));
    assert_non_null(m.xyz);
    assert_non_null(m.tris);
    assert_int_equal(sfa_get_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, 0), SFA_OK);
    return m;
}

/* The share of triangles with every angle in [theta_s, theta_l] (the paper's 15 and 160
 * degrees); 0 without triangles. */
static inline double share_of_good_triangles(const sfa_surface *s)
{
    sfa_mesh_data m = read_back(s);
    int32_t good = 0;
    for (int32_t t = 0; t < m.ntris; ++t) {
        int ok = 1;
        for (int k = 0; k < 3; ++k) {
            const double *a = m.xyz + 3 * m.tris[3 * t + k], *b = m.xyz + 3 * m.tris[3 * t + (k + 1) % 3],
                         *c = m.xyz + 3 * m.tris[3 * t + (k + 2) % 3];
            double u[3], w[3];
            for (int i = 0; i < 3; ++i) {
                u[i] = b[i] - a[i];
                w[i] = c[i] - a[i];
            }
            const double cross[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
            const double angle = atan2(sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]),
                                       u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) * 180 / 3.14159265358979323846;
            ok = ok && angle >= 15 && angle <= 160;
        }
        good += ok;
    }
    const double share = m.ntris ? (double)good / m.ntris : 0;
    mesh_free(&m);
    return share;
}

#ifndef SFA_NO_ALLOC_HOOK
#include "alloc_hook/alloc_hook.h"

/* Runs op(s) with its first, second, ... allocation failing until it succeeds: every
 * failure must be SFA_ERR_MEMORY, say "out of memory" and leave the surface exactly as it
 * was. Returns how many allocations the successful call made. */
static inline long expect_nothing_lost_at_every_allocation(sfa_surface *s, int (*op)(sfa_surface *))
{
    int rc = SFA_ERR_MEMORY;
    long n = 0;
    for (; rc == SFA_ERR_MEMORY && n < 1000000; ++n) {
        snapshot before, after;
        snapshot_take(s, &before);
        sfa_test_fail_allocation_after(n);
        rc = op(s);
        sfa_test_fail_allocation_after(-1);
        if (rc == SFA_ERR_MEMORY) {
            assert_true(contains_phrase(sfa_last_error(s), "out of memory"));
            snapshot_take(s, &after);
            assert_same_snapshot(&before, &after);
            snapshot_free(&after);
        }
        snapshot_free(&before);
    }
    assert_int_equal(rc, SFA_OK);
    return n - 1;
}
#endif

#endif

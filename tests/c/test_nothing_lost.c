/* SPDX-License-Identifier: BSD-3-Clause */
/* "Nothing lost" under std::bad_alloc: every mutating call is run with its n-th allocation
 * failing, n = 0, 1, 2, ..., until it succeeds. Each failure must be SFA_ERR_MEMORY with a
 * message and leave the surface (mesh, velocities, fields, parameters) exactly as it was.
 *
 * Needs the replacement operator new of alloc_hook.cpp; the sanitizer build cannot use
 * it and skips these tests. */
#include "support/testing.h"

#ifndef SFA_NO_ALLOC_HOOK
#include "alloc_hook/alloc_hook.h"
#endif

/* More allocations than any of these calls makes on these small meshes. */
#define MAX_FAILURE_POINT 100000

/* The rigid translation every loaded surface has as its velocities. */
static const double drift[3] = {0.125, -0.25, 0.5};

/* An icosphere with a non-default parameter, two fields and velocities. */
static sfa_surface *loaded_surface(sfa_mesh_data *mesh)
{
    *mesh = shape_icosphere(1, 1.0);
    sfa_surface *s = make_surface(mesh, 0);
    const int32_t n = mesh->nverts;
    double *buf = malloc(sizeof(double) * 3 * (size_t)n);
    assert_non_null(buf);
    for (int32_t i = 0; i < n; ++i)
        memcpy(buf + 3 * i, drift, sizeof drift);
    assert_int_equal(sfa_set_velocities(s, buf), SFA_OK);
    int32_t id;
    assert_int_equal(sfa_add_field(s, 3, mesh->xyz, &id), SFA_OK);
    for (int32_t i = 0; i < n; ++i)
        buf[i] = i * 0.5;
    assert_int_equal(sfa_add_field(s, 1, buf, &id), SFA_OK);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_FOLD_SAFETY, 0.75), SFA_OK);
    free(buf);
    return s;
}

#ifndef SFA_NO_ALLOC_HOOK
typedef enum {
    OP_SET_MESH,
    OP_SET_MESH_DROPPING,
    OP_SET_PARAM,
    OP_SET_VELOCITIES,
    OP_MOVE,
    OP_ADVECT,
    OP_ADVECT_COLLISION_SAFE,
    OP_ADD_FIELD
} operation;

static const char *const operation_name[] = {"sfa_set_mesh", "sfa_set_mesh (dropping unreferenced)",
                                             "sfa_set_param", "sfa_set_velocities", "sfa_move", "sfa_advect",
                                             "sfa_advect (collision-safe)", "sfa_add_field"};

static void swirl(void *ctx, int32_t n, const double *xyz, double t, double *vel)
{
    (void)ctx;
    for (int32_t i = 0; i < n; ++i) {
        vel[3 * i] = -xyz[3 * i + 1] + t;
        vel[3 * i + 1] = xyz[3 * i];
        vel[3 * i + 2] = 0.5 * xyz[3 * i + 2];
    }
}

/* The mesh of the OP_SET_MESH* calls: a larger sphere, optionally with unreferenced
 * vertices interleaved (every 10th vertex unused). */
static sfa_mesh_data replacement_mesh(int with_unreferenced)
{
    sfa_mesh_data m = shape_icosphere(2, 2.0);
    if (!with_unreferenced)
        return m;
    const int32_t extra = m.nverts / 10 + 1;
    sfa_mesh_data out = {m.nverts + extra, m.ntris, malloc(sizeof(double) * 3 * (size_t)(m.nverts + extra)),
                         malloc(sizeof(int32_t) * 3 * (size_t)m.ntris)};
    assert_non_null(out.xyz);
    assert_non_null(out.tris);
    int32_t *renumber = malloc(sizeof(int32_t) * (size_t)m.nverts);
    assert_non_null(renumber);
    int32_t next = 0;
    for (int32_t v = 0; v < m.nverts; ++v) {
        if (v % 10 == 0) { /* an unused point far away */
            out.xyz[3 * next] = 100 + v;
            out.xyz[3 * next + 1] = out.xyz[3 * next + 2] = 0;
            ++next;
        }
        memcpy(out.xyz + 3 * next, m.xyz + 3 * v, sizeof(double) * 3);
        renumber[v] = next++;
    }
    assert_int_equal(next, out.nverts);
    for (int32_t i = 0; i < 3 * m.ntris; ++i)
        out.tris[i] = renumber[m.tris[i]];
    free(renumber);
    mesh_free(&m);
    return out;
}

static int call(sfa_surface *s, operation op, const sfa_mesh_data *mesh, const sfa_mesh_data *replacement)
{
    const int32_t n = mesh->nverts;
    double taken = 0;
    int32_t id = -1;
    double *buf = malloc(sizeof(double) * 3 * (size_t)n);
    assert_non_null(buf);
    for (int32_t i = 0; i < 3 * n; ++i)
        buf[i] = 0.01 * (i % 7) - 0.02;
    int rc = SFA_ERR_INTERNAL;
    switch (op) {
    case OP_SET_MESH:
    case OP_SET_MESH_DROPPING:
        rc = sfa_set_mesh(s, replacement->nverts, replacement->xyz, replacement->ntris, replacement->tris, 0);
        break;
    case OP_SET_PARAM: rc = sfa_set_param(s, SFA_PARAM_SMALL_ANGLE, 20); break;
    case OP_SET_VELOCITIES: rc = sfa_set_velocities(s, buf); break;
    case OP_MOVE: rc = sfa_move(s, 0.125, &taken); break;
    case OP_ADVECT:
    case OP_ADVECT_COLLISION_SAFE: rc = sfa_advect(s, swirl, NULL, 0, 0.01, &taken); break;
    case OP_ADD_FIELD: rc = sfa_add_field(s, 3, buf, &id); break;
    }
    free(buf);
    return rc;
}

/* Fails allocation k of `op` for k = 0, 1, ... until the call succeeds. */
static void run_until_success(operation op)
{
    const sfa_mesh_data replacement = replacement_mesh(op == OP_SET_MESH_DROPPING);
    long failures = 0;
    for (long k = 0;; ++k) {
        if (k > MAX_FAILURE_POINT)
            fail_msg("%s still fails after %ld allocation failures", operation_name[op], k);
        sfa_mesh_data mesh;
        sfa_surface *s = loaded_surface(&mesh);
        if (op == OP_SET_MESH_DROPPING)
            assert_int_equal(sfa_set_param(s, SFA_PARAM_DROP_UNREFERENCED, 1), SFA_OK);
        /* Its broad phase collects pairs in parallel loops, as they are found. */
        if (op == OP_ADVECT_COLLISION_SAFE)
            assert_int_equal(sfa_set_param(s, SFA_PARAM_COLLISION_SAFE_MOTION, 1), SFA_OK);
        snapshot before, after;
        snapshot_take(s, &before);

        /* Armed only around the call, so that the test's own set-up cannot fail. */
        sfa_test_fail_allocation_after(k);
        const int rc = call(s, op, &mesh, &replacement);
        const int fired = sfa_test_allocation_failed();
        sfa_test_fail_allocation_after(-1);

        if (rc == SFA_OK) {
            assert_string_equal(sfa_last_error(s), "");
            snapshot_free(&before);
            sfa_destroy(s);
            mesh_free(&mesh);
            print_message("%s: %ld allocation failures survived, then success\n", operation_name[op], failures);
            break;
        }
        if (rc != SFA_ERR_MEMORY)
            fail_msg("%s with allocation %ld failing: status %d (%s), expected SFA_ERR_MEMORY: \"%s\"",
                     operation_name[op], k, rc, sfa_status_string(rc), sfa_last_error(s));
        assert_true(fired);
        ++failures;
        /* The message first: the getters of the snapshot reset it. */
        if (strlen(sfa_last_error(s)) == 0)
            fail_msg("%s with allocation %ld failing: SFA_ERR_MEMORY with no message", operation_name[op], k);
        snapshot_take(s, &after);
        char why[256];
        if (!snapshot_equal(&before, &after, why, sizeof why))
            fail_msg("%s with allocation %ld failing changed the surface: %s", operation_name[op], k, why);
        /* The velocities (which have no getter) are still the drift: a move shows them. */
        double taken = 0;
        assert_int_equal(sfa_move(s, 2.0, &taken), SFA_OK);
        assert_true(taken == 2.0);
        sfa_mesh_data moved = read_back(s);
        for (int32_t i = 0; i < 3 * mesh.nverts; ++i)
            assert_near(moved.xyz[i], mesh.xyz[i] + 2.0 * drift[i % 3], 1e-14);
        mesh_free(&moved);
        snapshot_free(&before);
        snapshot_free(&after);
        sfa_destroy(s);
        mesh_free(&mesh);
    }
    sfa_mesh_data r = replacement;
    mesh_free(&r);
}
#endif

#ifdef SFA_NO_ALLOC_HOOK
#define NEEDS_HOOK(body) skip()
#else
#define NEEDS_HOOK(body) body
#endif

static void create(void **state)
{
    (void)state;
#ifdef SFA_NO_ALLOC_HOOK
    skip();
#else
    for (long k = 0;; ++k) {
        if (k > MAX_FAILURE_POINT)
            fail_msg("sfa_create still fails after %ld allocation failures", k);
        static char not_null;
        sfa_surface *s = (sfa_surface *)(void *)&not_null; /* must be reset to NULL on failure */
        sfa_test_fail_allocation_after(k);
        const int rc = sfa_create(&s);
        sfa_test_fail_allocation_after(-1);
        if (rc == SFA_OK) {
            assert_non_null(s);
            assert_string_equal(sfa_last_error(s), "");
            sfa_destroy(s);
            print_message("sfa_create: %ld allocation failures survived, then success\n", k);
            break;
        }
        assert_int_equal(rc, SFA_ERR_MEMORY);
        assert_null(s);
    }
#endif
}

static void set_mesh(void **state)
{
    (void)state;
    NEEDS_HOOK(run_until_success(OP_SET_MESH));
}

static void set_mesh_dropping_unreferenced(void **state)
{
    (void)state;
    NEEDS_HOOK(run_until_success(OP_SET_MESH_DROPPING));
}

static void set_param(void **state)
{
    (void)state;
    NEEDS_HOOK(run_until_success(OP_SET_PARAM));
}

static void set_velocities(void **state)
{
    (void)state;
    NEEDS_HOOK(run_until_success(OP_SET_VELOCITIES));
}

static void move(void **state)
{
    (void)state;
    NEEDS_HOOK(run_until_success(OP_MOVE));
}

static void advect(void **state)
{
    (void)state;
    NEEDS_HOOK(run_until_success(OP_ADVECT));
}

static void advect_collision_safe(void **state)
{
    (void)state;
    NEEDS_HOOK(run_until_success(OP_ADVECT_COLLISION_SAFE));
}

static void add_field(void **state)
{
    (void)state;
    NEEDS_HOOK(run_until_success(OP_ADD_FIELD));
}

static void loaded_surface_is_sane(void **state)
{
    (void)state;
    /* The fixture itself, without any failure: what the other tests compare against. */
    sfa_mesh_data mesh;
    sfa_surface *s = loaded_surface(&mesh);
    double back[3 * 42];
    assert_int_equal(mesh.nverts, 42);
    assert_int_equal(sfa_get_field(s, 0, 3 * 42, back), SFA_OK);
    assert_memory_equal(back, mesh.xyz, sizeof back);
    double taken = 0;
    assert_int_equal(sfa_move(s, 2.0, &taken), SFA_OK);
    assert_true(taken == 2.0);
    sfa_destroy(s);
    mesh_free(&mesh);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(loaded_surface_is_sane),
        cmocka_unit_test(create),
        cmocka_unit_test(set_mesh),
        cmocka_unit_test(set_mesh_dropping_unreferenced),
        cmocka_unit_test(set_param),
        cmocka_unit_test(set_velocities),
        cmocka_unit_test(move),
        cmocka_unit_test(advect),
        cmocka_unit_test(advect_collision_safe),
        cmocka_unit_test(add_field),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

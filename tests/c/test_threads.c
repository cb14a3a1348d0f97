/* SPDX-License-Identifier: BSD-3-Clause */
/* Different handles used from different threads at the same time give the same results
 * as one after the other: the library keeps no global mutable state. */
#include "support/testing.h"

#include <threads.h>

#define NTHREADS 8
#define NSTEPS 40

typedef struct {
    int index;
    double volume, area;
    char error[256];      /* the message of a deliberately bad call */
    int32_t bad_triangle; /* which triangle was made bad, so each thread's message differs */
    int status;
} job;

static void spin(void *ctx, int32_t n, const double *xyz, double t, double *vel)
{
    const double w = *(const double *)ctx;
    for (int32_t i = 0; i < n; ++i) {
        vel[3 * i] = -w * xyz[3 * i + 1];
        vel[3 * i + 1] = w * xyz[3 * i];
        vel[3 * i + 2] = 0.1 * t;
    }
}

/* Everything here is per handle: a mesh per thread, a rejected mesh whose message names
 * this thread's triangle, then a few advection steps. */
static int work(void *arg)
{
    job *j = arg;
    j->status = -1;
    sfa_mesh_data sphere = shape_icosphere(2, 1.0 + 0.125 * j->index);
    sfa_surface *s = NULL;
    if (sfa_create(&s) != SFA_OK)
        return 0;
    int32_t *bad = malloc(sizeof(int32_t) * 3 * (size_t)sphere.ntris);
    if (!bad)
        return 0;
    memcpy(bad, sphere.tris, sizeof(int32_t) * 3 * (size_t)sphere.ntris);
    bad[3 * j->bad_triangle + 1] = sphere.nverts + j->index;
    if (sfa_set_mesh(s, sphere.nverts, sphere.xyz, sphere.ntris, bad, 0) != SFA_ERR_MESH)
        return 0;
    snprintf(j->error, sizeof j->error, "%s", sfa_last_error(s));
    free(bad);
    if (sfa_set_mesh(s, sphere.nverts, sphere.xyz, sphere.ntris, sphere.tris, 0) != SFA_OK)
        return 0;
    double w = 1.0 + j->index, taken;
    for (int step = 0; step < NSTEPS; ++step)
        if (sfa_advect(s, spin, &w, step * 0.01, 0.01, &taken) != SFA_OK)
            return 0;
    if (sfa_measure(s, SFA_MEASURE_VOLUME, &j->volume) != SFA_OK || sfa_measure(s, SFA_MEASURE_AREA, &j->area) != SFA_OK)
        return 0;
    sfa_destroy(s);
    mesh_free(&sphere);
    j->status = 0;
    return 0;
}

static void concurrent_handles_agree_with_serial(void **state)
{
    (void)state;
    job serial[NTHREADS], parallel[NTHREADS];
    for (int i = 0; i < NTHREADS; ++i) {
        serial[i] = (job){.index = i, .bad_triangle = 10 * i + 3};
        parallel[i] = serial[i];
        work(&serial[i]);
        assert_int_equal(serial[i].status, 0);
    }
    thrd_t threads[NTHREADS];
    for (int i = 0; i < NTHREADS; ++i)
        assert_int_equal(thrd_create(&threads[i], work, &parallel[i]), thrd_success);
    for (int i = 0; i < NTHREADS; ++i)
        assert_int_equal(thrd_join(threads[i], NULL), thrd_success);
    for (int i = 0; i < NTHREADS; ++i) {
        assert_int_equal(parallel[i].status, 0);
        assert_memory_equal(&parallel[i].volume, &serial[i].volume, sizeof(double));
        assert_memory_equal(&parallel[i].area, &serial[i].area, sizeof(double));
        assert_string_equal(parallel[i].error, serial[i].error);
        char expected[64];
        snprintf(expected, sizeof expected, "triangle %d", (int)parallel[i].bad_triangle);
        if (!contains_phrase(parallel[i].error, expected))
            fail_msg("thread %d got the message \"%s\"", i, parallel[i].error);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(concurrent_handles_agree_with_serial),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

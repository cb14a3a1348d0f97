/* SPDX-License-Identifier: BSD-3-Clause */
/* Benchmarks of the foundation: mesh validation (sfa_set_mesh), one explicit step
 * (sfa_move) and one RK4 step (sfa_advect) on icospheres of growing size. One JSON line
 * per case: the median of several runs, in seconds and nanoseconds per element. */
#define _POSIX_C_SOURCE 199309L
#include "icosphere.h"
#include "timing.h"

#include "surfadapt.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { runs = 7 };

/* A rigid rotation about the z axis: no triangle folds, so every step is taken whole. */
static void rotation(void *ctx, int32_t n, const double *xyz, double t, double *vel)
{
    (void)ctx;
    (void)t;
    for (int32_t i = 0; i < n; ++i) {
        vel[3 * i] = -xyz[3 * i + 1];
        vel[3 * i + 1] = xyz[3 * i];
        vel[3 * i + 2] = 0;
    }
}

/* unit: what the cost is divided by ("triangle" or "vertex"), count: how many there are. */
static void report(const char *name, int32_t nverts, int32_t ntris, double seconds, const char *unit, double count)
{
    printf("{\"bench\":\"%s\",\"vertices\":%d,\"triangles\":%d,\"median_s\":%.6f,\"ns_per_%s\":%.2f,"
           "\"runs\":%d}\n",
           name, nverts, ntris, seconds, unit, 1e9 * seconds / count, runs);
    fflush(stdout);
}

int main(void)
{
    const double center[3] = {0, 0, 0};
    for (int level = 5; level <= 8; level += 1) {
        int32_t nverts, ntris;
        double *xyz;
        int32_t *tris;
        if (icosphere(level, 1.0, center, &nverts, &xyz, &ntris, &tris) != 0)
            return 1;
        sfa_surface *s;
        if (sfa_create(&s) != SFA_OK)
            return 1;
        double samples[runs];

        for (int r = 0; r < runs; ++r) {
            const double t0 = now();
            if (sfa_set_mesh(s, nverts, xyz, ntris, tris, 0) != SFA_OK)
                return 1;
            samples[r] = now() - t0;
        }
        report("set_mesh", nverts, ntris, median(samples, runs), "triangle", ntris);

        double *vel = malloc(sizeof(double) * 3 * (size_t)nverts);
        rotation(NULL, nverts, xyz, 0, vel);
        sfa_set_velocities(s, vel);
        for (int r = 0; r < runs; ++r) {
            double taken;
            const double t0 = now();
            if (sfa_move(s, 1e-3, &taken) != SFA_OK)
                return 1;
            samples[r] = now() - t0;
        }
        report("move", nverts, ntris, median(samples, runs), "vertex", nverts);
        const double move_s = median(samples, runs);

        /* Baseline in the same run: the bare update x += dt v a host would write itself,
         * without fold control; the ratio is what the fold control costs. */
        for (int r = 0; r < runs; ++r) {
            const double t0 = now();
            for (int32_t i = 0; i < 3 * nverts; ++i)
                xyz[i] += 1e-3 * vel[i];
            samples[r] = now() - t0;
        }
        const double bare_s = median(samples, runs);
        printf("{\"bench\":\"move_vs_bare_update\",\"vertices\":%d,\"bare_median_s\":%.6f,\"ratio\":%.2f}\n",
               nverts, bare_s, move_s / bare_s);

        for (int r = 0; r < runs; ++r) {
            double taken;
            const double t0 = now();
            if (sfa_advect(s, rotation, NULL, 0, 1e-3, &taken) != SFA_OK)
                return 1;
            samples[r] = now() - t0;
        }
        report("advect", nverts, ntris, median(samples, runs), "vertex", nverts);

        free(vel);
        free(xyz);
        free(tris);
        sfa_destroy(s);
    }
    return 0;
}

/* SPDX-License-Identifier: BSD-3-Clause */
/* Benchmark of anisotropic smoothing: one sfa_smooth sweep (analysis, copy and commit
 * included) on a 1M-vertex geodesic sphere jittered tangentially; anisotropic with one
 * thread and with every core (OpenMP speed-up), and isotropic as a baseline. One JSON line
 * per case: the median of several runs, in seconds and ns per vertex. */
#define _DEFAULT_SOURCE /* sysconf(_SC_NPROCESSORS_ONLN) */
#include "jittered_sphere.h"
#include "timing.h"

#include "surfadapt.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

enum { runs = 5, frequency = 316 };

static double time_one_sweep(int32_t nverts, const double *xyz, int32_t ntris, const int32_t *tris, int anisotropic,
                             int threads)
{
    sfa_surface *s;
    if (sfa_create(&s) != SFA_OK || sfa_set_mesh(s, nverts, xyz, ntris, tris, 0) != SFA_OK)
        exit(1);
    sfa_set_param(s, SFA_PARAM_ANISOTROPIC, anisotropic);
    sfa_set_param(s, SFA_PARAM_THREADS, threads);
    double samples[runs];
    for (int r = 0; r < runs; ++r) {
        const double t0 = now();
        if (sfa_smooth(s, 1) != SFA_OK)
            exit(1);
        samples[r] = now() - t0;
    }
    sfa_destroy(s);
    const double seconds = median(samples, runs);
    printf("{\"bench\":\"smooth_sweep\",\"anisotropic\":%d,\"threads\":%d,\"vertices\":%d,\"median_s\":%.6f,"
           "\"ns_per_vertex\":%.1f,\"runs\":%d}\n",
           anisotropic, threads, nverts, seconds, 1e9 * seconds / nverts, runs);
    fflush(stdout);
    return seconds;
}

int main(void)
{
    int32_t nverts, ntris;
    double *xyz;
    int32_t *tris;
    if (jittered_sphere(frequency, &nverts, &xyz, &ntris, &tris) != 0)
        return 1;
    const int cores = (int)sysconf(_SC_NPROCESSORS_ONLN);
    const double serial = time_one_sweep(nverts, xyz, ntris, tris, 1, 1);
    const double parallel = time_one_sweep(nverts, xyz, ntris, tris, 1, cores);
    const double isotropic = time_one_sweep(nverts, xyz, ntris, tris, 0, cores);
    printf("{\"bench\":\"smooth_openmp_speedup\",\"vertices\":%d,\"threads\":%d,\"speedup\":%.2f}\n", nverts, cores,
           serial / parallel);
    printf("{\"bench\":\"smooth_anisotropic_vs_isotropic\",\"vertices\":%d,\"ratio\":%.2f}\n", nverts,
           parallel / isotropic);
    free(xyz);
    free(tris);
    return 0;
}

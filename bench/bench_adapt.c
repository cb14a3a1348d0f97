/* SPDX-License-Identifier: BSD-3-Clause */
/* Benchmark of the full adaptation: one sfa_adapt call on jittered geodesic spheres of
 * about 10k, 100k and 1M vertices at their own mean edge length (all default threads),
 * to see that the time per vertex stays flat as the mesh grows. One JSON line per size:
 * the median of the runs, in seconds and microseconds per vertex. */
#define _POSIX_C_SOURCE 199309L
#include "jittered_sphere.h"
#include "timing.h"

#include "surfadapt.h"

#include <stdio.h>
#include <stdlib.h>

int main(void)
{
    const int frequencies[] = {32, 100, 316}, runs[] = {5, 3, 1};
    for (int k = 0; k < 3; ++k) {
        int32_t nverts, ntris;
        double *xyz;
        int32_t *tris;
        if (jittered_sphere(frequencies[k], &nverts, &xyz, &ntris, &tris) != 0)
            return 1;
        double samples[5];
        int32_t out_verts = 0, out_tris = 0;
        for (int r = 0; r < runs[k]; ++r) {
            sfa_surface *s;
            if (sfa_create(&s) != SFA_OK || sfa_set_mesh(s, nverts, xyz, ntris, tris, 0) != SFA_OK)
                return 1;
            const double t0 = now();
            if (sfa_adapt(s) != SFA_OK) {
                fprintf(stderr, "sfa_adapt: %s\n", sfa_last_error(s));
                return 1;
            }
            samples[r] = now() - t0;
            sfa_get_counts(s, &out_verts, &out_tris);
            sfa_destroy(s);
        }
        const double seconds = median(samples, runs[k]);
        printf("{\"bench\":\"adapt\",\"vertices\":%d,\"vertices_after\":%d,\"median_s\":%.4f,"
               "\"us_per_vertex\":%.2f,\"runs\":%d}\n",
               nverts, out_verts, seconds, 1e6 * seconds / nverts, runs[k]);
        fflush(stdout);
        free(xyz);
        free(tris);
    }
    return 0;
}

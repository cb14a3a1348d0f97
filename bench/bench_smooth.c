/* Benchmark of anisotropic smoothing: one sfa_smooth sweep (analysis included) on
 * icospheres of growing size, and in the same run the isotropic mode as a baseline. One
 * JSON line per case: the median of several runs, in seconds and ns per vertex. */
#define _POSIX_C_SOURCE 199309L
#include "icosphere.h"
#include "timing.h"

#include "surfadapt.h"

#include <stdio.h>
#include <stdlib.h>

enum { runs = 5 };

int main(void)
{
    const double center[3] = {0, 0, 0};
    for (int level = 5; level <= 8; level += 3) {
        int32_t nverts, ntris;
        double *xyz;
        int32_t *tris;
        if (icosphere(level, 1.0, center, &nverts, &xyz, &ntris, &tris) != 0)
            return 1;
        double median_s[2];
        for (int anisotropic = 1; anisotropic >= 0; --anisotropic) {
            sfa_surface *s;
            if (sfa_create(&s) != SFA_OK || sfa_set_mesh(s, nverts, xyz, ntris, tris, 0) != SFA_OK)
                return 1;
            sfa_set_param(s, SFA_PARAM_ANISOTROPIC, anisotropic);
            double samples[runs];
            for (int r = 0; r < runs; ++r) {
                const double t0 = now();
                if (sfa_smooth(s, 1) != SFA_OK)
                    return 1;
                samples[r] = now() - t0;
            }
            median_s[anisotropic] = median(samples, runs);
            printf("{\"bench\":\"smooth_sweep\",\"anisotropic\":%d,\"vertices\":%d,\"median_s\":%.6f,"
                   "\"ns_per_vertex\":%.1f,\"runs\":%d}\n",
                   anisotropic, nverts, median_s[anisotropic], 1e9 * median_s[anisotropic] / nverts, runs);
            fflush(stdout);
            sfa_destroy(s);
        }
        printf("{\"bench\":\"smooth_anisotropic_vs_isotropic\",\"vertices\":%d,\"ratio\":%.2f}\n", nverts,
               median_s[1] / median_s[0]);
        free(xyz);
        free(tris);
    }
    return 0;
}

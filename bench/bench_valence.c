/* SPDX-License-Identifier: BSD-3-Clause */
/* Benchmark of sfa_adapt around one vertex of high valence (issue 18): a closed cone, an
 * apex over a ring of n vertices and the ring's centre, both of valence n, at n = 500,
 * 1000, 2000 and 4000, one call each. The time per call should grow about linearly with
 * n; quadratic growth (each of the ring's O(n) contractions checking the apex's whole fan)
 * shows here as a factor of 4 per doubling. One JSON line per size. */
#define _POSIX_C_SOURCE 199309L
#include "timing.h"

#include "surfadapt.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int main(void)
{
    const int valences[] = {500, 1000, 2000, 4000};
    for (int k = 0; k < 4; ++k) {
        const int n = valences[k], nverts = n + 2;
        double *xyz = malloc(sizeof(double) * 3 * (size_t)nverts);
        int32_t *tris = malloc(sizeof(int32_t) * 6 * (size_t)n);
        if (!xyz || !tris)
            return 1;
        xyz[0] = 0, xyz[1] = 0, xyz[2] = 1; /* the apex */
        for (int i = 0; i < n; ++i) {
            const double a = 2 * 3.14159265358979323846 * i / n;
            xyz[3 * (i + 1)] = cos(a), xyz[3 * (i + 1) + 1] = sin(a), xyz[3 * (i + 1) + 2] = 0;
        }
        xyz[3 * (n + 1)] = 0, xyz[3 * (n + 1) + 1] = 0, xyz[3 * (n + 1) + 2] = 0; /* the base's centre */
        for (int i = 0; i < n; ++i) {
            const int32_t a = 1 + i, b = 1 + (i + 1) % n;
            int32_t *t = tris + 6 * i;
            t[0] = 0, t[1] = a, t[2] = b;
            t[3] = n + 1, t[4] = b, t[5] = a;
        }
        sfa_surface *s;
        if (sfa_create(&s) != SFA_OK || sfa_set_mesh(s, nverts, xyz, 2 * n, tris, 0) != SFA_OK)
            return 1;
        const double t0 = now();
        if (sfa_adapt(s) != SFA_OK) {
            fprintf(stderr, "sfa_adapt: %s\n", sfa_last_error(s));
            return 1;
        }
        const double seconds = now() - t0;
        int32_t out_verts = 0;
        sfa_get_counts(s, &out_verts, NULL);
        printf("{\"bench\":\"adapt_cone\",\"valence\":%d,\"vertices_after\":%d,\"seconds\":%.4f}\n", n, out_verts,
               seconds);
        fflush(stdout);
        sfa_destroy(s);
        free(xyz);
        free(tris);
    }
    return 0;
}

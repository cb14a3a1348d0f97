/* SPDX-License-Identifier: BSD-3-Clause */
/* The input of the smoothing and flipping benchmarks: a unit geodesic sphere whose
 * vertices were moved along the sphere by up to a third of an edge (deterministically), so
 * that both smoothing and flipping have work to do. C and C++. */
#ifndef SURFADAPT_BENCH_JITTERED_SPHERE_H
#define SURFADAPT_BENCH_JITTERED_SPHERE_H

#include "icosphere.h"

#include <math.h>

/* As geodesic_sphere(frequency, 1, origin, ...); returns its status. */
static inline int jittered_sphere(int frequency, int32_t *nverts, double **xyz, int32_t *ntris, int32_t **tris)
{
    const double center[3] = {0, 0, 0};
    if (geodesic_sphere(frequency, 1.0, center, nverts, xyz, ntris, tris) != 0)
        return -1;
    const double edge = 1.1 / frequency; /* about the mean edge length */
    uint64_t state = 12345;
    for (int32_t v = 0; v < *nverts; ++v) {
        double *p = *xyz + 3 * v, d[3], radial = 0, norm = 0, length = 0;
        for (int k = 0; k < 3; ++k) {
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            d[k] = (double)(state >> 11) / (double)(1ULL << 53) - 0.5;
            radial += d[k] * p[k];
        }
        for (int k = 0; k < 3; ++k) {
            d[k] -= radial * p[k];
            norm += d[k] * d[k];
        }
        for (int k = 0; k < 3; ++k) {
            p[k] += edge / 3 * d[k] / sqrt(norm) * (double)(v % 7) / 7;
            length += p[k] * p[k];
        }
        for (int k = 0; k < 3; ++k)
            p[k] /= sqrt(length);
    }
    return 0;
}

#endif

/* SPDX-License-Identifier: BSD-3-Clause */
/* Generated spheres: the demo's and benchmarks' analytic input, with an exact answer. */
#ifndef SURFADAPT_APP_ICOSPHERE_H
#define SURFADAPT_APP_ICOSPHERE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* An icosahedron subdivided `subdivisions` times (each splits every triangle in four),
 * vertices projected on the sphere of `radius` about `center`; outward, counter-clockwise,
 * 0-based. 10*4^k + 2 vertices, 20*4^k triangles. The arrays are malloc'ed (free them);
 * returns 0, or -1 if out of memory or k > 10. */
int icosphere(int subdivisions, double radius, const double center[3], int32_t *nverts, double **xyz,
              int32_t *ntris, int32_t **tris);

/* The geodesic sphere of `frequency` n: every icosahedron face divided into n x n
 * triangles, then projected (as for icosphere); any size, not only powers of 4.
 * 10 n^2 + 2 vertices, 20 n^2 triangles (n = 48: 23,042 vertices; n = 316: 998,562).
 * Returns 0, or -1 if out of memory or n is not in [1, 10000]. */
int geodesic_sphere(int frequency, double radius, const double center[3], int32_t *nverts, double **xyz,
                    int32_t *ntris, int32_t **tris);

#ifdef __cplusplus
}
#endif

#endif

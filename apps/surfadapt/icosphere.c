#include "icosphere.h"

#include <math.h>
#include <stdlib.h>

/* The midpoint vertex of edge (a, b), created once: edges are found through a per-vertex
 * list of (neighbour, midpoint) pairs, which stays short (valence <= 6). */
typedef struct {
    int32_t *first;    /* first[v]: head of v's list in next/other/mid, -1 if empty */
    int32_t *next, *other, *mid;
    int32_t count;
} edge_table;

static int32_t midpoint(edge_table *e, double *xyz, int32_t *nverts, int32_t a, int32_t b)
{
    const int32_t lo = a < b ? a : b, hi = a < b ? b : a;
    for (int32_t k = e->first[lo]; k >= 0; k = e->next[k])
        if (e->other[k] == hi)
            return e->mid[k];
    const int32_t m = (*nverts)++;
    for (int c = 0; c < 3; ++c)
        xyz[3 * m + c] = 0.5 * (xyz[3 * a + c] + xyz[3 * b + c]);
    const int32_t k = e->count++;
    e->other[k] = hi;
    e->mid[k] = m;
    e->next[k] = e->first[lo];
    e->first[lo] = k;
    return m;
}

int icosphere(int subdivisions, double radius, const double center[3], int32_t *nverts_out, double **xyz_out,
              int32_t *ntris_out, int32_t **tris_out)
{
    if (subdivisions < 0 || subdivisions > 10)
        return -1;
    const double g = (1 + sqrt(5.0)) / 2;
    const double base_xyz[12][3] = {{-1, g, 0}, {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                                    {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    const int32_t base_tris[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                      {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                      {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                      {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    int64_t final_tris = 20, final_verts;
    for (int k = 0; k < subdivisions; ++k)
        final_tris *= 4;
    final_verts = final_tris / 2 + 2;

    double *xyz = malloc(sizeof(double) * 3 * (size_t)final_verts);
    int32_t *tris = malloc(sizeof(int32_t) * 3 * (size_t)final_tris);
    int32_t *scratch = malloc(sizeof(int32_t) * 3 * (size_t)final_tris);
    edge_table e = {malloc(sizeof(int32_t) * (size_t)final_verts), malloc(sizeof(int32_t) * (size_t)final_tris * 2),
                    malloc(sizeof(int32_t) * (size_t)final_tris * 2), malloc(sizeof(int32_t) * (size_t)final_tris * 2),
                    0};
    int ok = xyz && tris && scratch && e.first && e.next && e.other && e.mid;
    if (ok) {
        int32_t nverts = 12, ntris = 20;
        for (int v = 0; v < 12; ++v)
            for (int c = 0; c < 3; ++c)
                xyz[3 * v + c] = base_xyz[v][c];
        for (int t = 0; t < 20; ++t)
            for (int c = 0; c < 3; ++c)
                tris[3 * t + c] = base_tris[t][c];
        for (int level = 0; level < subdivisions; ++level) {
            e.count = 0;
            for (int32_t v = 0; v < nverts; ++v)
                e.first[v] = -1;
            int32_t out = 0;
            for (int32_t t = 0; t < ntris; ++t) {
                const int32_t a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
                const int32_t ab = midpoint(&e, xyz, &nverts, a, b), bc = midpoint(&e, xyz, &nverts, b, c),
                              ca = midpoint(&e, xyz, &nverts, c, a);
                const int32_t children[4][3] = {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}};
                for (int k = 0; k < 4; ++k)
                    for (int j = 0; j < 3; ++j)
                        scratch[out++] = children[k][j];
            }
            ntris *= 4;
            int32_t *swap = tris;
            tris = scratch;
            scratch = swap;
        }
        for (int32_t v = 0; v < nverts; ++v) {
            double *p = xyz + 3 * v;
            const double scale = radius / sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            for (int c = 0; c < 3; ++c)
                p[c] = center[c] + scale * p[c];
        }
        *nverts_out = nverts;
        *ntris_out = ntris;
        *xyz_out = xyz;
        *tris_out = tris;
    }
    free(scratch);
    free(e.first);
    free(e.next);
    free(e.other);
    free(e.mid);
    if (!ok) {
        free(xyz);
        free(tris);
        return -1;
    }
    return 0;
}

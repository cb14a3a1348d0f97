/* SPDX-License-Identifier: BSD-3-Clause */
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

/* The icosahedron: g is the golden ratio. */
#define G 1.6180339887498948482
static const double base_xyz[12][3] = {{-1, G, 0}, {1, G, 0},  {-1, -G, 0}, {1, -G, 0}, {0, -1, G},  {0, 1, G},
                                       {0, -1, -G}, {0, 1, -G}, {G, 0, -1}, {G, 0, 1},  {-G, 0, -1}, {-G, 0, 1}};
static const int32_t base_tris[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                         {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                         {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                         {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
#undef G

/* Every vertex projected onto the sphere. */
static void project(double *xyz, int32_t nverts, double radius, const double center[3])
{
    for (int32_t v = 0; v < nverts; ++v) {
        double *p = xyz + 3 * v;
        const double scale = radius / sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int c = 0; c < 3; ++c)
            p[c] = center[c] + scale * p[c];
    }
}

int icosphere(int subdivisions, double radius, const double center[3], int32_t *nverts_out, double **xyz_out,
              int32_t *ntris_out, int32_t **tris_out)
{
    if (subdivisions < 0 || subdivisions > 10)
        return -1;
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
        project(xyz, nverts, radius, center);
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

int geodesic_sphere(int frequency, double radius, const double center[3], int32_t *nverts_out, double **xyz_out,
                    int32_t *ntris_out, int32_t **tris_out)
{
    const int n = frequency;
    if (n < 1 || n > 10000)
        return -1;
    /* Vertices: the 12 corners, then n - 1 points on each of the 30 edges (numbered from
     * the edge's lower corner), then the points inside each face. */
    const int32_t nverts = 10 * n * n + 2, ntris = 20 * n * n;
    double *xyz = malloc(sizeof(double) * 3 * (size_t)nverts);
    int32_t *tris = malloc(sizeof(int32_t) * 3 * (size_t)ntris);
    int32_t *row = malloc(sizeof(int32_t) * (size_t)(n + 1) * (size_t)(n + 1)); /* one face's points */
    if (!xyz || !tris || !row) {
        free(xyz);
        free(tris);
        free(row);
        return -1;
    }
    int32_t edge_base[12][12];
    for (int a = 0; a < 12; ++a)
        for (int b = 0; b < 12; ++b)
            edge_base[a][b] = -1;
    int32_t count = 12, out = 0;
    for (int v = 0; v < 12; ++v)
        for (int c = 0; c < 3; ++c)
            xyz[3 * v + c] = base_xyz[v][c];
    /* The index of the point k steps (of n) from corner x towards corner y. */
#define EDGE_POINT(x, y, k) \
    ((x) < (y) ? edge_base[x][y] + (k) - 1 : edge_base[y][x] + (n - (k)) - 1)
    for (int f = 0; f < 20; ++f) {
        const int32_t a = base_tris[f][0], b = base_tris[f][1], c = base_tris[f][2];
        const int32_t corners[3][2] = {{a, b}, {b, c}, {c, a}};
        for (int e = 0; e < 3; ++e) {
            const int32_t lo = corners[e][0] < corners[e][1] ? corners[e][0] : corners[e][1];
            const int32_t hi = corners[e][0] ^ corners[e][1] ^ lo;
            if (edge_base[lo][hi] >= 0)
                continue;
            edge_base[lo][hi] = count;
            for (int k = 1; k < n; ++k, ++count)
                for (int d = 0; d < 3; ++d)
                    xyz[3 * count + d] = base_xyz[lo][d] + (base_xyz[hi][d] - base_xyz[lo][d]) * k / n;
        }
        /* Point (i, j) = a + i/n (b - a) + j/n (c - a), i + j <= n. */
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                int32_t id;
                if (i == 0 && j == 0)
                    id = a;
                else if (i == n)
                    id = b;
                else if (j == n)
                    id = c;
                else if (j == 0)
                    id = EDGE_POINT(a, b, i);
                else if (i == 0)
                    id = EDGE_POINT(a, c, j);
                else if (i + j == n)
                    id = EDGE_POINT(b, c, j);
                else {
                    id = count++;
                    for (int d = 0; d < 3; ++d)
                        xyz[3 * id + d] = base_xyz[a][d] + ((base_xyz[b][d] - base_xyz[a][d]) * i +
                                                            (base_xyz[c][d] - base_xyz[a][d]) * j) / n;
                }
                row[i * (n + 1) + j] = id;
            }
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j) {
                const int32_t p = row[i * (n + 1) + j], pb = row[(i + 1) * (n + 1) + j], pc = row[i * (n + 1) + j + 1];
                tris[out++] = p, tris[out++] = pb, tris[out++] = pc;
                if (i + j < n - 1) {
                    tris[out++] = pb;
                    tris[out++] = row[(i + 1) * (n + 1) + j + 1];
                    tris[out++] = pc;
                }
            }
    }
#undef EDGE_POINT
    free(row);
    project(xyz, nverts, radius, center);
    *nverts_out = nverts;
    *ntris_out = ntris;
    *xyz_out = xyz;
    *tris_out = tris;
    return 0;
}

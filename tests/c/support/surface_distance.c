/* SPDX-License-Identifier: BSD-3-Clause */
#include "support/surface_distance.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct {
    double lo[3], cell;
    int n[3];
    int32_t *start, *items; /* triangles of cell c: items[start[c] .. start[c+1]) */
} grid;

static void *checked_malloc(size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (!p) {
        fputs("test support: out of memory\n", stderr);
        abort();
    }
    return p;
}

static void sub(const double *a, const double *b, double *out)
{
    for (int k = 0; k < 3; ++k)
        out[k] = a[k] - b[k];
}
static double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Squared distance from p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5). */
static double point_triangle_distance2(const double *p, const double *a, const double *b, const double *c)
{
    double ab[3], ac[3], ap[3], bp[3], cp[3], q[3];
    sub(b, a, ab);
    sub(c, a, ac);
    sub(p, a, ap);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return dot(ap, ap);
    sub(p, b, bp);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return dot(bp, bp);
    const double vc = d1 * d4 - d3 * d2;
    double v, w;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        v = d1 / (d1 - d3);
        for (int k = 0; k < 3; ++k)
            q[k] = a[k] + v * ab[k];
    } else {
        sub(p, c, cp);
        const double d5 = dot(ab, cp), d6 = dot(ac, cp);
        if (d6 >= 0 && d5 <= d6)
            return dot(cp, cp);
        const double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            w = d2 / (d2 - d6);
            for (int k = 0; k < 3; ++k)
                q[k] = a[k] + w * ac[k];
        } else {
            const double va = d3 * d6 - d5 * d4;
            if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
                w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
                for (int k = 0; k < 3; ++k)
                    q[k] = b[k] + w * (c[k] - b[k]);
            } else {
                const double denom = 1 / (va + vb + vc);
                v = vb * denom;
                w = vc * denom;
                for (int k = 0; k < 3; ++k)
                    q[k] = a[k] + ab[k] * v + ac[k] * w;
            }
        }
    }
    double d[3];
    sub(p, q, d);
    return dot(d, d);
}

static int cell_of(const grid *g, double x, int axis)
{
    int i = (int)floor((x - g->lo[axis]) / g->cell);
    return i < 0 ? 0 : i >= g->n[axis] ? g->n[axis] - 1 : i;
}

/* Each triangle goes into every cell its bounding box touches. */
static grid build_grid(const sfa_mesh_data *m)
{
    grid g;
    double hi[3];
    for (int k = 0; k < 3; ++k)
        g.lo[k] = hi[k] = m->xyz[k];
    for (int32_t v = 0; v < m->nverts; ++v)
        for (int k = 0; k < 3; ++k) {
            g.lo[k] = fmin(g.lo[k], m->xyz[3 * v + k]);
            hi[k] = fmax(hi[k], m->xyz[3 * v + k]);
        }
    const double diagonal = sqrt((hi[0] - g.lo[0]) * (hi[0] - g.lo[0]) + (hi[1] - g.lo[1]) * (hi[1] - g.lo[1]) +
                                 (hi[2] - g.lo[2]) * (hi[2] - g.lo[2]));
    g.cell = diagonal / 64;
    for (int k = 0; k < 3; ++k)
        g.n[k] = (int)((hi[k] - g.lo[k]) / g.cell) + 1;
    const size_t cells = (size_t)g.n[0] * g.n[1] * g.n[2];
    g.start = checked_malloc(sizeof(int32_t) * (cells + 1));
    int32_t *cursor = checked_malloc(sizeof(int32_t) * (cells + 1));
    for (size_t c = 0; c <= cells; ++c)
        g.start[c] = 0;
    /* Pass 0 counts the triangles of each cell, pass 1 files them. */
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) {
            for (size_t c = 1; c <= cells; ++c)
                g.start[c] += g.start[c - 1];
            for (size_t c = 0; c <= cells; ++c)
                cursor[c] = g.start[c];
            g.items = checked_malloc(sizeof(int32_t) * (size_t)g.start[cells]);
        }
        for (int32_t t = 0; t < m->ntris; ++t) {
            int lo[3], up[3];
            for (int k = 0; k < 3; ++k) {
                double a = INFINITY, b = -INFINITY;
                for (int i = 0; i < 3; ++i) {
                    a = fmin(a, m->xyz[3 * m->tris[3 * t + i] + k]);
                    b = fmax(b, m->xyz[3 * m->tris[3 * t + i] + k]);
                }
                lo[k] = cell_of(&g, a, k);
                up[k] = cell_of(&g, b, k);
            }
            for (int i = lo[0]; i <= up[0]; ++i)
                for (int j = lo[1]; j <= up[1]; ++j)
                    for (int l = lo[2]; l <= up[2]; ++l) {
                        const size_t c = ((size_t)i * g.n[1] + j) * g.n[2] + l;
                        if (pass == 0)
                            ++g.start[c + 1];
                        else
                            g.items[cursor[c]++] = t;
                    }
        }
    }
    free(cursor);
    return g;
}

/* Distance from p to the mesh: cells in growing cubic shells until the nearest triangle
 * found is nearer than any unvisited cell can be. */
static double distance_to(const grid *g, const sfa_mesh_data *m, const double *p)
{
    const int centre[3] = {cell_of(g, p[0], 0), cell_of(g, p[1], 1), cell_of(g, p[2], 2)};
    double best2 = INFINITY;
    const int most = g->n[0] + g->n[1] + g->n[2];
    for (int r = 0; r <= most; ++r) {
        for (int i = centre[0] - r; i <= centre[0] + r; ++i)
            for (int j = centre[1] - r; j <= centre[1] + r; ++j)
                for (int l = centre[2] - r; l <= centre[2] + r; ++l) {
                    if (i < 0 || j < 0 || l < 0 || i >= g->n[0] || j >= g->n[1] || l >= g->n[2])
                        continue;
                    if (abs(i - centre[0]) != r && abs(j - centre[1]) != r && abs(l - centre[2]) != r)
                        continue; /* inside the shell: visited already */
                    const size_t c = ((size_t)i * g->n[1] + j) * g->n[2] + l;
                    for (int32_t k = g->start[c]; k < g->start[c + 1]; ++k) {
                        const int32_t *t = m->tris + 3 * g->items[k];
                        const double d2 = point_triangle_distance2(p, m->xyz + 3 * t[0], m->xyz + 3 * t[1], m->xyz + 3 * t[2]);
                        best2 = fmin(best2, d2);
                    }
                }
        /* Unvisited cells are at least r * cell away (p may sit anywhere in its cell). */
        if (best2 <= (r * g->cell) * (r * g->cell))
            break;
    }
    return sqrt(best2);
}

double sampled_distance(const sfa_mesh_data *from, const sfa_mesh_data *to)
{
    grid g = build_grid(to);
    double worst = 0;
    for (int32_t v = 0; v < from->nverts; ++v)
        worst = fmax(worst, distance_to(&g, to, from->xyz + 3 * v));
    for (int32_t t = 0; t < from->ntris; ++t) {
        double c[3] = {0, 0, 0};
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                c[k] += from->xyz[3 * from->tris[3 * t + i] + k] / 3;
        worst = fmax(worst, distance_to(&g, to, c));
    }
    free(g.start);
    free(g.items);
    return worst;
}

double sampled_hausdorff(const sfa_mesh_data *a, const sfa_mesh_data *b)
{
    return fmax(sampled_distance(a, b), sampled_distance(b, a));
}

double bounding_diagonal(const sfa_mesh_data *m)
{
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k)
        lo[k] = hi[k] = m->xyz[k];
    for (int32_t v = 0; v < m->nverts; ++v)
        for (int k = 0; k < 3; ++k) {
            lo[k] = fmin(lo[k], m->xyz[3 * v + k]);
            hi[k] = fmax(hi[k], m->xyz[3 * v + k]);
        }
    return sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

/* SPDX-License-Identifier: BSD-3-Clause */
#include "support/shapes.h"

#include "icosphere.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double shapes_pi = 3.14159265358979323846;

/* Test support: running out of memory here is not what is being tested. */
static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) {
        fputs("test support: out of memory\n", stderr);
        abort();
    }
    return p;
}

static sfa_mesh_data mesh_alloc(int32_t nverts, int32_t ntris)
{
    sfa_mesh_data m;
    m.nverts = nverts;
    m.ntris = ntris;
    m.xyz = xmalloc(sizeof(double) * 3 * (size_t)nverts);
    m.tris = xmalloc(sizeof(int32_t) * 3 * (size_t)ntris);
    return m;
}

sfa_mesh_data shape_unit_cube(void)
{
    static const double xyz[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    static const int32_t tris[12][3] = {{0, 2, 1}, {0, 3, 2},  /* z = 0 */
                                        {4, 5, 6}, {4, 6, 7},  /* z = 1 */
                                        {0, 1, 5}, {0, 5, 4},  /* y = 0 */
                                        {3, 7, 6}, {3, 6, 2},  /* y = 1 */
                                        {0, 4, 7}, {0, 7, 3},  /* x = 0 */
                                        {1, 2, 6}, {1, 6, 5}}; /* x = 1 */
    sfa_mesh_data m = mesh_alloc(8, 12);
    memcpy(m.xyz, xyz, sizeof xyz);
    memcpy(m.tris, tris, sizeof tris);
    return m;
}

sfa_mesh_data shape_box(int n, const double lo[3], const double hi[3])
{
    const int32_t side = n + 1;
    int32_t *id = xmalloc(sizeof(int32_t) * (size_t)side * (size_t)side * (size_t)side);
    for (int32_t i = 0; i < side * side * side; ++i)
        id[i] = -1;
    sfa_mesh_data m = mesh_alloc(6 * n * n + 2, 12 * n * n);
    int32_t nv = 0, nt = 0;
    for (int a = 0; a < 3; ++a) {
        /* (u, v, a) is a cyclic permutation, so e_u x e_v = e_a: a cell counter-clockwise in
         * (u, v) faces +e_a, which is outward on the side coordinate[a] = n. */
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        for (int s = 0; s <= n; s += n) {
            int32_t corner[2][2];
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    for (int di = 0; di < 2; ++di)
                        for (int dj = 0; dj < 2; ++dj) {
                            int c[3];
                            c[a] = s;
                            c[u] = i + di;
                            c[v] = j + dj;
                            int32_t *slot = &id[(c[0] * side + c[1]) * side + c[2]];
                            if (*slot < 0) {
                                *slot = nv++;
                                for (int k = 0; k < 3; ++k)
                                    m.xyz[3 * *slot + k] = lo[k] + (hi[k] - lo[k]) * c[k] / n;
                            }
                            corner[di][dj] = *slot;
                        }
                    const int32_t p00 = corner[0][0], p10 = corner[1][0], p11 = corner[1][1], p01 = corner[0][1];
                    const int32_t up[6] = {p00, p10, p11, p00, p11, p01};
                    const int32_t down[6] = {p00, p11, p10, p00, p01, p11};
                    memcpy(m.tris + 3 * nt, s == n ? up : down, sizeof up);
                    nt += 2;
                }
            if (n == 0)
                break;
        }
    }
    free(id);
    m.nverts = nv;
    m.ntris = nt;
    return m;
}

sfa_mesh_data shape_icosphere(int k, double r)
{
    const double center[3] = {0, 0, 0};
    sfa_mesh_data m;
    if (icosphere(k, r, center, &m.nverts, &m.xyz, &m.ntris, &m.tris) != 0) {
        fputs("test support: icosphere failed\n", stderr);
        abort();
    }
    return m;
}

sfa_mesh_data shape_two_icospheres(int k, double r, double distance)
{
    sfa_mesh_data m = shape_icosphere(k, r), right = shape_icosphere(k, r);
    const double left_shift[3] = {-distance / 2, 0, 0}, right_shift[3] = {distance / 2, 0, 0};
    mesh_translate(&m, left_shift);
    mesh_translate(&right, right_shift);
    mesh_append(&m, &right);
    mesh_free(&right);
    return m;
}

sfa_mesh_data shape_icosahedron(double r) { return shape_icosphere(0, r); }

sfa_mesh_data shape_grid(int nx, int ny, double h)
{
    sfa_mesh_data m = mesh_alloc((nx + 1) * (ny + 1), 2 * nx * ny);
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            double *p = m.xyz + 3 * (j * (nx + 1) + i);
            p[0] = i * h;
            p[1] = j * h;
            p[2] = 0;
        }
    int32_t *t = m.tris;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const int32_t p00 = j * (nx + 1) + i, p10 = p00 + 1, p01 = p00 + nx + 1, p11 = p01 + 1;
            const int32_t two[6] = {p00, p10, p11, p00, p11, p01};
            memcpy(t, two, sizeof two);
            t += 6;
        }
    return m;
}

sfa_mesh_data shape_capped_cylinder(double r, double h, int segments, int rings)
{
    const int32_t nring = segments, bottom = (rings + 1) * segments, top = bottom + 1;
    sfa_mesh_data m = mesh_alloc(bottom + 2, 2 * (rings + 1) * segments);
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const double phi = 2 * shapes_pi * i / segments;
            double *p = m.xyz + 3 * (j * nring + i);
            p[0] = r * cos(phi);
            p[1] = r * sin(phi);
            p[2] = -0.5 * h + h * j / rings;
        }
    const double centres[6] = {0, 0, -0.5 * h, 0, 0, 0.5 * h};
    memcpy(m.xyz + 3 * bottom, centres, sizeof centres);
    int32_t *t = m.tris;
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            /* e_phi x e_z = e_r: counter-clockwise in (phi, z) is outward. */
            const int32_t p00 = j * nring + i, p10 = j * nring + (i + 1) % segments;
            const int32_t p01 = p00 + nring, p11 = p10 + nring;
            const int32_t two[6] = {p00, p10, p11, p00, p11, p01};
            memcpy(t, two, sizeof two);
            t += 6;
        }
    for (int i = 0; i < segments; ++i) {
        const int32_t i1 = (i + 1) % segments, last = rings * nring;
        /* Increasing phi turns counter-clockwise seen from +z: reversed on the bottom. */
        const int32_t caps[6] = {bottom, i1, i, top, last + i, last + i1};
        memcpy(t, caps, sizeof caps);
        t += 6;
    }
    return m;
}

sfa_mesh_data shape_ellipsoid(int k, double a, double b, double c)
{
    sfa_mesh_data m = shape_icosphere(k, 1.0);
    for (int32_t v = 0; v < m.nverts; ++v) {
        m.xyz[3 * v] *= a;
        m.xyz[3 * v + 1] *= b;
        m.xyz[3 * v + 2] *= c;
    }
    return m;
}

sfa_mesh_data shape_spherical_cap(double r, double max_angle, int segments, int rings)
{
    sfa_mesh_data m = mesh_alloc(1 + rings * segments, segments * (2 * rings - 1));
    m.xyz[0] = 0;
    m.xyz[1] = 0;
    m.xyz[2] = r;
    for (int j = 1; j <= rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const double theta = max_angle * j / rings, phi = 2 * shapes_pi * i / segments;
            double *p = m.xyz + 3 * (1 + (j - 1) * segments + i);
            p[0] = r * sin(theta) * cos(phi);
            p[1] = r * sin(theta) * sin(phi);
            p[2] = r * cos(theta);
        }
    int32_t *t = m.tris;
    for (int i = 0; i < segments; ++i) {
        /* Seen from outside (+z at the pole) increasing phi is counter-clockwise. */
        const int32_t fan[3] = {0, 1 + i, 1 + (i + 1) % segments};
        memcpy(t, fan, sizeof fan);
        t += 3;
    }
    for (int j = 1; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            /* e_theta x e_phi = e_r: counter-clockwise in (theta, phi) is outward. */
            const int32_t p00 = 1 + (j - 1) * segments + i, p01 = 1 + (j - 1) * segments + (i + 1) % segments;
            const int32_t p10 = p00 + segments, p11 = p01 + segments;
            const int32_t two[6] = {p00, p10, p11, p00, p11, p01};
            memcpy(t, two, sizeof two);
            t += 6;
        }
    return m;
}

shapes_rng rng_seed(uint64_t seed)
{
    shapes_rng rng = {seed};
    return rng;
}

uint64_t rng_next(shapes_rng *rng)
{
    uint64_t z = (rng->state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

double rng_uniform(shapes_rng *rng) { return (double)(rng_next(rng) >> 11) * 0x1.0p-53; }

/* A uniform integer in [0, n), n > 0 (the modulo bias is irrelevant at test sizes). */
static int32_t rng_below(shapes_rng *rng, int32_t n) { return (int32_t)(rng_next(rng) % (uint64_t)n); }

void rotation_axis_angle(const double axis[3], double angle, double R[9])
{
    const double len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    const double x = axis[0] / len, y = axis[1] / len, z = axis[2] / len;
    const double c = cos(angle), s = sin(angle), C = 1 - c;
    const double rot[9] = {c + x * x * C,     x * y * C - z * s, x * z * C + y * s, /* Rodrigues */
                           y * x * C + z * s, c + y * y * C,     y * z * C - x * s,
                           z * x * C - y * s, z * y * C + x * s, c + z * z * C};
    memcpy(R, rot, sizeof rot);
}

void rotation_random(shapes_rng *rng, double R[9])
{
    /* A uniform direction: z uniform in [-1, 1] and a uniform azimuth (Archimedes). */
    const double z = 2 * rng_uniform(rng) - 1, phi = 2 * shapes_pi * rng_uniform(rng);
    const double rho = sqrt(1 - z * z);
    const double axis[3] = {rho * cos(phi), rho * sin(phi), z};
    rotation_axis_angle(axis, 2 * shapes_pi * rng_uniform(rng), R);
}

void mesh_rotate_scale(sfa_mesh_data *m, const double R[9], double scale)
{
    for (int32_t v = 0; v < m->nverts; ++v) {
        double *p = m->xyz + 3 * v;
        const double x[3] = {p[0], p[1], p[2]};
        for (int i = 0; i < 3; ++i)
            p[i] = scale * (R[3 * i] * x[0] + R[3 * i + 1] * x[1] + R[3 * i + 2] * x[2]);
    }
}

/* A random permutation of 0..n-1 (Fisher-Yates) into perm. */
static void random_permutation(shapes_rng *rng, int32_t n, int32_t *perm)
{
    for (int32_t i = 0; i < n; ++i)
        perm[i] = i;
    for (int32_t i = n - 1; i > 0; --i) {
        const int32_t j = rng_below(rng, i + 1), swap = perm[i];
        perm[i] = perm[j];
        perm[j] = swap;
    }
}

void mesh_permute(sfa_mesh_data *m, uint64_t seed, int32_t *vert_new, int32_t *tri_new)
{
    shapes_rng rng = rng_seed(seed);
    int32_t *vmap = xmalloc(sizeof(int32_t) * (size_t)m->nverts);
    int32_t *tmap = xmalloc(sizeof(int32_t) * (size_t)m->ntris);
    random_permutation(&rng, m->nverts, vmap);
    random_permutation(&rng, m->ntris, tmap);
    sfa_mesh_data p = mesh_alloc(m->nverts, m->ntris);
    for (int32_t v = 0; v < m->nverts; ++v)
        memcpy(p.xyz + 3 * vmap[v], m->xyz + 3 * v, 3 * sizeof(double));
    for (int32_t t = 0; t < m->ntris; ++t) {
        const int32_t shift = rng_below(&rng, 3);
        for (int k = 0; k < 3; ++k)
            p.tris[3 * tmap[t] + k] = vmap[m->tris[3 * t + (k + shift) % 3]];
    }
    if (vert_new)
        memcpy(vert_new, vmap, sizeof(int32_t) * (size_t)m->nverts);
    if (tri_new)
        memcpy(tri_new, tmap, sizeof(int32_t) * (size_t)m->ntris);
    free(vmap);
    free(tmap);
    mesh_free(m);
    *m = p;
}

int compare_index_pairs(const void *a, const void *b)
{
    const int32_t *x = a, *y = b;
    if (x[0] != y[0])
        return (x[0] > y[0]) - (x[0] < y[0]);
    return (x[1] > y[1]) - (x[1] < y[1]);
}

int32_t *mesh_edges(const sfa_mesh_data *m, int32_t *count)
{
    const size_t nh = 3 * (size_t)m->ntris;
    int32_t *e = xmalloc(sizeof(int32_t) * 2 * (nh ? nh : 1));
    for (size_t h = 0; h < nh; ++h) {
        const int32_t a = m->tris[h], b = m->tris[h % 3 == 2 ? h - 2 : h + 1];
        e[2 * h] = a < b ? a : b;
        e[2 * h + 1] = a < b ? b : a;
    }
    qsort(e, nh, 2 * sizeof(int32_t), compare_index_pairs);
    size_t n = 0;
    for (size_t h = 0; h < nh; ++h)
        if (n == 0 || compare_index_pairs(e + 2 * h, e + 2 * (n - 1)) != 0) {
            e[2 * n] = e[2 * h];
            e[2 * n + 1] = e[2 * h + 1];
            ++n;
        }
    *count = (int32_t)n;
    return e;
}

double mesh_mean_edge_length(const sfa_mesh_data *m)
{
    int32_t n = 0;
    int32_t *e = mesh_edges(m, &n);
    double sum = 0;
    for (int32_t k = 0; k < n; ++k) {
        const double *p = m->xyz + 3 * e[2 * k], *q = m->xyz + 3 * e[2 * k + 1];
        sum += sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    }
    free(e);
    return n ? sum / (double)n : 0;
}

sfa_mesh_data shape_noisy_icosphere(int k, double r, double fraction, uint64_t seed)
{
    sfa_mesh_data m = shape_icosphere(k, r);
    const double amplitude = fraction * mesh_mean_edge_length(&m);
    shapes_rng rng = rng_seed(seed);
    for (int32_t v = 0; v < m.nverts; ++v) {
        double *p = m.xyz + 3 * v;
        const double len = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        const double scale = (len + amplitude * (2 * rng_uniform(&rng) - 1)) / len;
        for (int i = 0; i < 3; ++i)
            p[i] *= scale;
    }
    return m;
}

sfa_mesh_data shape_jittered_icosphere(int k, double r, double fraction, uint64_t seed)
{
    sfa_mesh_data m = shape_icosphere(k, r);
    const double amplitude = fraction * mesh_mean_edge_length(&m);
    shapes_rng rng = rng_seed(seed);
    for (int32_t v = 0; v < m.nverts; ++v) {
        double *p = m.xyz + 3 * v, d[3], radial = 0, norm = 0, length = 0;
        for (int i = 0; i < 3; ++i) {
            d[i] = 2 * rng_uniform(&rng) - 1;
            radial += d[i] * p[i] / r;
        }
        for (int i = 0; i < 3; ++i) {
            d[i] -= radial * p[i] / r;
            norm += d[i] * d[i];
        }
        const double step = amplitude * rng_uniform(&rng) / sqrt(norm);
        for (int i = 0; i < 3; ++i) {
            p[i] += step * d[i];
            length += p[i] * p[i];
        }
        for (int i = 0; i < 3; ++i)
            p[i] *= r / sqrt(length);
    }
    return m;
}

sfa_mesh_data mesh_copy(const sfa_mesh_data *m)
{
    sfa_mesh_data c = mesh_alloc(m->nverts, m->ntris);
    memcpy(c.xyz, m->xyz, sizeof(double) * 3 * (size_t)m->nverts);
    memcpy(c.tris, m->tris, sizeof(int32_t) * 3 * (size_t)m->ntris);
    return c;
}

void mesh_reverse(sfa_mesh_data *m)
{
    for (int32_t t = 0; t < m->ntris; ++t) {
        const int32_t swap = m->tris[3 * t + 1];
        m->tris[3 * t + 1] = m->tris[3 * t + 2];
        m->tris[3 * t + 2] = swap;
    }
}

void mesh_translate(sfa_mesh_data *m, const double d[3])
{
    for (int32_t v = 0; v < m->nverts; ++v)
        for (int k = 0; k < 3; ++k)
            m->xyz[3 * v + k] += d[k];
}

void mesh_append(sfa_mesh_data *a, const sfa_mesh_data *b)
{
    sfa_mesh_data c = mesh_alloc(a->nverts + b->nverts, a->ntris + b->ntris);
    memcpy(c.xyz, a->xyz, sizeof(double) * 3 * (size_t)a->nverts);
    memcpy(c.xyz + 3 * a->nverts, b->xyz, sizeof(double) * 3 * (size_t)b->nverts);
    memcpy(c.tris, a->tris, sizeof(int32_t) * 3 * (size_t)a->ntris);
    for (int32_t i = 0; i < 3 * b->ntris; ++i)
        c.tris[3 * a->ntris + i] = b->tris[i] + a->nverts;
    mesh_free(a);
    *a = c;
}

sfa_surface *surface_from(const sfa_mesh_data *m, int base, char *err, size_t err_len)
{
    sfa_surface *s = NULL;
    if (err && err_len)
        err[0] = '\0';
    if (sfa_create(&s) != SFA_OK) {
        if (err && err_len)
            snprintf(err, err_len, "sfa_create failed");
        return NULL;
    }
    int32_t *tris = xmalloc(sizeof(int32_t) * 3 * (size_t)m->ntris);
    for (int32_t i = 0; i < 3 * m->ntris; ++i)
        tris[i] = m->tris[i] + base;
    const int rc = sfa_set_mesh(s, m->nverts, m->xyz, m->ntris, tris, base);
    free(tris);
    if (rc != SFA_OK) {
        if (err && err_len)
            snprintf(err, err_len, "%s", sfa_last_error(s));
        sfa_destroy(s);
        return NULL;
    }
    return s;
}

/* The pattern unwritten buffer space keeps, so that a getter writing more (or less)
 * than before shows up as a difference. */
#define SNAPSHOT_FILL 0xA5

void snapshot_take(const sfa_surface *s, snapshot *out)
{
    memset(out, 0, sizeof *out);
    out->counts_status = sfa_get_counts(s, &out->nverts, &out->ntris);
    const int32_t nv = out->nverts > 0 ? out->nverts : 0, nt = out->ntris > 0 ? out->ntris : 0;
    out->xyz = xmalloc(sizeof(double) * 3 * (size_t)nv);
    out->tris = xmalloc(sizeof(int32_t) * 3 * (size_t)nt);
    memset(out->xyz, SNAPSHOT_FILL, sizeof(double) * 3 * (size_t)nv);
    memset(out->tris, SNAPSHOT_FILL, sizeof(int32_t) * 3 * (size_t)nt);
    out->mesh_status = sfa_get_mesh(s, nv, out->xyz, nt, out->tris, 0);
    for (int k = 0; k < SHAPES_NPARAMS; ++k) {
        memset(&out->params[k], SNAPSHOT_FILL, sizeof(double));
        out->param_status[k] = sfa_get_param(s, k, &out->params[k]);
    }
    const size_t cap = (size_t)SNAPSHOT_MAX_NCOMP * (size_t)nv;
    for (int f = 0; f < SNAPSHOT_MAX_FIELDS; ++f) {
        out->fields[f] = xmalloc(sizeof(double) * cap);
        memset(out->fields[f], SNAPSHOT_FILL, sizeof(double) * cap);
        // Field ids are given out 0, 1, 2, ...: past the first id that fails, every one
        // fails the same way, and a field added later shows at that first id.
        out->field_status[f] = f > 0 && out->field_status[f - 1] != SFA_OK
                                   ? out->field_status[f - 1]
                                   : sfa_get_field(s, f, (int32_t)cap, out->fields[f]);
    }
}

void snapshot_free(snapshot *snap)
{
    free(snap->xyz);
    free(snap->tris);
    for (int f = 0; f < SNAPSHOT_MAX_FIELDS; ++f)
        free(snap->fields[f]);
    memset(snap, 0, sizeof *snap);
}

int snapshot_equal(const snapshot *a, const snapshot *b, char *why, size_t why_len)
{
#define DIFFERS(...)                                                                                                   \
    do {                                                                                                               \
        if (why && why_len)                                                                                            \
            snprintf(why, why_len, __VA_ARGS__);                                                                       \
        return 0;                                                                                                      \
    } while (0)
    if (a->counts_status != b->counts_status || a->nverts != b->nverts || a->ntris != b->ntris)
        DIFFERS("counts: status %d, %d vertices, %d triangles before; status %d, %d vertices, %d triangles after",
                a->counts_status, (int)a->nverts, (int)a->ntris, b->counts_status, (int)b->nverts, (int)b->ntris);
    const size_t nv = a->nverts > 0 ? (size_t)a->nverts : 0, nt = a->ntris > 0 ? (size_t)a->ntris : 0;
    if (a->mesh_status != b->mesh_status)
        DIFFERS("sfa_get_mesh status %d before, %d after", a->mesh_status, b->mesh_status);
    for (size_t i = 0; i < 3 * nv; ++i)
        if (memcmp(&a->xyz[i], &b->xyz[i], sizeof(double)) != 0)
            DIFFERS("coordinate %zu of vertex %zu: %.17g before, %.17g after", i % 3, i / 3, a->xyz[i], b->xyz[i]);
    for (size_t i = 0; i < 3 * nt; ++i)
        if (a->tris[i] != b->tris[i])
            DIFFERS("corner %zu of triangle %zu: vertex %d before, %d after", i % 3, i / 3, (int)a->tris[i],
                    (int)b->tris[i]);
    for (int k = 0; k < SHAPES_NPARAMS; ++k)
        if (a->param_status[k] != b->param_status[k] || memcmp(&a->params[k], &b->params[k], sizeof(double)) != 0)
            DIFFERS("parameter %d: %.17g (status %d) before, %.17g (status %d) after", k, a->params[k],
                    a->param_status[k], b->params[k], b->param_status[k]);
    const size_t cap = (size_t)SNAPSHOT_MAX_NCOMP * nv;
    for (int f = 0; f < SNAPSHOT_MAX_FIELDS; ++f) {
        if (a->field_status[f] != b->field_status[f])
            DIFFERS("field %d: sfa_get_field status %d before, %d after", f, a->field_status[f], b->field_status[f]);
        for (size_t i = 0; i < cap; ++i)
            if (memcmp(&a->fields[f][i], &b->fields[f][i], sizeof(double)) != 0)
                DIFFERS("field %d, value %zu: %.17g before, %.17g after", f, i, a->fields[f][i], b->fields[f][i]);
    }
#undef DIFFERS
    return 1;
}

const char *data_dir(void)
{
    const char *dir = getenv("SFA_DATA_DIR");
    return dir && *dir ? dir : "../shared/data";
}

int data_file(const char *name, char *buf, size_t len)
{
    snprintf(buf, len, "%s/%s", data_dir(), name);
    FILE *f = fopen(buf, "rb");
    if (!f)
        return 0;
    fclose(f);
    return 1;
}

void print_data_skip(const char *path)
{
    printf("skipped: needs %s, one of the paper's models (not part of the project; SFA_DATA_DIR=DIR reads "
           "them from DIR)\n",
           path);
    fflush(stdout);
}

/* SPDX-License-Identifier: BSD-3-Clause */
/* Random valid surfaces and smooth velocity fields for the soak (see surfaces.h). The
 * shapes the C tests already have (tests/c/support/shapes.h) are used as they are; the
 * torus, cone, open tube and bent sheet are made here, because only the soak needs them. */
#include "surfaces.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    if (!p) {
        fprintf(stderr, "soak: out of memory\n");
        abort();
    }
    return p;
}

static sfa_mesh_data mesh_new(int32_t nverts, int32_t ntris)
{
    sfa_mesh_data m = {nverts, ntris, xmalloc(sizeof(double) * 3 * (size_t)nverts),
                       xmalloc(sizeof(int32_t) * 3 * (size_t)ntris)};
    return m;
}

static void set_vertex(sfa_mesh_data *m, int32_t v, double x, double y, double z)
{
    m->xyz[3 * v] = x;
    m->xyz[3 * v + 1] = y;
    m->xyz[3 * v + 2] = z;
}

static void set_tri(sfa_mesh_data *m, int32_t t, int32_t a, int32_t b, int32_t c)
{
    m->tris[3 * t] = a;
    m->tris[3 * t + 1] = b;
    m->tris[3 * t + 2] = c;
}

static double uniform(shapes_rng *rng, double lo, double hi) { return lo + (hi - lo) * rng_uniform(rng); }
static int below(shapes_rng *rng, int n) { return (int)(rng_next(rng) % (uint64_t)n); }

/* Torus about the z axis, radii R > r: vertex (i, j) at tube angle v_j around the circle
 * at angle u_i; the triangles of a (u, v) quad are counter-clockwise seen from outside
 * because d/du x d/dv points out. */
static sfa_mesh_data torus(double R, double r, int nu, int nv)
{
    sfa_mesh_data m = mesh_new(nu * nv, 2 * nu * nv);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * PI * i / nu, v = 2 * PI * j / nv;
            set_vertex(&m, i * nv + j, (R + r * cos(v)) * cos(u), (R + r * cos(v)) * sin(u), r * sin(v));
        }
    int32_t t = 0;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const int32_t a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                          d = i * nv + (j + 1) % nv;
            set_tri(&m, t++, a, b, c);
            set_tri(&m, t++, a, c, d);
        }
    return m;
}

/* Closed cone: apex (0, 0, h) (a corner), `rings` circles of `segments` vertices down to
 * the base circle of radius r at z = 0, and the base as a fan about its centre. */
static sfa_mesh_data cone(double r, double h, int segments, int rings)
{
    const int32_t nverts = 2 + rings * segments, ntris = segments * (2 * rings);
    sfa_mesh_data m = mesh_new(nverts, ntris);
    set_vertex(&m, 0, 0, 0, h);
    for (int j = 1; j <= rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const double f = (double)j / rings, a = 2 * PI * i / segments;
            set_vertex(&m, 1 + (j - 1) * segments + i, f * r * cos(a), f * r * sin(a), h * (1 - f));
        }
    const int32_t centre = nverts - 1;
    set_vertex(&m, centre, 0, 0, 0);
#define RING(j, i) (1 + ((j) - 1) * segments + ((i) % segments))
    int32_t t = 0;
    for (int i = 0; i < segments; ++i)
        set_tri(&m, t++, 0, RING(1, i), RING(1, i + 1));
    for (int j = 1; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            set_tri(&m, t++, RING(j, i), RING(j + 1, i), RING(j + 1, i + 1));
            set_tri(&m, t++, RING(j, i), RING(j + 1, i + 1), RING(j, i + 1));
        }
    for (int i = 0; i < segments; ++i)
        set_tri(&m, t++, centre, RING(rings, i + 1), RING(rings, i));
#undef RING
    return m;
}

/* Open tube (no caps) of radius r along z in [-h/2, h/2]: two boundary circles. */
static sfa_mesh_data tube(double r, double h, int segments, int rings)
{
    sfa_mesh_data m = mesh_new((rings + 1) * segments, 2 * rings * segments);
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const double a = 2 * PI * i / segments;
            set_vertex(&m, j * segments + i, r * cos(a), r * sin(a), -h / 2 + h * j / rings);
        }
    int32_t t = 0;
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const int32_t a = j * segments + i, b = j * segments + (i + 1) % segments,
                          c = (j + 1) * segments + (i + 1) % segments, d = (j + 1) * segments + i;
            set_tri(&m, t++, a, b, c);
            set_tri(&m, t++, a, c, d);
        }
    return m;
}

/* An open sheet: shape_grid's patch, centred, with a smooth bump of height `bump` times
 * its width (z = bump w sin(kx x) sin(ky y)); the triangles are split along alternating
 * diagonals by shape_grid. */
static sfa_mesh_data bent_sheet(shapes_rng *rng, int n)
{
    const double h = 1.0 / n;
    sfa_mesh_data m = shape_grid(n, n, h);
    const double bump = uniform(rng, 0, 0.3), kx = uniform(rng, 1, 4), ky = uniform(rng, 1, 4);
    for (int32_t v = 0; v < m.nverts; ++v) {
        double *p = m.xyz + 3 * v;
        p[0] -= 0.5;
        p[1] -= 0.5;
        p[2] = bump * sin(kx * p[0] * PI) * sin(ky * p[1] * PI);
    }
    return m;
}

/* One closed piece for a surface of several components, its bounding radius in *radius. */
static sfa_mesh_data piece(shapes_rng *rng, double r, double *radius, char *what, size_t len)
{
    switch (below(rng, 4)) {
    case 0:
        snprintf(what, len, "sphere");
        *radius = r;
        return shape_icosphere(2 + below(rng, 2), r);
    case 1: {
        const double c = uniform(rng, 0.2, 1);
        snprintf(what, len, "ellipsoid");
        *radius = r;
        return shape_ellipsoid(2 + below(rng, 2), r, r * uniform(rng, 0.4, 1), r * c);
    }
    case 2: {
        const double lo[3] = {-r / 2, -r / 2, -r / 2}, hi[3] = {r / 2, r / 2, r / 2};
        snprintf(what, len, "box");
        *radius = r * sqrt(3) / 2;
        return shape_box(2 + below(rng, 4), lo, hi);
    }
    default:
        snprintf(what, len, "torus");
        *radius = r;
        return torus(0.7 * r, 0.3 * r, 24 + below(rng, 12), 10 + below(rng, 6));
    }
}

/* 2 to 5 closed pieces of radii 0.1 to 1 in a row along x, each gap 0.02 to 0.5 of the
 * smaller neighbour's radius (the nearest ones are closer than an edge: drops about to
 * meet, for the collision-safe motion and the topology change). */
static sfa_mesh_data components(shapes_rng *rng, char *what, size_t len)
{
    const int count = 2 + below(rng, 4);
    sfa_mesh_data all = {0, 0, NULL, NULL};
    double x = 0, previous = 0;
    size_t used = (size_t)snprintf(what, len, "%d components:", count);
    for (int k = 0; k < count; ++k) {
        double radius = 0;
        char name[32];
        sfa_mesh_data p = piece(rng, uniform(rng, 0.1, 1), &radius, name, sizeof name);
        if (used < len)
            used += (size_t)snprintf(what + used, len - used, " %s", name);
        double R[9];
        rotation_random(rng, R);
        mesh_rotate_scale(&p, R, 1);
        if (k > 0) {
            const double smaller = radius < previous ? radius : previous;
            x += previous + uniform(rng, 0.02, 0.5) * smaller + radius;
        }
        const double d[3] = {x, uniform(rng, -0.1, 0.1), uniform(rng, -0.1, 0.1)};
        mesh_translate(&p, d);
        if (k == 0)
            all = p;
        else {
            mesh_append(&all, &p);
            mesh_free(&p);
        }
        previous = radius;
    }
    return all;
}

soak_surface soak_random_surface(shapes_rng *rng)
{
    soak_surface out;
    memset(&out, 0, sizeof out);
    char shape[120];
    sfa_mesh_data m;
    switch (below(rng, 12)) {
    case 0: {
        const int k = 2 + below(rng, 3);
        snprintf(shape, sizeof shape, "sphere k=%d", k);
        m = shape_icosphere(k, 1);
        break;
    }
    case 1: {
        const int k = 2 + below(rng, 2);
        snprintf(shape, sizeof shape, "jittered sphere k=%d", k);
        m = shape_jittered_icosphere(k, 1, 0.3, rng_next(rng));
        break;
    }
    case 2: {
        const double r = uniform(rng, 0.1, 0.5);
        snprintf(shape, sizeof shape, "torus r/R=%.3g", r);
        m = torus(1, r, 24 + below(rng, 40), 8 + below(rng, 16));
        break;
    }
    case 3: {
        const double lo[3] = {0, 0, 0}, hi[3] = {1, uniform(rng, 0.3, 1), uniform(rng, 0.3, 1)};
        const int n = 2 + below(rng, 8);
        snprintf(shape, sizeof shape, "box n=%d", n);
        m = shape_box(n, lo, hi);
        break;
    }
    case 4: {
        const double h = uniform(rng, 0.3, 2);
        snprintf(shape, sizeof shape, "cone h/r=%.3g", h);
        m = cone(1, h, 16 + below(rng, 32), 4 + below(rng, 12));
        break;
    }
    case 5: {
        snprintf(shape, sizeof shape, "capped cylinder");
        m = shape_capped_cylinder(uniform(rng, 0.2, 1), uniform(rng, 0.5, 3), 12 + below(rng, 24),
                                  2 + below(rng, 12));
        break;
    }
    case 6: {
        const double t = uniform(rng, 0.02, 0.2);
        const double lo[3] = {0, 0, 0}, hi[3] = {1, uniform(rng, 0.5, 1), t};
        const int n = 4 + below(rng, 8);
        snprintf(shape, sizeof shape, "slab t=%.3g n=%d", t, n);
        m = shape_box(n, lo, hi);
        break;
    }
    case 7: {
        const double c = uniform(rng, 0.03, 0.2);
        snprintf(shape, sizeof shape, "thin ellipsoid c=%.3g", c);
        m = shape_ellipsoid(3 + below(rng, 2), 1, uniform(rng, 0.5, 1), c);
        break;
    }
    case 8:
    case 9: m = components(rng, shape, sizeof shape); break;
    case 10: {
        if (below(rng, 2)) {
            const int n = 8 + below(rng, 32);
            snprintf(shape, sizeof shape, "open sheet n=%d", n);
            m = bent_sheet(rng, n);
        } else {
            snprintf(shape, sizeof shape, "open spherical cap");
            m = shape_spherical_cap(1, uniform(rng, 0.3, 2.5), 12 + below(rng, 24), 3 + below(rng, 10));
        }
        break;
    }
    default: {
        snprintf(shape, sizeof shape, "open tube");
        m = tube(uniform(rng, 0.2, 1), uniform(rng, 0.5, 3), 12 + below(rng, 24), 2 + below(rng, 16));
        break;
    }
    }
    /* Orientation, numbering, scale and offset are what the library must not care about. */
    double R[9];
    rotation_random(rng, R);
    const double scale = pow(10, uniform(rng, -6, 6));
    mesh_rotate_scale(&m, R, scale);
    mesh_permute(&m, rng_next(rng), NULL, NULL);
    double offset[3] = {0, 0, 0}, far = 0;
    if (below(rng, 2)) {
        far = pow(10, uniform(rng, -1, 6));
        for (int k = 0; k < 3; ++k)
            offset[k] = uniform(rng, -1, 1) * far * scale;
        mesh_translate(&m, offset);
    }
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int32_t v = 0; v < m.nverts; ++v)
        for (int k = 0; k < 3; ++k) {
            lo[k] = fmin(lo[k], m.xyz[3 * v + k]);
            hi[k] = fmax(hi[k], m.xyz[3 * v + k]);
        }
    double diagonal = 0;
    for (int k = 0; k < 3; ++k) {
        out.centre[k] = 0.5 * (lo[k] + hi[k]);
        diagonal += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    }
    out.size = 0.5 * sqrt(diagonal);
    out.mesh = m;
    snprintf(out.what, sizeof out.what, "%s, %d vertices, scale %.3g, offset %.3g sizes", shape, (int)m.nverts,
             scale, far);
    return out;
}

/* ------------------------------------------------------------------ flows */

const char *soak_flow_name(int kind)
{
    static const char *names[FLOW_KINDS] = {"rotation", "shear", "vortex", "deformation", "translation",
                                            "expansion"};
    return kind >= 0 && kind < FLOW_KINDS ? names[kind] : "?";
}

int soak_flow_divergence_free(int kind) { return kind != FLOW_EXPANSION; }

soak_flow soak_random_flow(shapes_rng *rng, const soak_surface *surface)
{
    soak_flow f;
    memset(&f, 0, sizeof f);
    f.kind = below(rng, FLOW_KINDS);
    memcpy(f.centre, surface->centre, sizeof f.centre);
    f.size = surface->size;
    rotation_random(rng, f.R);
    for (int k = 0; k < 3; ++k)
        f.a[k] = uniform(rng, -1, 1);
    if (f.kind == FLOW_EXPANSION)
        f.a[0] *= 0.5; /* volume changes by exp(3 a t): keep it gentle */
    f.period = uniform(rng, 1, 4);
    return f;
}

void soak_flow_eval(void *ctx, int32_t n, const double *xyz, double t, double *vel)
{
    const soak_flow *f = ctx;
    for (int32_t v = 0; v < n; ++v) {
        double d[3], x[3], u[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k)
            d[k] = (xyz[3 * v + k] - f->centre[k]) / f->size;
        for (int k = 0; k < 3; ++k) /* x = R^T d */
            x[k] = f->R[k] * d[0] + f->R[3 + k] * d[1] + f->R[6 + k] * d[2];
        /* The periodic flows on [-1, 1]^3 mapped to the unit cube, where they are defined. */
        const double X = 0.5 * x[0] + 0.5, Y = 0.5 * x[1] + 0.5, Z = 0.5 * x[2] + 0.5;
        const double c = cos(PI * t / f->period);
        switch (f->kind) {
        case FLOW_ROTATION: /* a x x */
            u[0] = f->a[1] * x[2] - f->a[2] * x[1];
            u[1] = f->a[2] * x[0] - f->a[0] * x[2];
            u[2] = f->a[0] * x[1] - f->a[1] * x[0];
            break;
        case FLOW_SHEAR: u[0] = f->a[0] * x[1]; break;
        case FLOW_VORTEX:
            u[0] = sin(PI * X) * sin(PI * X) * sin(2 * PI * Y) * c;
            u[1] = -sin(2 * PI * X) * sin(PI * Y) * sin(PI * Y) * c;
            break;
        case FLOW_DEFORMATION:
            u[0] = 2 * sin(PI * X) * sin(PI * X) * sin(2 * PI * Y) * sin(2 * PI * Z) * c;
            u[1] = -sin(2 * PI * X) * sin(PI * Y) * sin(PI * Y) * sin(2 * PI * Z) * c;
            u[2] = -sin(2 * PI * X) * sin(2 * PI * Y) * sin(PI * Z) * sin(PI * Z) * c;
            break;
        case FLOW_TRANSLATION:
            for (int k = 0; k < 3; ++k)
                u[k] = f->a[k];
            break;
        default: /* FLOW_EXPANSION */
            for (int k = 0; k < 3; ++k)
                u[k] = f->a[0] * x[k];
            break;
        }
        for (int k = 0; k < 3; ++k) /* back to the host's frame and units: R u size */
            vel[3 * v + k] = (f->R[3 * k] * u[0] + f->R[3 * k + 1] * u[1] + f->R[3 * k + 2] * u[2]) * f->size;
    }
}

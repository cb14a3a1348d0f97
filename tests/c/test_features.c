/* SPDX-License-Identifier: BSD-3-Clause */
/* Feature detection (paper §2.2, §3.1): sfa_get_feature_ranks, sfa_get_ridge_edges and
 * sfa_get_vertex_frames on shapes whose features are known exactly, on a real CAD part, and
 * under the changes the answer must not depend on (rotation, scale, numbering). */
#include "support/testing.h"

static const double pi = 3.14159265358979323846;

#define SENTINEL_BYTE 0x5A

/* What the three functions say about one surface. degree[v] counts the ridge edges at v. */
typedef struct features {
    int32_t nverts, nridges;
    int32_t *ranks, *ridges, *degree;
    int32_t count[3]; /* vertices of rank 0, 1, 2 */
} features;

static void features_free(features *f)
{
    free(f->ranks);
    free(f->ridges);
    free(f->degree);
    memset(f, 0, sizeof *f);
}

/* Reads ranks and ridge edges and checks what the contract says of any mesh: ranks are 0, 1
 * or 2; ridge edges are edges of the mesh, smaller index first, sorted, without repeats; a
 * rank-1 vertex is on exactly two ridge edges; where curves end or meet (one, three or more
 * ridge edges) the vertex is a corner. */
static features features_of(const sfa_surface *s)
{
    features f;
    memset(&f, 0, sizeof f);
    int32_t ntris = 0;
    assert_int_equal(sfa_get_counts(s, &f.nverts, &ntris), SFA_OK);
    f.ranks = malloc(sizeof(int32_t) * (size_t)f.nverts);
    f.degree = calloc((size_t)f.nverts, sizeof(int32_t));
    assert_non_null(f.ranks);
    assert_non_null(f.degree);
    assert_ok(s, sfa_get_feature_ranks(s, f.nverts, f.ranks));
    assert_ok(s, sfa_get_ridge_edges(s, 0, NULL, &f.nridges, 0));
    assert_true(f.nridges >= 0);
    f.ridges = malloc(sizeof(int32_t) * 2 * (size_t)(f.nridges ? f.nridges : 1));
    assert_non_null(f.ridges);
    int32_t again = -1;
    assert_ok(s, sfa_get_ridge_edges(s, f.nridges, f.ridges, &again, 0));
    assert_int_equal(again, f.nridges);

    for (int32_t v = 0; v < f.nverts; ++v) {
        if (f.ranks[v] < 0 || f.ranks[v] > 2)
            fail_msg("vertex %d has rank %d", (int)v, (int)f.ranks[v]);
        ++f.count[f.ranks[v]];
    }
    sfa_mesh_data m = read_back(s);
    int32_t nedges = 0;
    int32_t *edges = mesh_edges(&m, &nedges);
    for (int32_t e = 0; e < f.nridges; ++e) {
        const int32_t *r = f.ridges + 2 * e;
        if (!(r[0] >= 0 && r[0] < r[1] && r[1] < f.nverts))
            fail_msg("ridge edge %d is (%d, %d) on %d vertices", (int)e, (int)r[0], (int)r[1], (int)f.nverts);
        if (e > 0 && compare_index_pairs(r - 2, r) >= 0)
            fail_msg("ridge edges %d and %d are out of order: (%d, %d), (%d, %d)", (int)e - 1, (int)e, (int)r[-2],
                     (int)r[-1], (int)r[0], (int)r[1]);
        if (!bsearch(r, edges, (size_t)nedges, 2 * sizeof(int32_t), compare_index_pairs))
            fail_msg("ridge edge (%d, %d) is not an edge of the mesh", (int)r[0], (int)r[1]);
        ++f.degree[r[0]];
        ++f.degree[r[1]];
    }
    free(edges);
    mesh_free(&m);
    for (int32_t v = 0; v < f.nverts; ++v) {
        if (f.ranks[v] == 1 && f.degree[v] != 2)
            fail_msg("vertex %d has rank 1 but %d ridge edges", (int)v, (int)f.degree[v]);
        if ((f.degree[v] == 1 || f.degree[v] >= 3) && f.ranks[v] != 2)
            fail_msg("vertex %d is on %d ridge edges but has rank %d, not 2", (int)v, (int)f.degree[v],
                     (int)f.ranks[v]);
    }
    return f;
}

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static double degrees_between_lines(const double *a, const double *b)
{
    const double c = fabs(dot3(a, b)) / sqrt(dot3(a, a) * dot3(b, b));
    return acos(c < 1 ? c : 1) * 180 / pi;
}

/* The largest aspect ratio the metric allows with the default bounds: sqrt(psi_u/psi_l). */
static double max_aspect_ratio(void) { return tan(15 * pi / 180) / tan(4 * pi / 180); }

/* Vertex frames, checked against the contract: unit normals, unit long directions in the
 * tangent plane, 1 <= aspect ratio <= sqrt(psi_u/psi_l) (default bounds). */
typedef struct frames {
    double *normals, *long_dirs, *aspect;
} frames;

static frames frames_of(const sfa_surface *s, int32_t nverts)
{
    frames fr;
    fr.normals = malloc(sizeof(double) * 3 * (size_t)nverts);
    fr.long_dirs = malloc(sizeof(double) * 3 * (size_t)nverts);
    fr.aspect = malloc(sizeof(double) * (size_t)nverts);
    assert_non_null(fr.normals);
    assert_non_null(fr.long_dirs);
    assert_non_null(fr.aspect);
    assert_ok(s, sfa_get_vertex_frames(s, nverts, fr.normals, fr.long_dirs, fr.aspect));
    const double bound = max_aspect_ratio() + 1e-12;
    for (int32_t v = 0; v < nverts; ++v) {
        const double *n = fr.normals + 3 * v, *l = fr.long_dirs + 3 * v;
        if (!(fabs(sqrt(dot3(n, n)) - 1) <= 1e-9 && fabs(sqrt(dot3(l, l)) - 1) <= 1e-9))
            fail_msg("vertex %d: |normal| = %.17g, |long direction| = %.17g, expected 1", (int)v, sqrt(dot3(n, n)),
                     sqrt(dot3(l, l)));
        if (!(fabs(dot3(n, l)) <= 1e-9))
            fail_msg("vertex %d: the long direction is not tangent, normal . long = %.3g", (int)v, dot3(n, l));
        if (!(fr.aspect[v] >= 1 - 1e-12 && fr.aspect[v] <= bound))
            fail_msg("vertex %d: aspect ratio %.17g outside [1, %.17g]", (int)v, fr.aspect[v], bound);
    }
    return fr;
}

static void frames_free(frames *fr)
{
    free(fr->normals);
    free(fr->long_dirs);
    free(fr->aspect);
}

/* ------------------------------------------------------------------ boxes */

/* One box with n x n cells per face, turned by R and scaled. Returns 1 if every expectation
 * holds, else 0 with the first difference in `why` (the answer is checked for many cases
 * before failing, so that a report shows all the cases that go wrong). */
static int box_case(int n, const double R[9], double scale, char *why, size_t why_len)
{
    const double lo[3] = {-0.5, -0.25, 0}, hi[3] = {0.5, 0.5, 0.6};
    sfa_mesh_data m = shape_box(n, lo, hi);
    /* Which coordinates of each vertex lie on the box's planes, before the transformation. */
    int *extreme = malloc(sizeof(int) * (size_t)m.nverts);
    assert_non_null(extreme);
    for (int32_t v = 0; v < m.nverts; ++v) {
        extreme[v] = 0;
        for (int k = 0; k < 3; ++k)
            if (m.xyz[3 * v + k] == lo[k] || m.xyz[3 * v + k] == hi[k])
                extreme[v] |= 1 << k;
    }
    const sfa_mesh_data box = mesh_copy(&m); /* the coordinates before the transformation */
    mesh_rotate_scale(&m, R, scale);
    sfa_surface *s = make_surface(&m, 0);
    features f = features_of(s);
    int ok = 1;
#define BOX_FAILS(...)                                                                                                 \
    do {                                                                                                               \
        snprintf(why, why_len, __VA_ARGS__);                                                                           \
        ok = 0;                                                                                                        \
        goto done;                                                                                                     \
    } while (0)
    if (f.count[2] != 8 || f.count[1] != 12 * (n - 1) || f.nridges != 12 * n)
        BOX_FAILS("%d corners (expected 8), %d ridge vertices (expected %d), %d ridge edges (expected %d)",
                  (int)f.count[2], (int)f.count[1], 12 * (n - 1), (int)f.nridges, 12 * n);
    for (int32_t v = 0; v < m.nverts; ++v) {
        const int bits = (extreme[v] & 1) + (extreme[v] >> 1 & 1) + (extreme[v] >> 2 & 1);
        const int expected = bits == 3 ? 2 : bits == 2 ? 1 : 0;
        if (f.ranks[v] != expected)
            BOX_FAILS("vertex %d at (%.6g, %.6g, %.6g) before the transformation has rank %d, expected %d (on %d "
                      "ridge edges)",
                      (int)v, box.xyz[3 * v], box.xyz[3 * v + 1], box.xyz[3 * v + 2], (int)f.ranks[v], expected,
                      (int)f.degree[v]);
    }
    /* Every ridge edge runs along one box edge: its ends share two coordinates that lie on
     * the box's planes. (A face diagonal of n = 1 joins two corners but shares only one.) */
    for (int32_t e = 0; e < f.nridges; ++e) {
        const int32_t a = f.ridges[2 * e], b = f.ridges[2 * e + 1];
        int shared = 0;
        for (int k = 0; k < 3; ++k)
            shared += (extreme[a] & extreme[b]) >> k & (box.xyz[3 * a + k] == box.xyz[3 * b + k]);
        if (shared < 2)
            BOX_FAILS("ridge edge (%d, %d) is not on an edge of the box", (int)a, (int)b);
    }
#undef BOX_FAILS
done:
    features_free(&f);
    sfa_destroy(s);
    free(extreme);
    mesh_free(&m);
    sfa_mesh_data unused = box;
    mesh_free(&unused);
    return ok;
}

static void boxes(void **state)
{
    (void)state;
    const int ns[] = {1, 2, 3, 4, 8, 16, 32};
    const double scales[] = {1, 1e-3, 1e3};
    const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    double turned[9];
    rotation_axis_angle((const double[3]){1, 2, 3}, 0.7, turned);
    int cases = 0, failures = 0;
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i)
        for (size_t j = 0; j < sizeof scales / sizeof scales[0]; ++j)
            for (int r = 0; r < 2; ++r) {
                char why[256];
                ++cases;
                if (!box_case(ns[i], r ? turned : identity, scales[j], why, sizeof why)) {
                    ++failures;
                    print_message("box n = %d, scale %g, %s: %s\n", ns[i], scales[j], r ? "rotated" : "axis-aligned",
                                  why);
                }
            }
    if (failures)
        fail_msg("%d of %d box cases are wrong (listed above)", failures, cases);
}

/* ------------------------------------------------------------ smooth shapes */

/* No feature at all: every rank 0, no ridge edge. Returns 1, or 0 after printing why. */
static int featureless(const sfa_mesh_data *m, const char *name)
{
    sfa_surface *s = make_surface(m, 0);
    features f = features_of(s);
    int first = -1;
    for (int32_t v = 0; v < f.nverts && first < 0; ++v)
        if (f.ranks[v] != 0)
            first = (int)v;
    const int ok = f.count[0] == f.nverts && f.nridges == 0;
    if (!ok)
        print_message("%s: %d ridge and %d corner vertices, %d ridge edges\n", name, (int)f.count[1],
                      (int)f.count[2], (int)f.nridges);
    if (first >= 0)
        print_message("%s: first feature vertex %d at (%.6g, %.6g, %.6g), rank %d\n", name, first, m->xyz[3 * first],
                      m->xyz[3 * first + 1], m->xyz[3 * first + 2], (int)f.ranks[first]);
    features_free(&f);
    sfa_destroy(s);
    return ok;
}

static void spheres_have_no_features(void **state)
{
    (void)state;
    int failures = 0;
    for (int k = 2; k <= 5; ++k) {
        char name[64];
        sfa_mesh_data m = shape_icosphere(k, 1.0);
        snprintf(name, sizeof name, "icosphere k = %d", k);
        failures += !featureless(&m, name);
        mesh_free(&m);
        m = shape_noisy_icosphere(k, 1.0, 0.005, 1234u + (uint64_t)k);
        snprintf(name, sizeof name, "icosphere k = %d with 0.5%% radial noise", k);
        failures += !featureless(&m, name);
        mesh_free(&m);
    }
    if (failures)
        fail_msg("%d of 8 spheres show features (listed above)", failures);
}

/* ---------------------------------------------------------------- cylinder */

static void capped_cylinder(void **state)
{
    (void)state;
    enum { segments = 32, rings = 10 };
    sfa_mesh_data m = shape_capped_cylinder(1.0, 2.0, segments, rings);
    sfa_surface *s = make_surface(&m, 0);
    features f = features_of(s);
    print_message("capped cylinder (%d segments): ranks 0/1/2: %d/%d/%d, %d ridge edges\n", segments,
                  (int)f.count[0], (int)f.count[1], (int)f.count[2], (int)f.nridges);
    for (int32_t v = 0; v < m.nverts; ++v) {
        const int rim = v < segments || (v >= rings * segments && v < (rings + 1) * segments);
        if (f.ranks[v] != rim)
            fail_msg("vertex %d at (%.6g, %.6g, %.6g) (%s) has rank %d, expected %d", (int)v, m.xyz[3 * v],
                     m.xyz[3 * v + 1], m.xyz[3 * v + 2], rim ? "rim" : "side or cap centre", (int)f.ranks[v], rim);
    }
    assert_int_equal(f.nridges, 2 * segments);
    /* Each ridge edge joins neighbours on one rim. */
    for (int32_t e = 0; e < f.nridges; ++e) {
        const int32_t a = f.ridges[2 * e], b = f.ridges[2 * e + 1];
        if (!(a / segments == b / segments && (b - a == 1 || b - a == segments - 1)))
            fail_msg("ridge edge (%d, %d) is not a rim edge", (int)a, (int)b);
    }

    /* On the side the minimum curvature direction is the axis; the metric wants triangles
     * long along it. */
    frames fr = frames_of(s, m.nverts);
    double worst = 0, amin = INFINITY, amax = 0;
    for (int32_t v = segments; v < rings * segments; ++v) {
        const double angle = degrees_between_lines(fr.long_dirs + 3 * v, (const double[3]){0, 0, 1});
        if (angle > worst)
            worst = angle;
        amin = fmin(amin, fr.aspect[v]);
        amax = fmax(amax, fr.aspect[v]);
        if (!(angle <= 5))
            fail_msg("side vertex %d at (%.6g, %.6g, %.6g): long direction (%.6f, %.6f, %.6f) is %.3f degrees off the "
                     "axis",
                     (int)v, m.xyz[3 * v], m.xyz[3 * v + 1], m.xyz[3 * v + 2], fr.long_dirs[3 * v],
                     fr.long_dirs[3 * v + 1], fr.long_dirs[3 * v + 2], angle);
    }
    print_message("side vertices: long direction at most %.3g degrees off the axis, aspect ratios %.4f to %.4f "
                  "(bound %.4f)\n",
                  worst, amin, amax, max_aspect_ratio());
    frames_free(&fr);
    features_free(&f);
    sfa_destroy(s);
    mesh_free(&m);
}

/* ----------------------------------------------------------------- ellipsoids */

/* The analytic direction of minimum curvature of x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 at p, and
 * the ratio of the principal curvatures (>= 1). With D = diag(1/a^2, 1/b^2, 1/c^2) the second
 * fundamental form is D / |D p| on the tangent plane, so the principal directions are the
 * eigenvectors of D restricted to it. */
static double min_curvature_direction(const double p[3], const double axes[3], double dir[3])
{
    const double d[3] = {1 / (axes[0] * axes[0]), 1 / (axes[1] * axes[1]), 1 / (axes[2] * axes[2])};
    double n[3] = {d[0] * p[0], d[1] * p[1], d[2] * p[2]};
    const double len = sqrt(dot3(n, n));
    for (int k = 0; k < 3; ++k)
        n[k] /= len;
    /* A tangent basis t1, t2. */
    double t1[3];
    const double helper[3] = {fabs(n[0]) < 0.6 ? 1 : 0, fabs(n[0]) < 0.6 ? 0 : 1, 0};
    const double h = dot3(helper, n);
    for (int k = 0; k < 3; ++k)
        t1[k] = helper[k] - h * n[k];
    const double l1 = sqrt(dot3(t1, t1));
    for (int k = 0; k < 3; ++k)
        t1[k] /= l1;
    const double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
    double b11 = 0, b12 = 0, b22 = 0;
    for (int k = 0; k < 3; ++k) {
        b11 += d[k] * t1[k] * t1[k];
        b12 += d[k] * t1[k] * t2[k];
        b22 += d[k] * t2[k] * t2[k];
    }
    /* Smaller eigenvalue of the symmetric 2x2 [b11 b12; b12 b22] and its eigenvector. */
    const double mean = 0.5 * (b11 + b22), radius = sqrt(0.25 * (b11 - b22) * (b11 - b22) + b12 * b12);
    const double kmin = mean - radius, kmax = mean + radius;
    double u = b12, w = kmin - b11; /* from the first row */
    if (fabs(u) + fabs(w) < 1e-14 * (fabs(b11) + fabs(b22))) {
        u = kmin - b22; /* from the second row */
        w = b12;
    }
    for (int k = 0; k < 3; ++k)
        dir[k] = u * t1[k] + w * t2[k];
    return kmax / kmin;
}

/* The share of the vertices in the chosen region whose long direction is within 5 degrees
 * of the analytic minimum curvature direction. The region: metric aspect ratio > 1.05 (where
 * the metric is isotropic, or clamped to it, its long direction means nothing), principal
 * curvatures differing by at least 30% (away from the four umbilics, where the direction is
 * undefined and the discrete one arbitrary), and more than 0.15 from the ends of the axes
 * (where the stretched icosphere's triangles are most distorted relative to the curvature
 * directions). The region shrinks under refinement: the quadric's eigenvalue ratios fall
 * like the squared edge length, so more of the surface is clamped to an isotropic metric. */
static double ellipsoid_agreement(int k, const double axes[3], int *considered)
{
    sfa_mesh_data m = shape_ellipsoid(k, axes[0], axes[1], axes[2]);
    sfa_surface *s = make_surface(&m, 0);
    features f = features_of(s);
    if (f.nridges != 0 || f.count[0] != f.nverts)
        fail_msg("ellipsoid (%g, %g, %g), k = %d: %d ridge and %d corner vertices, %d ridge edges; expected none",
                 axes[0], axes[1], axes[2], k, (int)f.count[1], (int)f.count[2], (int)f.nridges);
    frames fr = frames_of(s, m.nverts);
    int in_region = 0, agree = 0;
    double worst = 0;
    int worst_vertex = -1;
    for (int32_t v = 0; v < m.nverts; ++v) {
        const double *p = m.xyz + 3 * v;
        double dir[3];
        const double ratio = min_curvature_direction(p, axes, dir);
        int near_end = 0;
        for (int a = 0; a < 3; ++a)
            for (int sign = -1; sign <= 1; sign += 2) {
                double q[3] = {0, 0, 0};
                q[a] = sign * axes[a];
                const double dq[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
                near_end |= sqrt(dot3(dq, dq)) < 0.15;
            }
        if (fr.aspect[v] <= 1.05 || ratio < 1.3 || near_end)
            continue;
        ++in_region;
        const double angle = degrees_between_lines(fr.long_dirs + 3 * v, dir);
        agree += angle <= 5;
        if (angle > worst) {
            worst = angle;
            worst_vertex = (int)v;
        }
    }
    print_message("ellipsoid (%g, %g, %g), k = %d, %d vertices: %d in the region, %d (%.1f%%) within 5 degrees of "
                  "the minimum curvature direction; worst %.2f degrees at vertex %d\n",
                  axes[0], axes[1], axes[2], k, (int)m.nverts, in_region, agree,
                  in_region ? 100.0 * agree / in_region : 0.0, worst, worst_vertex);
    frames_free(&fr);
    features_free(&f);
    sfa_destroy(s);
    mesh_free(&m);
    *considered = in_region;
    return in_region ? (double)agree / in_region : 0;
}

static void ellipsoid_long_directions(void **state)
{
    (void)state;
    const double axes[3] = {1, 0.6, 0.3};
    for (int k = 3; k <= 4; ++k) {
        int considered = 0;
        const double share = ellipsoid_agreement(k, axes, &considered);
        /* The region must not be a handful of lucky vertices. */
        if (considered < 100)
            fail_msg("k = %d: only %d vertices in the region", k, considered);
        if (share < 0.9)
            fail_msg("k = %d: only %.1f%% of the %d vertices agree within 5 degrees (expected >= 90%%)", k,
                     100 * share, considered);
    }
}

/* On the oblate spheroid (1, 1, 0.3) the curvature along the circles of latitude is the
 * smaller one everywhere but at the poles: within |z| < 0.2 (the rim region, where the
 * meridians bend sharply), wherever the metric is anisotropic (aspect ratio > 1.05; where it
 * is clamped to isotropic its long direction means nothing), the long direction is tangent
 * to the circle of latitude. */
static void oblate_rim_long_directions(void **state)
{
    (void)state;
    sfa_mesh_data m = shape_ellipsoid(4, 1, 1, 0.3);
    sfa_surface *s = make_surface(&m, 0);
    features f = features_of(s);
    assert_int_equal(f.nridges, 0);
    assert_int_equal(f.count[0], f.nverts);
    frames fr = frames_of(s, m.nverts);
    int region = 0, agree = 0;
    double worst = 0;
    for (int32_t v = 0; v < m.nverts; ++v) {
        const double *p = m.xyz + 3 * v;
        if (fabs(p[2]) >= 0.2 || fr.aspect[v] <= 1.05)
            continue;
        const double circle[3] = {-p[1], p[0], 0};
        const double angle = degrees_between_lines(fr.long_dirs + 3 * v, circle);
        ++region;
        agree += angle <= 5;
        worst = fmax(worst, angle);
    }
    print_message("oblate spheroid rim: %d of %d vertices within 5 degrees of the circle of latitude, worst %.2f\n",
                  agree, region, worst);
    assert_true(region > 100);
    if (agree != region)
        fail_msg("%d of %d rim vertices have a long direction more than 5 degrees off the circle of latitude "
                 "(worst %.2f degrees)",
                 region - agree, region, worst);
    frames_free(&fr);
    features_free(&f);
    sfa_destroy(s);
    mesh_free(&m);
}

/* --------------------------------------------------------------- open surfaces */

static void open_grid(void **state)
{
    (void)state;
    enum { nx = 6, ny = 4 };
    sfa_mesh_data m = shape_grid(nx, ny, 0.1);
    sfa_surface *s = make_surface(&m, 0);
    features f = features_of(s);
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const int32_t v = j * (nx + 1) + i;
            const int boundary = i == 0 || i == nx || j == 0 || j == ny;
            const int corner = (i == 0 || i == nx) && (j == 0 || j == ny);
            const int expected = corner ? 2 : boundary ? 1 : 0;
            if (f.ranks[v] != expected)
                fail_msg("grid vertex (%d, %d) = %d has rank %d, expected %d", i, j, (int)v, (int)f.ranks[v], expected);
        }
    /* The ridge edges are the boundary edges, all of them and nothing else. */
    assert_int_equal(f.nridges, 2 * (nx + ny));
    for (int32_t e = 0; e < f.nridges; ++e) {
        const int32_t a = f.ridges[2 * e], b = f.ridges[2 * e + 1];
        const int ia = a % (nx + 1), ja = a / (nx + 1), ib = b % (nx + 1), jb = b / (nx + 1);
        const int on_boundary = (ja == jb && (ja == 0 || ja == ny)) || (ia == ib && (ia == 0 || ia == nx));
        if (!on_boundary || abs(ia - ib) + abs(ja - jb) != 1)
            fail_msg("ridge edge (%d, %d) is not a boundary edge", (int)a, (int)b);
    }
    features_free(&f);
    sfa_destroy(s);
    mesh_free(&m);
}

static void open_cap(void **state)
{
    (void)state;
    enum { segments = 32, rings = 8 };
    sfa_mesh_data m = shape_spherical_cap(1.0, 80 * pi / 180, segments, rings);
    sfa_surface *s = make_surface(&m, 0);
    features f = features_of(s);
    const int32_t first_boundary = m.nverts - segments;
    for (int32_t v = 0; v < m.nverts; ++v) {
        const int expected = v >= first_boundary;
        if (f.ranks[v] != expected)
            fail_msg("cap vertex %d at (%.6g, %.6g, %.6g) has rank %d, expected %d", (int)v, m.xyz[3 * v],
                     m.xyz[3 * v + 1], m.xyz[3 * v + 2], (int)f.ranks[v], expected);
    }
    assert_int_equal(f.nridges, segments);
    for (int32_t e = 0; e < f.nridges; ++e)
        assert_true(f.ridges[2 * e] >= first_boundary);
    features_free(&f);
    sfa_destroy(s);
    mesh_free(&m);
}

/* ---------------------------------------------------------------- fandisk */

static void fandisk(void **state)
{
    (void)state;
    sfa_mesh_data m;
    read_data_or_skip("fandisk.obj", &m);
    sfa_surface *s = make_surface(&m, 0);
    features f = features_of(s); /* includes: every rank-1 vertex has two ridge edges */
    print_message("fandisk: %d vertices: ranks 0/1/2: %d/%d/%d, %d ridge edges\n", (int)f.nverts, (int)f.count[0],
                  (int)f.count[1], (int)f.count[2], (int)f.nridges);
    assert_true(f.count[1] > 0 && f.count[2] > 0);
    sfa_destroy(s);

    shapes_rng rng = rng_seed(2024);
    const double scales[] = {1, 1e3, 1e-3};
    for (size_t i = 0; i < sizeof scales / sizeof scales[0]; ++i) {
        double R[9];
        rotation_random(&rng, R);
        sfa_mesh_data t = mesh_copy(&m);
        mesh_rotate_scale(&t, R, scales[i]);
        sfa_surface *st = make_surface(&t, 0);
        features g = features_of(st);
        print_message("fandisk turned, scaled by %g: ranks 0/1/2: %d/%d/%d, %d ridge edges\n", scales[i],
                      (int)g.count[0], (int)g.count[1], (int)g.count[2], (int)g.nridges);
        if (memcmp(f.count, g.count, sizeof f.count) != 0 || f.nridges != g.nridges)
            fail_msg("the counts changed under a rotation and a scaling by %g", scales[i]);
        features_free(&g);
        sfa_destroy(st);
        mesh_free(&t);
    }
    features_free(&f);
    mesh_free(&m);
}

/* ---------------------------------------------------------------- invariance */

/* Ranks vertex by vertex, and the ridge edges, are the same after a rotation (with the
 * given scale) and after renumbering vertices and triangles (mapped back). */
static void check_invariance(const sfa_mesh_data *m, const char *name)
{
    sfa_surface *s = make_surface(m, 0);
    features f = features_of(s);
    sfa_destroy(s);

    shapes_rng rng = rng_seed(77);
    for (int trial = 0; trial < 3; ++trial) {
        double R[9];
        rotation_random(&rng, R);
        sfa_mesh_data t = mesh_copy(m);
        mesh_rotate_scale(&t, R, 1.0);
        sfa_surface *st = make_surface(&t, 0);
        features g = features_of(st);
        for (int32_t v = 0; v < f.nverts; ++v)
            if (f.ranks[v] != g.ranks[v])
                fail_msg("%s, rotation %d: vertex %d at (%.6g, %.6g, %.6g) has rank %d, %d before", name, trial, (int)v,
                         m->xyz[3 * v], m->xyz[3 * v + 1], m->xyz[3 * v + 2], (int)g.ranks[v], (int)f.ranks[v]);
        assert_int_equal(g.nridges, f.nridges);
        assert_memory_equal(g.ridges, f.ridges, sizeof(int32_t) * 2 * (size_t)f.nridges);
        features_free(&g);
        sfa_destroy(st);
        mesh_free(&t);
    }

    for (uint64_t seed = 1; seed <= 3; ++seed) {
        sfa_mesh_data p = mesh_copy(m);
        int32_t *vert_new = malloc(sizeof(int32_t) * (size_t)m->nverts);
        assert_non_null(vert_new);
        mesh_permute(&p, seed, vert_new, NULL);
        sfa_surface *sp = make_surface(&p, 0);
        features g = features_of(sp);
        for (int32_t v = 0; v < f.nverts; ++v)
            if (f.ranks[v] != g.ranks[vert_new[v]])
                fail_msg("%s, permutation %d: vertex %d (now %d) at (%.6g, %.6g, %.6g) has rank %d, %d before", name,
                         (int)seed, (int)v, (int)vert_new[v], m->xyz[3 * v], m->xyz[3 * v + 1], m->xyz[3 * v + 2],
                         (int)g.ranks[vert_new[v]], (int)f.ranks[v]);
        /* The ridge edges, mapped back to the original numbering, are the same set. */
        assert_int_equal(g.nridges, f.nridges);
        int32_t *inverse = malloc(sizeof(int32_t) * (size_t)m->nverts);
        int32_t *back = malloc(sizeof(int32_t) * 2 * (size_t)(f.nridges ? f.nridges : 1));
        assert_non_null(inverse);
        assert_non_null(back);
        for (int32_t v = 0; v < m->nverts; ++v)
            inverse[vert_new[v]] = v;
        for (int32_t e = 0; e < g.nridges; ++e) {
            const int32_t a = inverse[g.ridges[2 * e]], b = inverse[g.ridges[2 * e + 1]];
            back[2 * e] = a < b ? a : b;
            back[2 * e + 1] = a < b ? b : a;
        }
        qsort(back, (size_t)g.nridges, 2 * sizeof(int32_t), compare_index_pairs);
        assert_memory_equal(back, f.ridges, sizeof(int32_t) * 2 * (size_t)f.nridges);
        free(back);
        free(inverse);
        free(vert_new);
        features_free(&g);
        sfa_destroy(sp);
        mesh_free(&p);
    }
    features_free(&f);
}

static void invariance_box(void **state)
{
    (void)state;
    const double lo[3] = {0, 0, 0}, hi[3] = {2, 1, 1.5};
    sfa_mesh_data m = shape_box(4, lo, hi);
    check_invariance(&m, "box");
    mesh_free(&m);
}

static void invariance_fandisk(void **state)
{
    (void)state;
    sfa_mesh_data m;
    read_data_or_skip("fandisk.obj", &m);
    check_invariance(&m, "fandisk");
    mesh_free(&m);
}

/* ------------------------------------------------------------ arguments, state */

/* Calls `call` on a loaded cube and checks the outcome and that nothing changed. */
#define expect_on_cube(call, expected, ...)                                                                            \
    do {                                                                                                               \
        sfa_surface *s = make_cube_surface();                                                                          \
        expect_unchanged(s, call, expected, __VA_ARGS__);                                                              \
        sfa_destroy(s);                                                                                                \
    } while (0)

static void assert_untouched(const void *buffer, size_t size)
{
    for (size_t b = 0; b < size; ++b)
        if (((const unsigned char *)buffer)[b] != SENTINEL_BYTE)
            fail_msg("byte %zu of an output buffer was written by a failed call", b);
}

static sfa_surface *empty_surface(void)
{
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    return s;
}

static void feature_ranks_arguments(void **state)
{
    (void)state;
    int32_t ranks[9];
    memset(ranks, SENTINEL_BYTE, sizeof ranks);
    assert_int_equal(sfa_get_feature_ranks(NULL, 8, ranks), SFA_ERR_ARGUMENT);
    expect_on_cube(sfa_get_feature_ranks(s, 8, NULL), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_get_feature_ranks(s, 7, ranks), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_get_feature_ranks(s, 0, ranks), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_get_feature_ranks(s, -1, ranks), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_get_feature_ranks(s, INT32_MIN, ranks), SFA_ERR_ARGUMENT, "");
    assert_untouched(ranks, sizeof ranks);
    sfa_surface *empty = empty_surface();
    assert_error(empty, sfa_get_feature_ranks(empty, 8, ranks), SFA_ERR_STATE, "");
    assert_untouched(ranks, sizeof ranks);
    sfa_destroy(empty);
    /* A larger buffer than needed: 8 ranks written, the rest untouched. */
    expect_on_cube(sfa_get_feature_ranks(s, 9, ranks), SFA_OK, "");
    for (int v = 0; v < 8; ++v)
        assert_int_equal(ranks[v], 2);
    assert_untouched(ranks + 8, sizeof ranks[8]);
}

static void vertex_frames_arguments(void **state)
{
    (void)state;
    double normals[3 * 9], dirs[3 * 9], aspect[9];
    memset(normals, SENTINEL_BYTE, sizeof normals);
    memset(dirs, SENTINEL_BYTE, sizeof dirs);
    memset(aspect, SENTINEL_BYTE, sizeof aspect);
    assert_int_equal(sfa_get_vertex_frames(NULL, 8, normals, dirs, aspect), SFA_ERR_ARGUMENT);
    expect_on_cube(sfa_get_vertex_frames(s, 7, normals, dirs, aspect), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_get_vertex_frames(s, -1, normals, dirs, aspect), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_get_vertex_frames(s, 7, NULL, NULL, aspect), SFA_ERR_ARGUMENT, "");
    assert_untouched(normals, sizeof normals);
    assert_untouched(dirs, sizeof dirs);
    assert_untouched(aspect, sizeof aspect);
    sfa_surface *empty = empty_surface();
    assert_error(empty, sfa_get_vertex_frames(empty, 8, normals, dirs, aspect), SFA_ERR_STATE, "");
    sfa_destroy(empty);
    assert_untouched(aspect, sizeof aspect);
    /* Any output may be NULL; the others are written, and only nverts entries of them. */
    expect_on_cube(sfa_get_vertex_frames(s, 8, NULL, NULL, NULL), SFA_OK, "");
    expect_on_cube(sfa_get_vertex_frames(s, 9, NULL, NULL, aspect), SFA_OK, "");
    assert_untouched(normals, sizeof normals);
    assert_untouched(aspect + 8, sizeof aspect[8]);
    for (int v = 0; v < 8; ++v)
        assert_true(aspect[v] >= 1 - 1e-12 && aspect[v] <= max_aspect_ratio() + 1e-12);
    expect_on_cube(sfa_get_vertex_frames(s, 8, normals, NULL, NULL), SFA_OK, "");
    assert_untouched(dirs, sizeof dirs);
    /* The unit cube's corner normals point out, away from the centre. */
    const double centre[3] = {0.5, 0.5, 0.5};
    sfa_mesh_data cube = shape_unit_cube();
    for (int v = 0; v < 8; ++v) {
        const double out[3] = {cube.xyz[3 * v] - centre[0], cube.xyz[3 * v + 1] - centre[1],
                               cube.xyz[3 * v + 2] - centre[2]};
        assert_true(dot3(normals + 3 * v, out) > 0);
    }
    mesh_free(&cube);
}

static void ridge_edges_arguments(void **state)
{
    (void)state;
    int32_t edges[2 * 13], count = -1;
    memset(edges, SENTINEL_BYTE, sizeof edges);
    assert_int_equal(sfa_get_ridge_edges(NULL, 12, edges, &count, 0), SFA_ERR_ARGUMENT);
    expect_on_cube(sfa_get_ridge_edges(s, 11, edges, &count, 0), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_get_ridge_edges(s, -1, edges, &count, 0), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_get_ridge_edges(s, 12, edges, &count, 2), SFA_ERR_ARGUMENT, "");
    expect_on_cube(sfa_get_ridge_edges(s, 12, edges, &count, -1), SFA_ERR_ARGUMENT, "");
    assert_untouched(edges, sizeof edges);
    sfa_surface *empty = empty_surface();
    assert_error(empty, sfa_get_ridge_edges(empty, 12, edges, &count, 0), SFA_ERR_STATE, "");
    assert_error(empty, sfa_get_ridge_edges(empty, 0, NULL, &count, 0), SFA_ERR_STATE, "");
    sfa_destroy(empty);
    assert_untouched(edges, sizeof edges);

    /* edges == NULL: the count only, whatever the capacity. */
    count = -1;
    expect_on_cube(sfa_get_ridge_edges(s, 0, NULL, &count, 0), SFA_OK, "");
    assert_int_equal(count, 12);
    /* count may be NULL when the caller knows it. */
    expect_on_cube(sfa_get_ridge_edges(s, 13, edges, NULL, 0), SFA_OK, "");
    assert_untouched(edges + 24, 2 * sizeof edges[0]);

    /* The 12 edges of the unit cube (shape_unit_cube's numbering), smaller first, sorted;
     * index base 1 adds 1 to each. */
    static const int32_t cube_edges[24] = {0, 1, 0, 3, 0, 4, 1, 2, 1, 5, 2, 3, 2, 6, 3, 7, 4, 5, 4, 7, 5, 6, 6, 7};
    int32_t base0[24], base1[24];
    count = -1;
    expect_on_cube(sfa_get_ridge_edges(s, 12, base0, &count, 0), SFA_OK, "");
    assert_int_equal(count, 12);
    assert_memory_equal(base0, cube_edges, sizeof cube_edges);
    count = -1;
    expect_on_cube(sfa_get_ridge_edges(s, 12, base1, &count, 1), SFA_OK, "");
    assert_int_equal(count, 12);
    for (int i = 0; i < 24; ++i)
        assert_int_equal(base1[i], base0[i] + 1);
}

/* ---------------------------------------------------------------- parameters */

static void ridge_angle_matters(void **state)
{
    (void)state;
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    sfa_mesh_data m = shape_box(4, lo, hi);
    sfa_surface *s = make_surface(&m, 0);
    /* The box's dihedral angles are 90 degrees: above that no edge is a ridge. */
    assert_ok(s, sfa_set_param(s, SFA_PARAM_RIDGE_ANGLE, 120));
    features f = features_of(s);
    print_message("box n = 4 with SFA_PARAM_RIDGE_ANGLE 120: ranks 0/1/2: %d/%d/%d, %d ridge edges\n",
                  (int)f.count[0], (int)f.count[1], (int)f.count[2], (int)f.nridges);
    assert_int_equal(f.nridges, 0);
    assert_int_equal(f.count[1], 0);
    features_free(&f);
    /* And back: the parameter is read at each call. */
    assert_ok(s, sfa_set_param(s, SFA_PARAM_RIDGE_ANGLE, 45));
    f = features_of(s);
    assert_int_equal(f.nridges, 48);
    features_free(&f);
    sfa_destroy(s);
    mesh_free(&m);
}

/* The rims of a 12-segment cylinder turn by 30 degrees at each vertex: ridge vertices with
 * the default turn angle (40), corners below 30. */
static void ridge_turn_angle_matters(void **state)
{
    (void)state;
    enum { segments = 12, rings = 4 };
    sfa_mesh_data m = shape_capped_cylinder(1.0, 1.0, segments, rings);
    sfa_surface *s = make_surface(&m, 0);
    features f = features_of(s);
    assert_int_equal(f.count[1], 2 * segments);
    assert_int_equal(f.count[2], 0);
    assert_int_equal(f.nridges, 2 * segments);
    features_free(&f);
    assert_ok(s, sfa_set_param(s, SFA_PARAM_RIDGE_TURN_ANGLE, 25));
    f = features_of(s);
    assert_int_equal(f.count[1], 0);
    assert_int_equal(f.count[2], 2 * segments);
    assert_int_equal(f.nridges, 2 * segments);
    features_free(&f);
    sfa_destroy(s);
    mesh_free(&m);
}

/* Isotropic mode: the frames still come, with aspect ratio 1 everywhere. */
static void isotropic_aspect_ratio(void **state)
{
    (void)state;
    sfa_mesh_data m = shape_capped_cylinder(1.0, 2.0, 32, 10);
    sfa_surface *s = make_surface(&m, 0);
    assert_ok(s, sfa_set_param(s, SFA_PARAM_ANISOTROPIC, 0));
    frames fr = frames_of(s, m.nverts);
    for (int32_t v = 0; v < m.nverts; ++v)
        if (fr.aspect[v] != 1)
            fail_msg("isotropic mode: vertex %d has aspect ratio %.17g", (int)v, fr.aspect[v]);
    frames_free(&fr);
    sfa_destroy(s);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(boxes),
        cmocka_unit_test(spheres_have_no_features),
        cmocka_unit_test(capped_cylinder),
        cmocka_unit_test(ellipsoid_long_directions),
        cmocka_unit_test(oblate_rim_long_directions),
        cmocka_unit_test(open_grid),
        cmocka_unit_test(open_cap),
        cmocka_unit_test(fandisk),
        cmocka_unit_test(invariance_box),
        cmocka_unit_test(invariance_fandisk),
        cmocka_unit_test(feature_ranks_arguments),
        cmocka_unit_test(vertex_frames_arguments),
        cmocka_unit_test(ridge_edges_arguments),
        cmocka_unit_test(ridge_angle_matters),
        cmocka_unit_test(ridge_turn_angle_matters),
        cmocka_unit_test(isotropic_aspect_ratio),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

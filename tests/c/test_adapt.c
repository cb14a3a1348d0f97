/* SPDX-License-Identifier: BSD-3-Clause */
/* The full adaptation (sfa_adapt, paper §3-§4): refinement and coarsening to the desired
 * edge length with features, volume and host fields kept, and its determinism. */
#include "support/surface_distance.h"
#include "support/testing.h"

#include <threads.h>



/* How many of the three coordinates of p lie on the box's bounds (to tol). */
static int coordinates_on_bounds(const double *p, const double lo[3], const double hi[3], double tol)
{
    int on = 0;
    for (int k = 0; k < 3; ++k)
        on += fabs(p[k] - lo[k]) <= tol || fabs(p[k] - hi[k]) <= tol;
    return on;
}

/* The 2 x 1 x 0.5 box of 26 vertices refined to edge length 0.08 in three calls: the
 * corners stay exactly where they were, every vertex stays on a face, the volume is 1, a
 * linear field stays linear, and the triangles along the ridges are longer along them
 * than across (the anisotropic band of the paper's Fig. 2). */
static void box_refined_keeps_corners_faces_volume_and_linear_fields(void **state)
{
    (void)state;
    const double lo[3] = {0, 0, 0}, hi[3] = {2, 1, 0.5};
    sfa_mesh_data m = shape_box(2, lo, hi);
    sfa_surface *s = make_surface(&m, 0);
    double *field = malloc(sizeof(double) * 2 * (size_t)m.nverts);
    for (int32_t v = 0; v < m.nverts; ++v) {
        const double *p = m.xyz + 3 * v;
        field[2 * v] = 1 + 2 * p[0] - 3 * p[1] + 0.5 * p[2];
        field[2 * v + 1] = -p[2];
    }
    int32_t id;
    assert_int_equal(sfa_add_field(s, 2, field, &id), SFA_OK);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.08), SFA_OK);
    for (int call = 0; call < 3; ++call)
        assert_ok(s, sfa_adapt(s));

    sfa_mesh_data out = read_back(s);
    double *values = malloc(sizeof(double) * 2 * (size_t)out.nverts);
    assert_int_equal(sfa_get_field(s, id, 2 * out.nverts, values), SFA_OK);
    int corners = 0;
    double worst_field = 0;
    for (int32_t v = 0; v < out.nverts; ++v) {
        const double *p = out.xyz + 3 * v;
        assert_true(coordinates_on_bounds(p, lo, hi, 1e-12) >= 1);
        corners += coordinates_on_bounds(p, lo, hi, 0) == 3;
        worst_field = fmax(worst_field, fabs(values[2 * v] - (1 + 2 * p[0] - 3 * p[1] + 0.5 * p[2])));
        worst_field = fmax(worst_field, fabs(values[2 * v + 1] + p[2]));
    }
    /* Triangles with an edge on a ridge: that edge's length against the height across. */
    double band_ratio = 0;
    int band = 0;
    for (int32_t t = 0; t < out.ntris; ++t)
        for (int k = 0; k < 3; ++k) {
            const double *a = out.xyz + 3 * out.tris[3 * t + k], *b = out.xyz + 3 * out.tris[3 * t + (k + 1) % 3],
                         *c = out.xyz + 3 * out.tris[3 * t + (k + 2) % 3];
            if (coordinates_on_bounds(a, lo, hi, 1e-12) < 2 || coordinates_on_bounds(b, lo, hi, 1e-12) < 2)
                continue;
            double ab[3], ac[3], cross[3], length2 = 0, cross2 = 0, shared = 0;
            for (int i = 0; i < 3; ++i) {
                ab[i] = b[i] - a[i];
                ac[i] = c[i] - a[i];
                length2 += ab[i] * ab[i];
            }
            for (int i = 0; i < 3; ++i)
                shared += fabs(ab[i]) < 1e-12; /* along an axis: two coordinates constant */
            if (shared < 2)
                continue;
            cross[0] = ab[1] * ac[2] - ab[2] * ac[1];
            cross[1] = ab[2] * ac[0] - ab[0] * ac[2];
            cross[2] = ab[0] * ac[1] - ab[1] * ac[0];
            for (int i = 0; i < 3; ++i)
                cross2 += cross[i] * cross[i];
            band_ratio += length2 / sqrt(cross2); /* length / height */
            ++band;
        }
    band_ratio /= band;
    const double volume = measure(s, SFA_MEASURE_VOLUME);
    print_message("box: %d -> %d vertices, %d corners, volume %.15f, linear field error %.2e, ridge band: %d "
                  "triangles, mean length along / height across %.2f, min angle %.2f, max angle %.2f\n",
                  m.nverts, out.nverts, corners, volume, worst_field, band, band_ratio,
                  measure(s, SFA_MEASURE_MIN_ANGLE), measure(s, SFA_MEASURE_MAX_ANGLE));
    assert_true(out.nverts > 5 * m.nverts);
    assert_int_equal(corners, 8);
    assert_true(fabs(volume - 1) <= 1e-9);
    assert_true(worst_field <= 1e-9);
    assert_true(band_ratio > 1.5);
    free(values);
    free(field);
    mesh_free(&out);
    mesh_free(&m);
    sfa_destroy(s);
}

/* A closed unit sphere jittered along itself, adapted at its own mean edge length: its
 * angles improve to over 20 degrees and its volume stays within 0.2 %. */
static void sphere_at_its_own_edge_length_gets_good_angles_and_keeps_volume(void **state)
{
    (void)state;
    sfa_mesh_data m = shape_jittered_icosphere(4, 1.0, 1.0 / 3, 7);
    sfa_surface *s = make_surface(&m, 0);
    const double volume = measure(s, SFA_MEASURE_VOLUME), min_angle = measure(s, SFA_MEASURE_MIN_ANGLE);
    assert_ok(s, sfa_adapt(s));
    int32_t nverts, ntris;
    assert_int_equal(sfa_get_counts(s, &nverts, &ntris), SFA_OK);
    const double change = measure(s, SFA_MEASURE_VOLUME) / volume - 1;
    print_message("sphere: %d -> %d vertices, min angle %.2f -> %.2f, max angle %.2f, volume change %.2e\n", m.nverts,
                  nverts, min_angle, measure(s, SFA_MEASURE_MIN_ANGLE), measure(s, SFA_MEASURE_MAX_ANGLE), change);
    assert_true(measure(s, SFA_MEASURE_MIN_ANGLE) > 20);
    assert_true(fabs(change) < 2e-3);
    mesh_free(&m);
    sfa_destroy(s);
}

/* A shallow open fan (issue 18): the apex (0, 0, 0.1) joined to n vertices on the unit
 * circle at z = 0 by n slivers, every normal pointing up. The cone is so flat that the apex
 * is a smooth vertex of valence n. */
static sfa_mesh_data shallow_fan(int32_t n)
{
    sfa_mesh_data m;
    m.nverts = n + 1;
    m.ntris = n;
    m.xyz = malloc(sizeof(double) * 3 * (size_t)m.nverts);
    m.tris = malloc(sizeof(int32_t) * 3 * (size_t)m.ntris);
    assert_non_null(m.xyz);
    assert_non_null(m.tris);
    m.xyz[0] = 0;
    m.xyz[1] = 0;
    m.xyz[2] = 0.1;
    for (int32_t k = 0; k < n; ++k) {
        const double angle = 2 * 3.14159265358979323846 * k / n;
        m.xyz[3 * (k + 1)] = cos(angle);
        m.xyz[3 * (k + 1) + 1] = sin(angle);
        m.xyz[3 * (k + 1) + 2] = 0;
        m.tris[3 * k] = 0;
        m.tris[3 * k + 1] = 1 + k;
        m.tris[3 * k + 2] = 1 + (k + 1) % n;
    }
    return m;
}

/* The number of triangles whose normal does not point up (z <= 0): turned over against
 * the fan, which is a graph over the plane z = 0. */
static int32_t triangles_facing_down(const sfa_mesh_data *m)
{
    int32_t down = 0;
    for (int32_t t = 0; t < m->ntris; ++t) {
        const double *a = m->xyz + 3 * m->tris[3 * t], *b = m->xyz + 3 * m->tris[3 * t + 1],
                     *c = m->xyz + 3 * m->tris[3 * t + 2];
        const double normal_z = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        down += !(normal_z > 0);
    }
    return down;
}

/* The shallow fan of 200 and of 1000 slivers adapted three times at l = 0.05: no triangle
 * turns over and the surface never crosses itself. Each operation bounded a face's turn
 * only relative to the face just before it, and a split, contractions and sweeps turned
 * slivers around the apex over one after another: 12 of 242 triangles faced down after
 * one pass at n = 200, and the fan crossed itself in 93 pairs (1,349 at n = 1000). */
/* A 1000 x 1 x 0.001 ellipsoid, a sheet far thinner than its edges, adapted at twice its
 * mean edge: the volume correction's offset, one distance for every smooth vertex, carried
 * one side through the other at the second call (2 crossing pairs) until offsets larger
 * than a hundredth of the component's thickness were certified like collision-safe motion. */
static void thin_ellipsoid_is_not_carried_through_itself(void **state)
{
    (void)state;
    sfa_mesh_data m = shape_ellipsoid(5, 1000, 1, 0.001);
    sfa_surface *s = make_surface(&m, 0);
    double mean = 0, crossings = -1;
    assert_ok(s, sfa_measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH, &mean));
    assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 2 * mean));
    for (int call = 0; call < 3; ++call) {
        assert_ok(s, sfa_adapt(s));
        assert_ok(s, sfa_measure(s, SFA_MEASURE_SELF_INTERSECTIONS, &crossings));
        if (crossings != 0)
            fail_msg("call %d left %g crossing pairs", call, crossings);
    }
    sfa_destroy(s);
    mesh_free(&m);
}

static void shallow_fan_is_never_turned_over_nor_crosses_itself(void **state)
{
    (void)state;
    const int32_t sizes[] = {200, 1000};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; ++k) {
        sfa_mesh_data m = shallow_fan(sizes[k]);
        sfa_surface *s = make_surface(&m, 0);
        assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.05), SFA_OK);
        for (int call = 0; call < 3; ++call) {
            assert_ok(s, sfa_adapt(s));
            sfa_mesh_data out = read_back(s);
            const int32_t down = triangles_facing_down(&out);
            const double crossings = measure(s, SFA_MEASURE_SELF_INTERSECTIONS);
            print_message("fan of %d, call %d: %d triangles, %d facing down, %g crossing pairs, angles %.1f..%.1f\n",
                          sizes[k], call, out.ntris, down, crossings, measure(s, SFA_MEASURE_MIN_ANGLE),
                          measure(s, SFA_MEASURE_MAX_ANGLE));
            assert_int_equal(down, 0);
            assert_true(crossings == 0);
            mesh_free(&out);
        }
        mesh_free(&m);
        sfa_destroy(s);
    }
}

/* A blade 1 x 1 x 0.004 adapted at l = 0.1: its rims are two ridge curves 0.004 apart,
 * nearer than the 0.01 (r l) at which feature vertices count as one feature, the way the
 * vortex flow squeezes a sheet's rim into a cusp. The rims merge instead of leaving
 * needles across the blade's edge; the volume stays. */
static void ridge_curves_nearer_than_r_l_merge_instead_of_leaving_needles(void **state)
{
    (void)state;
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 0.004};
    sfa_mesh_data m = shape_box(10, lo, hi);
    sfa_surface *s = make_surface(&m, 0);
    const double volume = measure(s, SFA_MEASURE_VOLUME), min_angle = measure(s, SFA_MEASURE_MIN_ANGLE);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.1), SFA_OK);
    for (int call = 0; call < 3; ++call)
        assert_ok(s, sfa_adapt(s));
    const double change = measure(s, SFA_MEASURE_VOLUME) / volume - 1;
    print_message("blade: min angle %.2f -> %.2f, max angle %.2f, volume change %.2e\n", min_angle,
                  measure(s, SFA_MEASURE_MIN_ANGLE), measure(s, SFA_MEASURE_MAX_ANGLE), change);
    assert_true(measure(s, SFA_MEASURE_MIN_ANGLE) > 5);
    assert_true(fabs(change) < 1e-12);
    mesh_free(&m);
    sfa_destroy(s);
}

/* The distance from a mesh to an exact surface, sampled at every triangle's centroid and
 * edge midpoints (where chords are farthest from a curved surface). */
typedef double (*exact_distance_fn)(const double p[3]);

typedef struct {
    int32_t vertices;
    double mean, max;
} surface_error;

static surface_error error_against(const sfa_surface *s, exact_distance_fn distance)
{
    sfa_mesh_data m = read_back(s);
    surface_error e = {m.nverts, 0, 0};
    for (int32_t t = 0; t < m.ntris; ++t)
        for (int k = 0; k < 4; ++k) {
            double p[3] = {0, 0, 0};
            for (int i = 0; i < 3; ++i) {
                const double *q = m.xyz + 3 * m.tris[3 * t + i];
                const double w = k == 3 ? 1.0 / 3 : (i == k || i == (k + 1) % 3) ? 0.5 : 0;
                for (int j = 0; j < 3; ++j)
                    p[j] += w * q[j];
            }
            const double d = distance(p);
            e.mean += d;
            e.max = fmax(e.max, d);
        }
    e.mean /= 4.0 * m.ntris;
    mesh_free(&m);
    return e;
}

/* The ellipsoid x^2 + (y/0.6)^2 + (z/0.3)^2 = 1: first-order distance |F| / |grad F|. */
static double ellipsoid_distance(const double p[3])
{
    const double a2 = 1, b2 = 0.36, c2 = 0.09;
    const double f = p[0] * p[0] / a2 + p[1] * p[1] / b2 + p[2] * p[2] / c2 - 1;
    const double g[3] = {2 * p[0] / a2, 2 * p[1] / b2, 2 * p[2] / c2};
    return fabs(f) / sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
}

/* The open tube of radius 0.5 about the z axis. */
static double tube_distance(const double p[3]) { return fabs(sqrt(p[0] * p[0] + p[1] * p[1]) - 0.5); }

static surface_error adapted_error(const sfa_mesh_data *m, int anisotropic, double edge_length,
                                   exact_distance_fn distance)
{
    sfa_surface *s = make_surface(m, 0);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_ANISOTROPIC, anisotropic), SFA_OK);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, edge_length), SFA_OK);
    for (int call = 0; call < 3; ++call)
        assert_ok(s, sfa_adapt(s));
    const surface_error e = error_against(s, distance);
    sfa_destroy(s);
    return e;
}

/* Anisotropic at edge length l, then isotropic at an edge length chosen so that it gets
 * at least as many vertices. Measured so far: on the ellipsoid the anisotropic mesh's
 * largest distance is 25 % smaller and its mean distance within 1 %; on the tube both are
 * 12-13 % smaller. Not the clear win the paper reports (the quadric metric turns isotropic
 * once a surface is resolved to about 8 degrees per triangle), so what this test holds
 * the code to is: never more than 5 % farther in either distance, closer in one. */
static void compare_at_equal_vertex_count(const char *name, const sfa_mesh_data *m, double l, exact_distance_fn distance)
{
    const surface_error anisotropic = adapted_error(m, 1, l, distance);
    double iso_l = l;
    surface_error isotropic = adapted_error(m, 0, iso_l, distance);
    /* The vertex count goes as 1 / l^2 */
    for (int attempt = 0; attempt < 4 && isotropic.vertices < anisotropic.vertices; ++attempt) {
        iso_l *= 0.99 * sqrt((double)isotropic.vertices / anisotropic.vertices);
        isotropic = adapted_error(m, 0, iso_l, distance);
    }
    print_message("%s: anisotropic (l = %.3f) %d vertices, mean distance %.3e, max %.3e; isotropic (l = %.3f) %d "
                  "vertices, mean distance %.3e, max %.3e\n",
                  name, l, anisotropic.vertices, anisotropic.mean, anisotropic.max, iso_l, isotropic.vertices,
                  isotropic.mean, isotropic.max);
    assert_true(isotropic.vertices >= anisotropic.vertices);
    assert_true(anisotropic.mean < 1.05 * isotropic.mean);
    assert_true(anisotropic.max < 1.05 * isotropic.max);
    assert_true(anisotropic.mean < isotropic.mean || anisotropic.max < isotropic.max);
}

static void anisotropic_meshes_are_as_close_to_the_surface_with_as_many_vertices(void **state)
{
    (void)state;
    sfa_mesh_data ellipsoid = shape_ellipsoid(5, 1, 0.6, 0.3);
    compare_at_equal_vertex_count("ellipsoid (1, 0.6, 0.3)", &ellipsoid, 0.1, ellipsoid_distance);
    /* The capped cylinder without its caps: the last two vertices and 2 x 96 triangles. */
    sfa_mesh_data tube = shape_capped_cylinder(0.5, 2, 96, 61);
    tube.nverts -= 2;
    tube.ntris -= 2 * 96;
    compare_at_equal_vertex_count("tube (r = 0.5, length 2)", &tube, 0.2, tube_distance);
    mesh_free(&ellipsoid);
    mesh_free(&tube);
}

/* Feature curves: ridge edges joined through ridge (rank 1) vertices, cut at corners. */
typedef struct {
    int32_t corners, curves;
    double *corner_xyz; /* 3 per corner, sorted */
    double mean_edge;   /* of the mesh they were found on */
} feature_curves;

static int compare_points(const void *a, const void *b)
{
    const double *p = a, *q = b;
    for (int k = 0; k < 3; ++k)
        if (p[k] != q[k])
            return p[k] < q[k] ? -1 : 1;
    return 0;
}

static int32_t find_root(int32_t *parent, int32_t x)
{
    while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
    return x;
}

static feature_curves curves_of(const sfa_surface *s)
{
    sfa_mesh_data m = read_back(s);
    int32_t *rank = malloc(sizeof(int32_t) * (size_t)m.nverts), count = 0;
    assert_int_equal(sfa_get_feature_ranks(s, m.nverts, rank), SFA_OK);
    assert_int_equal(sfa_get_ridge_edges(s, 0, NULL, &count, 0), SFA_OK);
    int32_t *edges = malloc(sizeof(int32_t) * 2 * (size_t)(count + 1));
    assert_int_equal(sfa_get_ridge_edges(s, count, edges, &count, 0), SFA_OK);
    /* Union-find over edges; the edge through which each ridge vertex was first reached. */
    int32_t *parent = malloc(sizeof(int32_t) * (size_t)(count + 1)), *seen = malloc(sizeof(int32_t) * (size_t)m.nverts);
    for (int32_t v = 0; v < m.nverts; ++v)
        seen[v] = -1;
    for (int32_t e = 0; e < count; ++e) {
        parent[e] = e;
        for (int k = 0; k < 2; ++k) {
            const int32_t v = edges[2 * e + k];
            if (rank[v] != 1)
                continue;
            if (seen[v] < 0)
                seen[v] = e;
            else
                parent[find_root(parent, e)] = find_root(parent, seen[v]);
        }
    }
    feature_curves f = {0, 0, malloc(sizeof(double) * 3 * (size_t)m.nverts), measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH)};
    for (int32_t e = 0; e < count; ++e)
        f.curves += find_root(parent, e) == e;
    for (int32_t v = 0; v < m.nverts; ++v)
        if (rank[v] == 2) {
            for (int k = 0; k < 3; ++k)
                f.corner_xyz[3 * f.corners + k] = m.xyz[3 * v + k];
            ++f.corners;
        }
    qsort(f.corner_xyz, (size_t)f.corners, 3 * sizeof(double), compare_points);
    free(parent);
    free(seen);
    free(edges);
    free(rank);
    mesh_free(&m);
    return f;
}


/* The number of corners of `a` that `b` has within `distance` of theirs. */
static int32_t corners_within(const feature_curves *a, const feature_curves *b, double distance)
{
    int32_t near = 0;
    for (int32_t i = 0; i < a->corners; ++i) {
        int found = 0;
        for (int32_t j = 0; j < b->corners && !found; ++j) {
            double d2 = 0;
            for (int k = 0; k < 3; ++k)
                d2 += pow(a->corner_xyz[3 * i + k] - b->corner_xyz[3 * j + k], 2);
            found = d2 <= distance * distance;
        }
        near += found;
    }
    return near;
}

/* The number of corners of `a` that `b` has at exactly the same place. */
static int32_t corners_in_place(const feature_curves *a, const feature_curves *b)
{
    int32_t same = 0;
    for (int32_t i = 0; i < a->corners; ++i)
        same += bsearch(a->corner_xyz + 3 * i, b->corner_xyz, (size_t)b->corners, 3 * sizeof(double),
                        compare_points) != NULL;
    return same;
}

/* A real model adapted at `scale` times its mean edge length (three calls). Gives the
 * features before and after (detected afresh on the result, as a host sees them), checks
 * the volume (within 0.5 %), and returns the share of triangles with angles in [15, 160]. */
static double adapt_real_model(const char *name, double scale, feature_curves *before, feature_curves *after)
{
    sfa_mesh_data m;
    read_data_or_skip(name, &m);
    sfa_surface *s = make_surface(&m, 0);
    *before = curves_of(s);
    const double volume = measure(s, SFA_MEASURE_VOLUME), good_before = share_of_good_triangles(s);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, scale * measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH)), SFA_OK);
    for (int call = 0; call < 3; ++call)
        assert_ok(s, sfa_adapt(s));
    *after = curves_of(s);
    sfa_mesh_data out = read_back(s);
    const double change = measure(s, SFA_MEASURE_VOLUME) / volume - 1;
    const double distance = sampled_hausdorff(&m, &out) / bounding_diagonal(&m);
    print_message("%s at %.1fx its mean edge length: %d -> %d vertices, corners %d -> %d (%d in place), curves %d -> "
                  "%d, volume change %.2e, triangles with angles in [15, 160]: %.1f%% -> %.1f%%, min/max angle "
                  "%.2f/%.2f, Hausdorff distance to the input %.2e of the bounding-box diagonal\n",
                  name, scale, m.nverts, out.nverts, before->corners, after->corners, corners_in_place(before, after),
                  before->curves, after->curves, change, 100 * good_before, 100 * share_of_good_triangles(s),
                  measure(s, SFA_MEASURE_MIN_ANGLE), measure(s, SFA_MEASURE_MAX_ANGLE), distance);
    assert_true(fabs(change) < 5e-3);
    const double good = share_of_good_triangles(s);
    mesh_free(&out);
    mesh_free(&m);
    sfa_destroy(s);
    return good;
}

/* A CAD part: the same feature curves and corners, each corner within an edge and a half
 * of its place, and all but two exactly in place. Where a crease fades out (three corners
 * of the fandisk, at y = 15.5 to 15.8) the crease's end is only known to an edge: detected
 * afresh on the result, such a corner may sit at the neighbouring ridge vertex (0.05 to
 * 0.13 away at edge lengths of 0.06 and 0.25; at 0.25 the ridge edges there are longer
 * than the mean edge), as the smooth vertices around it settle. */
static void fandisk_keeps_its_features_and_volume(void **state)
{
    (void)state;
    for (int k = 0; k < 2; ++k) {
        feature_curves before, after;
        adapt_real_model("fandisk.obj", k == 0 ? 0.5 : 2, &before, &after);
        assert_int_equal(after.corners, before.corners);
        assert_int_equal(after.curves, before.curves);
        assert_int_equal(corners_within(&before, &after, 1.5 * after.mean_edge), before.corners);
        assert_true(corners_in_place(&before, &after) >= before.corners - 2);
        free(before.corner_xyz);
        free(after.corner_xyz);
    }
}

/* A smooth model: the volume stays, and nearly every triangle has its angles within the
 * paper's bounds. Its detected "features" are not held to the input's: they are creases of
 * barely 45 degrees between coarse triangles, which refinement (vertices on the smooth
 * surface, halved dihedral angles) removes and coarsening (sharper kinks) multiplies;
 * both counts are printed. */
static void spot_keeps_its_volume_and_triangle_quality(void **state)
{
    (void)state;
    for (int k = 0; k < 2; ++k) {
        feature_curves before, after;
        const double good = adapt_real_model("spot.obj", k == 0 ? 0.5 : 2, &before, &after);
        assert_true(good >= 0.99);
        free(before.corner_xyz);
        free(after.corner_xyz);
    }
}

/* Out of memory at any allocation inside sfa_adapt: the surface and its fields are as
 * before. Then, allowed to finish, it carries the host's velocities to the new vertices
 * (a uniform velocity stays exactly uniform). */
static void nothing_lost_when_memory_runs_out(void **state)
{
    (void)state;
#ifdef SFA_NO_ALLOC_HOOK
    skip();
#else
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    sfa_mesh_data m = shape_box(1, lo, hi);
    sfa_surface *s = make_surface(&m, 0);
    double *field = malloc(sizeof(double) * (size_t)m.nverts), *velocity = malloc(sizeof(double) * 3 * (size_t)m.nverts);
    for (int32_t v = 0; v < m.nverts; ++v) {
        field[v] = m.xyz[3 * v] + 2 * m.xyz[3 * v + 2];
        velocity[3 * v] = 0.25, velocity[3 * v + 1] = -0.5, velocity[3 * v + 2] = 1;
    }
    int32_t id;
    assert_int_equal(sfa_add_field(s, 1, field, &id), SFA_OK);
    assert_int_equal(sfa_set_velocities(s, velocity), SFA_OK);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.4), SFA_OK);
    print_message("sfa_adapt succeeded once %ld allocations were allowed\n",
                  expect_nothing_lost_at_every_allocation(s, sfa_adapt));
    sfa_mesh_data adapted = read_back(s);
    assert_true(adapted.nverts > m.nverts);
    double dt_taken;
    assert_int_equal(sfa_move(s, 0.5, &dt_taken), SFA_OK);
    assert_true(dt_taken == 0.5);
    sfa_mesh_data moved = read_back(s);
    const double step[3] = {0.125, -0.25, 0.5};
    for (int32_t i = 0; i < 3 * adapted.nverts; ++i)
        assert_true(fabs(moved.xyz[i] - (adapted.xyz[i] + step[i % 3])) <= 1e-15);
    mesh_free(&moved);
    mesh_free(&adapted);
    free(field);
    free(velocity);
    mesh_free(&m);
    sfa_destroy(s);
#endif
}

/* One adaptation of a jittered sphere refined to 0.6 of its edge length, with a field. */
static snapshot adapted_sphere(int threads, double radius)
{
    sfa_mesh_data m = shape_jittered_icosphere(3, radius, 0.3, 11);
    sfa_surface *s = make_surface(&m, 0);
    double *field = malloc(sizeof(double) * (size_t)m.nverts);
    for (int32_t v = 0; v < m.nverts; ++v)
        field[v] = sin(3 * m.xyz[3 * v]) + m.xyz[3 * v + 1];
    int32_t id;
    snapshot out;
    if (sfa_add_field(s, 1, field, &id) != SFA_OK || sfa_set_param(s, SFA_PARAM_THREADS, threads) != SFA_OK ||
        sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.6 * mesh_mean_edge_length(&m)) != SFA_OK || sfa_adapt(s) != SFA_OK ||
        sfa_set_param(s, SFA_PARAM_THREADS, 0) != SFA_OK) {
        memset(&out, 0, sizeof out);
        out.counts_status = -1;
    } else {
        snapshot_take(s, &out);
    }
    free(field);
    mesh_free(&m);
    sfa_destroy(s);
    return out;
}

static void expect_same(const snapshot *a, const snapshot *b, const char *what)
{
    char why[256];
    if (!snapshot_equal(a, b, why, sizeof why))
        fail_msg("%s: %s", what, why);
}

/* The same input gives bit-identical output, for any number of threads. */
static void adaptation_is_deterministic_for_any_thread_count(void **state)
{
    (void)state;
    snapshot reference = adapted_sphere(1, 1.0);
    const int threads[] = {2, 3, 0, 1};
    for (size_t k = 0; k < sizeof threads / sizeof threads[0]; ++k) {
        snapshot other = adapted_sphere(threads[k], 1.0);
        expect_same(&reference, &other, "another thread count");
        snapshot_free(&other);
    }
    snapshot_free(&reference);
}

typedef struct {
    double radius;
    snapshot result;
} adapt_job;

static int adapt_in_thread(void *arg)
{
    adapt_job *job = arg;
    job->result = adapted_sphere(0, job->radius);
    return 0;
}

/* Four handles adapted in four threads at once give what they give one after another. */
static void concurrent_handles_give_the_sequential_results(void **state)
{
    (void)state;
    enum { jobs = 4 };
    adapt_job concurrent[jobs];
    thrd_t thread[jobs];
    for (int k = 0; k < jobs; ++k) {
        concurrent[k].radius = 1 + 0.5 * k;
        assert_int_equal(thrd_create(&thread[k], adapt_in_thread, &concurrent[k]), thrd_success);
    }
    for (int k = 0; k < jobs; ++k)
        assert_int_equal(thrd_join(thread[k], NULL), thrd_success);
    for (int k = 0; k < jobs; ++k) {
        snapshot sequential = adapted_sphere(0, 1 + 0.5 * k);
        assert_true(concurrent[k].result.counts_status == SFA_OK);
        expect_same(&sequential, &concurrent[k].result, "a concurrent handle");
        snapshot_free(&sequential);
        snapshot_free(&concurrent[k].result);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_refined_keeps_corners_faces_volume_and_linear_fields),
        cmocka_unit_test(sphere_at_its_own_edge_length_gets_good_angles_and_keeps_volume),
        cmocka_unit_test(anisotropic_meshes_are_as_close_to_the_surface_with_as_many_vertices),
        cmocka_unit_test(ridge_curves_nearer_than_r_l_merge_instead_of_leaving_needles),
        cmocka_unit_test(shallow_fan_is_never_turned_over_nor_crosses_itself),
        cmocka_unit_test(thin_ellipsoid_is_not_carried_through_itself),
        cmocka_unit_test(fandisk_keeps_its_features_and_volume),
        cmocka_unit_test(spot_keeps_its_volume_and_triangle_quality),
        cmocka_unit_test(nothing_lost_when_memory_runs_out),
        cmocka_unit_test(adaptation_is_deterministic_for_any_thread_count),
        cmocka_unit_test(concurrent_handles_give_the_sequential_results),
    };
    return cmocka_run_group_tests_name("adapt", tests, NULL, NULL);
}

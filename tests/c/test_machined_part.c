/* SPDX-License-Identifier: BSD-3-Clause */
/* The demo's machined part (apps/surfadapt/machined_part.h): a valid closed surface with
 * the volume it should have, whose corners and ridges the library finds, on the CAD-like
 * input and after sfa_adapt, and nothing on its smooth curved patches. A fresh clone runs
 * this without the paper's models. */
#include "machined_part.h"
#include "support/testing.h"

/* The demo's resolution and edge length (apps/surfadapt/demo.cpp). */
#define DEMO_RESOLUTION 24
#define DEMO_EDGE_LENGTH 0.08
/* A 45-degree chamfer turns the surface by 45 degrees at each of its edges: the default
 * ridge angle exactly, where the chamfer's vertical edges are not found (both its edges
 * turn by 45 however it is cut: together they turn the block's 90). The demo sets 30, and
 * so do these tests; the fillet's and the hole's segments turn by 15 at most. */
#define DEMO_RIDGE_ANGLE 30
/* Points within this of a corner or a ridge curve are on it, as in the demo: the chords of
 * the arcs stay within r (1 - cos(t / 2)) = 0.009 of them at 24 segments, and it is a
 * quarter of the demo's edge length. */
#define ON_FEATURE 0.02

static sfa_mesh_data part(int resolution)
{
    sfa_mesh_data m;
    if (machined_part(resolution, &m.nverts, &m.xyz, &m.ntris, &m.tris) != 0)
        fail_msg("machined_part(%d) failed", resolution);
    return m;
}

/* Every directed edge once and its reverse once: closed, manifold along edges, and every
 * triangle oriented as its neighbours. */
static void assert_closed_and_consistent(const sfa_mesh_data *m)
{
    const size_t n = 3 * (size_t)m->ntris;
    int32_t *directed = malloc(sizeof(int32_t) * 2 * n);
    assert_non_null(directed);
    for (int32_t t = 0; t < m->ntris; ++t)
        for (int k = 0; k < 3; ++k) {
            directed[2 * (3 * (size_t)t + k)] = m->tris[3 * t + k];
            directed[2 * (3 * (size_t)t + k) + 1] = m->tris[3 * t + (k + 1) % 3];
        }
    qsort(directed, n, 2 * sizeof(int32_t), compare_index_pairs);
    for (size_t e = 0; e < n; ++e) {
        const int32_t *d = directed + 2 * e;
        if (e + 1 < n && d[0] == d[2] && d[1] == d[3])
            fail_msg("the directed edge (%d, %d) is in two triangles", (int)d[0], (int)d[1]);
        const int32_t reverse[2] = {d[1], d[0]};
        if (!bsearch(reverse, directed, n, 2 * sizeof(int32_t), compare_index_pairs))
            fail_msg("the edge (%d, %d) has no triangle on its other side turned the other way", (int)d[0],
                     (int)d[1]);
    }
    free(directed);
}

/* Closed, manifold (the library accepts it), of genus 1 (the hole), consistently
 * oriented, outward (positive volume), not passing through itself, and as large as the
 * part to within the bound of its chords, at every resolution. */
static void part_is_a_valid_closed_surface(void **state)
{
    (void)state;
    const int resolutions[] = {8, 12, 24, 48, 96, 400, 4096};
    for (size_t r = 0; r < sizeof resolutions / sizeof *resolutions; ++r) {
        sfa_mesh_data m = part(resolutions[r]);
        assert_closed_and_consistent(&m);
        int32_t nedges = 0;
        free(mesh_edges(&m, &nedges));
        assert_int_equal(m.nverts - nedges + m.ntris, 0); /* Euler characteristic 2 - 2 g, g = 1 */
        sfa_surface *s = make_surface(&m, 0);
        int32_t components = 0;
        assert_ok(s, sfa_get_component_count(s, &components));
        assert_int_equal(components, 1);
        const double volume = measure(s, SFA_MEASURE_VOLUME), exact = machined_part_volume();
        const double bound = machined_part_volume_bound(resolutions[r]);
        print_message("resolution %3d: %5d vertices, %5d triangles, volume %.9f, exact %.9f, off by %.2e (bound "
                      "%.2e), angles %.2f to %.2f\n",
                      resolutions[r], (int)m.nverts, (int)m.ntris, volume, exact, volume - exact, bound,
                      measure(s, SFA_MEASURE_MIN_ANGLE), measure(s, SFA_MEASURE_MAX_ANGLE));
        assert_true(volume > 0);
        assert_near(volume, exact, bound);
        assert_true(measure(s, SFA_MEASURE_SELF_INTERSECTIONS) == 0);
        sfa_destroy(s);
        mesh_free(&m);
    }
    int32_t nv, nt;
    double *xyz;
    int32_t *tris;
    assert_int_equal(machined_part(7, &nv, &xyz, &nt, &tris), -1);
    assert_int_equal(machined_part(4, &nv, &xyz, &nt, &tris), -1);
}

/* The bound is not loose by orders of magnitude: the error is the hole's t^2 term (the
 * bound) less the fillet's, 0.31 of the bound, so halving the segments' angle quarters both. */
static void volume_error_shrinks_as_the_bound_says(void **state)
{
    (void)state;
    double previous = 0;
    for (int resolution = 24; resolution <= 192; resolution *= 2) {
        sfa_mesh_data m = part(resolution);
        sfa_surface *s = make_surface(&m, 0);
        const double error = measure(s, SFA_MEASURE_VOLUME) - machined_part_volume();
        assert_true(error > 0); /* the hole's polygon, inside the hole, is the larger term */
        assert_true(error > 0.25 * machined_part_volume_bound(resolution));
        if (previous > 0)
            assert_near(previous / error, 4, 0.05);
        previous = error;
        sfa_destroy(s);
        mesh_free(&m);
    }
}

static machined_part_features features_found(const sfa_surface *s)
{
    sfa_mesh_data m = read_back(s);
    int32_t *ranks = malloc(sizeof(int32_t) * (size_t)m.nverts), nridges = 0;
    assert_non_null(ranks);
    assert_ok(s, sfa_get_feature_ranks(s, m.nverts, ranks));
    assert_ok(s, sfa_get_ridge_edges(s, 0, NULL, &nridges, 0));
    int32_t *ridges = malloc(sizeof(int32_t) * 2 * (size_t)(nridges ? nridges : 1));
    assert_non_null(ridges);
    assert_ok(s, sfa_get_ridge_edges(s, nridges, ridges, &nridges, 0));
    machined_part_features f;
    machined_part_features_of(m.nverts, m.xyz, ranks, nridges, ridges, ON_FEATURE, &f);
    free(ranks);
    free(ridges);
    mesh_free(&m);
    return f;
}

/* Exactly the part's features: its 8 corners and no other, its 14 ridge curves whole and no
 * ridge edge anywhere else (so none on the fillet, at its tangent lines or on the hole's
 * wall). */
static void assert_exactly_the_parts_features(const machined_part_features *f, const char *when)
{
    print_message("%s: corners %d of %d (%d elsewhere), ridge curves %d of %d (%d edges; %d elsewhere, %d on the "
                  "fillet, %d on the hole's wall)\n",
                  when, f->corners_found, MACHINED_PART_CORNERS, f->corners_elsewhere, f->ridges_found,
                  MACHINED_PART_RIDGES, (int)f->ridge_edges, (int)f->ridge_edges_elsewhere, (int)f->on_fillet,
                  (int)f->on_hole_wall);
    for (int k = 0; k < MACHINED_PART_RIDGES; ++k)
        if (!machined_part_ridge_found(f, k))
            print_message("  %s: %d edges cover %.4f of %.4f\n", machined_part_ridge_name(k), (int)f->edges_on[k],
                          f->covered[k], machined_part_ridge_length(k));
    assert_int_equal(f->corners_found, MACHINED_PART_CORNERS);
    assert_int_equal(f->corners_elsewhere, 0);
    assert_int_equal(f->ridges_found, MACHINED_PART_RIDGES);
    assert_int_equal(f->on_fillet, 0);
    assert_int_equal(f->on_hole_wall, 0);
    assert_int_equal(f->ridge_edges_elsewhere, 0);
}

/* The part at the demo's resolution, with the demo's ridge angle. */
static sfa_surface *demo_surface(const sfa_mesh_data *m)
{
    sfa_surface *s = make_surface(m, 0);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_RIDGE_ANGLE, DEMO_RIDGE_ANGLE), SFA_OK);
    return s;
}

static void input_has_exactly_the_parts_features(void **state)
{
    (void)state;
    sfa_mesh_data m = part(DEMO_RESOLUTION);
    sfa_surface *s = demo_surface(&m);
    machined_part_features f = features_found(s);
    assert_exactly_the_parts_features(&f, "input");
    sfa_destroy(s);
    mesh_free(&m);
}


/* What the demo does (three sfa_adapt calls at edge length 0.08): the features stay
 * exactly the part's, the volume stays to round-off, and the long thin triangles of the
 * export become well shaped ones. */
static void adapted_part_keeps_exactly_its_features(void **state)
{
    (void)state;
    sfa_mesh_data m = part(DEMO_RESOLUTION);
    sfa_surface *s = demo_surface(&m);
    const double volume = measure(s, SFA_MEASURE_VOLUME), good_before = share_of_good_triangles(s);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, DEMO_EDGE_LENGTH), SFA_OK);
    for (int call = 0; call < 3; ++call)
        assert_ok(s, sfa_adapt(s));
    int32_t nv = 0, nt = 0;
    assert_int_equal(sfa_get_counts(s, &nv, &nt), SFA_OK);
    const double change = measure(s, SFA_MEASURE_VOLUME) / volume - 1, good = share_of_good_triangles(s);
    print_message("adapted: %d -> %d vertices, volume change %.2e, triangles with angles in [15, 160]: %.1f%% -> "
                  "%.1f%%, angles %.2f to %.2f\n",
                  (int)m.nverts, (int)nv, change, 100 * good_before, 100 * good, measure(s, SFA_MEASURE_MIN_ANGLE),
                  measure(s, SFA_MEASURE_MAX_ANGLE));
    machined_part_features f = features_found(s);
    assert_exactly_the_parts_features(&f, "adapted");
    assert_true(fabs(change) < 1e-9);
    assert_true(good > good_before);
    assert_true(measure(s, SFA_MEASURE_SELF_INTERSECTIONS) == 0);
    sfa_destroy(s);
    mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(part_is_a_valid_closed_surface),
        cmocka_unit_test(volume_error_shrinks_as_the_bound_says),
        cmocka_unit_test(input_has_exactly_the_parts_features),
        cmocka_unit_test(adapted_part_keeps_exactly_its_features),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

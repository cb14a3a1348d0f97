/* SPDX-License-Identifier: BSD-3-Clause */
/* Components (bubbles, drops, sheets in one surface): their count and deterministic
 * numbering, per-component measures and their errors, and each closed component keeping
 * its own volume through smoothing and adaptation, whatever the others do. */
#include "support/shapes.h"
#include "support/testing.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A big sphere (r 0.3, first), a small one (r 0.1, at x = 1) and an open grid beside
 * them (z = -1), in one mesh. */
static sfa_mesh_data two_bubbles_and_a_sheet(void)
{
    const sfa_mesh_data parts[3] = {shape_icosphere(3, 0.3), shape_icosphere(3, 0.1), shape_grid(8, 8, 0.1)};
    const double shift[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}};
    sfa_mesh_data all = {0, 0, NULL, NULL};
    for (int p = 0; p < 3; ++p) {
        all.nverts += parts[p].nverts;
        all.ntris += parts[p].ntris;
    }
    all.xyz = malloc(sizeof(double) * 3 * (size_t)all.nverts);
    all.tris = malloc(sizeof(int32_t) * 3 * (size_t)all.ntris);
    int32_t v = 0, t = 0;
    for (int p = 0; p < 3; ++p) {
        for (int32_t i = 0; i < parts[p].nverts; ++i)
            for (int k = 0; k < 3; ++k)
                all.xyz[3 * (v + i) + k] = parts[p].xyz[3 * i + k] + shift[p][k];
        for (int32_t i = 0; i < 3 * parts[p].ntris; ++i)
            all.tris[3 * t + i] = parts[p].tris[i] + v;
        v += parts[p].nverts;
        t += parts[p].ntris;
    }
    for (int p = 0; p < 3; ++p)
        mesh_free((sfa_mesh_data *)&parts[p]);
    return all;
}

static double component_measure(const sfa_surface *s, int32_t c, int quantity)
{
    double value = NAN;
    assert_ok(s, sfa_measure_component(s, c, quantity, &value));
    return value;
}

static void components_are_numbered_by_their_first_vertex(void **state)
{
    (void)state;
    sfa_mesh_data m = two_bubbles_and_a_sheet();
    sfa_surface *s = make_surface(&m, 0);
    int32_t count = -1;
    assert_ok(s, sfa_get_component_count(s, &count));
    assert_int_equal(count, 3);
    int32_t *of = malloc(sizeof(int32_t) * (size_t)m.nverts);
    assert_ok(s, sfa_get_components(s, m.nverts, of));
    const int32_t big = 642, small = 642; /* vertices of a level-3 icosphere */
    for (int32_t v = 0; v < m.nverts; ++v)
        assert_int_equal(of[v], v < big ? 0 : v < big + small ? 1 : 2);

    /* Renumbered so that the sheet comes first: it becomes component 0. */
    sfa_mesh_data r = m;
    r.xyz = malloc(sizeof(double) * 3 * (size_t)m.nverts);
    r.tris = malloc(sizeof(int32_t) * 3 * (size_t)m.ntris);
    const int32_t sheet = m.nverts - big - small;
    for (int32_t v = 0; v < m.nverts; ++v) {
        const int32_t to = (v + sheet) % m.nverts; /* the last `sheet` vertices go first */
        memcpy(r.xyz + 3 * to, m.xyz + 3 * v, 3 * sizeof(double));
    }
    for (int32_t i = 0; i < 3 * m.ntris; ++i)
        r.tris[i] = (m.tris[i] + sheet) % m.nverts;
    assert_ok(s, sfa_set_mesh(s, r.nverts, r.xyz, r.ntris, r.tris, 0));
    assert_ok(s, sfa_get_components(s, m.nverts, of));
    assert_int_equal(of[0], 0);
    assert_int_equal(of[sheet], 1);
    assert_int_equal(of[sheet + big], 2);

    /* sfa_adapt renumbers the vertices for locality: the components follow the same rule. */
    assert_ok(s, sfa_adapt(s));
    int32_t nv = 0;
    assert_ok(s, sfa_get_counts(s, &nv, NULL));
    of = realloc(of, sizeof(int32_t) * (size_t)nv);
    assert_ok(s, sfa_get_components(s, nv, of));
    int32_t seen = 0; /* components met so far: each first vertex opens the next number */
    for (int32_t v = 0; v < nv; ++v) {
        assert_true(of[v] <= seen);
        seen += of[v] == seen;
    }
    assert_int_equal(seen, 3);
    free(of);
    mesh_free(&r);
    mesh_free(&m);
    sfa_destroy(s);
}

static void per_component_measures_add_up(void **state)
{
    (void)state;
    sfa_mesh_data m = two_bubbles_and_a_sheet();
    sfa_surface *s = make_surface(&m, 0);
    const double pi = 3.14159265358979323846;
    /* An inscribed level-3 icosphere holds about 0.99 of its sphere's volume. */
    assert_near(component_measure(s, 0, SFA_MEASURE_VOLUME) / (4.0 / 3 * pi * 0.027), 0.99, 0.01);
    assert_near(component_measure(s, 1, SFA_MEASURE_VOLUME) / (4.0 / 3 * pi * 0.001), 0.99, 0.01);
    assert_near(component_measure(s, 2, SFA_MEASURE_AREA), 0.64, 1e-12);
    double total = 0, area = 0;
    assert_ok(s, sfa_measure(s, SFA_MEASURE_AREA, &total));
    for (int32_t c = 0; c < 3; ++c)
        area += component_measure(s, c, SFA_MEASURE_AREA);
    assert_near(area, total, 1e-12 * total);
    double smallest = 0;
    assert_ok(s, sfa_measure(s, SFA_MEASURE_MIN_ANGLE, &smallest));
    assert_near(component_measure(s, 2, SFA_MEASURE_MIN_ANGLE), 45, 1e-9); /* the grid's right triangles */
    assert_true(component_measure(s, 0, SFA_MEASURE_MIN_ANGLE) >= smallest);
    assert_near(component_measure(s, 2, SFA_MEASURE_MAX_ANGLE), 90, 1e-9);
    assert_near(component_measure(s, 0, SFA_MEASURE_SELF_INTERSECTIONS), 0, 0);
    mesh_free(&m);
    sfa_destroy(s);
}

static void bad_component_arguments_change_nothing(void **state)
{
    (void)state;
    sfa_surface *none;
    assert_int_equal(sfa_create(&none), SFA_OK);
    double v = 7;
    int32_t count = 5;
    assert_error(none, sfa_get_component_count(none, &count), SFA_ERR_STATE, "no mesh");
    assert_error(none, sfa_measure_component(none, 0, SFA_MEASURE_VOLUME, &v), SFA_ERR_STATE, "no mesh");
    assert_int_equal(count, 5);
    sfa_destroy(none);

    sfa_mesh_data m = two_bubbles_and_a_sheet();
    sfa_surface *s = make_surface(&m, 1);
    expect_unchanged(s, sfa_measure_component(s, 3, SFA_MEASURE_VOLUME, &v), SFA_ERR_ARGUMENT, "component 3",
                     "has 3");
    expect_unchanged(s, sfa_measure_component(s, -1, SFA_MEASURE_VOLUME, &v), SFA_ERR_ARGUMENT, "component -1");
    expect_unchanged(s, sfa_measure_component(s, 0, SFA_MEASURE_SECONDS_ANALYSIS, &v), SFA_ERR_ARGUMENT,
                     "not one of its components");
    expect_unchanged(s, sfa_measure_component(s, 0, SFA_MEASURE_VOLUME_CORRECTION, &v), SFA_ERR_ARGUMENT,
                     "not one of its components");
    expect_unchanged(s, sfa_measure_component(s, 0, 999, &v), SFA_ERR_ARGUMENT, "unknown quantity 999");
    expect_unchanged(s, sfa_measure_component(s, 0, SFA_MEASURE_VOLUME, NULL), SFA_ERR_ARGUMENT, "NULL");
    assert_true(v == 7);
    int32_t *of = malloc(sizeof(int32_t) * (size_t)m.nverts);
    of[0] = -9;
    expect_unchanged(s, sfa_get_components(s, m.nverts - 1, of), SFA_ERR_ARGUMENT, "capacity too small");
    assert_int_equal(of[0], -9);
    expect_unchanged(s, sfa_get_components(s, m.nverts, NULL), SFA_ERR_ARGUMENT, "NULL");
    expect_unchanged(s, sfa_get_component_count(s, NULL), SFA_ERR_ARGUMENT, "NULL");
    free(of);
    mesh_free(&m);
    sfa_destroy(s);
}

/* The component whose vertices' mean lies nearest `point` (sfa_adapt renumbers the
 * vertices, and with them the components). */
static int32_t component_near(const sfa_surface *s, const double point[3])
{
    int32_t nv = 0, nt = 0, count = 0;
    assert_ok(s, sfa_get_counts(s, &nv, &nt));
    assert_ok(s, sfa_get_component_count(s, &count));
    double *xyz = malloc(sizeof(double) * 3 * (size_t)nv);
    int32_t *tris = malloc(sizeof(int32_t) * 3 * (size_t)nt), *of = malloc(sizeof(int32_t) * (size_t)nv);
    assert_ok(s, sfa_get_mesh(s, nv, xyz, nt, tris, 0));
    assert_ok(s, sfa_get_components(s, nv, of));
    int32_t best = -1;
    double best_distance = INFINITY;
    for (int32_t c = 0; c < count; ++c) {
        double mean[3] = {0, 0, 0};
        int32_t members = 0;
        for (int32_t v = 0; v < nv; ++v)
            if (of[v] == c) {
                for (int k = 0; k < 3; ++k)
                    mean[k] += xyz[3 * v + k];
                ++members;
            }
        double d = 0;
        for (int k = 0; k < 3; ++k)
            d += (mean[k] / members - point[k]) * (mean[k] / members - point[k]);
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    free(xyz);
    free(tris);
    free(of);
    return best;
}

/* Adapts (or smooths) the two bubbles and the sheet; each closed component's volume after,
 * relative to before, and the call's SFA_MEASURE_VOLUME_CORRECTION. */
static double relative_volume_changes(int adapt, double correction, double change[2])
{
    sfa_mesh_data m = two_bubbles_and_a_sheet();
    sfa_surface *s = make_surface(&m, 0);
    assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.04)); /* about 16 edges around the small bubble */
    assert_ok(s, sfa_set_param(s, SFA_PARAM_VOLUME_CORRECTION, correction));
    const double before[2] = {component_measure(s, 0, SFA_MEASURE_VOLUME), component_measure(s, 1, SFA_MEASURE_VOLUME)};
    assert_ok(s, adapt ? sfa_adapt(s) : sfa_smooth(s, 3));
    int32_t count = 0;
    assert_ok(s, sfa_get_component_count(s, &count));
    assert_int_equal(count, 3);
    const double centre[2][3] = {{0, 0, 0}, {1, 0, 0}};
    for (int c = 0; c < 2; ++c)
        change[c] = (component_measure(s, component_near(s, centre[c]), SFA_MEASURE_VOLUME) - before[c]) / before[c];
    double reported = -1;
    assert_ok(s, sfa_measure(s, SFA_MEASURE_VOLUME_CORRECTION, &reported));
    mesh_free(&m);
    sfa_destroy(s);
    return reported;
}

static void each_bubble_keeps_its_own_volume(void **state)
{
    (void)state;
    for (int adapt = 0; adapt < 2; ++adapt) {
        double kept[2], left[2];
        const double reported_kept = relative_volume_changes(adapt, 1, kept);
        const double reported_left = relative_volume_changes(adapt, 0, left);
        print_message("%s: operations alone change the volumes by %.3g and %.3g; corrected, %.3g and %.3g\n",
                      adapt ? "sfa_adapt" : "sfa_smooth", left[0], left[1], kept[0], kept[1]);
        for (int c = 0; c < 2; ++c)
            assert_near(kept[c], 0, 1e-12); /* round-off, for the small bubble as for the big one */
        /* Without the correction, the measure is what the operations left. */
        assert_near(reported_left, fmax(fabs(left[0]), fabs(left[1])), 1e-9);
        assert_true(reported_left > 1e-12);
        /* With it: sfa_adapt makes the same operations, then corrects once, and reports the
         * same; sfa_smooth corrects after each sweep and reports the largest change a
         * sweep made, which is no more than what three uncorrected sweeps add up to. */
        if (adapt)
            assert_near(reported_kept, reported_left, 1e-12);
        else
            assert_true(reported_kept > 0.2 * reported_left && reported_kept <= reported_left);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(components_are_numbered_by_their_first_vertex),
        cmocka_unit_test(per_component_measures_add_up),
        cmocka_unit_test(bad_component_arguments_change_nothing),
        cmocka_unit_test(each_bubble_keeps_its_own_volume),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

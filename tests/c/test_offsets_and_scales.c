/* SPDX-License-Identifier: BSD-3-Clause */
/* The same jittered sphere far from the origin and at very different scales, through
 * sfa_smooth and sfa_adapt: relative results as at the origin at scale 1, to what the
 * coordinates can hold.
 *
 * A sphere of radius r centred at (o, o, o) r has its shape in the digits of its coordinates
 * below o r: about u = 2.2e-16 (1 + o) of r is their resolution (1.5e-8 r at o = 1e8). The
 * library computes every sum about a point near the surface (the volume about each
 * component's centre), so what it can lose is that resolution and no more: the volume
 * correction restores each volume exactly for the coordinates as they are, and rounding
 * the corrected vertices to their coordinates then moves each by at most half a unit of
 * their last place (0.87 u r in length) along the surface's normal, which changes the
 * volume by at most 0.87 u r times the area, 2.6 u V on a sphere. So |dV / V| <= 4 u +
 * 1e-13 (the sums' own round-off), and every relative figure of the shape agrees with the
 * reference run to a few u. Volumes used to be summed about the origin: at o = 1e5 the sum
 * kept one digit, and the correction moved the vertices to match it (-24 % in one
 * sfa_adapt; at 1e6 the sphere was destroyed). */
#include "support/testing.h"

/* What a run gives, relative to the sphere (radius r, centre c): the relative volume change,
 * the largest and the mean |(|x - c| / r) - 1| over the vertices, the smallest angle, the
 * mean edge length over r and the vertex count. */
typedef struct {
    double volume_change, worst_radius, mean_radius, min_angle, mean_edge;
    int32_t nverts;
} outcome;

/* The enclosed volume about c, computed here: x - c is exact far from the origin, so this
 * does not depend on how the library sums. */
static double volume_about(const sfa_mesh_data *m, double c)
{
    double sum = 0;
    for (int32_t t = 0; t < m->ntris; ++t) {
        double p[3][3];
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a)
                p[k][a] = m->xyz[3 * m->tris[3 * t + k] + a] - c;
        sum += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
               p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    }
    return sum / 6;
}

static outcome run(int adapt, double offset, double scale)
{
    sfa_mesh_data m = shape_jittered_icosphere(3, 1.0, 0.25, 17);
    const double c = offset * scale;
    for (int32_t k = 0; k < 3 * m.nverts; ++k)
        m.xyz[k] = m.xyz[k] * scale + c;
    sfa_surface *s = make_surface(&m, 0);
    const double before = volume_about(&m, c);
    assert_near(measure(s, SFA_MEASURE_VOLUME), before, 1e-13 * before);
    if (adapt) {
        /* Refine a little: 0.1 of the radius (the start has edges of about 0.13). */
        assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.1 * scale));
        assert_ok(s, sfa_adapt(s));
    } else {
        assert_ok(s, sfa_smooth(s, 3));
    }
    outcome out;
    out.min_angle = measure(s, SFA_MEASURE_MIN_ANGLE);
    out.mean_edge = measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH) / scale;
    sfa_mesh_data after = read_back(s);
    const double volume = volume_about(&after, c);
    assert_near(measure(s, SFA_MEASURE_VOLUME), volume, 1e-13 * volume);
    out.volume_change = (volume - before) / before;
    out.nverts = after.nverts;
    out.worst_radius = 0;
    out.mean_radius = 0;
    for (int32_t v = 0; v < after.nverts; ++v) {
        /* x - c is exact: both are within a factor 2 of each other far from the origin. */
        const double *x = after.xyz + 3 * v;
        const double d = fabs(sqrt((x[0] - c) * (x[0] - c) + (x[1] - c) * (x[1] - c) + (x[2] - c) * (x[2] - c)) / scale - 1);
        out.worst_radius = fmax(out.worst_radius, d);
        out.mean_radius += d / after.nverts;
    }
    mesh_free(&after);
    sfa_destroy(s);
    mesh_free(&m);
    return out;
}

static void check_against(const outcome *got, const outcome *reference, double offset, double scale, const char *call)
{
    const double u = 2.220446049250313e-16 * (1 + offset);
    print_message("%s at offset %g r, r = %g: dV/V %.2e, worst |r - 1| %.6e, mean %.6e, min angle %.4f, mean edge %.6f r, "
                  "%d vertices\n",
                  call, offset, scale, got->volume_change, got->worst_radius, got->mean_radius, got->min_angle,
                  got->mean_edge, (int)got->nverts);
    if (!(fabs(got->volume_change) <= 4 * u + 1e-13))
        fail_msg("%s at offset %g, scale %g: the volume changed by %.3e (allowed %.3e)", call, offset, scale,
                 got->volume_change, 4 * u + 1e-13);
    assert_int_equal(got->nverts, reference->nverts);
    assert_near(got->worst_radius, reference->worst_radius, 8 * u + 1e-12);
    assert_near(got->mean_radius, reference->mean_radius, 8 * u + 1e-12);
    assert_near(got->mean_edge, reference->mean_edge, 8 * u + 1e-12);
    assert_near(got->min_angle, reference->min_angle, 1e6 * u + 1e-9); /* degrees: u over a short edge */
}

static void same_relative_results_at_any_offset_and_scale(int adapt)
{
    const char *call = adapt ? "sfa_adapt" : "sfa_smooth(3)";
    const outcome reference = run(adapt, 0, 1);
    check_against(&reference, &reference, 0, 1, call);
    const double offsets[] = {0, 1e3, 1e5, 1e8}, scales[] = {1e-12, 1, 1e12};
    for (size_t i = 0; i < sizeof offsets / sizeof offsets[0]; ++i)
        for (size_t j = 0; j < sizeof scales / sizeof scales[0]; ++j) {
            if (offsets[i] == 0 && scales[j] == 1)
                continue;
            const outcome got = run(adapt, offsets[i], scales[j]);
            check_against(&got, &reference, offsets[i], scales[j], call);
        }
}

static void smoothing_far_from_the_origin(void **state)
{
    (void)state;
    same_relative_results_at_any_offset_and_scale(0);
}

static void adaptation_far_from_the_origin(void **state)
{
    (void)state;
    same_relative_results_at_any_offset_and_scale(1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(smoothing_far_from_the_origin),
        cmocka_unit_test(adaptation_far_from_the_origin),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}

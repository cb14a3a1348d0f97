/* SPDX-License-Identifier: BSD-3-Clause */
/* Collision-safe motion (SFA_PARAM_COLLISION_SAFE_MOTION): two drops driven into each other
 * by the host are stopped apart, or the call fails cleanly, and the surface never passes
 * through itself; without it they pass through each other. The same through sfa_advect.
 * Two triangles that touch within rounding are not rounded through each other. */
#include "support/testing.h"

/* Two spheres of radius 0.2 whose centres are 0.46 apart on the x axis (a gap of 0.06). */
static sfa_surface *two_drops(void)
{
    sfa_mesh_data m = shape_two_icospheres(3, 0.2, 0.46);
    sfa_surface *s = make_surface(&m, 1);
    mesh_free(&m);
    return s;
}

/* Each drop's vertices at speed 0.25 toward the other. */
static double *toward_each_other(const sfa_surface *s, int32_t *nverts)
{
    sfa_mesh_data m = read_back(s);
    *nverts = m.nverts;
    double *vel = malloc(sizeof(double) * 3 * (size_t)m.nverts);
    for (int32_t v = 0; v < m.nverts; ++v) {
        vel[3 * v] = m.xyz[3 * v] < 0 ? 0.25 : -0.25;
        vel[3 * v + 1] = vel[3 * v + 2] = 0;
    }
    mesh_free(&m);
    return vel;
}

static double self_intersections(const sfa_surface *s)
{
    double count = -1;
    assert_ok(s, sfa_measure(s, SFA_MEASURE_SELF_INTERSECTIONS, &count));
    return count;
}

/* Moves the drops toward each other for up to 80 calls of dt = 0.01, adapting at l = 0.03
 * after each: returns the number of calls made before one failed (80 if none did), and the
 * largest self-intersection count seen after any call. */
static int drive_together(sfa_surface *s, int adapt, double *worst_crossings)
{
    *worst_crossings = 0;
    for (int call = 0; call < 80; ++call) {
        int32_t n = 0;
        double *vel = toward_each_other(s, &n), dt_taken = 0;
        assert_ok(s, sfa_set_velocities_checked(s, n, vel));
        free(vel);
        snapshot before, after;
        snapshot_take(s, &before);
        const int rc = sfa_move(s, 0.01, &dt_taken);
        if (rc != SFA_OK) {
            /* A clean failure: the status, a message naming the pair, nothing changed. */
            assert_error(s, rc, SFA_ERR_NUMERIC, "triangles", "apart", "closing");
            print_message("stopped after %d calls: %s\n", call, sfa_last_error(s));
            snapshot_take(s, &after);
            assert_same_snapshot(&before, &after);
            snapshot_free(&before);
            snapshot_free(&after);
            return call;
        }
        snapshot_free(&before);
        if (adapt)
            assert_ok(s, sfa_adapt(s));
        *worst_crossings = fmax(*worst_crossings, self_intersections(s));
    }
    return 80;
}

static void drops_driven_together_never_cross(void **state)
{
    (void)state;
    sfa_surface *s = two_drops();
    assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.03));
    assert_ok(s, sfa_set_param(s, SFA_PARAM_COLLISION_SAFE_MOTION, 1));
    assert_ok(s, sfa_adapt(s));
    double crossings = 0;
    const int calls = drive_together(s, 1, &crossings);
    assert_true(calls < 80); /* they keep closing, so the motion must stop them */
    assert_true(crossings == 0);
    int32_t count = 0;
    assert_ok(s, sfa_get_component_count(s, &count));
    assert_int_equal(count, 2);
    sfa_destroy(s);
}

/* The control: the same drive without the check passes one drop through the other. */
static void without_the_check_the_drops_pass_through_each_other(void **state)
{
    (void)state;
    sfa_surface *s = two_drops();
    double crossings = 0;
    const int calls = drive_together(s, 0, &crossings);
    assert_int_equal(calls, 80);
    print_message("without the check: up to %.0f crossing pairs\n", crossings);
    assert_true(crossings > 0);
    sfa_destroy(s);
}

/* Without adaptation, every step is cut by the check alone: the gap closes by at most half
 * per call, and the call that cannot advance fails before the drops touch. */
static void the_gap_halves_at_most_per_call(void **state)
{
    (void)state;
    sfa_surface *s = two_drops();
    assert_ok(s, sfa_set_param(s, SFA_PARAM_COLLISION_SAFE_MOTION, 1));
    double crossings = 0;
    const int calls = drive_together(s, 0, &crossings);
    /* 0.06 apart, closing at 0.5: 0.12 of time, 12 full steps, then halvings down to a
     * millionth of an edge (about 0.1 long): some twenty more. */
    assert_true(calls >= 12 && calls < 80);
    assert_true(crossings == 0);
    sfa_destroy(s);
}

/* sfa_advect with a field that drives the drops together (the first half of the vertices
 * is the left drop): the same guarantee. */
static void toward_each_other_by_index(void *ctx, int32_t n, const double *xyz, double t, double *vel)
{
    (void)ctx;
    (void)xyz;
    (void)t;
    for (int32_t v = 0; v < n; ++v) {
        vel[3 * v] = v < n / 2 ? 0.25 : -0.25;
        vel[3 * v + 1] = vel[3 * v + 2] = 0;
    }
}

static void advected_drops_never_cross(void **state)
{
    (void)state;
    sfa_surface *s = two_drops();
    assert_ok(s, sfa_set_param(s, SFA_PARAM_COLLISION_SAFE_MOTION, 1));
    double t = 0;
    for (int call = 0; call < 80; ++call) {
        double dt_taken = 0;
        const int rc = sfa_advect(s, toward_each_other_by_index, NULL, t, 0.01, &dt_taken);
        if (rc != SFA_OK) {
            assert_error(s, rc, SFA_ERR_NUMERIC, "triangles", "closing");
            print_message("advection stopped at t = %.9f (contact at 0.12): %s\n", t, sfa_last_error(s));
            break;
        }
        t += dt_taken;
        assert_true(self_intersections(s) == 0);
    }
    assert_true(t < 0.12 && t > 0.119);
    sfa_destroy(s);
}

/* With topology change on, sheets that meet and are not merged (here: no sfa_adapt to
 * merge them) are in contact: their triangles move together instead of stopping the
 * step, so the host's time goes on and the drops still never cross. */
static void with_topology_change_touching_drops_move_on_together(void **state)
{
    (void)state;
    sfa_surface *s = two_drops();
    assert_ok(s, sfa_set_param(s, SFA_PARAM_TOPOLOGY_CHANGE, 1));
    double moved = 0, crossings = 0;
    for (int call = 0; call < 30; ++call) {
        int32_t n = 0;
        double *vel = toward_each_other(s, &n), dt_taken = 0;
        assert_ok(s, sfa_set_velocities_checked(s, n, vel));
        free(vel);
        assert_ok(s, sfa_move(s, 0.01, &dt_taken));
        moved += dt_taken;
        crossings = fmax(crossings, self_intersections(s));
    }
    /* The drops touch at 0.12: without contact the calls after it halve their steps until
     * one fails, short of 0.12. With it, each ring of triangles that comes to touch cuts a
     * few steps before it joins the contact, and the rest are whole (0.257). */
    print_message("30 calls of 0.01 advanced %.4f\n", moved);
    assert_true(moved > 0.2);
    assert_true(crossings == 0);
    int32_t count = 0;
    assert_ok(s, sfa_get_component_count(s, &count));
    assert_int_equal(count, 2);
    sfa_destroy(s);
}

static void with_topology_change_advected_drops_move_on_together(void **state)
{
    (void)state;
    sfa_surface *s = two_drops();
    assert_ok(s, sfa_set_param(s, SFA_PARAM_TOPOLOGY_CHANGE, 1));
    double t = 0;
    for (int call = 0; call < 30; ++call) {
        double dt_taken = 0;
        assert_ok(s, sfa_advect(s, toward_each_other_by_index, NULL, t, 0.01, &dt_taken));
        t += dt_taken;
        assert_true(self_intersections(s) == 0);
    }
    print_message("30 calls of 0.01 reached t = %.4f\n", t);
    assert_true(t > 0.2);
    sfa_destroy(s);
}

/* Two triangles that touch within the rounding of their coordinates (an edge of each
 * passes the other's a hair apart), as an adaptation left them in a soak (seed
 * 20261215006110), and a uniform translation, which moves neither relative to the other.
 * Each corner's x + dt v is rounded on its own, and that carries one through the other. */
static const double touching_xyz[18] = {
    -77.873409080925597, 427.59687682882253,  -344.63315513547957, -100.44766048276591, 417.95652652563422,
    -350.03944560530056, -77.567464426031862, 430.29100905441339,  -344.17342887587733, -75.584532482022837,
    422.48164700866636,  -343.01099599971343, -95.859264382713818, 414.8436398112907,   -354.93944932392606,
    -81.000409007886475, 429.71831454172599,  -341.29379407419805};
static const int32_t touching_tris[6] = {1, 2, 3, 4, 5, 6};
static const double translation_dt = 0.21019420662315624;

static sfa_surface *touching_pair(int collision_safe)
{
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    assert_ok(s, sfa_set_param(s, SFA_PARAM_COLLISION_SAFE_MOTION, collision_safe));
    assert_ok(s, sfa_set_mesh(s, 6, touching_xyz, 2, touching_tris, 1));
    assert_true(self_intersections(s) == 0);
    return s;
}

static void translation(void *ctx, int32_t n, const double *xyz, double t, double *vel)
{
    (void)ctx, (void)xyz, (void)t;
    for (int32_t v = 0; v < n; ++v) {
        vel[3 * v] = 36.77749154987;
        vel[3 * v + 1] = 292.76650504786585;
        vel[3 * v + 2] = -617.4492053123314;
    }
}

/* Without the check the rounding carries them through each other; with it the step is
 * refused, naming the pair in the caller's numbering, and nothing moves (sfa_move), or it
 * goes through without a crossing (sfa_advect's positions are rounded otherwise). */
static void rounding_never_carries_touching_triangles_through_each_other(void **state)
{
    (void)state;
    double vel[18], dt_taken = 0;
    translation(NULL, 6, touching_xyz, 0, vel);
    sfa_surface *unsafe = touching_pair(0);
    assert_ok(unsafe, sfa_set_velocities(unsafe, vel));
    assert_ok(unsafe, sfa_move(unsafe, translation_dt, &dt_taken));
    assert_true(self_intersections(unsafe) == 1);
    sfa_destroy(unsafe);

    sfa_surface *s = touching_pair(1);
    assert_ok(s, sfa_set_velocities(s, vel));
    expect_unchanged(s, sfa_move(s, translation_dt, &dt_taken), SFA_ERR_NUMERIC, "triangles 1 and 2", "rounding");
    /* With topology change, whose contact moves touching pairs together, the same. */
    sfa_surface *in_contact = touching_pair(1);
    assert_ok(in_contact, sfa_set_param(in_contact, SFA_PARAM_TOPOLOGY_CHANGE, 1));
    assert_ok(in_contact, sfa_set_velocities(in_contact, vel));
    expect_unchanged(in_contact, sfa_move(in_contact, translation_dt, &dt_taken), SFA_ERR_NUMERIC,
                     "triangles 1 and 2", "rounding");
    sfa_destroy(in_contact);
    snapshot before, after;
    snapshot_take(s, &before);
    int refused = 0;
    for (int call = 0; call < 20; ++call) {
        const int advected = sfa_advect(s, translation, NULL, 0, translation_dt / (call + 1), &dt_taken);
        if (advected != SFA_OK) {
            ++refused;
            assert_error(s, advected, SFA_ERR_NUMERIC, "triangles 1 and 2", "rounding");
            snapshot_take(s, &after);
            assert_same_snapshot(&before, &after);
            snapshot_free(&after);
        } else {
            assert_true(self_intersections(s) == 0);
            snapshot_free(&before);
            snapshot_take(s, &before);
        }
    }
    print_message("sfa_advect: %d of 20 steps refused, the others without a crossing\n", refused);
    snapshot_free(&before);
    sfa_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(drops_driven_together_never_cross),
        cmocka_unit_test(without_the_check_the_drops_pass_through_each_other),
        cmocka_unit_test(the_gap_halves_at_most_per_call),
        cmocka_unit_test(advected_drops_never_cross),
        cmocka_unit_test(with_topology_change_touching_drops_move_on_together),
        cmocka_unit_test(with_topology_change_advected_drops_move_on_together),
        cmocka_unit_test(rounding_never_carries_touching_triangles_through_each_other),
    };
    return cmocka_run_group_tests_name("test_collision_safe_motion", tests, NULL, NULL);
}

// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the collision-safe step (first_approach): on random pairs of triangles
// with random velocities no pair meets at any time of the step it allows (checked with
// the exact triangle test at many times), the step is not needlessly short where the
// answer is known (two parallel plates closing: a quarter of the gap per triangle), pairs
// that share a vertex or already meet are not limited, pairs within the rounding of the
// step's positions are listed for the caller's exact check, and the result is the same for
// any number of threads.
#include "geometry/triangle_intersection.hpp"
#include "mesh/parallel.hpp"
#include "geometry/collision_time.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <setjmp.h>

extern "C" {
#include <cmocka.h>
}

#include "numbers.hpp"

using namespace sfa;

namespace {


TriMesh two_triangles(const Vec3 (&x)[6])
{
    TriMesh mesh;
    mesh.pos.assign(x, x + 6);
    mesh.tri = {Triangle{0, 1, 2}, Triangle{3, 4, 5}};
    return mesh;
}

bool meet_at(const TriMesh &mesh, const std::vector<Vec3> &v, double t)
{
    Vec3 x[6];
    for (int k = 0; k < 6; ++k)
        x[k] = mesh.pos[k] + t * v[k];
    return triangles_intersect(x[0], x[1], x[2], x[3], x[4], x[5]);
}

void random_pairs_never_meet_within_the_allowed_step(void **)
{
    Numbers rng{7};
    int limited = 0, checked = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        Vec3 x[6];
        for (int k = 0; k < 3; ++k) {
            x[k] = rng.point(1);
            x[3 + k] = rng.point(1) + Vec3(rng.uniform(0, 1.5), 0, 0);
        }
        const TriMesh mesh = two_triangles(x);
        if (triangles_intersect(x[0], x[1], x[2], x[3], x[4], x[5]))
            continue;
        std::vector<Vec3> v(6);
        for (Vec3 &w : v)
            w = rng.point(2);
        const double dt = 1;
        const Approach a = first_approach(mesh, v, dt);
        assert_true(a.time > 0 && a.time <= dt);
        limited += a.time < dt;
        for (int s = 0; s <= 64; ++s) {
            if (meet_at(mesh, v, a.time * s / 64))
                fail_msg("trial %d: the pair meets at t = %g within the allowed %g", trial, a.time * s / 64, a.time);
            ++checked;
        }
    }
    print_message("%d steps limited, %d times checked\n", limited, checked);
    assert_true(limited > 5000);
}

// Two parallel unit plates 0.1 apart: one still, the other closing at speed 1. The plane
// between them moves at their mean speed, and each may take a quarter of the gap toward
// it: the gap halves, in 0.05.
void closing_plates_may_take_a_quarter_of_their_gap(void **)
{
    const Vec3 x[6] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                       Vec3(0, 0, 0.1), Vec3(0, 1, 0.1), Vec3(1, 0, 0.1)};
    const TriMesh mesh = two_triangles(x);
    std::vector<Vec3> v(6, Vec3::Zero());
    for (int k = 3; k < 6; ++k)
        v[k] = Vec3(0, 0, -1);
    const Approach a = first_approach(mesh, v, 1);
    assert_true(std::abs(a.time - 0.05) < 1e-12);
    assert_true(std::abs(a.gap - 0.1) < 1e-12 && std::abs(a.closing - 1) < 1e-12);
    assert_true(a.first == 0 && a.second == 1);
    // Sliding past each other at any speed costs nothing.
    for (int k = 3; k < 6; ++k)
        v[k] = Vec3(100, -50, 0);
    assert_true(first_approach(mesh, v, 1).time == 1);
}

// Two plates a ten-thousandth of their size apart, turning together about an axis between
// them (as the two layers of a cusp do): a plane fixed at the start is soon crossed, but
// their distance does not shrink, so they may move the whole step; and they never meet.
// Closing in as well, they are stopped before they do.
void layers_turning_a_hair_apart_may_move_on(void **)
{
    const double gap = 1e-4;
    const Vec3 x[6] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                       Vec3(0, 0, gap), Vec3(0, 1, gap), Vec3(1, 0, gap)};
    const TriMesh mesh = two_triangles(x);
    const Vec3 axis(0.3, 0.3, gap / 2), turn(0.01, -0.01, 0); // radians per unit time
    std::vector<Vec3> v(6);
    for (int k = 0; k < 6; ++k)
        v[k] = turn.cross(x[k] - axis);
    const Approach a = first_approach(mesh, v, 0.1);
    assert_true(a.time == 0.1); // a plane fixed at the start would allow 0.002
    for (int s = 0; s <= 1000; ++s)
        assert_false(meet_at(mesh, v, 0.1 * s / 1000));
    for (int k = 3; k < 6; ++k)
        v[k] += Vec3(0, 0, -0.01); // meets at t = 0.01
    const Approach b = first_approach(mesh, v, 0.1);
    assert_true(b.time < 0.01 && b.time > 0);
    for (int s = 0; s <= 1000; ++s)
        assert_false(meet_at(mesh, v, b.time * s / 1000));
}

// Two triangles whose edges cross at a point, touching (no plane separates them by more
// than round-off) without meeting in the exact test, as smoothing can leave them. Pushed
// into each other they are held at once; sliding along their contact, or apart, they move
// the whole step. Before, a touching pair counted as meeting and was let through (a soak
// finding: a cone whose faces touched 8e-15 apart crossed in one sfa_move).
void touching_pairs_may_slide_or_open_but_not_close(void **)
{
    // Edge (0, 1) of the first along x at z = 0, edge (3, 4) of the second along y at
    // z = 1e-16, over the first's middle; the first lies below, the second above.
    const Vec3 x[6] = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 0.3, -1),
                       Vec3(0, -1, 1e-16), Vec3(0, 1, 1e-16), Vec3(0.3, 0, 1)};
    const TriMesh mesh = two_triangles(x);
    std::vector<Vec3> v(6, Vec3::Zero());
    assert_false(meet_at(mesh, v, 0));
    for (int k = 3; k < 6; ++k)
        v[k] = Vec3(0, 0, -1); // down through the first
    assert_true(first_approach(mesh, v, 1).time < 1e-12);
    for (int k = 3; k < 6; ++k)
        v[k] = Vec3(0, 0, 1); // up and away
    assert_true(first_approach(mesh, v, 1).time == 1);
    for (int k = 3; k < 6; ++k)
        v[k] = Vec3(0, 0.5, 0); // along the contact
    assert_true(first_approach(mesh, v, 1).time == 1);
}

// A pair that touches within the rounding of the step's positions is listed for the
// caller's exact check after the step, whichever way it moves; one a hair further apart
// than that rounding is not.
void pairs_within_rounding_are_listed(void **)
{
    for (const double gap : {1e-16, 0.0, 4e-15, 1e-10}) { // touching, touching, apart but near, apart
        const Vec3 x[6] = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 0.3, -1),
                           Vec3(0, -1, gap), Vec3(0, 1, gap), Vec3(0.3, 0, 1)};
        const TriMesh mesh = two_triangles(x);
        for (const Vec3 &w : {Vec3(0, 0, 1), Vec3(0, 0.5, 0), Vec3(100, 100, 100)}) {
            const std::vector<Vec3> v(6, w); // the first along with the second: no relative motion
            TrianglePairs listed;
            first_approach(mesh, v, 1, nullptr, nullptr, &listed);
            if (gap < 1e-10) {
                assert_int_equal(listed.size(), 1);
                assert_true(listed[0] == std::make_pair(0, 1));
            } else {
                assert_true(listed.empty());
            }
        }
    }
}

// Neighbours (a shared vertex) are the fold control's, and a pair that already meets has
// no plane to keep: neither limits the step.
void neighbours_and_meeting_pairs_do_not_limit(void **)
{
    TriMesh fan;
    fan.pos = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0.1), Vec3(0, -1, 0.1)};
    fan.tri = {Triangle{0, 1, 2}, Triangle{0, 3, 4}};
    std::vector<Vec3> v(5, Vec3::Zero());
    v[3] = v[4] = Vec3(5, 5, -1);
    assert_true(first_approach(fan, v, 1).time == 1);
    const Vec3 x[6] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                       Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(0.3, 0.5, 1)};
    const TriMesh crossing = two_triangles(x);
    std::vector<Vec3> w(6, Vec3::Zero());
    w[0] = Vec3(0, 0, 1);
    assert_true(first_approach(crossing, w, 1).time == 1);
}

// Triangles side by side in 40 layers, each moving at its own random speed: nearly all
// closing on others.
TriMesh closing_layers(std::vector<Vec3> &v)
{
    TriMesh mesh;
    Numbers rng{11};
    for (int layer = 0; layer < 40; ++layer)
        for (int k = 0; k < 30; ++k) {
            const int base = static_cast<int>(mesh.pos.size());
            const Vec3 at(0.1 * k, 0, 0.05 * layer);
            mesh.pos.push_back(at);
            mesh.pos.push_back(at + Vec3(0.1, 0, 0));
            mesh.pos.push_back(at + Vec3(0.05, 0.1, 0));
            mesh.tri.push_back(Triangle{base, base + 1, base + 2});
            const Vec3 speed = rng.point(0.5);
            for (int c = 0; c < 3; ++c)
                v.push_back(speed + rng.point(0.05));
        }
    return mesh;
}

// The same answer, and the same pair, for one thread and for two.
void the_answer_does_not_depend_on_threads(void **)
{
    std::vector<Vec3> v;
    const TriMesh mesh = closing_layers(v);
    Approach by[2];
    for (int threads = 1; threads <= 2; ++threads) {
        ThreadLimit limit(threads);
        by[threads - 1] = first_approach(mesh, v, 1);
    }
    assert_true(by[0].time < 1);
    assert_true(by[0].time == by[1].time && by[0].first == by[1].first && by[0].second == by[1].second);
}

// With `among` (the contact rounds of motion/safe_motion), the first approach of the pairs
// with a triangle among them: each such pair measured alone, the earliest, found only
// among the triangles near them. Three layers in the middle; and a triangle far from all.
void among_a_few_is_the_earliest_of_their_pairs(void **)
{
    std::vector<Vec3> v;
    TriMesh mesh = closing_layers(v);
    std::vector<int32_t> among;
    for (int32_t t = 20 * 30; t < 23 * 30; t += 2)
        among.push_back(t);
    Approach expected;
    expected.time = 1;
    for (int32_t s = 0; s < mesh.num_triangles(); ++s)
        for (int32_t t : among) {
            if (s == t)
                continue;
            const int32_t a = std::min(s, t), b = std::max(s, t);
            Vec3 x[6];
            std::vector<Vec3> w(6);
            for (int k = 0; k < 3; ++k) {
                x[k] = mesh.pos[mesh.tri[a][k]];
                x[3 + k] = mesh.pos[mesh.tri[b][k]];
                w[k] = v[mesh.tri[a][k]];
                w[3 + k] = v[mesh.tri[b][k]];
            }
            Approach pair = first_approach(two_triangles(x), w, 1);
            pair.first = a;
            pair.second = b;
            if (pair.time < expected.time || (pair.time == expected.time && pair.time < 1 &&
                                              std::make_pair(a, b) < std::make_pair(expected.first, expected.second)))
                expected = pair;
        }
    const Approach found = first_approach(mesh, v, 1, &among);
    assert_true(expected.time < 1);
    assert_true(found.time == expected.time && found.first == expected.first && found.second == expected.second);

    // A triangle far from the others: nothing limits it.
    const int32_t far = static_cast<int32_t>(mesh.pos.size());
    for (const Vec3 &corner : {Vec3(50, 0, 0), Vec3(50.1, 0, 0), Vec3(50, 0.1, 0)}) {
        mesh.pos.push_back(corner);
        v.push_back(Vec3(-1, 0, 0));
    }
    mesh.tri.push_back(Triangle{far, far + 1, far + 2});
    const std::vector<int32_t> alone = {mesh.num_triangles() - 1};
    assert_true(first_approach(mesh, v, 1, &alone).time == 1);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(random_pairs_never_meet_within_the_allowed_step),
        cmocka_unit_test(closing_plates_may_take_a_quarter_of_their_gap),
        cmocka_unit_test(layers_turning_a_hair_apart_may_move_on),
        cmocka_unit_test(touching_pairs_may_slide_or_open_but_not_close),
        cmocka_unit_test(pairs_within_rounding_are_listed),
        cmocka_unit_test(neighbours_and_meeting_pairs_do_not_limit),
        cmocka_unit_test(the_answer_does_not_depend_on_threads),
        cmocka_unit_test(among_a_few_is_the_earliest_of_their_pairs),
    };
    return cmocka_run_group_tests_name("unit_collision_time", tests, nullptr, nullptr);
}

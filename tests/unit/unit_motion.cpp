// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the fold control: the quadratic's first root and the fold time of a
// triangle under linear motion, against hand-computed answers.
#include "motion/fold_time.hpp"

#include "mesh/parallel.hpp"

#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <limits>
#include <vector>
#include <setjmp.h>

extern "C" {
#include <cmocka.h>
}

using namespace sfa;

namespace {

const double inf = std::numeric_limits<double>::infinity();

void first_positive_root_of_quadratics(void **)
{
    // (1 - t)(1 - t/2) = 1 - 1.5 t + 0.5 t^2: first root 1.
    assert_float_equal(first_positive_root(1, -1.5, 0.5), 1.0, 1e-15);
    // 1 - t: linear.
    assert_float_equal(first_positive_root(1, -1, 0), 1.0, 1e-15);
    // 1 + t + t^2 never vanishes; 1 + t vanishes only at negative t.
    assert_true(first_positive_root(1, 1, 1) == inf);
    assert_true(first_positive_root(1, 1, 0) == inf);
    // 1 - t^2: root at 1 (the other at -1).
    assert_float_equal(first_positive_root(1, 0, -1), 1.0, 1e-15);
    // Tiny quadratic term does not spoil the linear root (cancellation-free formula).
    assert_float_equal(first_positive_root(1, -1, 1e-20), 1.0, 1e-12);
}

TriMesh one_triangle()
{
    TriMesh mesh;
    mesh.pos = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.tri = {Triangle{0, 1, 2}};
    return mesh;
}

void apex_crossing_the_base_folds_when_it_reaches_it(void **)
{
    // Vertex 2 moves down at speed 1: the triangle is flat at t = 1 and inverted after.
    const TriMesh mesh = one_triangle();
    const std::vector<Vec3> velocity = {Vec3::Zero(), Vec3::Zero(), Vec3(0, -1, 0)};
    assert_float_equal(first_fold_time(mesh, velocity), 1.0, 1e-15);
}

void translation_and_stretching_never_fold(void **)
{
    const TriMesh mesh = one_triangle();
    assert_true(first_fold_time(mesh, {Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3)}) == inf);
    assert_true(first_fold_time(mesh, {Vec3::Zero(), Vec3(5, 0, 0), Vec3(0, 5, 0)}) == inf);
}

void faster_apex_folds_sooner(void **)
{
    // The apex at speed 4 towards and through the base: flat at t = 1/4.
    const TriMesh mesh = one_triangle();
    assert_float_equal(first_fold_time(mesh, {Vec3::Zero(), Vec3::Zero(), Vec3(1, -4, 0)}), 0.25, 1e-15);
}

// The fold time does not depend on the size of the triangle or of its velocities: a
// triangle 1e-100 across whose apex crosses its base at 1e-100 per unit time folds at
// t = 1 as the unit one does (its squared normal, 1e-400, used to underflow to 0 and the
// "safe step" with it), and so do triangles up to the largest coordinates with velocities
// from 1e-200 to 1e200 scaled alike. Scaled by powers of two, to the last bit.
void fold_time_is_the_same_at_every_scale(void **)
{
    const Vec3 e1(1, 0, 0), e2(0.3, 1, 0), d1 = Vec3::Zero(), d2(0.1, -1, 0.2);
    const double unit = triangle_fold_time(e1, e2, d1, d2);
    assert_float_equal(unit, 1.0, 1e-15);
    for (double length : {1e-100, 1e-50, 1.0, 1e50})
        for (double speed : {1e-200, 1e-100, 1.0, 1e100, 1e200}) {
            const double t = triangle_fold_time(length * e1, length * e2, speed * d1, speed * d2);
            const double expected = length / speed; // from 1e-300 to 1e250: a normal double
            if (!(std::abs(t / expected - 1) <= 1e-15))
                fail_msg("length %g, speed %g: fold at %.17g, expected %.17g", length, speed, t, expected);
        }
    for (int k : {-300, -100, 100, 300})
        for (int j : {-300, 0, 300}) {
            const double a = std::ldexp(1.0, k), b = std::ldexp(1.0, j);
            assert_true(triangle_fold_time(a * e1, a * e2, b * d1, b * d2) == std::ldexp(unit, k - j));
        }
    // No relative motion: never; a flat triangle: at once.
    assert_true(triangle_fold_time(e1, e2, Vec3::Zero(), Vec3::Zero()) == inf);
    assert_true(triangle_fold_time(e1, 2 * e1, d1, d2) == 0);
}

// The first fold names its triangle (the lowest of equal times).
void first_fold_names_the_triangle(void **)
{
    TriMesh mesh;
    mesh.pos = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
    mesh.tri = {Triangle{0, 1, 2}, Triangle{1, 3, 2}};
    // Vertex 3 moves through the edge (1, 2) at speed 1: triangle 1 flat at t = 1/2.
    const Fold fold = first_fold(mesh, {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3(-1, -1, 0)});
    assert_int_equal(fold.triangle, 1);
    assert_float_equal(fold.time, 0.5, 1e-15);
    assert_int_equal(first_fold(mesh, std::vector<Vec3>(4, Vec3(1, 2, 3))).triangle, -1);
}

// Among many triangles, in blocks that threads take apart, the first fold is the earliest
// and, of equal times, the lowest triangle, whatever the number of threads: 30,000
// separate triangles, each with its apex moving through its base at a speed of its own;
// the fastest, at triangles 9,000, 17,000 and 25,000, fold first and together.
void first_fold_is_the_lowest_of_the_earliest_among_many(void **)
{
    TriMesh mesh;
    std::vector<Vec3> velocity;
    for (int32_t k = 0; k < 30000; ++k) {
        const Vec3 at(3.0 * k, 0, 0);
        for (const Vec3 &corner : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)})
            mesh.pos.push_back(at + corner);
        mesh.tri.push_back(Triangle{3 * k, 3 * k + 1, 3 * k + 2});
        const bool fastest = k == 9000 || k == 17000 || k == 25000;
        velocity.insert(velocity.end(), {Vec3::Zero(), Vec3::Zero(), Vec3(0, fastest ? -4.0 : -1.0 - k * 1e-5, 0)});
    }
    for (int threads : {1, 2, 3}) {
        const ThreadLimit limit(threads);
        const Fold fold = first_fold(mesh, velocity);
        assert_int_equal(fold.triangle, 9000);
        assert_float_equal(fold.time, 0.25, 1e-15);
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(first_positive_root_of_quadratics),
        cmocka_unit_test(apex_crossing_the_base_folds_when_it_reaches_it),
        cmocka_unit_test(translation_and_stretching_never_fold),
        cmocka_unit_test(faster_apex_folds_sooner),
        cmocka_unit_test(fold_time_is_the_same_at_every_scale),
        cmocka_unit_test(first_fold_names_the_triangle),
        cmocka_unit_test(first_fold_is_the_lowest_of_the_earliest_among_many),
    };
    return cmocka_run_group_tests_name("unit_motion", tests, nullptr, nullptr);
}

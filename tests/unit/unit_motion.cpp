// Unit tests of the fold control: the quadratic's first root and the fold time of a
// triangle under linear motion, against hand-computed answers.
#include "motion/fold_time.hpp"

#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <limits>
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

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(first_positive_root_of_quadratics),
        cmocka_unit_test(apex_crossing_the_base_folds_when_it_reaches_it),
        cmocka_unit_test(translation_and_stretching_never_fold),
        cmocka_unit_test(faster_apex_folds_sooner),
    };
    return cmocka_run_group_tests_name("unit_motion", tests, nullptr, nullptr);
}

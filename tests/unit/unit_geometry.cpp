// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the quadric analysis and the metric: the eigen-solver choice on
// near-degenerate tensors, the frame rotation of §3.2, metric lengths (eq. 4) and the
// clamping of eq. 12.
#include "geometry/direction_classes.hpp"
#include "geometry/metric.hpp"
#include "geometry/quadric_error.hpp"
#include "geometry/triangle_intersection.hpp"

#include "numbers.hpp"

#include <cmath>
#include <cstdlib>
#include <cstdarg>
#include <cstddef>
#include <limits>
#include <setjmp.h>

extern "C" {
#include <cmocka.h>
}

using namespace sfa;

namespace {

constexpr double pi = 3.14159265358979323846;

// A rotation that mixes every axis, so that no answer is axis-aligned by accident.
Mat3 some_rotation()
{
    return (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(-1.1, Vec3(-2, 1, 0.5).normalized()))
        .toRotationMatrix();
}

void decomposition_recovers_near_degenerate_spectra(void **)
{
    const Mat3 rotation = some_rotation();
    // Flat (lambda2 = lambda3 ~ 0), cylinder-like (lambda3 << lambda2 << lambda1), and a
    // nearly repeated pair (lambda2 ~ lambda3), where the closed form loses accuracy.
    // Then spectra where lambda1 is not well separated (a ridge, a corner), which the
    // smooth vertices' method leaves to the general one, and the same at any magnitude.
    const Eigen::Vector3d spectra[] = {{1, 1e-17, 0},       {1, 1e-2, 1e-15},       {1, 1e-3, 1e-3 * (1 - 1e-9)},
                                       {2, 1, 1e-6},        {1, 1 - 1e-9, 0.2},     {1, 1 - 1e-4, 1e-3},
                                       {1, 0.999, 0.998},   {1, 0.5, 0.5 - 1e-12}, {1, 0, 0}};
    for (const double magnitude : {1.0, 1e-200, 1e200})
        for (const Eigen::Vector3d &unit_lambda : spectra) {
            const Eigen::Vector3d lambda = magnitude * unit_lambda;
            const Mat3 a = rotation * lambda.asDiagonal() * rotation.transpose();
            const QuadricEigen eigen = decompose(a);
            for (int i = 0; i < 3; ++i)
                assert_true(std::abs(eigen.values[i] - lambda[i]) <= 1e-12 * magnitude);
            assert_true(eigen.values[0] >= eigen.values[1] && eigen.values[1] >= eigen.values[2]);
            // Where e1 is well separated it must match the rotated x axis.
            if (unit_lambda[0] - unit_lambda[1] > 1e-3)
                assert_true(std::abs(std::abs(eigen.e(0).dot(rotation.col(0))) - 1) < 1e-12);
            // Every returned pair is an eigenpair of A to round-off, the vectors orthonormal
            // (Eigen's closed form, for the spectra not a smooth vertex's, errs by 2e-13
            // where two eigenvalues are 1e-4 apart).
            assert_true(((a * eigen.vectors - eigen.vectors * eigen.values.asDiagonal()) / magnitude).norm() < 1e-12);
            assert_true((eigen.vectors.transpose() * eigen.vectors - Mat3::Identity()).norm() < 1e-13);
        }
    // Equal eigenvalues (a cube's corner): any orthonormal frame.
    const QuadricEigen corner = decompose(Mat3::Identity());
    assert_true((corner.values - Eigen::Vector3d::Ones()).norm() < 1e-15);
    assert_true((corner.vectors.transpose() * corner.vectors - Mat3::Identity()).norm() < 1e-15);
    // No face: all zero.
    assert_true(decompose(Mat3::Zero()).values.norm() == 0);
}

QuadricEigen eigen_of(const Eigen::Vector3d &values, const Mat3 &vectors) { return QuadricEigen{values, vectors}; }

void metric_is_identity_where_flat_and_clamped_to_the_bounds(void **)
{
    const MetricBounds bounds{8 * pi / 180, 30 * pi / 180, true};
    const double ratio = std::pow(std::tan(15 * pi / 180) / std::tan(4 * pi / 180), 2);
    const VertexMetric flat = vertex_metric(eigen_of({2, 0, 0}, Mat3::Identity()), Vec3(1, 0, 0), bounds);
    assert_float_equal(flat.m_major, 1, 1e-15);
    assert_float_equal(flat.m_minor, 1, 1e-15);
    const VertexMetric ridge = vertex_metric(eigen_of({1, 1, 0}, Mat3::Identity()), Vec3(1, 0, 0), bounds);
    assert_float_equal(ridge.m_major, ratio, 1e-12);
    assert_float_equal(ridge.aspect_ratio(), std::tan(15 * pi / 180) / std::tan(4 * pi / 180), 1e-12);
    const VertexMetric isotropic =
        vertex_metric(eigen_of({1, 1, 0}, Mat3::Identity()), Vec3(1, 0, 0), MetricBounds{0.1, 0.5, false});
    assert_float_equal(isotropic.aspect_ratio(), 1, 0);
}

void normal_points_outward_and_frame_is_right_handed(void **)
{
    const VertexMetric m = vertex_metric(eigen_of({1, 0.1, 0}, Mat3::Identity()), Vec3(-3, 0.2, 0),
                                         MetricBounds{8 * pi / 180, 30 * pi / 180, true});
    assert_float_equal(m.normal.x(), -1, 0);
    assert_float_equal(m.major.cross(m.minor).dot(m.normal), 1, 1e-15);
}

void frame_rotation_is_exact_for_a_shared_normal(void **)
{
    // Two frames in the same plane, rotated by 0.4 rad about the common normal z.
    Eigen::Matrix<double, 3, 2> tp, tq;
    tp << 1, 0, 0, 1, 0, 0;
    tq << std::cos(0.4), -std::sin(0.4), std::sin(0.4), std::cos(0.4), 0, 0;
    const Eigen::Matrix2d r = frame_rotation(tq, tp);
    assert_true((r - tq.transpose() * tp).norm() < 1e-15);
    assert_true((r.transpose() * r - Eigen::Matrix2d::Identity()).norm() < 1e-15);
}

void frame_rotation_stays_a_rotation_when_normals_differ(void **)
{
    Eigen::Matrix<double, 3, 2> tp, tq;
    tp << 1, 0, 0, 1, 0, 0;
    const Mat3 tilt = Eigen::AngleAxisd(0.3, Vec3(1, 1, 0).normalized()).toRotationMatrix();
    tq = tilt * tp;
    const Eigen::Matrix2d r = frame_rotation(tq, tp);
    assert_true((r.transpose() * r - Eigen::Matrix2d::Identity()).norm() < 1e-14);
    // R_2 is along the projection of p's second axis onto q's frame.
    const Eigen::Vector2d s2 = tq.transpose() * tp.col(1);
    assert_true((r.col(1) - s2.normalized()).norm() < 1e-14);
}

void tensor_in_frame_is_the_rotated_tensor(void **)
{
    // The closed form against its definition R^T M_q R with R = frame_rotation, for frames
    // tilted every way, including the sign flip of R's first column.
    std::srand(7);
    const auto random_unit = [] {
        return Vec3(std::rand() / (double)RAND_MAX - 0.5, std::rand() / (double)RAND_MAX - 0.5,
                    std::rand() / (double)RAND_MAX - 0.5)
            .normalized();
    };
    for (int trial = 0; trial < 1000; ++trial) {
        VertexMetric p, q;
        for (VertexMetric *m : {&p, &q}) {
            m->normal = random_unit();
            m->major = (random_unit().cross(m->normal)).normalized();
            m->minor = (trial % 2 ? -1.0 : 1.0) * m->normal.cross(m->major);
        }
        q.m_major = 1 + 10.0 * std::rand() / RAND_MAX;
        q.m_minor = 1;
        const Eigen::Matrix2d r = frame_rotation(q.frame(), p.frame());
        assert_true((tensor_in_frame(q, p) - r.transpose() * q.tensor() * r).norm() < 1e-12 * q.m_major);
    }
}

void metric_length_scales_with_direction(void **)
{
    // A ridge along y at both ends: short across (x, factor sqrt(m_major)), physical along y.
    const MetricBounds bounds{8 * pi / 180, 30 * pi / 180, true};
    Mat3 axes;
    axes.col(0) = Vec3(0, 0, 1); // e1: normal
    axes.col(1) = Vec3(1, 0, 0); // e2: across the ridge
    axes.col(2) = Vec3(0, 1, 0); // e3: along it
    const VertexMetric m = vertex_metric(eigen_of({1, 1, 0}, axes), Vec3(0, 0, 1), bounds);
    assert_float_equal(metric_edge_length(Vec3(0, 0, 0), m, Vec3(0, 0.5, 0), m), 0.5, 1e-15);
    assert_float_equal(metric_edge_length(Vec3(0, 0, 0), m, Vec3(0.5, 0, 0), m), 0.5 * std::sqrt(m.m_major), 1e-14);
}

void tensor_square_roots_match_the_eigen_decomposition(void **)
{
    // Rotated diagonal tensors from isotropic to the metric's strongest anisotropy.
    for (const double ratio : {1.0, 1.7, 30.0, 1e4})
        for (const double angle : {0.0, 0.3, 1.2}) {
            const Eigen::Matrix2d r = Eigen::Rotation2Dd(angle).toRotationMatrix();
            const Eigen::Matrix2d m = r * Eigen::Vector2d(2.5 * ratio, 2.5).asDiagonal() * r.transpose();
            const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(m);
            const double tolerance = 1e-14 * std::sqrt(ratio);
            assert_true((tensor_sqrt(m) - eigen.operatorSqrt()).norm() < tolerance * m.norm());
            assert_true((tensor_inverse_sqrt(m) - eigen.operatorInverseSqrt()).norm() < tolerance);
            assert_true((tensor_sqrt(m) * tensor_sqrt(m) - m).norm() < 1e-14 * m.norm());
        }
}

void triangle_pairs_intersect_where_they_share_a_point(void **)
{
    const Vec3 a0(0, 0, 0), a1(1, 0, 0), a2(0, 1, 0);
    // Through a's interior, across it, beside it, above it, touching its corner, and in its plane.
    assert_true(triangles_intersect(a0, a1, a2, Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), Vec3(0.3, 0.5, 1)));
    assert_false(triangles_intersect(a0, a1, a2, Vec3(2, 2, -1), Vec3(2, 2, 1), Vec3(2, 3, 1)));
    assert_false(triangles_intersect(a0, a1, a2, Vec3(0, 0, 1e-3), Vec3(1, 0, 1e-3), Vec3(0, 1, 1e-3)));
    assert_true(triangles_intersect(a0, a1, a2, Vec3(1, 0, 0), Vec3(2, 0, 1), Vec3(2, 1, -1)));
    assert_true(triangles_intersect(a0, a1, a2, Vec3(0.4, 0.4, 0), Vec3(2, 0.4, 0), Vec3(0.4, 2, 0)));
    assert_false(triangles_intersect(a0, a1, a2, Vec3(0.6, 0.6, 0), Vec3(2, 0.6, 0), Vec3(0.6, 2, 0)));
    // One inside the other, in the same plane.
    assert_true(triangles_intersect(a0, a1, a2, Vec3(0.1, 0.1, 0), Vec3(0.3, 0.1, 0), Vec3(0.1, 0.3, 0)));
}

// One face in the plane z = 0; from x = (0, 0, 1e-3) along a direction that nearly lies in
// that plane, the quadric error minimum is 0.1 away: further than a shift of 0.01 allows
// (x stays), within a shift of 1 (the point lands on the plane).
void quadric_error_minimum_stays_within_its_shift(void **)
{
    TriMesh mesh;
    mesh.pos = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(0, 1, 0)};
    mesh.tri = {Triangle{0, 1, 2}};
    const auto faces = [](auto &&visit) { visit(0); };
    const Vec3 x(0, 0, 1e-3), direction = Vec3(1, 0, 0.01).normalized();
    assert_true(quadric_error_minimum_along(mesh, faces, x, direction, 0.01) == x);
    const Vec3 landed = quadric_error_minimum_along(mesh, faces, x, direction, 1.0);
    assert_true(std::abs(landed.z()) < 1e-15);
    assert_true(std::abs((landed - x).norm() - 0.1 * Vec3(1, 0, 0.01).norm()) < 1e-12);
}

// The search for facing sheets passes over two edges whose normals' classes cannot pair:
// no two directions nearly opposite may ever be in such classes, on a cube's edges and
// corners (where a direction's class is decided by rounding) as anywhere; and two
// directions of one smooth sheet, 30 degrees apart, are never compared. The searches pass
// vectors of any length (the sum of two triangles' unit normals): the same holds for them.
void direction_classes_part_no_facing_directions(void **)
{
    const double cosine = -0.5;
    const DirectionClasses classes(cosine);
    Numbers numbers{20261203};
    const double at_edges[] = {-1, -0.5, 0, 0.5, 1};
    const auto random_direction = [&]() {
        if (numbers.pick(2) == 0)
            return numbers.point(1).normalized().eval();
        Vec3 n(at_edges[numbers.pick(5)], at_edges[numbers.pick(5)], at_edges[numbers.pick(5)]);
        n[numbers.pick(3)] = numbers.pick(2) ? 1 : -1;
        n += numbers.point(1e-15);
        return n.normalized().eval();
    };
    int facing = 0;
    for (int k = 0; k < 200000; ++k) {
        const Vec3 a = random_direction(), b = random_direction();
        const auto any_length = [&](const Vec3 &n) { return (std::exp(numbers.uniform(-7, 7)) * n).eval(); };
        const int ca = classes.of(any_length(a)), cb = classes.of(any_length(b));
        assert_true(ca >= 0 && ca < DirectionClasses::count && cb >= 0 && cb < DirectionClasses::count);
        if (a.dot(b) < cosine) {
            ++facing;
            assert_true(classes.may_pair(ca, cb) && classes.may_pair(cb, ca));
        }
        // b turned 30 degrees from a, about a direction across it.
        const Vec3 across = a.cross(numbers.point(1)).normalized();
        const Vec3 near = Eigen::AngleAxisd(pi / 6, across) * a;
        assert_false(classes.may_pair(ca, classes.of(any_length(near))));
    }
    assert_true(facing > 10000);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Vec3 &odd : {Vec3(0, 0, 0), Vec3(nan, 0, 1), Vec3(nan, nan, nan)}) {
        const int c = classes.of(odd);
        assert_true(c >= 0 && c < DirectionClasses::count);
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(decomposition_recovers_near_degenerate_spectra),
        cmocka_unit_test(metric_is_identity_where_flat_and_clamped_to_the_bounds),
        cmocka_unit_test(normal_points_outward_and_frame_is_right_handed),
        cmocka_unit_test(frame_rotation_is_exact_for_a_shared_normal),
        cmocka_unit_test(frame_rotation_stays_a_rotation_when_normals_differ),
        cmocka_unit_test(tensor_in_frame_is_the_rotated_tensor),
        cmocka_unit_test(metric_length_scales_with_direction),
        cmocka_unit_test(tensor_square_roots_match_the_eigen_decomposition),
        cmocka_unit_test(triangle_pairs_intersect_where_they_share_a_point),
        cmocka_unit_test(quadric_error_minimum_stays_within_its_shift),
        cmocka_unit_test(direction_classes_part_no_facing_directions),
    };
    return cmocka_run_group_tests_name("unit_geometry", tests, nullptr, nullptr);
}

// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/local_fit.hpp"

#include <cmath>
#include <utility>

namespace sfa {

Vec3 onto_fitted_surface(const TriMesh &mesh, int32_t v, const VertexMetric &frame, const Vec3 &target)
{
    Vec3 placed = target;
    fitted_surface_point(mesh, v, frame, target, placed);
    return placed;
}

bool fitted_surface_point(const TriMesh &mesh, int32_t v, const VertexMetric &frame, const Vec3 &target, Vec3 &placed)
{
    const Vec3 &p = mesh.pos[v];
    // Normal equations of the fit, scaled by the squared mean edge length so that their
    // conditioning does not depend on the mesh's size.
    using Vector5 = Eigen::Matrix<double, 5, 1>;
    using Matrix5 = Eigen::Matrix<double, 5, 5>;
    Matrix5 normal_matrix = Matrix5::Zero();
    Vector5 right_side = Vector5::Zero();
    // The neighbours' offsets are read once (a fan of more than `kept` twice): the smoothing
    // sweeps fit every vertex.
    constexpr int kept = 32;
    Vec3 offset[kept];
    double scale2 = 0;
    int count = 0;
    mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
        const Vec3 d = mesh.pos[w] - p;
        scale2 += d.squaredNorm();
        if (count < kept)
            offset[count] = d;
        ++count;
    });
    if (count < 5 || !(scale2 > 0))
        return false;
    scale2 /= count;
    const double scale = std::sqrt(scale2);
    const auto add = [&](const Vec3 &d) {
        const double u = d.dot(frame.major), s = d.dot(frame.minor), h = d.dot(frame.normal);
        const double basis[5] = {u * u / scale2, u * s / scale2, s * s / scale2, u / scale, s / scale};
        for (int i = 0; i < 5; ++i) {
            for (int j = 0; j <= i; ++j) // the lower triangle: all the Cholesky factorization reads
                normal_matrix(i, j) += basis[i] * basis[j];
            right_side[i] += basis[i] * h;
        }
    };
    if (count <= kept)
        for (int k = 0; k < count; ++k)
            add(offset[k]);
    else
        mesh.for_each_neighbour(v, [&](int32_t w, int32_t) { add(mesh.pos[w] - p); });
    const Eigen::LLT<Matrix5> solver(normal_matrix);
    // Neighbours on two lines through v (or fewer directions) cannot fix three
    // coefficients, and five neighbours nearly so make a fit that amplifies every wiggle:
    // keep to the tangent plane where the reciprocal condition number is 1e-8 or less.
    // Its estimate costs several solves; the squared ratio of the smallest to the largest
    // Cholesky pivot costs nothing and bounds it from above (the pivots lie between the
    // extreme eigenvalues), so it settles a clear rejection at once, and on real meshes it
    // exceeds the estimate at most about a hundredfold, so that well above the threshold
    // the estimate is not needed either.
    if (solver.info() != Eigen::Success)
        return false;
    const auto pivots = solver.matrixLLT().diagonal();
    const double pivot_ratio2 = std::pow(pivots.minCoeff() / pivots.maxCoeff(), 2);
    if (!(pivot_ratio2 > 1e-8) || (pivot_ratio2 < 1e-3 && !(solver.rcond() > 1e-8)))
        return false;
    const Vector5 coefficients = solver.solve(right_side);
    const Vec3 d = target - p;
    const double u = d.dot(frame.major), s = d.dot(frame.minor);
    Vector5 at_target;
    at_target << u * u / scale2, u * s / scale2, s * s / scale2, u / scale, s / scale;
    const double height = coefficients.dot(at_target);
    placed = p + u * frame.major + s * frame.minor + height * frame.normal;
    return true;
}

bool onto_fitted_surface_of_ends(const TriMesh &mesh, const std::vector<VertexMetric> &frames, int32_t a, bool fit_a,
                                 int32_t b, bool fit_b, const Vec3 &start, double max_shift, Vec3 &placed)
{
    Vec3 sum = Vec3::Zero(), point;
    int fitted = 0;
    for (const auto &[end, fit] : {std::pair{a, fit_a}, std::pair{b, fit_b}})
        if (fit && fitted_surface_point(mesh, end, frames[end], start, point)) {
            sum += point;
            ++fitted;
        }
    if (fitted == 0 || !((sum / fitted - start).norm() <= max_shift))
        return false;
    placed = sum / fitted;
    return true;
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/quadric.hpp"

#include "mesh/parallel.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace sfa {

std::vector<Vec3> face_area_vectors(const TriMesh &mesh)
{
    std::vector<Vec3> area(mesh.tri.size());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        area[t] = face_area_vector(mesh, t);
    return area;
}

std::vector<Vec3> weighted_normals(const std::vector<Vec3> &area_vectors)
{
    std::vector<Vec3> weighted(area_vectors.size());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t t = 0; t < static_cast<int32_t>(area_vectors.size()); ++t)
        weighted[t] = weighted_normal(area_vectors[t]);
    return weighted;
}

Mat3 face_quadric(const Vec3 &area_vector)
{
    const double area = area_vector.norm();
    return !(area > 0) ? Mat3::Zero() : Mat3(area_vector * area_vector.transpose() / area);
}

QuadricEigen decompose(const Mat3 &quadric)
{
    // Eigen's closed-form 3x3 solver is several times faster than the iterative one, but
    // loses accuracy when eigenvalues nearly coincide (errors ~1e-9 lambda1 seen for a
    // pair 1e-12 apart). Keep its answer when every eigenpair's residual is below 1e-10
    // of |A|: far below what the thresholds on lambda_i/lambda1 (>= 1e-3) can notice, and
    // loose enough that the umbilic points of a sphere (lambda2 ~ lambda3) stay on the fast
    // path. Otherwise use the iterative solver.
    // Its errors grow as round-off over the gap between eigenvalues, so the check is
    // needed only where a gap is below 1e-3 |A|, where they could reach the tolerance.
    Eigen::SelfAdjointEigenSolver<Mat3> solver;
    solver.computeDirect(quadric);
    const double scale = std::max(quadric.norm(), 1e-300);
    const Eigen::Vector3d &values = solver.eigenvalues();
    if (!(std::min(values[1] - values[0], values[2] - values[1]) > 1e-3 * scale)) {
        const Mat3 residual = quadric * solver.eigenvectors() - solver.eigenvectors() * values.asDiagonal();
        const double orthogonality = (solver.eigenvectors().transpose() * solver.eigenvectors() - Mat3::Identity()).norm();
        if (!(residual.norm() <= 1e-10 * scale && orthogonality <= 1e-10))
            solver.compute(quadric);
    }
    // Eigen sorts increasingly; the paper numbers them decreasingly.
    QuadricEigen out;
    for (int i = 0; i < 3; ++i) {
        out.values[i] = std::max(solver.eigenvalues()[2 - i], 0.0); // A is positive semi-definite
        out.vectors.col(i) = solver.eigenvectors().col(2 - i);
    }
    return out;
}

} // namespace sfa

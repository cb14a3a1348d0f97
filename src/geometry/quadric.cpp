// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/quadric.hpp"

#include "mesh/parallel.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

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

namespace {

// The eigen-decomposition by Eigen's solvers: the closed form, checked, else the iterative
// one. For any symmetric matrix, however its eigenvalues cluster.
QuadricEigen decompose_by_eigen(const Mat3 &quadric)
{
    // Eigen's closed-form 3x3 solver is several times faster than the iterative one, but
    // loses accuracy when eigenvalues nearly coincide (errors ~1e-9 lambda1 seen for a
    // pair 1e-12 apart). Keep its answer when every eigenpair's residual is below 1e-10
    // of |A|: far below what the thresholds on lambda_i/lambda1 (>= 1e-3) can notice.
    // Otherwise use the iterative solver.
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

// The largest eigenvalue of symmetric positive semi-definite b by Halley's method on its
// characteristic polynomial f(x) = det(x I - b), from b's Frobenius norm, which is no
// smaller. At a smooth vertex the norm is within about (lambda2 / lambda1)^2 of it, and
// one step, whose error is about the cube of the last, settles it: a step below 1e-6 x
// leaves less than round-off. (Newton's method took three or four steps, each a division
// the next one waits for.) False if `iterations` steps leave it unsettled (a largest
// eigenvalue nearly repeated, where the convergence is slow). The caller checks that the
// root found is the largest.
bool largest_eigenvalue(const Mat3 &b, double &x)
{
    constexpr int iterations = 8;
    const double b00 = b(0, 0), b11 = b(1, 1), b22 = b(2, 2), b01 = b(0, 1), b02 = b(0, 2), b12 = b(1, 2);
    const double c2 = b00 + b11 + b22;
    const double c1 = b00 * b11 - b01 * b01 + b00 * b22 - b02 * b02 + b11 * b22 - b12 * b12;
    const double c0 = b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) + b02 * (b01 * b12 - b11 * b02);
    x = b.norm();
    for (int k = 0; k < iterations; ++k) {
        const double f = ((x - c2) * x + c1) * x - c0, slope = (3 * x - 2 * c2) * x + c1, bend = 6 * x - 2 * c2;
        const double step = 2 * f * slope / (2 * slope * slope - f * bend);
        if (!std::isfinite(step))
            return false;
        x -= step;
        if (std::abs(step) <= 1e-6 * x)
            return true;
    }
    return false;
}

} // namespace

QuadricEigen decompose(const Mat3 &quadric)
{
    // A smooth vertex's quadric has one eigenvalue far above the other two (its normal's,
    // §2.2), which may nearly coincide (a sphere's umbilic points). So the largest is found
    // first (largest_eigenvalue); its eigenvector is the cross product of two rows of
    // A - lambda1 I (the largest of the three such products), and the other two are those
    // of A restricted to the plane normal to it, a 2 x 2 problem solved in closed form to
    // round-off of |A| however near lambda2 and lambda3 are. Eigen's closed form takes an
    // arc tangent, a sine and a cosine, and its residuals must be checked wherever two
    // roots come near, which at a smooth vertex they always do: on vortex T = 2 the
    // decompositions took 7.6 G instructions that way and take 3.6 G this way. Where the
    // largest eigenvalue is not well separated (a ridge, a corner), Eigen's solvers decide.
    //
    // b = A / scale, scale the power of two above A's largest entry (exact): no cube in f
    // overflows or underflows. (Eigen's closed form, too, loses accuracy at 1e-200.) The
    // power is read off the entry's exponent bits: frexp and ldexp are library calls, which
    // took a fifth of the decomposition. A zero or extreme A, or one with an entry not a
    // number, goes to Eigen's solvers whole.
    const double largest_entry = quadric.cwiseAbs().maxCoeff();
    if (!(largest_entry >= 1e-290 && largest_entry <= 1e290))
        return decompose_by_eigen(quadric);
    uint64_t bits = 0;
    std::memcpy(&bits, &largest_entry, sizeof bits);
    bits &= 0x7ff0000000000000u; // the exponent alone: the power of two at or below
    double scale = 0;
    std::memcpy(&scale, &bits, sizeof scale);
    scale *= 2;
    const Mat3 b = quadric * (1 / scale);
    const auto by_eigen = [&] {
        QuadricEigen out = decompose_by_eigen(b);
        out.values *= scale;
        return out;
    };
    double lambda1 = 0;
    if (!largest_eigenvalue(b, lambda1))
        return by_eigen();
    const Vec3 r0(b(0, 0) - lambda1, b(0, 1), b(0, 2)), r1(b(1, 0), b(1, 1) - lambda1, b(1, 2)),
        r2(b(2, 0), b(2, 1), b(2, 2) - lambda1); // the rows of b - lambda1 I
    Vec3 e1 = r0.cross(r1);
    double largest = e1.squaredNorm();
    for (const Vec3 &c : {Vec3(r0.cross(r2)), Vec3(r1.cross(r2))})
        if (const double n2 = c.squaredNorm(); n2 > largest) {
            e1 = c;
            largest = n2;
        }
    if (!(largest > 0))
        return by_eigen();
    e1 *= 1 / std::sqrt(largest);
    const Vec3 u = e1.unitOrthogonal(), w = e1.cross(u); // an orthonormal basis of the plane normal to e1
    const auto times_b = [&b](const Vec3 &x) { // b x (Eigen's product was a call)
        return Vec3(b(0, 0) * x[0] + b(0, 1) * x[1] + b(0, 2) * x[2], b(1, 0) * x[0] + b(1, 1) * x[1] + b(1, 2) * x[2],
                    b(2, 0) * x[0] + b(2, 1) * x[1] + b(2, 2) * x[2]);
    };
    const Vec3 bu = times_b(u), bw = times_b(w);
    const double p = u.dot(bu), q = u.dot(bw), r = w.dot(bw);
    // [p q; q r]'s eigenvalues are mean +- radius; the larger's vector in (u, w) comes from
    // whichever of its two forms adds rather than cancels.
    const double half = (p - r) / 2, radius = std::sqrt(half * half + q * q), mean = (p + r) / 2;
    double along_u = half >= 0 ? half + radius : q, along_w = half >= 0 ? q : radius - half;
    if (const double length = std::sqrt(along_u * along_u + along_w * along_w); length > 0) {
        along_u /= length;
        along_w /= length;
    } else { // p = r and q = 0: any pair
        along_u = 1;
        along_w = 0;
    }
    const double mu[2] = {mean + radius, mean - radius};
    const Vec3 v[2] = {along_u * u + along_w * w, along_u * w - along_w * u};
    const double rayleigh = e1.dot(times_b(e1));
    // The root found is the largest, and e1's error (round-off over its gap to the others)
    // below 1e-12 for a gap of 1e-3.
    if (!(rayleigh - mu[0] > 1e-3 * rayleigh))
        return by_eigen();
    QuadricEigen out;
    out.values = Eigen::Vector3d(rayleigh, std::max(mu[0], 0.0), std::max(mu[1], 0.0)) * scale;
    out.vectors.col(0) = e1;
    out.vectors.col(1) = v[0];
    out.vectors.col(2) = v[1];
    return out;
}

} // namespace sfa

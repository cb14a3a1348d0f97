// SPDX-License-Identifier: BSD-3-Clause
// The anisotropic Riemannian metric of §3.1 (eqs. 11-12) in each vertex's tangent frame,
// the transformation of a neighbour's frame into a vertex's (§3.2), and edge lengths in
// metric space (eq. 4).
#pragma once

#include "geometry/quadric.hpp"

#include <cmath>

namespace sfa {

struct MetricBounds {
    // psi_l = lambda1 tan^2(lower_angle/2), psi_u = lambda1 tan^2(upper_angle/2); angles in radians.
    MetricBounds(double lower_angle, double upper_angle, bool anisotropic_metric);
    double lower_ratio; // psi_l / lambda1
    double upper_ratio; // psi_u / lambda1
    bool anisotropic;   // false: the identity metric (isotropic adaptation, for comparison)
};

// M = m_major e2 e2^T + m_minor e3 e3^T on the tangent plane spanned by e2 (major) and e3
// (minor, the direction along which triangles may be long). Eq. 12 clamps lambda2 and lambda3
// to [psi_l, psi_u]; the result is divided by psi_l so that a flat region, where both clamp
// to psi_l, has the identity metric and metric lengths are physical lengths there. Triangles
// then shrink by up to sqrt(psi_u/psi_l) across directions of high curvature.
struct VertexMetric {
    Vec3 normal; // e1, oriented outward
    Vec3 major;  // e2
    Vec3 minor;  // e3
    double m_major;
    double m_minor;

    double aspect_ratio() const { return std::sqrt(m_major / m_minor); }
    // The tangent frame T = [e2 e3] (3x2) of §3.2.
    Eigen::Matrix<double, 3, 2> frame() const;
    // The 2x2 tensor in that frame.
    Eigen::Matrix2d tensor() const { return Eigen::Vector2d(m_major, m_minor).asDiagonal(); }
};

// outward: any vector on the outer side (the sum of the vertex's face area vectors).
VertexMetric vertex_metric(const QuadricEigen &eigen, const Vec3 &outward, const MetricBounds &bounds);

// The 2x2 rotation R taking tangent coordinates at q into those at p (§3.2): with
// S = T_q^T T_p, R_2 = S_2 / |S_2| and R_1 the unit part of S_1 orthogonal to R_2. When both
// frames share e1 it is the exact rotation T_q^T T_p.
Eigen::Matrix2d frame_rotation(const Eigen::Matrix<double, 3, 2> &frame_q, const Eigen::Matrix<double, 3, 2> &frame_p);

// The metric of q expressed in p's tangent frame: R^T M_q R. Inline, in closed form: the
// smoothing sweep calls it for every edge end. R is orthonormal, its second column
// r = (x, y) = S_2 / |S_2| and its first one r rotated a quarter turn, with the sign of S_1
// on it (sigma), so that R^T diag(a, b) R has the entries below; the same fallbacks as
// frame_rotation.
inline Eigen::Matrix2d tensor_in_frame(const VertexMetric &q, const VertexMetric &p)
{
    const double a = q.m_major, b = q.m_minor;
    if (a == b) // isotropic: the same in every frame (flat regions, --isotropic)
        return a * Eigen::Matrix2d::Identity();
    const double s2x = q.major.dot(p.minor), s2y = q.minor.dot(p.minor);
    const double n2 = std::sqrt(s2x * s2x + s2y * s2y);
    if (!(n2 >= 1e-12))
        return q.tensor();
    const double x = s2x / n2, y = s2y / n2;
    const double across = q.major.dot(p.major) * y - q.minor.dot(p.major) * x; // S_1 . (y, -x)
    const double sigma = across <= -1e-12 ? -1 : 1;
    const double off = sigma * x * y * (a - b);
    Eigen::Matrix2d m;
    m << a * y * y + b * x * x, off, off, a * x * x + b * y * y;
    return m;
}

// The square root of a 2x2 symmetric positive definite tensor, in closed form:
// sqrt(M) = (M + s I) / t with s = sqrt(det M), t = sqrt(trace M + 2 s).
inline Eigen::Matrix2d tensor_sqrt(const Eigen::Matrix2d &m)
{
    const double s = std::sqrt(m.determinant()), t = std::sqrt(m.trace() + 2 * s);
    return (m + s * Eigen::Matrix2d::Identity()) / t;
}

// Its inverse, adj(M + s I) / (s t).
inline Eigen::Matrix2d tensor_inverse_sqrt(const Eigen::Matrix2d &m)
{
    const double s = std::sqrt(m.determinant()), t = std::sqrt(m.trace() + 2 * s);
    Eigen::Matrix2d adjugate;
    adjugate << m(1, 1) + s, -m(0, 1), -m(1, 0), m(0, 0) + s;
    return adjugate / (s * t);
}

// Eq. 4 at p: sqrt(d^T T_p M_half T_p^T d), d = p - q, M_half = (M_p + M_q in p's frame) / 2.
double metric_edge_length(const Vec3 &p_position, const VertexMetric &p, const Vec3 &q_position, const VertexMetric &q);

} // namespace sfa

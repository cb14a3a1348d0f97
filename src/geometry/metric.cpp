// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/metric.hpp"

#include <algorithm>
#include <cmath>

namespace sfa {

Eigen::Matrix<double, 3, 2> VertexMetric::frame() const
{
    Eigen::Matrix<double, 3, 2> t;
    t.col(0) = major;
    t.col(1) = minor;
    return t;
}

MetricBounds::MetricBounds(double lower_angle, double upper_angle, bool anisotropic_metric)
    : lower_ratio(std::pow(std::tan(lower_angle / 2), 2)), upper_ratio(std::pow(std::tan(upper_angle / 2), 2)),
      anisotropic(anisotropic_metric)
{
}

VertexMetric vertex_metric(const QuadricEigen &eigen, const Vec3 &outward, const MetricBounds &bounds)
{
    VertexMetric metric;
    metric.normal = eigen.e(0).dot(outward) < 0 ? Vec3(-eigen.e(0)) : eigen.e(0);
    // e1 is well separated wherever it matters and so accurate to round-off; e2 and e3 of a
    // nearly flat vertex are only as accurate as the solver's tolerance. Making the tangent
    // frame exactly orthogonal to e1 keeps motion in it exactly within the tangent plane.
    metric.major = (eigen.e(1) - eigen.e(1).dot(metric.normal) * metric.normal).normalized();
    // A right-handed frame (e2, e3, e1), so that tangent coordinates keep their orientation.
    metric.minor = metric.normal.cross(metric.major);
    if (!bounds.anisotropic) {
        metric.m_major = metric.m_minor = 1;
        return metric;
    }
    const double lambda1 = eigen.values[0];
    const double psi_l = lambda1 * bounds.lower_ratio, psi_u = lambda1 * bounds.upper_ratio;
    const auto clamped = [&](double lambda) { return std::min(std::max(lambda, psi_l), psi_u) / psi_l; };
    metric.m_major = clamped(eigen.values[1]);
    metric.m_minor = clamped(eigen.values[2]);
    return metric;
}

Eigen::Matrix2d frame_rotation(const Eigen::Matrix<double, 3, 2> &frame_q, const Eigen::Matrix<double, 3, 2> &frame_p)
{
    const Eigen::Matrix2d s = frame_q.transpose() * frame_p;
    Eigen::Matrix2d r;
    const double n2 = s.col(1).norm();
    // Frames at right angles (q's tangent plane contains p's normal) have no meaningful
    // projection; fall back to the identity rather than divide by zero.
    if (!(n2 >= 1e-12))
        return Eigen::Matrix2d::Identity();
    r.col(1) = s.col(1) / n2;
    const Eigen::Vector2d rest = s.col(0) - r.col(1).dot(s.col(0)) * r.col(1);
    const double n1 = rest.norm();
    r.col(0) = !(n1 >= 1e-12) ? Eigen::Vector2d(r(1, 1), -r(0, 1)) : Eigen::Vector2d(rest / n1);
    return r;
}

double metric_edge_length(const Vec3 &p_position, const VertexMetric &p, const Vec3 &q_position, const VertexMetric &q)
{
    const Eigen::Matrix2d half = 0.5 * (p.tensor() + tensor_in_frame(q, p));
    const Eigen::Vector2d d = p.frame().transpose() * (p_position - q_position);
    return std::sqrt(d.dot(half * d));
}

} // namespace sfa

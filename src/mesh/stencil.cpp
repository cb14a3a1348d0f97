// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/stencil.hpp"

namespace sfa {

Eigen::Vector3d barycentric(const Vec3 &x, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    const Vec3 normal = (b - a).cross(c - a);
    const double twice_area = normal.squaredNorm();
    const double wa = (c - b).cross(x - b).dot(normal) / twice_area;
    const double wb = (a - c).cross(x - c).dot(normal) / twice_area;
    return Eigen::Vector3d(wa, wb, 1 - wa - wb);
}

} // namespace sfa

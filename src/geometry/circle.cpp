// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/circle.hpp"

#include <cmath>

namespace sfa {

bool circle_through(const Vec3 &a, const Vec3 &b, const Vec3 &c, Circle &circle)
{
    // Centre a + (|u|^2 w x n + |w|^2 n x u) / (2 |n|^2), n = u x w, u = b - a, w = c - a.
    const Vec3 u = b - a, w = c - a, n = u.cross(w);
    if (!(n.squaredNorm() > 1e-24 * u.squaredNorm() * w.squaredNorm())) // collinear, or NaN
        return false;
    const Vec3 to_centre = (u.squaredNorm() * w.cross(n) + w.squaredNorm() * n.cross(u)) / (2 * n.squaredNorm());
    circle = {a + to_centre, n.normalized(), to_centre.norm()};
    return true;
}

Vec3 along_circle(const Circle &circle, const Vec3 &from, const Vec3 &direction, double distance)
{
    const Vec3 radial = from - circle.centre;
    Vec3 tangent = circle.axis.cross(radial / circle.radius);
    if (tangent.dot(direction) < 0)
        tangent = -tangent;
    const double angle = distance / circle.radius;
    return circle.centre + std::cos(angle) * radial + std::sin(angle) * circle.radius * tangent;
}

namespace {

Vec3 arc_midpoint(const Vec3 *third, const Vec3 &a, const Vec3 &b)
{
    const Vec3 chord_midpoint = (a + b) / 2;
    Circle circle;
    if (!third || !circle_through(*third, a, b, circle))
        return chord_midpoint;
    const Vec3 out = chord_midpoint - circle.centre;
    if (!(out.squaredNorm() > 1e-24 * circle.radius * circle.radius))
        return chord_midpoint; // a and b opposite: no curve this coarse is worth following
    return circle.centre + circle.radius * out.normalized();
}

} // namespace

Vec3 curve_midpoint(const Vec3 *before, const Vec3 &a, const Vec3 &b, const Vec3 *after)
{
    if (!before || !after)
        return (a + b) / 2;
    return (arc_midpoint(before, a, b) + arc_midpoint(after, a, b)) / 2;
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/direction_classes.hpp"

#include "geometry/angles.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace sfa {
namespace {

// A direction's square is found by rounding: one just past a square's edge may be placed in
// the next. Widening every class by this angle covers that.
constexpr double margin = radians_per_degree;

// The square of the central projection's coordinate u / largest (in [-1, 1]), counted
// by comparisons, not divisions (this runs for every edge of each merge search and every
// vertex of each crossing guard); NaN in the first, a zero vector in the last.
int square_of(double u, double largest)
{
    int square = 0;
    for (int i = 1; i < DirectionClasses::divisions; ++i)
        square += u >= (-1 + 2.0 * i / DirectionClasses::divisions) * largest;
    return square;
}

// The direction of the central projection's point (u, v) on face (axis, sign).
Vec3 direction(int axis, int sign, double u, double v)
{
    Vec3 n;
    n[axis] = sign;
    n[(axis + 1) % 3] = u;
    n[(axis + 2) % 3] = v;
    return n.normalized();
}

double angle_between(const Vec3 &a, const Vec3 &b) { return std::acos(std::clamp(a.dot(b), -1.0, 1.0)); }

} // namespace

DirectionClasses::DirectionClasses(double cosine) : may_pair_(static_cast<size_t>(count) * count, 0)
{
    constexpr int d = divisions;
    std::array<Vec3, count> centre;
    std::array<double, count> radius;
    for (int face = 0; face < 6; ++face)
        for (int i = 0; i < d; ++i)
            for (int j = 0; j < d; ++j) {
                const int c = (face * d + i) * d + j, axis = face / 2, sign = face % 2 ? -1 : 1;
                const double u0 = -1 + 2.0 * i / d, u1 = -1 + 2.0 * (i + 1) / d;
                const double v0 = -1 + 2.0 * j / d, v1 = -1 + 2.0 * (j + 1) / d;
                centre[c] = direction(axis, sign, (u0 + u1) / 2, (v0 + v1) / 2);
                radius[c] = 0;
                for (double u : {u0, u1})
                    for (double v : {v0, v1})
                        radius[c] = std::max(radius[c], angle_between(centre[c], direction(axis, sign, u, v)));
            }
    // Two directions of classes a and b are at most angle(centres) + both radii apart.
    const double wanted = std::acos(cosine);
    for (int a = 0; a < count; ++a)
        for (int b = 0; b < count; ++b)
            may_pair_[static_cast<size_t>(a * count + b)] =
                angle_between(centre[a], centre[b]) + radius[a] + radius[b] + 2 * margin > wanted;
}

int DirectionClasses::of(const Vec3 &n) const
{
    const double x = std::abs(n[0]), y = std::abs(n[1]), z = std::abs(n[2]);
    const int axis = x >= y ? (x >= z ? 0 : 2) : (y >= z ? 1 : 2); // the first largest
    const double largest = std::abs(n[axis]);
    const int face = 2 * axis + (n[axis] < 0);
    return (face * divisions + square_of(n[(axis + 1) % 3], largest)) * divisions +
           square_of(n[(axis + 2) % 3], largest);
}

} // namespace sfa

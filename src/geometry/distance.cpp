// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sfa {

std::pair<Vec3, Vec3> closest_points(const Vec3 &p0, const Vec3 &p1, const Vec3 &q0, const Vec3 &q1)
{
    const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    const auto clamp01 = [](double x) { return x > 0 ? (x < 1 ? x : 1) : 0; }; // NaN: 0
    double s = 0, t = 0;
    if (a <= 0 && e <= 0)
        return {p0, q0};
    if (a <= 0) {
        t = clamp01(f / e);
    } else {
        const double c = d1.dot(r);
        if (e <= 0) {
            s = clamp01(-c / a);
        } else {
            const double b = d1.dot(d2), denominator = a * e - b * b;
            s = denominator > 0 ? clamp01((b * f - c * e) / denominator) : 0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = clamp01(-c / a);
            } else if (t > 1) {
                t = 1;
                s = clamp01((b - c) / a);
            }
        }
    }
    return {p0 + s * d1, q0 + t * d2};
}

Vec3 closest_point_on_triangle(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    // Which Voronoi region of the triangle p lies in: a corner, an edge or the face.
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0)
        return a;
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3)
        return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return a + d1 / (d1 - d3) * ab;
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6)
        return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denominator = va + vb + vc;
    if (!(denominator > 0)) // a triangle of no area: its edges hold every closest point
        return a;
    return a + (vb / denominator) * ab + (vc / denominator) * ac;
}

double triangle_distance(const Vec3 a[3], const Vec3 b[3])
{
    double least = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        least = std::min(least, (a[k] - closest_point_on_triangle(a[k], b[0], b[1], b[2])).squaredNorm());
        least = std::min(least, (b[k] - closest_point_on_triangle(b[k], a[0], a[1], a[2])).squaredNorm());
        for (int j = 0; j < 3; ++j) {
            const auto [p, q] = closest_points(a[k], a[(k + 1) % 3], b[j], b[(j + 1) % 3]);
            least = std::min(least, (p - q).squaredNorm());
        }
    }
    return std::sqrt(least);
}

} // namespace sfa

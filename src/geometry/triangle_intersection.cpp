// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/triangle_intersection.hpp"

#include "geometry/predicates.hpp"

#include <algorithm>

namespace sfa {
namespace {

// Two closed triangles meet if and only if an edge of one meets the other: their
// intersection is convex, and its extreme points lie on the boundary of one of them.
// A segment meets a triangle it crosses the plane of where the line through it passes
// inside the triangle: the three orientations of the line with the triangle's edges
// then agree in sign (they are the crossing point's barycentric coordinates, scaled).
// Points in one plane are decided in the projections onto the coordinate planes: at
// least one of them is one-to-one on that plane, and none separates points that meet.

using Point2 = double[2];

// The projection that drops coordinate `axis`.
void project(const Vec3 &x, int axis, Point2 out)
{
    out[0] = x[(axis + 1) % 3];
    out[1] = x[(axis + 2) % 3];
}

bool boxes_overlap_2d(const Point2 p, const Point2 q, const Point2 r, const Point2 s)
{
    for (int k = 0; k < 2; ++k)
        if (std::max(p[k], q[k]) < std::min(r[k], s[k]) || std::max(r[k], s[k]) < std::min(p[k], q[k]))
            return false;
    return true;
}

// Closed segments in the plane, either possibly a point.
bool segments_meet_2d(const Point2 p, const Point2 q, const Point2 r, const Point2 s)
{
    const int o1 = orient2d(p, q, r), o2 = orient2d(p, q, s);
    if (o1 * o2 > 0)
        return false;
    const int o3 = orient2d(r, s, p), o4 = orient2d(r, s, q);
    if (o3 * o4 > 0)
        return false;
    if (o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0) // on one line: they meet where their boxes do
        return boxes_overlap_2d(p, q, r, s);
    return true;
}

// A closed segment and a closed triangle (possibly degenerate) in the plane.
bool segment_meets_triangle_2d(const Point2 p, const Point2 q, const Point2 a, const Point2 b, const Point2 c)
{
    if (segments_meet_2d(p, q, a, b) || segments_meet_2d(p, q, b, c) || segments_meet_2d(p, q, c, a))
        return true;
    // Otherwise they meet only if the segment lies inside the triangle: test one end.
    const int turn = orient2d(a, b, c);
    if (turn == 0)
        return false; // a degenerate triangle is its edges
    const int s0 = orient2d(a, b, p), s1 = orient2d(b, c, p), s2 = orient2d(c, a, p);
    return s0 != -turn && s1 != -turn && s2 != -turn;
}

// A segment and a triangle known to lie in one plane (or on one line).
bool coplanar_segment_meets_triangle(const Vec3 &p, const Vec3 &q, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    for (int axis = 0; axis < 3; ++axis) {
        Point2 p2, q2, a2, b2, c2;
        project(p, axis, p2);
        project(q, axis, q2);
        project(a, axis, a2);
        project(b, axis, b2);
        project(c, axis, c2);
        if (!segment_meets_triangle_2d(p2, q2, a2, b2, c2))
            return false;
    }
    return true;
}

bool segments_meet_3d(const Vec3 &p, const Vec3 &q, const Vec3 &r, const Vec3 &s)
{
    if (orient3d(p, q, r, s) != 0)
        return false;
    for (int axis = 0; axis < 3; ++axis) {
        Point2 p2, q2, r2, s2;
        project(p, axis, p2);
        project(q, axis, q2);
        project(r, axis, r2);
        project(s, axis, s2);
        if (!segments_meet_2d(p2, q2, r2, s2))
            return false;
    }
    return true;
}

bool is_degenerate(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    for (int axis = 0; axis < 3; ++axis) {
        Point2 a2, b2, c2;
        project(a, axis, a2);
        project(b, axis, b2);
        project(c, axis, c2);
        if (orient2d(a2, b2, c2) != 0)
            return false;
    }
    return true;
}

// The segment (p, q) against the triangle (a, b, c), given the sides of p and q of the
// triangle's plane (orient3d(a, b, c, .)).
bool segment_meets_triangle(const Vec3 &p, const Vec3 &q, int side_p, int side_q, const Vec3 &a, const Vec3 &b,
                            const Vec3 &c)
{
    if (side_p * side_q > 0)
        return false; // both strictly on one side
    if (side_p == 0 && side_q == 0) {
        if (is_degenerate(a, b, c)) // a segment or a point: every orientation with it is 0
            return segments_meet_3d(p, q, a, b) || segments_meet_3d(p, q, b, c) || segments_meet_3d(p, q, c, a);
        return coplanar_segment_meets_triangle(p, q, a, b, c);
    }
    const int s0 = orient3d(p, q, a, b), s1 = orient3d(p, q, b, c), s2 = orient3d(p, q, c, a);
    const bool positive = s0 > 0 || s1 > 0 || s2 > 0, negative = s0 < 0 || s1 < 0 || s2 < 0;
    return !(positive && negative);
}

} // namespace

bool segment_meets_triangle(const Vec3 &p, const Vec3 &q, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    return segment_meets_triangle(p, q, orient3d(a, b, c, p), orient3d(a, b, c, q), a, b, c);
}

bool triangles_intersect(const Vec3 &a0, const Vec3 &a1, const Vec3 &a2, const Vec3 &b0, const Vec3 &b1,
                         const Vec3 &b2)
{
    const Vec3 *a[3] = {&a0, &a1, &a2}, *b[3] = {&b0, &b1, &b2};
    int side_of_b[3], side_of_a[3]; // each triangle's corners against the other's plane
    for (int k = 0; k < 3; ++k)
        side_of_b[k] = orient3d(a0, a1, a2, *b[k]);
    if (side_of_b[0] * side_of_b[1] > 0 && side_of_b[1] * side_of_b[2] > 0)
        return false; // b strictly on one side of a's plane
    for (int k = 0; k < 3; ++k)
        side_of_a[k] = orient3d(b0, b1, b2, *a[k]);
    if (side_of_a[0] * side_of_a[1] > 0 && side_of_a[1] * side_of_a[2] > 0)
        return false;
    for (int k = 0; k < 3; ++k) {
        const int l = (k + 1) % 3;
        if (segment_meets_triangle(*a[k], *a[l], side_of_a[k], side_of_a[l], b0, b1, b2) ||
            segment_meets_triangle(*b[k], *b[l], side_of_b[k], side_of_b[l], a0, a1, a2))
            return true;
    }
    return false;
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// Closest points and distances between segments, points and triangles (Ericson,
// Real-Time Collision Detection, §5.1.5 and §5.1.9), in floating point: for decisions
// that tolerate rounding (which pairs are near, how far a pair may move), never for
// whether two triangles meet (geometry/triangle_intersection does that exactly).
#pragma once

#include "mesh/tri_mesh.hpp"

#include <utility>

namespace sfa {

// The closest points of segments p0-p1 and q0-q1: p0 + s (p1 - p0) and q0 + t (q1 - q0),
// s and t in [0, 1].
std::pair<Vec3, Vec3> closest_points(const Vec3 &p0, const Vec3 &p1, const Vec3 &q0, const Vec3 &q1);

// The point of triangle abc closest to p.
Vec3 closest_point_on_triangle(const Vec3 &p, const Vec3 &a, const Vec3 &b, const Vec3 &c);

// The distance between triangles a0a1a2 and b0b1b2 that do not meet: the least of the six
// corner-to-triangle and nine edge-to-edge distances (0 if they meet is not guaranteed).
double triangle_distance(const Vec3 a[3], const Vec3 b[3]);

} // namespace sfa

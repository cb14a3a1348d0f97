// SPDX-License-Identifier: BSD-3-Clause
// Circles through three points: vertices on curved ridges and boundaries (a cylinder's rim)
// are moved and placed along them, so that the curve keeps its shape instead of being cut
// by chords. Collinear points mean a straight curve, which stays exactly straight.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

struct Circle {
    Vec3 centre;
    Vec3 axis; // unit normal of the circle's plane
    double radius;
};

// False (and `circle` untouched) if a, b, c are collinear to round-off.
bool circle_through(const Vec3 &a, const Vec3 &b, const Vec3 &c, Circle &circle);

// The point of `circle` an arc length `distance` away from `from` (a point on it), in the
// sense of `direction`.
Vec3 along_circle(const Circle &circle, const Vec3 &from, const Vec3 &direction, double distance);

// Where a new vertex between curve vertices a and b goes: the midpoint of the arc a-b on
// the circle through (before, a, b) and on the one through (a, b, after), averaged (a
// straight triple gives the chord's midpoint for its side). Next to the end of a curve
// (before or after nullptr: a corner) the chord's midpoint, so that the segment into a
// corner stays straight and the corner keeps its whole turn: following the curve there
// would share the turn with the new vertex, and the corner could stop being one.
Vec3 curve_midpoint(const Vec3 *before, const Vec3 &a, const Vec3 &b, const Vec3 *after);

} // namespace sfa

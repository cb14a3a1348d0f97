// SPDX-License-Identifier: BSD-3-Clause
// Whether two closed triangles in space share a point, decided exactly: every decision is
// the sign of an orientation determinant (geometry/predicates.hpp), so nearly coplanar,
// touching and needle-thin configurations get the answer exact arithmetic would give.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

// True if the closed triangles (a0, a1, a2) and (b0, b1, b2) share a point; touching at a
// corner or along an edge counts. Degenerate triangles (collinear or coincident corners)
// are the segments or points they are.
bool triangles_intersect(const Vec3 &a0, const Vec3 &a1, const Vec3 &a2, const Vec3 &b0, const Vec3 &b1,
                         const Vec3 &b2);

// True if the closed segment (p, q) and the closed triangle (a, b, c) share a point.
bool segment_meets_triangle(const Vec3 &p, const Vec3 &q, const Vec3 &a, const Vec3 &b, const Vec3 &c);

} // namespace sfa

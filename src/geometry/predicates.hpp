// SPDX-License-Identifier: BSD-3-Clause
// Exact orientation predicates: the sign of a determinant, always right. A floating-point
// evaluation decides when its error bound allows (nearly always); otherwise the
// determinant is evaluated exactly in expansion arithmetic (geometry/expansion.hpp).
// After Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
// Predicates" (1997), §4: the same determinants and the same first error bounds.
//
// Exact for finite coordinates within the library's range (surfadapt.h); NaN gives 0.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

// +1 if d lies on the side of the plane through a, b, c that the normal (b - a) x (c - a)
// points to, -1 on the other side, 0 if the four points are coplanar (or a, b, c are
// collinear). The sign of det[b - a; c - a; d - a].
int orient3d(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d);

// +1 if a, b, c turn counter-clockwise in the plane, -1 clockwise, 0 if collinear. The
// points are (x[0], x[1]).
int orient2d(const double a[2], const double b[2], const double c[2]);

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// The coordinates the library computes in (stated in surfadapt.h, "Coordinates").
//
// Its geometry is made of products of coordinate differences: an area vector of two, a
// volume term of three, a fold test n(0).n(t) or a squared area of four, the fold time's
// c0 c2 and c1^2 of six (with the velocities'). Within these bounds none of them overflows,
// and none of the mesh's own size underflows:
// - every |coordinate| at most 1e50: a difference is at most 2e50, a product of six at
//   most 6.4e301, below the largest double (1.8e308) with room for sums of thousands;
// - the mesh's extent (the diagonal of its bounding box) at least 1e-50: a product of six
//   differences of that size is at least 1e-300, above the smallest normal double
//   (2.2e-308), so no digit is lost to subnormal numbers.
// Outside them, a product overflows to infinity, or infinity minus infinity makes NaN, and
// tests of area or fold read garbage: a sphere of radius 1e120 reported thousands of
// self-intersections, one of radius 1e-100 looked "flat". Parts much smaller than the
// extent (a sliver among large triangles) can still underflow locally; every test that
// reads such a product is written so that NaN or zero fails it (!(x > 0)).
#pragma once

#include "mesh/tri_mesh.hpp"

#include <cstdint>
#include <vector>

namespace sfa {

inline constexpr double max_abs_coordinate = 1e50;
inline constexpr double min_extent = 1e-50;

// Whether a point is within max_abs_coordinate on every axis (false for NaN).
inline bool coordinate_in_range(const Vec3 &p) { return p.cwiseAbs().maxCoeff() <= max_abs_coordinate; }

// The diagonal of the points' bounding box (0 for none).
double extent_of(const std::vector<Vec3> &points);

// The first point outside the range (-1 if none), or, if they are all in it but span less
// than min_extent, the number of points: one check for every place that makes positions.
int32_t first_out_of_range(const std::vector<Vec3> &points);

// "every |coordinate| at most 1e+50, the mesh spanning at least 1e-50", for messages.
const char *coordinate_range_text();

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// The smooth surface around a vertex, fitted to its neighbours: where a vertex that slides
// in its tangent plane should land so that it stays on the surface.
#pragma once

#include "geometry/metric.hpp"

#include <vector>

namespace sfa {

// The point of the quadratic height function h(u, w) = a u^2 + b u w + c w^2 + d u + e w
// over v's tangent plane (frame e2, e3, normal e1 of `frame`; the linear terms absorb the
// error of the quadric's normal on an irregular mesh), least-squares fitted to v's
// neighbours, above `target`'s tangent coordinates. A vertex moved within its tangent plane by d leaves a
// surface of curvature k by k d^2 / 2 (with the anisotropic metric, d reaches a whole edge
// along ridges: 7e-3 on a cylinder of radius 0.5 meshed at 0.08); lifted onto the fit it
// stays on the surface to third order. With fewer than five neighbours, or neighbours
// that cannot determine the fit, `target` itself. Allocates nothing.
Vec3 onto_fitted_surface(const TriMesh &mesh, int32_t v, const VertexMetric &frame, const Vec3 &target);

// The same, but false (and `placed` untouched) where the fit cannot be made.
bool fitted_surface_point(const TriMesh &mesh, int32_t v, const VertexMetric &frame, const Vec3 &target, Vec3 &placed);

// Where a vertex made on the edge a-b goes (a split's new vertex, §4.1, a contraction's
// merged one, §4.2): the points over `start` on the surfaces fitted around the ends that
// `fit_a` and `fit_b` allow (the smooth ones: a feature end's fan reaches across its
// crease), averaged, so that it does not depend on which end is which. False if no end
// can be fitted or the point lies more than `max_shift` from `start` (the ends' fans then
// describe no single smooth sheet). `frames` holds the frames of a and b.
bool onto_fitted_surface_of_ends(const TriMesh &mesh, const std::vector<VertexMetric> &frames, int32_t a, bool fit_a,
                                 int32_t b, bool fit_b, const Vec3 &start, double max_shift, Vec3 &placed);

} // namespace sfa

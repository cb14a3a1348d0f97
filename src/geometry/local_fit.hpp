// The smooth surface around a vertex, fitted to its neighbours: where a vertex that slides
// in its tangent plane should land so that it stays on the surface.
#pragma once

#include "geometry/metric.hpp"

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

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// Anisotropic edge flipping (paper §3.3).
#pragma once

#include "adapt/edge_pass.hpp"
#include "adapt/settings.hpp"

namespace sfa {

// One greedy pass (edge_pass.hpp): every edge that fails the Delaunay test in its own
// metric space is a candidate; candidates are flipped in decreasing order of their larger
// opposite angle, each at most once, if they still fail the test when their turn comes and
// the flip keeps the surface (no ridge or boundary edge, no duplicate edge, no fold, both
// the old and the new pair of triangles within max_dihedral of flat). Vertex positions
// never change. `analysis` needs the quadrics only. With a guard, a flip whose new faces
// would pass through a watched face is not made. Returns the number of flips.
int32_t flipping_pass(const PassContext &context, const SurfaceAnalysis &analysis, const FlipSettings &settings);

// True if the angles at p and q opposite edge (a, b) of the quad (a, b, p), (b, a, q) are
// sure to be acute in the metric space that the flip test derives from the quad's summed
// quadric `summed` (eq. 12 with `bounds`; old0 and old1 the two triangles' area vectors),
// without decomposing it: then the test keeps the edge whatever the decomposition gives.
bool surely_acute_opposite(const Mat3 &summed, const Vec3 &a, const Vec3 &b, const Vec3 &p, const Vec3 &q,
                           const Vec3 &old0, const Vec3 &old1, const MetricBounds &bounds);

// The same pass on its own, outside an adaptation: the mesh edited directly, with the
// features of `analysis` and no guard (for tests and benchmarks).
int32_t flipping_pass(TriMesh &mesh, const SurfaceAnalysis &analysis, const FlipSettings &settings);

} // namespace sfa

// Anisotropic edge flipping (paper §3.3).
#pragma once

#include "geometry/analysis.hpp"
#include "geometry/crossing_guard.hpp"

namespace sfa {

struct FlipSettings {
    MetricBounds bounds;  // the metric of eq. 12 (or the identity in isotropic mode)
    double max_dihedral;  // radians: flips only where the quad is this close to flat
};

// One greedy pass: every edge that fails the Delaunay test in its own metric space is a
// candidate; candidates are flipped in decreasing order of their larger opposite angle,
// each at most once, if they still fail the test when their turn comes and the flip keeps
// the surface (no ridge or boundary edge, no duplicate edge, no fold, both the old and the
// new pair of triangles within max_dihedral of flat). Vertex positions never change.
// `analysis` needs the quadrics and the features only. Returns the number of flips.
// The four vertices of every flipped quad are marked in `changed`, if given (one mark per
// vertex; update_geometry). With a guard, a flip whose new faces would pass through a
// watched face is not made.
int32_t flipping_pass(TriMesh &mesh, const SurfaceAnalysis &analysis, const FlipSettings &settings,
                      std::vector<char> *changed = nullptr, CrossingGuard *guard = nullptr);

} // namespace sfa

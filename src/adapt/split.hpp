// SPDX-License-Identifier: BSD-3-Clause
// Anisotropy-aware edge splitting (paper §4.1).
#pragma once

#include "adapt/edge_pass.hpp"
#include "adapt/settings.hpp"
#include "geometry/analysis.hpp"

namespace sfa {

// One pass (edge_pass.hpp): every edge that is absolutely long (the longest of its
// triangles and longer than L) or relatively long (longer than l, opposite an angle above
// theta_l, and no edge of its triangles shorter than s) is split, longest first, if it
// still is when its turn comes. The new vertex goes onto the surface fitted around the
// edge's smooth ends (`analysis` gives their frames), over the edge's centre; where they
// cannot be fitted, to the quadric error minimum of the faces around them; on a ridge or
// boundary edge it goes to the midpoint of the curve through the ridge neighbours (the
// centre of a straight one). Vertices and triangles are appended. With a guard, a split
// whose new faces would pass through a watched face is not made. Returns the number of
// splits.
int32_t splitting_pass(const PassContext &context, const SurfaceAnalysis &analysis, const RepairSettings &settings);

} // namespace sfa

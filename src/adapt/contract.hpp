// SPDX-License-Identifier: BSD-3-Clause
// Anisotropy-aware edge contraction (paper §4.2).
#pragma once

#include "adapt/edge_pass.hpp"
#include "adapt/settings.hpp"
#include "geometry/analysis.hpp"

namespace sfa {

// One pass (edge_pass.hpp): every edge meeting one of the four criteria of §4.2 (absolute
// small angle, relative shortness, absolute small triangle, relative small triangle in
// physical and metric space) is contracted, shortest first, if it still meets one when its
// turn comes. The merged vertex takes the place of the end with the higher feature rank;
// two ridge vertices merge at the midpoint of their ridge curve (geometry/circle.hpp), two
// smooth ones over their midpoint on the surface fitted around both (geometry/local_fit.hpp),
// or where that fit cannot be made, at their midpoint moved along the normal to the
// quadric error minimum.
// Refused: two corners, two feature vertices not joined by a ridge edge (that would merge
// two ridge curves), unless they are nearer than r l (one feature, then: they merge at the
// one of higher rank, or halfway); anything the link condition forbids, any result that
// turns a face by more than 60 degrees or nearly flattens it, or whose faces would pass
// through the faces around the ends' neighbours or (with a guard) a watched face.
// `analysis` gives the metric and frames of the mesh as the pass finds it. The dead
// vertices and triangles stay until the edit compacts the mesh. Returns the number of
// contractions; adds to `clearance_tests` the exact triangle tests made by the check that
// the faces pass through none around the neighbours (a count of work: it grew with the
// square of a vertex's valence before fan_sectors).
int32_t contraction_pass(const PassContext &context, const SurfaceAnalysis &analysis, const RepairSettings &settings,
                         int64_t &clearance_tests);

} // namespace sfa

// Anisotropy-aware edge contraction (paper §4.2).
#pragma once

#include "adapt/carried_features.hpp"
#include "adapt/repair_settings.hpp"
#include "fields/vertex_fields.hpp"
#include "geometry/analysis.hpp"
#include "geometry/crossing_guard.hpp"

#include <vector>

namespace sfa {

// One pass: every edge meeting one of the four criteria of §4.2 (absolute small angle,
// relative shortness, absolute small triangle, relative small triangle in physical and
// metric space) is contracted, shortest first, if it still meets one when its turn comes.
// The merged vertex takes the place of the end with the higher feature rank; two ridge
// vertices merge at the midpoint of their ridge curve (geometry/circle.hpp), two smooth
// ones at their midpoint moved along the normal to the quadric error minimum. Refused: two corners, two feature vertices not joined by a ridge edge
// (that would merge two ridge curves), anything the link condition forbids, and any result
// that turns a face by more than 60 degrees or nearly flattens it. Fields are interpolated
// at the merged vertex, and the features follow. Ends with compaction (the mesh, fields
// and features are dense again). `analysis` gives the metric of the mesh as it was, and is
// renumbered with the mesh; `changed` (one mark per vertex) too, after every vertex whose
// fan a contraction changed was marked in it (update_geometry).
// With a guard, a contraction whose faces would pass through a watched face is refused,
// and the guard is renumbered with the mesh. Returns the number of contractions.
int32_t contraction_pass(TriMesh &mesh, SurfaceAnalysis &analysis, const RepairSettings &settings,
                         CarriedFeatures &features, std::vector<VertexField> &fields, std::vector<char> &changed,
                         CrossingGuard *guard = nullptr);

} // namespace sfa

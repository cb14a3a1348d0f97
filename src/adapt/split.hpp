// Anisotropy-aware edge splitting (paper §4.1).
#pragma once

#include "adapt/carried_features.hpp"
#include "adapt/repair_settings.hpp"
#include "fields/vertex_fields.hpp"
#include "geometry/crossing_guard.hpp"

#include <vector>

namespace sfa {

// One pass: every edge that is absolutely long (the longest of its triangles and longer
// than L) or relatively long (longer than l, opposite an angle above theta_l, and no edge
// of its triangles shorter than s) is split, longest first, if it still is when its turn
// comes. The new vertex goes to the edge's centre, then along the normal to the quadric
// error minimum of the faces around the edge's ends; on a ridge or boundary edge it goes
// to the midpoint of the curve through the ridge neighbours (the centre of a straight one). Fields get the values interpolated there. Returns the
// number of splits; the mesh stays dense (vertices and triangles are appended). With a
// guard, a split whose new faces would pass through a watched face is not made, and the
// new vertex is watched where either end was.
int32_t splitting_pass(TriMesh &mesh, const RepairSettings &settings, CarriedFeatures &features,
                       std::vector<VertexField> &fields, std::vector<char> &changed, CrossingGuard *guard = nullptr);

} // namespace sfa

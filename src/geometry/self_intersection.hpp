// SPDX-License-Identifier: BSD-3-Clause
// Whether a surface passes through itself: the one sure sign that a surface was folded
// over. A sharp edge or a cusp (the rim of a sheet thinner than an edge) turns the normals
// of two neighbouring triangles by nearly 180 degrees without any crossing; a surface
// folded back over itself crosses itself.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

// The number of pairs of triangles that share no vertex yet intersect (touching counts;
// decided exactly, geometry/triangle_intersection.hpp).
// Pairs are found through collision-safe motion's broad phase at rest (swept_pairs.hpp); the
// count is the same for any number of threads.
int32_t self_intersection_count(const TriMesh &mesh);

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// The shape of an edge's one or two triangles, which the splitting and contraction
// criteria of §4.1 and §4.2 read. Angles come as cosines: every edge of the mesh is looked
// at in each pass, and the criteria only compare them with fixed angles.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

struct EdgeNeighbourhood {
    double length;               // of the edge
    int triangles;               // 1 on a boundary, else 2
    double opposite_cos[2];      // cosine of the angle opposite the edge in each triangle
    double triangle_longest[2];  // the longest edge of each triangle
    double longest, shortest;    // over all edges of the triangles (the edge included)
};

EdgeNeighbourhood edge_neighbourhood(const TriMesh &mesh, int32_t h);

} // namespace sfa

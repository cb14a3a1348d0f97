// The shape of an edge's one or two triangles, which the splitting and contraction
// criteria of §4.1 and §4.2 read.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

struct EdgeNeighbourhood {
    double length;               // of the edge
    int triangles;               // 1 on a boundary, else 2
    double opposite_angle[2];    // radians, opposite the edge in each triangle
    double triangle_longest[2];  // the longest edge of each triangle
    double longest, shortest;    // over all edges of the triangles (the edge included)
};

EdgeNeighbourhood edge_neighbourhood(const TriMesh &mesh, int32_t h);

} // namespace sfa

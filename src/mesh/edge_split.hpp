// Edge splitting, the topological half of §4.1: a new vertex on an edge, joined to the
// opposite vertices.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

// Splits the edge of half-edge h = (a -> b) with a new vertex m at `position` (appended:
// m = the old vertex count). Triangle (a, b, p) of h becomes (a, m, p) and (m, b, p) is
// appended; if the edge is interior, its twin's (b, a, q) becomes (b, m, q) and (m, a, q)
// is appended after. Half-edge h becomes a -> m. O(1). Returns m.
int32_t split_edge(TriMesh &mesh, int32_t h, const Vec3 &position);

} // namespace sfa

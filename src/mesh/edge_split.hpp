// SPDX-License-Identifier: BSD-3-Clause
// Edge splitting, the topological half of §4.1: a new vertex on an edge, joined to the
// opposite vertices.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

// Where the elements of a split went, for the data that lives on half-edges and faces
// (mesh_edit.hpp). Entries of the twin's side are -1 when the edge was on the boundary.
struct SplitRecord {
    int32_t vertex;            // m, the new vertex
    int32_t a, b, p, q;        // the edge a -> b and its opposite vertices (q = -1 on a boundary)
    int32_t old_faces[2];      // (a, b, p), now (a, m, p); (b, a, q), now (b, m, q)
    int32_t new_faces[2];      // (m, b, p) and (m, a, q): the other halves of old_faces
    int32_t halves[2][2];      // a -> m, m -> b; b -> m, m -> a: the halves of the split edge
    int32_t moved_from[2], moved_to[2]; // b -> p and a -> q moved into the new faces
    int32_t fresh[4];          // m -> p, p -> m, m -> q, q -> m: the edges that are new
};

// Splits the edge of half-edge h = (a -> b) with a new vertex m at `position` (appended:
// m = the old vertex count). Triangle (a, b, p) of h becomes (a, m, p) and (m, b, p) is
// appended; if the edge is interior, its twin's (b, a, q) becomes (b, m, q) and (m, a, q)
// is appended after. Half-edge h becomes a -> m. O(1).
SplitRecord split_edge(TriMesh &mesh, int32_t h, const Vec3 &position);

} // namespace sfa

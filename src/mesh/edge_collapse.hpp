// Edge contraction, the topological half of §4.2: the two ends of an edge merged into one.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

// True if contracting the edge of h keeps the surface a manifold with the same topology:
// the ends' common neighbours are exactly the edge's opposite vertices (the link
// condition), an interior edge does not join two boundary vertices (that would pinch the
// surface), and no opposite vertex is left with fewer than three neighbours (a
// tetrahedron's edges, or an ear of an open surface).
bool collapse_keeps_manifold(const TriMesh &mesh, int32_t h);

// Contracts h = (gone -> keep): keep moves to `position`, every triangle of gone's takes
// keep instead, and gone and the edge's one or two triangles are marked dead (v2h[gone] =
// -1, corners -1) until compact() removes them. Requires collapse_keeps_manifold. O(valence).
void collapse_edge(TriMesh &mesh, int32_t h, const Vec3 &position);

// Dead elements of a mesh being changed by collapse_edge.
inline bool is_dead_vertex(const TriMesh &mesh, int32_t v) { return mesh.v2h[v] < 0; }
inline bool is_dead_triangle(const TriMesh &mesh, int32_t t) { return mesh.tri[t][0] < 0; }

} // namespace sfa

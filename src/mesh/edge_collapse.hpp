// SPDX-License-Identifier: BSD-3-Clause
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

// Where the elements of a contraction went, for the data that lives on half-edges and
// faces (mesh_edit.hpp). Entries of the twin's side are -1 when the edge was on the boundary.
struct CollapseRecord {
    int32_t gone, keep;
    int32_t opposite[2];      // p of (gone, keep, p) and q of (keep, gone, q)
    int32_t dead_faces[2];    // those two triangles
    // Each dead face's two other edges became one edge: joined[k] are its half-edges now
    // (twins; one of them is -1 where the edge is on the boundary), and dead_halves[k] the
    // dead face's own halves of the two edges, which still hold their data.
    int32_t joined[2][2];
    int32_t dead_halves[2][2];
};

// Contracts h = (gone -> keep): keep moves to `position`, every triangle of gone's takes
// keep instead, and gone and the edge's one or two triangles are marked dead (v2h[gone] =
// -1, corners -1) until compact() removes them. Requires collapse_keeps_manifold. O(valence).
CollapseRecord collapse_edge(TriMesh &mesh, int32_t h, const Vec3 &position);

// Dead elements of a mesh being changed by collapse_edge.
inline bool is_dead_vertex(const TriMesh &mesh, int32_t v) { return mesh.v2h[v] < 0; }
inline bool is_dead_triangle(const TriMesh &mesh, int32_t t) { return mesh.tri[t][0] < 0; }

} // namespace sfa

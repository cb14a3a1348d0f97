// SPDX-License-Identifier: BSD-3-Clause
// The edge flip, the topological half of §3.3: replacing the diagonal of the quad formed by
// two triangles with the other diagonal. Geometry (which flips are good) is adapt/flip's.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <array>

namespace sfa {

// The quad around interior half-edge h = (a -> b) in triangle (a, b, p), whose twin
// (b -> a) is in triangle (b, a, q): a flip replaces the edge a-b with p-q.
struct FlipQuad {
    int32_t a, b, p, q;
};
FlipQuad flip_quad(const TriMesh &mesh, int32_t h);

// True if h may be flipped topologically: it is interior and p-q is not already an edge
// (the flip would create a duplicate edge and a non-manifold surface). A tetrahedron's
// edges are the smallest case where that happens.
bool flip_keeps_manifold(const TriMesh &mesh, int32_t h);

// Where the four outer half-edges of the quad went: the half-edge that was at index
// from[k] is at index to[k] after the flip. The two triangles keep their indices and the
// new edge keeps the old one's half-edges: h becomes q -> p, its twin p -> q. Callers that
// keep per-half-edge data move it with these pairs.
struct FlipMoves {
    std::array<int32_t, 4> from, to;
};

// Flips h (requires flip_keeps_manifold). O(1): only the two triangles, the twins of their
// outer edges and the vertex half-edges of the four corners change.
FlipMoves flip_edge(TriMesh &mesh, int32_t h);

} // namespace sfa

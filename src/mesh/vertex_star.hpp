// SPDX-License-Identifier: BSD-3-Clause
// The half-edges leaving each vertex, grouped by vertex (compressed rows): the one
// structure from which twins are found and fans are checked, in O(valence) per vertex
// and without sorting all edges of the mesh.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <cstdint>
#include <vector>

namespace sfa {

struct VertexStar {
    std::vector<int32_t> first; // first[v] .. first[v+1]-1 index into outgoing
    std::vector<int32_t> outgoing; // half-edges, grouped by their tail vertex
    std::vector<int32_t> head;     // head[k]: the vertex outgoing[k] points to (saves a lookup in tri)

    VertexStar(int32_t num_vertices, const std::vector<Triangle> &tri);

    int32_t begin(int32_t v) const { return first[v]; }
    int32_t end(int32_t v) const { return first[v + 1]; }
    int32_t valence(int32_t v) const { return first[v + 1] - first[v]; }
};

// opp[h] for every half-edge, assuming every edge has at most two opposite half-edges.
void link_twins(TriMesh &mesh, const VertexStar &star);

// v2h[v]: the boundary half-edge leaving v if there is one, else the first one.
void assign_vertex_halfedges(TriMesh &mesh, const VertexStar &star);

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/vertex_star.hpp"

namespace sfa {

VertexStar::VertexStar(int32_t num_vertices, const std::vector<Triangle> &tri)
    : first(static_cast<size_t>(num_vertices) + 1, 0), outgoing(3 * tri.size()), head(3 * tri.size())
{
    for (const Triangle &t : tri)
        for (int32_t v : t)
            ++first[v + 1];
    for (int32_t v = 0; v < num_vertices; ++v)
        first[v + 1] += first[v];
    std::vector<int32_t> fill(first.begin(), first.end() - 1);
    const int32_t num_halfedges = static_cast<int32_t>(outgoing.size());
    for (int32_t h = 0; h < num_halfedges; ++h) {
        const int32_t k = fill[tri[h / 3][h % 3]]++;
        outgoing[k] = h;
        head[k] = tri[h / 3][(h + 1) % 3];
    }
}

void link_twins(TriMesh &mesh, const VertexStar &star)
{
    mesh.opp.assign(3 * mesh.tri.size(), -1);
    const int32_t num_halfedges = static_cast<int32_t>(mesh.opp.size());
    for (int32_t h = 0; h < num_halfedges; ++h) {
        const int32_t a = mesh.tail(h), b = mesh.head(h);
        // The twin of a->b leaves b and arrives at a.
        for (int32_t k = star.begin(b); k < star.end(b); ++k) {
            if (star.head[k] == a) {
                mesh.opp[h] = star.outgoing[k];
                break;
            }
        }
    }
}

void assign_vertex_halfedges(TriMesh &mesh, const VertexStar &star)
{
    const int32_t n = mesh.num_vertices();
    mesh.v2h.assign(n, -1);
    for (int32_t v = 0; v < n; ++v) {
        for (int32_t k = star.begin(v); k < star.end(v); ++k) {
            const int32_t h = star.outgoing[k];
            if (mesh.v2h[v] < 0 || mesh.opp[h] < 0)
                mesh.v2h[v] = h;
            if (mesh.opp[h] < 0)
                break;
        }
    }
}

} // namespace sfa

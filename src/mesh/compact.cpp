// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/compact.hpp"

#include "mesh/edge_collapse.hpp"

namespace sfa {

Renumbering compact(TriMesh &mesh)
{
    Renumbering renumbering;
    renumbering.keeps_order = true;
    std::vector<int32_t> &vertex_map = renumbering.vertex_map, &triangle_map = renumbering.triangle_map;
    vertex_map.assign(mesh.pos.size(), -1);
    triangle_map.assign(mesh.tri.size(), -1);
    int32_t vertices = 0, triangles = 0;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        if (!is_dead_vertex(mesh, v))
            vertex_map[v] = vertices++;
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        if (!is_dead_triangle(mesh, t))
            triangle_map[t] = triangles++;
    if (vertices == mesh.num_vertices() && triangles == mesh.num_triangles())
        return renumbering;

    const auto new_halfedge = [&](int32_t h) { return renumbering.new_halfedge(h); };
    TriMesh out;
    out.pos.reserve(vertices);
    out.v2h.reserve(vertices);
    out.tri.reserve(triangles);
    out.opp.reserve(3 * static_cast<size_t>(triangles));
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        if (vertex_map[v] >= 0) {
            out.pos.push_back(mesh.pos[v]);
            out.v2h.push_back(new_halfedge(mesh.v2h[v]));
        }
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        if (triangle_map[t] >= 0) {
            const Triangle &c = mesh.tri[t];
            out.tri.push_back({vertex_map[c[0]], vertex_map[c[1]], vertex_map[c[2]]});
            for (int i = 0; i < 3; ++i)
                out.opp.push_back(new_halfedge(mesh.opp[3 * t + i]));
        }
    mesh = std::move(out);
    return renumbering;
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/compact.hpp"

#include "mesh/edge_collapse.hpp"
#include "mesh/parallel.hpp"

namespace sfa {

Renumbering compact(TriMesh &mesh)
{
    Renumbering renumbering;
    renumbering.keeps_order = true;
    std::vector<int32_t> &vertex_map = renumbering.vertex_map, &triangle_map = renumbering.triangle_map;
    const int32_t vertices =
        number_kept(mesh.num_vertices(), [&](int32_t v) { return !is_dead_vertex(mesh, v); }, vertex_map);
    const int32_t triangles =
        number_kept(mesh.num_triangles(), [&](int32_t t) { return !is_dead_triangle(mesh, t); }, triangle_map);
    if (vertices == mesh.num_vertices() && triangles == mesh.num_triangles())
        return renumbering;

    const auto new_halfedge = [&](int32_t h) { return renumbering.new_halfedge(h); };
    TriMesh out;
    out.pos.resize(vertices);
    out.v2h.resize(vertices);
    out.tri.resize(triangles);
    out.opp.resize(3 * static_cast<size_t>(triangles));
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        if (const int32_t to = vertex_map[v]; to >= 0) {
            out.pos[to] = mesh.pos[v];
            out.v2h[to] = new_halfedge(mesh.v2h[v]);
        }
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        if (const int32_t to = triangle_map[t]; to >= 0) {
            const Triangle &c = mesh.tri[t];
            out.tri[to] = {vertex_map[c[0]], vertex_map[c[1]], vertex_map[c[2]]};
            for (int i = 0; i < 3; ++i)
                out.opp[3 * static_cast<size_t>(to) + i] = new_halfedge(mesh.opp[3 * t + i]);
        }
    mesh = std::move(out);
    return renumbering;
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/components.hpp"

#include <algorithm>

namespace sfa {

Components connected_components(const TriMesh &mesh)
{
    Components out;
    const int32_t n = mesh.num_vertices();
    out.of_vertex.assign(n, -1);
    std::vector<int32_t> stack;
    for (int32_t seed = 0; seed < n; ++seed) {
        if (out.of_vertex[seed] >= 0)
            continue;
        const int32_t c = out.count++;
        out.closed.push_back(1);
        out.of_vertex[seed] = c;
        stack.assign(1, seed);
        while (!stack.empty()) {
            const int32_t v = stack.back();
            stack.pop_back();
            if (mesh.is_boundary_vertex(v))
                out.closed[c] = 0;
            mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
                if (out.of_vertex[w] < 0) {
                    out.of_vertex[w] = c;
                    stack.push_back(w);
                }
            });
        }
    }
    index_components(mesh, out);
    return out;
}

void index_components(const TriMesh &mesh, Components &components)
{
    // The new number of each old one, given as the components' first vertices come (a
    // label no vertex has any more is dropped).
    std::vector<int32_t> renumbered(components.count, -1);
    int32_t next = 0;
    for (int32_t label : components.of_vertex)
        if (renumbered[label] < 0)
            renumbered[label] = next++;
    std::vector<char> closed(next);
    for (int32_t c = 0; c < components.count; ++c)
        if (renumbered[c] >= 0)
            closed[renumbered[c]] = components.closed[c];
    for (int32_t &label : components.of_vertex)
        label = renumbered[label];
    components.closed.swap(closed);
    components.count = next;

    // Counting sort of the triangles by component.
    components.triangle_start.assign(components.count + 1, 0);
    for (const Triangle &t : mesh.tri)
        ++components.triangle_start[components.of_vertex[t[0]] + 1];
    for (int32_t c = 0; c < components.count; ++c)
        components.triangle_start[c + 1] += components.triangle_start[c];
    components.triangles.resize(mesh.tri.size());
    std::vector<int32_t> filled(components.triangle_start.begin(), components.triangle_start.end() - 1);
    for (size_t t = 0; t < mesh.tri.size(); ++t)
        components.triangles[filled[components.of_vertex[mesh.tri[t][0]]]++] = static_cast<int32_t>(t);
}

TriMesh component_mesh(const TriMesh &mesh, const Components &components, int32_t c)
{
    const auto first = components.triangles.begin() + components.triangle_start[c],
               last = components.triangles.begin() + components.triangle_start[c + 1];
    std::vector<int32_t> vertices; // of the component, in mesh order
    for (auto t = first; t != last; ++t)
        vertices.insert(vertices.end(), mesh.tri[*t].begin(), mesh.tri[*t].end());
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    const auto local = [&](int32_t v) {
        return static_cast<int32_t>(std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin());
    };
    TriMesh part;
    for (int32_t v : vertices)
        part.pos.push_back(mesh.pos[v]);
    for (auto t = first; t != last; ++t)
        part.tri.push_back({local(mesh.tri[*t][0]), local(mesh.tri[*t][1]), local(mesh.tri[*t][2])});
    build_adjacency(part);
    return part;
}

} // namespace sfa

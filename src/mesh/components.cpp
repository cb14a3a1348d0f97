#include "mesh/components.hpp"

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
    return out;
}

TriMesh component_mesh(const TriMesh &mesh, const Components &components, int32_t c)
{
    std::vector<int32_t> local(mesh.pos.size(), -1);
    TriMesh part;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        if (components.of_vertex[v] == c) {
            local[v] = part.num_vertices();
            part.pos.push_back(mesh.pos[v]);
        }
    for (size_t t = 0; t < mesh.tri.size(); ++t)
        if (components.of_vertex[mesh.tri[t][0]] == c)
            part.tri.push_back({local[mesh.tri[t][0]], local[mesh.tri[t][1]], local[mesh.tri[t][2]]});
    build_adjacency(part);
    return part;
}

} // namespace sfa

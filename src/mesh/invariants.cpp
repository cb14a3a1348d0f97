#include "mesh/invariants.hpp"

#include <cmath>
#include <vector>

namespace sfa {

std::string invariant_violation(const TriMesh &mesh)
{
    const int32_t nv = mesh.num_vertices(), nt = mesh.num_triangles();
    const std::string none;
    if (mesh.opp.size() != 3 * mesh.tri.size() || mesh.v2h.size() != mesh.pos.size())
        return "adjacency arrays do not match the element counts";
    for (int32_t v = 0; v < nv; ++v)
        if (!mesh.pos[v].allFinite())
            return "vertex " + std::to_string(v) + " has a non-finite coordinate";
    for (int32_t t = 0; t < nt; ++t) {
        const Triangle &c = mesh.tri[t];
        for (int k = 0; k < 3; ++k)
            if (c[k] < 0 || c[k] >= nv)
                return "triangle " + std::to_string(t) + " refers to a vertex out of range";
        if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
            return "triangle " + std::to_string(t) + " repeats a vertex";
    }
    for (int32_t h = 0; h < 3 * nt; ++h) {
        const int32_t g = mesh.opp[h];
        if (g < 0)
            continue;
        if (g >= 3 * nt || mesh.opp[g] != h)
            return "half-edge " + std::to_string(h) + " and its twin do not point at each other";
        if (mesh.tail(g) != mesh.head(h) || mesh.head(g) != mesh.tail(h))
            return "half-edge " + std::to_string(h) + " and its twin do not run opposite ways on one edge";
    }
    // Every vertex: v2h leaves it, is the boundary one if any, and one walk covers its
    // whole star (manifold, no dead references).
    std::vector<int32_t> valence(nv, 0);
    for (const Triangle &c : mesh.tri)
        for (int32_t v : c)
            ++valence[v];
    for (int32_t v = 0; v < nv; ++v) {
        const int32_t h = mesh.v2h[v];
        if (h < 0 || h >= 3 * nt || mesh.tail(h) != v)
            return "vertex " + std::to_string(v) + " has no valid outgoing half-edge";
        int32_t visited = 0, boundary = 0;
        mesh.for_each_outgoing(v, [&](int32_t g) {
            ++visited;
            boundary += mesh.opp[g] < 0;
        });
        if (visited != valence[v])
            return "vertex " + std::to_string(v) + " is not manifold: one fan covers " + std::to_string(visited) +
                   " of its " + std::to_string(valence[v]) + " triangles";
        if (boundary > 0 && mesh.opp[h] >= 0)
            return "vertex " + std::to_string(v) + " is on a boundary but v2h is not its boundary half-edge";
    }
    return none;
}

} // namespace sfa

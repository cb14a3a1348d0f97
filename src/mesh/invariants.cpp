// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/invariants.hpp"

#include "mesh/parallel.hpp"

#include <cmath>
#include <vector>

namespace sfa {

std::string invariant_violation(const TriMesh &mesh)
{
    const int32_t nv = mesh.num_vertices(), nt = mesh.num_triangles();
    if (mesh.opp.size() != 3 * mesh.tri.size() || mesh.v2h.size() != mesh.pos.size())
        return "adjacency arrays do not match the element counts";
    if (const int32_t v = first_where(nv, [&](int32_t i) { return !mesh.pos[i].allFinite(); }); v < nv)
        return "vertex " + std::to_string(v) + " has a non-finite coordinate";

    const auto out_of_range = [&](int32_t t) {
        const Triangle &c = mesh.tri[t];
        return c[0] < 0 || c[0] >= nv || c[1] < 0 || c[1] >= nv || c[2] < 0 || c[2] >= nv;
    };
    const auto repeats = [&](int32_t t) {
        const Triangle &c = mesh.tri[t];
        return c[0] == c[1] || c[1] == c[2] || c[0] == c[2];
    };
    if (const int32_t t = first_where(nt, [&](int32_t i) { return out_of_range(i) || repeats(i); }); t < nt)
        return "triangle " + std::to_string(t) + (out_of_range(t) ? " refers to a vertex out of range" : " repeats a vertex");

    const auto unpaired = [&](int32_t h) {
        const int32_t g = mesh.opp[h];
        return g >= 3 * nt || mesh.opp[g] != h;
    };
    const auto misaligned = [&](int32_t h) {
        const int32_t g = mesh.opp[h];
        return mesh.tail(g) != mesh.head(h) || mesh.head(g) != mesh.tail(h);
    };
    if (const int32_t h = first_where(3 * nt, [&](int32_t i) { return mesh.opp[i] >= 0 && (unpaired(i) || misaligned(i)); });
        h < 3 * nt)
        return "half-edge " + std::to_string(h) +
               (unpaired(h) ? " and its twin do not point at each other" : " and its twin do not run opposite ways on one edge");

    // Every vertex: v2h leaves it, is the boundary one if any, and one walk covers its
    // whole star (manifold, no dead references).
    std::vector<int32_t> valence(nv, 0);
    for (const Triangle &c : mesh.tri)
        for (int32_t v : c)
            ++valence[v];
    const auto no_outgoing = [&](int32_t v) {
        const int32_t h = mesh.v2h[v];
        return h < 0 || h >= 3 * nt || mesh.tail(h) != v;
    };
    struct Fan {
        int32_t visited = 0, boundary = 0;
    };
    const auto fan = [&](int32_t v) {
        Fan out;
        mesh.for_each_outgoing(v, [&](int32_t g) {
            ++out.visited;
            out.boundary += mesh.opp[g] < 0;
        });
        return out;
    };
    const int32_t v = first_where(nv, [&](int32_t i) {
        if (no_outgoing(i))
            return true;
        const Fan f = fan(i);
        return f.visited != valence[i] || (f.boundary > 0 && mesh.opp[mesh.v2h[i]] >= 0);
    });
    if (v == nv)
        return std::string();
    if (no_outgoing(v))
        return "vertex " + std::to_string(v) + " has no valid outgoing half-edge";
    const Fan f = fan(v);
    if (f.visited != valence[v])
        return "vertex " + std::to_string(v) + " is not manifold: one fan covers " + std::to_string(f.visited) +
               " of its " + std::to_string(valence[v]) + " triangles";
    return "vertex " + std::to_string(v) + " is on a boundary but v2h is not its boundary half-edge";
}

} // namespace sfa

#include "adapt/carried_features.hpp"

#include "mesh/parallel.hpp"

#include <algorithm>

namespace sfa {

RidgeSet::RidgeSet(const std::vector<std::array<int32_t, 2>> &edges)
{
    for (const auto &e : edges)
        add(e[0], e[1]);
}

std::vector<std::array<int32_t, 2>> RidgeSet::edges() const
{
    std::vector<std::array<int32_t, 2>> out;
    out.reserve(keys_.size());
    for (uint64_t k : keys_)
        out.push_back({static_cast<int32_t>(k >> 32), static_cast<int32_t>(k & 0xffffffffu)});
    std::sort(out.begin(), out.end());
    return out;
}

CarriedFeatures::CarriedFeatures(const Features &detected) : rank(detected.rank), ridges(detected.ridge_edges) {}

const Vec3 *CarriedFeatures::next_along(const TriMesh &mesh, int32_t v, int32_t not_this) const
{
    if (rank[v] != 1)
        return nullptr;
    const Vec3 *found = nullptr;
    mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
        if (w != not_this && ridges.contains(v, w))
            found = &mesh.pos[w];
    });
    return found;
}

void CarriedFeatures::renumber(const std::vector<int32_t> &vertex_map)
{
    std::vector<int8_t> new_rank;
    for (size_t v = 0; v < vertex_map.size(); ++v)
        if (vertex_map[v] >= 0)
            new_rank.push_back(rank[v]);
    std::vector<std::array<int32_t, 2>> kept;
    for (const auto &e : ridges.edges())
        if (vertex_map[e[0]] >= 0 && vertex_map[e[1]] >= 0)
            kept.push_back({vertex_map[e[0]], vertex_map[e[1]]});
    rank.swap(new_rank);
    ridges = RidgeSet(kept);
}

Features CarriedFeatures::as_features(const TriMesh &mesh) const
{
    Features f;
    f.rank = rank;
    f.ridge_halfedge.assign(mesh.opp.size(), 0);
    // Only an edge between two feature vertices can be a ridge: no look-up for the others.
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t h = 0; h < static_cast<int32_t>(mesh.opp.size()); ++h) {
        const int32_t a = mesh.tail(h), b = mesh.head(h);
        f.ridge_halfedge[h] = rank[a] > 0 && rank[b] > 0 && ridges.contains(a, b);
    }
    f.ridge_edges = ridges.edges();
    return f;
}

} // namespace sfa

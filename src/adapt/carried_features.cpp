// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/carried_features.hpp"

#include <algorithm>

namespace sfa {

const Vec3 *CarriedFeatures::next_along(const TriMesh &mesh, int32_t v, int32_t not_this) const
{
    if (rank_[v] != 1)
        return nullptr;
    const Vec3 *found = nullptr;
    mesh.for_each_neighbour(v, [&](int32_t w, int32_t h) {
        if (w != not_this && ridges_[h])
            found = &mesh.pos[w];
    });
    return found;
}

Features CarriedFeatures::as_features(const TriMesh &mesh) const
{
    Features f;
    f.rank = rank_;
    f.ridge_halfedge = ridges_.flags();
    for (int32_t h = 0; h < static_cast<int32_t>(mesh.opp.size()); ++h)
        if (ridges_[h] && (mesh.opp[h] < 0 || mesh.opp[h] > h)) {
            const int32_t a = mesh.tail(h), b = mesh.head(h);
            f.ridge_edges.push_back({std::min(a, b), std::max(a, b)});
        }
    std::sort(f.ridge_edges.begin(), f.ridge_edges.end());
    return f;
}

void CarriedFeatures::split(const TriMesh &mesh, const SplitChange &change)
{
    const SplitRecord &r = change.record;
    const bool on_ridge = ridges_[r.halves[0][0]] || r.q < 0; // a ridge or a boundary edge
    ridges_.split(mesh, change);
    rank_.push_back(on_ridge ? 1 : 0);
}

void CarriedFeatures::collapse(const TriMesh &mesh, const CollapseChange &change)
{
    ridges_.collapse(mesh, change);
    rank_[change.record.keep] = std::max(rank_[change.record.keep], rank_[change.record.gone]);
}

void CarriedFeatures::renumber(const Renumbering &renumbering)
{
    renumbering.apply_to_vertices(rank_);
    ridges_.renumber(renumbering);
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/halfedge_flags.hpp"

namespace sfa {

void HalfedgeFlags::split(const TriMesh &mesh, const SplitChange &change)
{
    const SplitRecord &r = change.record;
    flags_.resize(mesh.opp.size(), 0);
    for (int side = 0; side < 2; ++side) {
        if (r.moved_from[side] < 0)
            continue;
        flags_[r.moved_to[side]] = flags_[r.moved_from[side]]; // before moved_from is fresh
        flags_[r.halves[side][1]] = flags_[r.halves[side][0]];
    }
    for (int32_t h : r.fresh)
        if (h >= 0)
            flags_[h] = 0;
}

void HalfedgeFlags::collapse(const TriMesh &, const CollapseChange &change)
{
    const CollapseRecord &r = change.record;
    for (int side = 0; side < 2; ++side) {
        if (r.dead_faces[side] < 0)
            continue;
        const char merged = flags_[r.dead_halves[side][0]] || flags_[r.dead_halves[side][1]];
        for (int32_t h : r.joined[side])
            if (h >= 0)
                flags_[h] = merged;
    }
}

void HalfedgeFlags::flip(const TriMesh &, const FlipChange &change)
{
    // The moves overlap (one's target is another's source): read all four first.
    char moved[4];
    for (int k = 0; k < 4; ++k)
        moved[k] = flags_[change.moves.from[k]];
    for (int k = 0; k < 4; ++k)
        flags_[change.moves.to[k]] = moved[k];
    for (int32_t h : change.diagonal)
        flags_[h] = 0;
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// A flag on every edge (both halves of an interior edge carry it), carried through every
// change: the halves of a split edge keep it, the new edges of a split or flip do not have
// it, and the edge that two edges of a contracted triangle become has it if either had it.
// Ridge edges (adapt/carried_features.hpp) are such flags.
#pragma once

#include "mesh/mesh_edit.hpp"

#include <utility>
#include <vector>

namespace sfa {

class HalfedgeFlags : public EditListener {
public:
    HalfedgeFlags() = default;
    explicit HalfedgeFlags(std::vector<char> flags) : flags_(std::move(flags)) {}

    bool operator[](int32_t h) const { return flags_[h] != 0; }
    const std::vector<char> &flags() const { return flags_; }

    void split(const TriMesh &mesh, const SplitChange &change) override;
    void collapse(const TriMesh &mesh, const CollapseChange &change) override;
    void flip(const TriMesh &mesh, const FlipChange &change) override;
    void renumber(const Renumbering &renumbering) override { renumbering.apply_to_halfedges(flags_); }

private:
    std::vector<char> flags_; // per half-edge
};

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// Marks on the vertices whose fans an edit changed: what a partial analysis must look at
// again (update_geometry), and what tells a pass that a verdict it made on the mesh as it
// found it may no longer stand (edge_pass.hpp).
#pragma once

#include "mesh/mesh_edit.hpp"

#include <vector>

namespace sfa {

class ChangedVertices : public EditListener {
public:
    explicit ChangedVertices(int32_t vertices) : marks_(vertices, 0) {}

    const std::vector<char> &marks() const { return marks_; }
    bool operator[](int32_t v) const { return marks_[v] != 0; }
    void clear() { marks_.assign(marks_.size(), 0); }

    void split(const TriMesh &, const SplitChange &change) override;
    void collapse(const TriMesh &, const CollapseChange &change) override { mark(change.fans); }
    void flip(const TriMesh &, const FlipChange &change) override { mark(change.fans); }
    // A sweep leaves most fans of a settled mesh alone (smooth.cpp: settled_imbalance):
    // a fan changed if its vertex or one of its neighbours moved.
    void move(const TriMesh &mesh, const MoveChange &change) override;
    void renumber(const Renumbering &renumbering) override { renumbering.apply_to_vertices(marks_); }

private:
    void mark(const std::vector<int32_t> &vertices)
    {
        for (int32_t v : vertices)
            marks_[v] = 1;
    }
    std::vector<char> marks_;
};

inline void ChangedVertices::move(const TriMesh &mesh, const MoveChange &change)
{
    // Heard before the move: mesh.pos still holds the old positions.
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        if (change.positions[v] != mesh.pos[v]) {
            marks_[v] = 1;
            mesh.for_each_neighbour(v, [&](int32_t w, int32_t) { marks_[w] = 1; });
        }
}

inline void ChangedVertices::split(const TriMesh &, const SplitChange &change)
{
    marks_.push_back(0);
    mark(change.fans);
}

} // namespace sfa

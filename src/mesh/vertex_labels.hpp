// SPDX-License-Identifier: BSD-3-Clause
// A label on every vertex that a change never alters: a new vertex takes its edge's ends'
// label (they have the same one), a merged vertex keeps the kept end's. The component a
// vertex belongs to is such a label, as long as the topology does not change.
#pragma once

#include "mesh/mesh_edit.hpp"

#include <utility>
#include <vector>

namespace sfa {

class VertexLabels : public EditListener {
public:
    explicit VertexLabels(std::vector<int32_t> labels) : labels_(std::move(labels)) {}

    const std::vector<int32_t> &labels() const { return labels_; }

    void split(const TriMesh &, const SplitChange &change) override { labels_.push_back(labels_[change.record.a]); }
    void renumber(const Renumbering &renumbering) override { renumbering.apply_to_vertices(labels_); }

private:
    std::vector<int32_t> labels_;
};

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// The crossing guard as a listener of an edit: its index is built when a pass begins its
// changes, every face a change made or reshaped is entered again, a new vertex is watched
// where either end of its edge was, and the watched marks follow every renumbering.
#pragma once

#include "geometry/crossing_guard.hpp"
#include "mesh/mesh_edit.hpp"

namespace sfa {

class GuardListener : public EditListener {
public:
    explicit GuardListener(CrossingGuard &guard) : guard_(guard) {}

    void begin_changes(const TriMesh &mesh) override { guard_.index_faces(mesh, mesh.pos); }
    void split(const TriMesh &mesh, const SplitChange &change) override
    {
        const SplitRecord &r = change.record;
        guard_.add_vertex_between(r.a, r.b);
        refresh_fan(mesh, r.vertex);
    }
    void collapse(const TriMesh &mesh, const CollapseChange &change) override { refresh_fan(mesh, change.record.keep); }
    void flip(const TriMesh &mesh, const FlipChange &change) override
    {
        for (int32_t f : change.faces)
            guard_.refresh(mesh, mesh.pos, f);
    }
    void renumber(const Renumbering &renumbering) override { guard_.renumber(renumbering.vertex_map); }

private:
    void refresh_fan(const TriMesh &mesh, int32_t v)
    {
        mesh.for_each_outgoing(v, [&](int32_t g) { guard_.refresh(mesh, mesh.pos, TriMesh::face(g)); });
    }
    CrossingGuard &guard_;
};

} // namespace sfa

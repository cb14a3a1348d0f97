// SPDX-License-Identifier: BSD-3-Clause
// Host fields (one value set per vertex) carried through every change of an edit: a new,
// merged or moved vertex takes the barycentric interpolation of the old values at its
// stencil (mesh/stencil.hpp); compaction and renumbering move the values with their
// vertices. The velocities travel the same way, as one more field. The fields' value arrays
// (the std::vector objects) stay where they are, so that a reference to one, such as the
// size field's (adapt/size_field.hpp), stays valid through every change.
#pragma once

#include "fields/vertex_fields.hpp"
#include "mesh/mesh_edit.hpp"

#include <vector>

namespace sfa {

class CarriedFields : public EditListener {
public:
    explicit CarriedFields(std::vector<VertexField> &fields) : fields_(fields) {}

    bool interpolates() const override { return !fields_.empty(); }
    void split(const TriMesh &, const SplitChange &change) override;
    void collapse(const TriMesh &, const CollapseChange &change) override;
    void move(const TriMesh &mesh, const MoveChange &change) override;
    void renumber(const Renumbering &renumbering) override;

private:
    std::vector<VertexField> &fields_;
};

} // namespace sfa

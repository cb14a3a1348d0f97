// SPDX-License-Identifier: BSD-3-Clause
// What the host pins (sfa_set_fixed_vertices, sfa_set_required_edges): a contact line, the
// seam with a structure, later a partition seam. Smoothing and adaptation treat a fixed
// vertex as a corner that can never be merged away: it is never moved (smoothing, the
// volume correction) and never removed (a contraction next to it keeps it, in place; one
// between two fixed vertices is refused). A required edge is never split, flipped or
// contracted, and its ends are fixed. Motion still moves them all with their velocities.
#pragma once

#include "mesh/halfedge_flags.hpp"
#include "mesh/mesh_edit.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace sfa {

// The host's form, in the handle's current numbering.
struct Constraints {
    std::vector<char> fixed;                      // per vertex, as the host set them; empty: none
    std::vector<std::array<int32_t, 2>> required; // vertex pairs (smaller first), each an edge

    bool empty() const { return fixed.empty() && required.empty(); }
};

// Carried through every change of an edit. Attach only when !constraints.empty(): an
// empty one answers every question with false.
class CarriedConstraints : public EditListener {
public:
    CarriedConstraints() = default;
    CarriedConstraints(const TriMesh &mesh, const Constraints &constraints);

    // Fixed by the host or the end of a required edge.
    bool fixed(int32_t v) const { return !fixed_.empty() && fixed_[v]; }
    bool required(int32_t h) const { return !required_.flags().empty() && required_[h]; }

    // The ranks of detected features with every fixed vertex made a corner (rank 2), which
    // smoothing and the volume correction never move.
    void impose_on(std::vector<int8_t> &rank) const;
    // In the host's form again, numbered as the mesh is now.
    Constraints as_host(const TriMesh &mesh) const;

    void split(const TriMesh &mesh, const SplitChange &change) override;
    void collapse(const TriMesh &mesh, const CollapseChange &change) override;
    void flip(const TriMesh &mesh, const FlipChange &change) override;
    void renumber(const Renumbering &renumbering) override;

private:
    std::vector<char> host_fixed_; // as the host set them (empty: none)
    std::vector<char> fixed_;      // host_fixed_ and the ends of required edges (empty: none)
    HalfedgeFlags required_;       // empty flags: none
};

} // namespace sfa

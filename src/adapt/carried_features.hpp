// SPDX-License-Identifier: BSD-3-Clause
// The features of the surface as sfa_adapt found them, carried through its splits,
// contractions and flips rather than detected again after every step: within one call a
// feature stays a feature. Otherwise refining a crease that is just sharp enough (a coarse
// model's) halves its dihedral angles, and the next analysis would lose it (spot lost 18 of
// its 30 corners that way). The next call detects afresh, so that features of a moving
// surface can still appear and vanish.
#pragma once

#include "geometry/features.hpp"
#include "mesh/halfedge_flags.hpp"

#include <cstdint>
#include <vector>

namespace sfa {

// How features are carried: a vertex made on a ridge or boundary edge is a ridge vertex
// (else smooth); a merged vertex takes the higher rank of the two; ridge edges are
// half-edge flags (halfedge_flags.hpp). No operation flips a ridge edge (flip.hpp).
class CarriedFeatures : public EditListener {
public:
    explicit CarriedFeatures(const Features &detected)
        : rank_(detected.rank), ridges_(detected.ridge_halfedge) {}

    int8_t rank(int32_t v) const { return rank_[v]; }
    const std::vector<int8_t> &ranks() const { return rank_; }
    // True if h's edge is a ridge edge.
    bool is_ridge(int32_t h) const { return ridges_[h]; }

    // The position of v's ridge neighbour other than `not_this`, or nullptr if v is not a
    // ridge vertex (rank 1: exactly two ridge neighbours) or has none.
    const Vec3 *next_along(const TriMesh &mesh, int32_t v, int32_t not_this) const;

    // As the analysis presents features (ranks, ridge half-edge flags, sorted ridge edges).
    Features as_features(const TriMesh &mesh) const;

    void split(const TriMesh &mesh, const SplitChange &change) override;
    void collapse(const TriMesh &mesh, const CollapseChange &change) override;
    void flip(const TriMesh &mesh, const FlipChange &change) override { ridges_.flip(mesh, change); }
    void renumber(const Renumbering &renumbering) override;

private:
    std::vector<int8_t> rank_; // per vertex: 0 smooth, 1 ridge, 2 corner
    HalfedgeFlags ridges_;
};

} // namespace sfa

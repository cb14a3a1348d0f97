// SPDX-License-Identifier: BSD-3-Clause
// Where each vertex came from (sfa_get_vertex_origins): for every vertex of the mesh after
// a call (sfa_smooth, sfa_adapt), the triangle of the mesh as it was before the call that
// the vertex lies over, and its barycentric coordinates there, so that a host carries data
// of its own through the call (value at the vertex = sum of weights[k] times the value at
// the triangle's corner k). Exact where the surface was flat, first order where it was
// curved (the vertex is placed at its closest point on a flat triangle).
//
// Two halves, so that a call that is never asked for origins pays almost nothing: the
// edit carries a hint per vertex (OriginHints, O(1) per change, always attached), and the
// origins are found only when asked (locate_origins: from each hint, a short walk over the
// mesh as it was).
#pragma once

#include "mesh/mesh_edit.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace sfa {

// A point over a triangle of the mesh as it was: weights are in [0, 1] and
// weights[0] + weights[1] + weights[2], added in that order, is exactly 1.
struct VertexOrigin {
    int32_t triangle; // -1: no hint (a vertex the edit did not account for)
    Eigen::Vector3d weights;
};

// For every vertex of the mesh being edited, a triangle of the mesh as it was when the
// listener was made (or reset) near which the vertex lies: at first a face of the vertex's
// own fan; a new vertex takes the hint of the nearer end of its edge, a merged vertex the
// hint of the end nearer to where it is placed. Moves and offsets leave the hints alone:
// a vertex moves by a fraction of an edge per sweep, and the walk of locate_origins goes
// the rest of the way. The hints index the triangles of the mesh as it was, which the
// caller must keep (a copy; a smoothing call, whose connectivity does not change, need
// only keep the positions).
class OriginHints : public EditListener {
public:
    explicit OriginHints(const TriMesh &before) { reset(before); }
    // Hints made already (by a change of topology before the edit begins).
    explicit OriginHints(std::vector<int32_t> hints) : hints_(std::move(hints)) {}

    // Starts over from `before` (the next call), keeping the storage.
    void reset(const TriMesh &before);

    // One per vertex of the mesh as it is now (dead vertices included until compaction).
    const std::vector<int32_t> &hints() const { return hints_; }

    void before_collapse(const TriMesh &mesh, int32_t h) override;
    void split(const TriMesh &mesh, const SplitChange &change) override;
    void collapse(const TriMesh &mesh, const CollapseChange &change) override;
    void renumber(const Renumbering &renumbering) override;

private:
    std::vector<int32_t> hints_;
    // The ends of the edge being contracted, where they were (before_collapse): collapse()
    // only sees the merged vertex's new place.
    Vec3 gone_was_ = Vec3::Zero(), keep_was_ = Vec3::Zero();
};

// The walk's bound (triangles visited per point). A vertex drifts a few edges from its
// hint in one call; the bound only matters for a point far from the surface, or for a
// walk that goes round in a cycle, and keeps either to a few microseconds.
inline constexpr int32_t origin_walk_steps = 256;

// The triangle of the mesh as it was (its connectivity and positions apart, so that a
// smoothing call need not copy its connectivity) that x lies over, found by walking from
// `hint`: in each triangle, x is projected onto its plane; if a barycentric coordinate is
// negative, the walk crosses the edge opposite the most negative one (or the next most
// negative, where that edge is on the boundary or leads back to a triangle it has just
// been through); it stops at a triangle whose coordinates are all >= 0 (to rounding), at
// the boundary, where every way on leads back, or after max_steps triangles. The result
// is the nearest triangle the walk saw (the distance from x to its closest point; the
// later one at a tie), with the barycentric coordinates of that closest point. It only
// crosses edges, so it stays on the hint's sheet where two sheets face each other.
// Allocates nothing.
VertexOrigin locate_origin(const TriMesh &before_topology, const std::vector<Vec3> &before_positions, int32_t hint,
                           const Vec3 &x, int32_t max_steps = origin_walk_steps);

// locate_origin for every vertex v: from hints[v], of positions[v] (one hint per
// position). In parallel; allocates only the result.
std::vector<VertexOrigin> locate_origins(const TriMesh &before_topology, const std::vector<Vec3> &before_positions,
                                         const std::vector<int32_t> &hints, const std::vector<Vec3> &positions);

} // namespace sfa

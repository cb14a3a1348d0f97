// SPDX-License-Identifier: BSD-3-Clause
// Bubbles that merge and drops that break up (SFA_PARAM_TOPOLOGY_CHANGE): the first stage
// of an sfa_adapt call, before the adaptation (adapt.hpp) cleans up what it made.
//
// - Merge: two edges on sheets that face each other (their normals within 60 degrees of
//   opposite) are zipped (mesh/surgery.hpp), nearest pair first, where they are closer
//   than the merge distance d (the ratio times their desired length l) across the outer
//   phase (each on the side of the other its normal points to), or closer than d / 4
//   across the inner phase (a bubble's walls pressed together). Events of one call stay 2 l apart: a contact
//   patch is joined by one tube per call, which the adaptation then widens or leaves.
// - Pinch: a loop of three edges, each shorter than d, that is not a triangle (a neck or
//   filament that contraction has thinned to three vertices around) is cut, and each
//   side's copies of the loop's corners move towards the centre of their side's
//   neighbours, so that the two closing triangles part by 2 d (not yet cut where they
//   cannot), and the two ends do not merge again at once.
// - Removal: a closed component less than two merge distances across (a drop below what
//   the mesh resolves, most often what a pinch left between two ends) is removed.
//
// Every event is checked with the exact predicates: if a triangle it made or moved meets a
// triangle it shares no corner with, it is undone. The surface after the stage is a valid
// manifold that crosses itself nowhere it did not before. Vertices the host fixed, and the
// ends of required edges, take part in no event. What lives on the mesh follows: vertex
// fields and the size field are copied to the copies of a pinch's corners, face-field
// densities are pooled over each event's triangles (their integral is kept; a removed
// drop takes its own), origins' hints are carried (a copy has its corner's).
#pragma once

#include "adapt/surface_data.hpp"
#include "mesh/components.hpp"

#include <cstdint>
#include <vector>

namespace sfa {

struct TopologyCounts {
    int32_t merges = 0, pinches = 0, removals = 0;
    // The volume the events made or destroyed, each event's |change| summed; length units cubed.
    double volume_change = 0;
};

// `components`: those of the mesh on entry, numbered and indexed; on return those of the
// returned mesh, likewise. `merge_distance`: d as a ratio of l; `edge_length`: l where
// data.size does not give it. `origin_hints`: per vertex of the mesh on entry a triangle
// of the mesh as the call found it; on return, per vertex of the returned mesh.
TopologyCounts change_topology(TriMesh &mesh, SurfaceData &data, Components &components, double merge_distance,
                               double edge_length, std::vector<int32_t> &origin_hints);

} // namespace sfa

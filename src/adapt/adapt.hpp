// SPDX-License-Identifier: BSD-3-Clause
// The full adaptation (§3-§4): mesh optimization (smoothing, flipping) and mesh repair
// (splitting, contraction), iterated.
#pragma once

#include "adapt/phase_times.hpp"
#include "adapt/settings.hpp"
#include "adapt/surface_data.hpp"
#include "adapt/topology_change.hpp"
#include "mesh/components.hpp"

#include <vector>

namespace sfa {

struct AdaptCounts {
    int32_t passes = 0, splits = 0, contractions = 0, flips = 0;
    int64_t clearance_tests = 0; // contraction_pass's count of exact triangle tests
    // The largest relative volume change of a closed component that the operations made
    // (restore_enclosed_volumes), and the correction took back if it was on.
    double volume_correction = 0;
    // The largest relative volume change of a closed component the correction left.
    double volume_left = 0;
    TopologyCounts topology; // the merges and pinches made first (SFA_PARAM_TOPOLOGY_CHANGE)
    PhaseTimes seconds;
};

// Features are detected once, then carried through the call (carried_features.hpp). Each
// pass: split, contract, flip, then smooth, every step on the geometry as it then is
// (analysed anew where the step before changed it); until a pass changes the connectivity
// of at most 1 in 100 vertices or max_passes were made. Each closed component then gets
// its own enclosed volume back (restore_enclosed_volumes, unless settings say not to), and
// if edges were split or contracted,
// the mesh is renumbered for locality (locality_order.hpp). Every change goes through one
// edit (mesh/mesh_edit.hpp), which carries the host's data (surface_data.hpp) and
// everything else that lives on the mesh. Where the host set a size field, it is graded
// (size_field.hpp) and takes the place of the global l; fixed vertices and required edges
// stay as they are (constraints.hpp). The mesh stays dense and valid. The seconds of
// each phase are counted in the result. With the crossing guard, no step carries the
// surface through itself where it is thinner than an edge (crossing_guard.hpp): the
// vertices near a facing sheet are found at the start and carried through the call; on
// return `near_sheet` holds them, numbered as the returned mesh (empty without the guard).
// With topology change on, merges and pinches come first (topology_change.hpp), and the
// components are those they leave.
// The analyses are made in `workspace`, whose contents on entry do not matter and on
// return mean nothing; keeping it from call to call keeps its memory. `components` are
// those of the mesh on entry, and on return those of the returned mesh, numbered and
// indexed as connected_components would.
AdaptCounts adapt_surface(TriMesh &mesh, SurfaceData &data, const AdaptSettings &settings,
                          std::vector<char> &near_sheet, SurfaceAnalysis &workspace, Components &components);

} // namespace sfa

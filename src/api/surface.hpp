// SPDX-License-Identifier: BSD-3-Clause
// The state behind one sfa_surface handle. Every entry point builds what it changes aside
// and commits it with non-throwing moves and swaps, so that a failure at any point, out of
// memory included, leaves this exactly as it was ("nothing lost", API.md).
#pragma once

#include "adapt/parameters.hpp"
#include "adapt/phase_times.hpp"
#include "adapt/surface_data.hpp"
#include "adapt/topology_change.hpp"
#include "geometry/analysis.hpp"
#include "geometry/block_partition.hpp"
#include "mesh/components.hpp"
#include "mesh/tri_mesh.hpp"

#include <cstdint>
#include <vector>

namespace sfa {

// What sfa_get_vertex_origins needs from the last successful sfa_smooth or sfa_adapt call
// (fields/vertex_origins.hpp); the origins are found only when asked. The mesh as it was
// is kept whole after sfa_adapt (it would have been freed: keeping it costs memory, not
// time); after sfa_smooth, which keeps the connectivity, only its positions.
struct OriginsRecord {
    bool valid = false;          // false until such a call, and after sfa_set_mesh
    bool same_connectivity = false; // sfa_smooth: the handle's mesh has the connectivity of `before`
    TriMesh before;              // sfa_adapt: the mesh as it was (its positions after sfa_smooth)
    std::vector<int32_t> hints;  // sfa_adapt: one per vertex (sfa_smooth: from the mesh)
    std::vector<Vec3> after;     // the positions right after the call
};

} // namespace sfa

struct sfa_surface {
    sfa::TriMesh mesh;
    bool has_mesh = false;
    int32_t index_base = 0; // the base of the last sfa_set_mesh, used to number vertices in messages
    const char *counts_set_by = "sfa_set_mesh"; // the last call that changed the counts, for messages
    double mean_edge_length_at_set = 0; // what SFA_PARAM_EDGE_LENGTH = 0 stands for
    sfa::Parameters params;
    std::vector<sfa::Vec3> velocity; // empty until sfa_set_velocities
    std::vector<sfa::VertexField> fields;
    std::vector<double> size_field;           // per vertex; empty until sfa_set_size_field
    std::vector<sfa::FaceField> face_fields;
    sfa::Constraints constraints;             // sfa_set_fixed_vertices, sfa_set_required_edges
    // The components of the current connectivity, numbered and indexed (mesh/components.hpp),
    // which only sfa_set_mesh and sfa_adapt change: each closed one keeps its own volume.
    sfa::Components components;
    sfa::OriginsRecord origins;
    sfa::PhaseTimes seconds_spent; // by the successful sfa_smooth and sfa_adapt calls
    double volume_correction = 0;  // SFA_MEASURE_VOLUME_CORRECTION of the last of them
    double volume_left = 0;        // SFA_MEASURE_VOLUME_LEFT of the last of them
    sfa::TopologyCounts topology;  // SFA_MEASURE_MERGES, _PINCHES, _TOPOLOGY_VOLUME_CHANGE of the last sfa_adapt
    // The vertices near a facing sheet (geometry/crossing_guard.hpp) as the last sfa_adapt
    // found them, for the sfa_smooth calls until the next; empty if the connectivity
    // changed since (sfa_set_mesh).
    std::vector<char> near_sheet;
    // The triangles as collision-safe motion's search dealt them into blocks, kept for the
    // steps until the triangles change (sfa_set_mesh, sfa_adapt drop it): it spares the
    // search a seventh of its work (geometry/block_partition.hpp).
    sfa::BlockPartition collision_blocks;
    // Memory for the analyses of sfa_smooth and sfa_adapt, kept so that a flow, which calls
    // them on every step, does not allocate it anew each time; its contents mean nothing
    // between calls.
    sfa::SurfaceAnalysis analysis_workspace;

    // A fixed buffer, so that reporting an error (out of memory included) never allocates.
    mutable char last_error[1024] = "";
};

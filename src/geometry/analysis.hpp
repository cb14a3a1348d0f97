// SPDX-License-Identifier: BSD-3-Clause
// Everything the adaptation needs to know about the surface at once: quadrics, feature
// ranks and ridge edges, and the anisotropic metric at every vertex.
#pragma once

#include "geometry/features.hpp"
#include "geometry/metric.hpp"

namespace sfa {

struct SurfaceAnalysis {
    std::vector<Mat3> quadric; // A_v of §2.2
    std::vector<QuadricEigen> eigen;
    Features features;
    std::vector<VertexMetric> metric;
    // Per vertex: the sum of its faces' area vectors, the side the surface faces there
    // (surface_side.hpp). Around an interior vertex it is the vector area of the closed
    // loop of its neighbours, whatever the shape of the faces between.
    std::vector<Vec3> fan_area;
};

SurfaceAnalysis analyze_surface(const TriMesh &mesh, const FeatureThresholds &thresholds, const MetricBounds &bounds);

// The same without feature detection (features left empty), for callers that carry
// features of their own.
SurfaceAnalysis analyze_geometry(const TriMesh &mesh, const MetricBounds &bounds);

// Both written over `analysis`, whatever it held (analyze_geometry leaves its features as
// they are), in the memory it already has. A flow analyses a surface of 10^5 vertices on
// every step: allocating its 25 MB afresh each time costs as much in zeroing and page
// faults, all on one thread, as a tenth of the whole run.
void analyze_surface(const TriMesh &mesh, const FeatureThresholds &thresholds, const MetricBounds &bounds,
                     SurfaceAnalysis &analysis);
void analyze_geometry(const TriMesh &mesh, const MetricBounds &bounds, SurfaceAnalysis &analysis);

// Brings the geometry of `analysis` up to date after local changes: the vertices marked in
// `changed` (one mark per vertex of the mesh as it now is: their fans changed, or they are
// new) get their quadric, decomposition and metric anew. Every other vertex's fan is as it
// was, so its entries are what analyze_geometry would give, to the last bit; this costs a
// fraction of it where few vertices changed. Features are left as they are.
void update_geometry(const TriMesh &mesh, const std::vector<char> &changed, const MetricBounds &bounds,
                     SurfaceAnalysis &analysis);

// Renumbers the per-vertex entries after compaction (vertex v's go to vertex_map[v], or
// away if it is -1), in place: compaction keeps the order of the vertices it keeps.
void renumber_vertices(SurfaceAnalysis &analysis, const std::vector<int32_t> &vertex_map);

} // namespace sfa

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
};

SurfaceAnalysis analyze_surface(const TriMesh &mesh, const FeatureThresholds &thresholds, const MetricBounds &bounds);

// The same without feature detection (features left empty), for callers that carry
// features of their own.
SurfaceAnalysis analyze_geometry(const TriMesh &mesh, const MetricBounds &bounds);

// The quadrics alone (eigen, metric and features left empty): for edge flipping, which
// decomposes sums of them itself (flip.hpp).
SurfaceAnalysis analyze_quadrics(const TriMesh &mesh);

} // namespace sfa

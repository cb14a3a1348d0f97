#include "geometry/analysis.hpp"

namespace sfa {

SurfaceAnalysis analyze_surface(const TriMesh &mesh, const FeatureThresholds &thresholds, const MetricBounds &bounds)
{
    SurfaceAnalysis analysis;
    const std::vector<Vec3> area_vectors = face_area_vectors(mesh);
    analysis.quadric = vertex_quadrics(mesh, area_vectors);

    std::vector<Vec3> outward(mesh.pos.size(), Vec3::Zero());
    for (size_t t = 0; t < mesh.tri.size(); ++t)
        for (int32_t v : mesh.tri[t])
            outward[v] += area_vectors[t];

    analysis.eigen.resize(mesh.pos.size());
    analysis.metric.resize(mesh.pos.size());
    for (size_t v = 0; v < mesh.pos.size(); ++v) {
        analysis.eigen[v] = decompose(analysis.quadric[v]);
        analysis.metric[v] = vertex_metric(analysis.eigen[v], outward[v], bounds);
    }
    analysis.features = detect_features(mesh, analysis.eigen, area_vectors, thresholds);
    return analysis;
}

} // namespace sfa

#include "geometry/analysis.hpp"

#include "mesh/parallel.hpp"

namespace sfa {
namespace {

SurfaceAnalysis geometry_of(const TriMesh &mesh, const std::vector<Vec3> &area_vectors, const MetricBounds &bounds)
{
    SurfaceAnalysis analysis;
    analysis.quadric = vertex_quadrics(mesh, area_vectors);

    analysis.eigen.resize(mesh.pos.size());
    analysis.metric.resize(mesh.pos.size());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        Vec3 outward = Vec3::Zero(); // the side the face normals point to
        mesh.for_each_outgoing(v, [&](int32_t h) { outward += area_vectors[TriMesh::face(h)]; });
        analysis.eigen[v] = decompose(analysis.quadric[v]);
        analysis.metric[v] = vertex_metric(analysis.eigen[v], outward, bounds);
    }
    return analysis;
}

} // namespace

SurfaceAnalysis analyze_geometry(const TriMesh &mesh, const MetricBounds &bounds)
{
    return geometry_of(mesh, face_area_vectors(mesh), bounds);
}

SurfaceAnalysis analyze_quadrics(const TriMesh &mesh)
{
    SurfaceAnalysis analysis;
    analysis.quadric = vertex_quadrics(mesh, face_area_vectors(mesh));
    return analysis;
}

SurfaceAnalysis analyze_surface(const TriMesh &mesh, const FeatureThresholds &thresholds, const MetricBounds &bounds)
{
    const std::vector<Vec3> area_vectors = face_area_vectors(mesh);
    SurfaceAnalysis analysis = geometry_of(mesh, area_vectors, bounds);
    analysis.features = detect_features(mesh, analysis.eigen, area_vectors, thresholds);
    return analysis;
}

} // namespace sfa

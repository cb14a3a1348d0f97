// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/analysis.hpp"

#include "mesh/parallel.hpp"

namespace sfa {
namespace {

// Quadric, eigen-decomposition and metric of vertex v, from its own fan alone: the area
// vectors of its faces (area_vector(t)) and their quadric terms (weighted(t)). Full and
// partial analyses both come here, so that they agree to the last bit.
template <class AreaVector, class Weighted>
void analyze_vertex(const TriMesh &mesh, int32_t v, AreaVector &&area_vector, Weighted &&weighted,
                    const MetricBounds &bounds, SurfaceAnalysis &analysis)
{
    analysis.quadric[v] = vertex_quadric(mesh, v, weighted);
    Vec3 outward = Vec3::Zero(); // the side the face normals point to
    mesh.for_each_outgoing(v, [&](int32_t h) { outward += area_vector(TriMesh::face(h)); });
    analysis.eigen[v] = decompose(analysis.quadric[v]);
    analysis.metric[v] = vertex_metric(analysis.eigen[v], outward, bounds);
    analysis.fan_area[v] = outward;
}

void geometry_of(const TriMesh &mesh, const std::vector<Vec3> &area_vectors, const MetricBounds &bounds,
                 SurfaceAnalysis &analysis)
{
    const std::vector<Vec3> weighted = weighted_normals(area_vectors);
    analysis.quadric.resize(mesh.pos.size());
    analysis.eigen.resize(mesh.pos.size());
    analysis.metric.resize(mesh.pos.size());
    analysis.fan_area.resize(mesh.pos.size());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        analyze_vertex(
            mesh, v, [&](int32_t t) -> const Vec3 & { return area_vectors[t]; },
            [&](int32_t t) -> const Vec3 & { return weighted[t]; }, bounds, analysis);
}

} // namespace

void analyze_geometry(const TriMesh &mesh, const MetricBounds &bounds, SurfaceAnalysis &analysis)
{
    geometry_of(mesh, face_area_vectors(mesh), bounds, analysis);
}

void analyze_surface(const TriMesh &mesh, const FeatureThresholds &thresholds, const MetricBounds &bounds,
                     SurfaceAnalysis &analysis)
{
    const std::vector<Vec3> area_vectors = face_area_vectors(mesh);
    geometry_of(mesh, area_vectors, bounds, analysis);
    analysis.features = detect_features(mesh, analysis.eigen, area_vectors, thresholds);
}

SurfaceAnalysis analyze_geometry(const TriMesh &mesh, const MetricBounds &bounds)
{
    SurfaceAnalysis analysis;
    analyze_geometry(mesh, bounds, analysis);
    return analysis;
}

SurfaceAnalysis analyze_surface(const TriMesh &mesh, const FeatureThresholds &thresholds, const MetricBounds &bounds)
{
    SurfaceAnalysis analysis;
    analyze_surface(mesh, thresholds, bounds, analysis);
    return analysis;
}

void update_geometry(const TriMesh &mesh, const std::vector<char> &changed, const MetricBounds &bounds,
                     SurfaceAnalysis &analysis)
{
    analysis.quadric.resize(mesh.pos.size());
    analysis.eigen.resize(mesh.pos.size());
    analysis.metric.resize(mesh.pos.size());
    analysis.fan_area.resize(mesh.pos.size());
    const auto area_vector = [&](int32_t t) { return face_area_vector(mesh, t); };
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 1024)
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        if (changed[v])
            analyze_vertex(
                mesh, v, area_vector, [&](int32_t t) { return weighted_normal(area_vector(t)); }, bounds, analysis);
}

void renumber_vertices(SurfaceAnalysis &analysis, const std::vector<int32_t> &vertex_map)
{
    // vertex_map[v] <= v, increasing: each entry moves down onto one already read.
    const auto renumbered = [&](auto &values) {
        size_t count = 0;
        for (size_t v = 0; v < vertex_map.size(); ++v)
            if (vertex_map[v] >= 0) {
                values[vertex_map[v]] = values[v];
                ++count;
            }
        values.resize(count);
    };
    renumbered(analysis.quadric);
    renumbered(analysis.eigen);
    renumbered(analysis.metric);
    renumbered(analysis.fan_area);
}

} // namespace sfa

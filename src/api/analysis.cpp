// Analysis: sfa_measure, sfa_get_feature_ranks, sfa_get_vertex_frames, sfa_get_ridge_edges.
#include "api/boundary.hpp"

#include "adapt/settings.hpp"
#include "geometry/measures.hpp"
#include "geometry/self_intersection.hpp"

using namespace sfa;

namespace {

void require_capacity(const sfa_surface *s, int32_t capacity)
{
    if (capacity < s->mesh.num_vertices()) {
        char message[120];
        std::snprintf(message, sizeof message, "capacity too small: the mesh has %d vertices, room was given for %d",
                      s->mesh.num_vertices(), capacity);
        fail(Status::argument, message);
    }
}

// The analysis of the surface's current mesh with its parameters. Computed on demand: it
// costs about a microsecond per vertex, and a cache would have to follow every change of
// mesh or parameter.
SurfaceAnalysis current_analysis(const sfa_surface *s)
{
    return analyze_surface(s->mesh, feature_thresholds(s->params), metric_bounds(s->params));
}

} // namespace

extern "C" {

SFA_EXPORT int sfa_measure(const sfa_surface *s, int quantity, double *value)
{
    return call(s, "sfa_measure", [&] {
        require(value != nullptr, "value is NULL");
        if (quantity < SFA_MEASURE_VOLUME || quantity > SFA_MEASURE_SELF_INTERSECTIONS) {
            char message[120];
            std::snprintf(message, sizeof message,
                          "unknown quantity %d (quantities are 0 to %d, enum sfa_measure_quantity)", quantity,
                          SFA_MEASURE_SELF_INTERSECTIONS);
            fail(Status::argument, message);
        }
        switch (quantity) {
        case SFA_MEASURE_SECONDS_ANALYSIS: *value = s->seconds_spent.analysis; return;
        case SFA_MEASURE_SECONDS_SMOOTHING: *value = s->seconds_spent.smoothing; return;
        case SFA_MEASURE_SECONDS_FLIPPING: *value = s->seconds_spent.flipping; return;
        case SFA_MEASURE_SECONDS_REPAIR: *value = s->seconds_spent.repair; return;
        }
        require_mesh(s);
        const TriMesh &mesh = s->mesh;
        switch (quantity) {
        case SFA_MEASURE_VOLUME: *value = enclosed_volume(mesh); break;
        case SFA_MEASURE_AREA: *value = surface_area(mesh); break;
        case SFA_MEASURE_MIN_ANGLE: *value = angle_range(mesh).min_degrees; break;
        case SFA_MEASURE_MAX_ANGLE: *value = angle_range(mesh).max_degrees; break;
        case SFA_MEASURE_MEAN_EDGE_LENGTH: *value = edge_lengths(mesh).mean; break;
        case SFA_MEASURE_MAX_ASPECT_RATIO: *value = max_aspect_ratio(mesh); break;
        case SFA_MEASURE_MIN_EDGE_LENGTH: *value = edge_lengths(mesh).min; break;
        case SFA_MEASURE_MAX_EDGE_LENGTH: *value = edge_lengths(mesh).max; break;
        case SFA_MEASURE_MAX_NORMAL_TURN: *value = max_normal_turn_degrees(mesh); break;
        case SFA_MEASURE_SELF_INTERSECTIONS: *value = self_intersection_count(mesh); break;
        }
    });
}

SFA_EXPORT int sfa_get_feature_ranks(const sfa_surface *s, int32_t capacity, int32_t *ranks)
{
    return call(s, "sfa_get_feature_ranks", [&] {
        require(ranks != nullptr, "ranks is NULL");
        require_mesh(s);
        require_capacity(s, capacity);
        const SurfaceAnalysis analysis = current_analysis(s);
        for (size_t v = 0; v < analysis.features.rank.size(); ++v)
            ranks[v] = analysis.features.rank[v];
    });
}

SFA_EXPORT int sfa_get_vertex_frames(const sfa_surface *s, int32_t capacity, double *normals, double *long_directions,
                                     double *aspect_ratios)
{
    return call(s, "sfa_get_vertex_frames", [&] {
        require_mesh(s);
        require_capacity(s, capacity);
        const SurfaceAnalysis analysis = current_analysis(s);
        for (size_t v = 0; v < analysis.metric.size(); ++v) {
            const VertexMetric &m = analysis.metric[v];
            for (int k = 0; k < 3; ++k) {
                if (normals)
                    normals[3 * v + k] = m.normal[k];
                if (long_directions)
                    long_directions[3 * v + k] = m.minor[k];
            }
            if (aspect_ratios)
                aspect_ratios[v] = m.aspect_ratio();
        }
    });
}

SFA_EXPORT int sfa_get_ridge_edges(const sfa_surface *s, int32_t capacity, int32_t *edges, int32_t *count,
                                   int32_t index_base)
{
    return call(s, "sfa_get_ridge_edges", [&] {
        require(index_base == 0 || index_base == 1, "index_base must be 0 or 1");
        require_mesh(s);
        const SurfaceAnalysis analysis = current_analysis(s);
        const auto &ridges = analysis.features.ridge_edges;
        const int32_t found = static_cast<int32_t>(ridges.size());
        if (count)
            *count = found;
        if (!edges)
            return;
        if (capacity < found) {
            char message[120];
            std::snprintf(message, sizeof message, "capacity too small: there are %d ridge edges, room was given for %d",
                          found, capacity);
            fail(Status::argument, message);
        }
        for (int32_t e = 0; e < found; ++e) {
            edges[2 * e] = ridges[e][0] + index_base;
            edges[2 * e + 1] = ridges[e][1] + index_base;
        }
    });
}

} // extern "C"

// SPDX-License-Identifier: BSD-3-Clause
// Analysis: sfa_measure, sfa_get_feature_ranks, sfa_get_vertex_frames, sfa_get_ridge_edges.
#include "api/boundary.hpp"

#include "adapt/settings.hpp"
#include "geometry/measures.hpp"
#include "geometry/self_intersection.hpp"
#include "geometry/surface_resolution.hpp"
#include "mesh/components.hpp"

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

void require_known_quantity(int quantity)
{
    if (quantity < SFA_MEASURE_VOLUME || quantity > SFA_MEASURE_MIN_ANGLE_RESOLVED) {
        char message[120];
        std::snprintf(message, sizeof message, "unknown quantity %d (quantities are 0 to %d, enum sfa_measure_quantity)",
                      quantity, SFA_MEASURE_MIN_ANGLE_RESOLVED);
        fail(Status::argument, message);
    }
}

// The quantities that measure the calls made on the surface, not its mesh: true and the
// value for those, false for a measure of the mesh.
bool call_measure(const sfa_surface *s, int quantity, double &value)
{
    switch (quantity) {
    case SFA_MEASURE_SECONDS_ANALYSIS: value = s->seconds_spent.analysis; return true;
    case SFA_MEASURE_SECONDS_SMOOTHING: value = s->seconds_spent.smoothing; return true;
    case SFA_MEASURE_SECONDS_FLIPPING: value = s->seconds_spent.flipping; return true;
    case SFA_MEASURE_SECONDS_REPAIR: value = s->seconds_spent.repair; return true;
    case SFA_MEASURE_VOLUME_CORRECTION: value = s->volume_correction; return true;
    case SFA_MEASURE_MERGES: value = s->topology.merges; return true;
    case SFA_MEASURE_PINCHES: value = s->topology.pinches; return true;
    case SFA_MEASURE_TOPOLOGY_VOLUME_CHANGE: value = s->topology.volume_change; return true;
    case SFA_MEASURE_DROPS_REMOVED: value = s->topology.removals; return true;
    case SFA_MEASURE_VOLUME_LEFT: value = s->volume_left; return true;
    default: return false;
    }
}

double mesh_measure(const TriMesh &mesh, int quantity)
{
    switch (quantity) {
    case SFA_MEASURE_VOLUME: return enclosed_volume(mesh);
    case SFA_MEASURE_AREA: return surface_area(mesh);
    case SFA_MEASURE_MIN_ANGLE: return angle_range(mesh).min_degrees;
    case SFA_MEASURE_MAX_ANGLE: return angle_range(mesh).max_degrees;
    case SFA_MEASURE_MEAN_EDGE_LENGTH: return edge_lengths(mesh).mean;
    case SFA_MEASURE_MAX_ASPECT_RATIO: return max_aspect_ratio(mesh);
    case SFA_MEASURE_MIN_EDGE_LENGTH: return edge_lengths(mesh).min;
    case SFA_MEASURE_MAX_EDGE_LENGTH: return edge_lengths(mesh).max;
    case SFA_MEASURE_MAX_NORMAL_TURN: return max_normal_turn_degrees(mesh);
    case SFA_MEASURE_SELF_INTERSECTIONS: return self_intersection_count(mesh);
    case SFA_MEASURE_UNRESOLVED_AREA: return resolved_angles(mesh, unresolved_triangles(mesh)).unresolved_area;
    case SFA_MEASURE_MIN_ANGLE_RESOLVED: return resolved_angles(mesh, unresolved_triangles(mesh)).min_degrees;
    }
    fail(Status::internal, "a mesh measure without a formula");
}

} // namespace

extern "C" {

SFA_EXPORT int sfa_measure(const sfa_surface *s, int quantity, double *value)
{
    return call(s, "sfa_measure", [&] {
        require(value != nullptr, "value is NULL");
        require_known_quantity(quantity);
        if (call_measure(s, quantity, *value))
            return;
        require_mesh(s);
        // The volume is summed per component: the handle knows its components.
        *value = quantity == SFA_MEASURE_VOLUME ? enclosed_volume(s->mesh, s->components)
                                                : mesh_measure(s->mesh, quantity);
    });
}

SFA_EXPORT int sfa_measure_component(const sfa_surface *s, int32_t component, int quantity, double *value)
{
    return call(s, "sfa_measure_component", [&] {
        require(value != nullptr, "value is NULL");
        require_known_quantity(quantity);
        double unused = 0;
        if (call_measure(s, quantity, unused)) {
            char message[160];
            std::snprintf(message, sizeof message,
                          "quantity %d measures the calls made on the surface, not one of its components: ask "
                          "sfa_measure",
                          quantity);
            fail(Status::argument, message);
        }
        require_mesh(s);
        const Components &components = s->components;
        if (component < 0 || component >= components.count) {
            char message[160];
            std::snprintf(message, sizeof message, "there is no component %d: the surface has %d (numbered 0 to %d)",
                          component, components.count, components.count - 1);
            fail(Status::argument, message);
        }
        *value = mesh_measure(component_mesh(s->mesh, components, component), quantity);
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

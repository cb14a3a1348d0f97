// Analysis: sfa_measure, sfa_get_feature_ranks.
#include "api/boundary.hpp"

#include "geometry/measures.hpp"

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_measure(const sfa_surface *s, int quantity, double *value)
{
    return call(s, "sfa_measure", [&] {
        require(value != nullptr, "value is NULL");
        if (quantity < SFA_MEASURE_VOLUME || quantity > SFA_MEASURE_MAX_EDGE_LENGTH) {
            char message[120];
            std::snprintf(message, sizeof message,
                          "unknown quantity %d (quantities are 0 to %d, enum sfa_measure_quantity)", quantity,
                          SFA_MEASURE_MAX_EDGE_LENGTH);
            fail(Status::argument, message);
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
        }
    });
}

SFA_EXPORT int sfa_get_feature_ranks(const sfa_surface *s, int32_t capacity, int32_t *ranks)
{
    return call(s, "sfa_get_feature_ranks", [&] {
        require(ranks != nullptr, "ranks is NULL");
        require_mesh(s);
        require(capacity >= s->mesh.num_vertices(), "capacity is smaller than the number of vertices");
        fail(Status::internal, "not implemented yet: feature detection (paper §2.2, §3.1) comes in a later release");
    });
}

} // extern "C"

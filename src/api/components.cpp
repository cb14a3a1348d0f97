// SPDX-License-Identifier: BSD-3-Clause
// Components: sfa_get_component_count, sfa_get_components.
#include "api/boundary.hpp"

#include "mesh/components.hpp"

#include <algorithm>

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_get_component_count(const sfa_surface *s, int32_t *count)
{
    return call(s, "sfa_get_component_count", [&] {
        require(count != nullptr, "count is NULL");
        require_mesh(s);
        *count = s->components.count; // the handle's own: kept for every change of connectivity
    });
}

SFA_EXPORT int sfa_get_components(const sfa_surface *s, int32_t capacity, int32_t *vertex_component)
{
    return call(s, "sfa_get_components", [&] {
        require(vertex_component != nullptr, "vertex_component is NULL");
        require_mesh(s);
        if (capacity < s->mesh.num_vertices()) {
            char message[120];
            std::snprintf(message, sizeof message, "capacity too small: the mesh has %d vertices, room was given for %d",
                          s->mesh.num_vertices(), capacity);
            fail(Status::argument, message);
        }
        std::copy(s->components.of_vertex.begin(), s->components.of_vertex.end(), vertex_component);
    });
}

} // extern "C"

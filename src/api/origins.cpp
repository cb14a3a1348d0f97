// SPDX-License-Identifier: BSD-3-Clause
// Where each vertex came from: sfa_get_vertex_origins (fields/vertex_origins.hpp).
#include "api/boundary.hpp"

#include "fields/vertex_origins.hpp"

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_get_vertex_origins(const sfa_surface *s, int32_t capacity, int32_t *triangle, double *barycentric,
                                      int32_t index_base)
{
    return call(s, "sfa_get_vertex_origins", [&] {
        require(triangle && barycentric, "triangle or barycentric is NULL");
        require(index_base == 0 || index_base == 1, "index_base must be 0 or 1");
        require_mesh(s);
        const OriginsRecord &r = s->origins;
        if (!r.valid)
            fail(Status::state, "no sfa_smooth or sfa_adapt call since the mesh was set: there are no origins yet");
        const int32_t n = s->mesh.num_vertices();
        if (capacity < n) {
            char message[120];
            std::snprintf(message, sizeof message,
                          "capacity too small: the mesh has %d vertices, room was given for %d", n, capacity);
            fail(Status::argument, message);
        }
        const TriMesh &topology = r.same_connectivity ? s->mesh : r.before;
        const std::vector<VertexOrigin> origins =
            locate_origins(topology, r.before.pos,
                           r.same_connectivity ? OriginHints(topology).hints() : r.hints, r.after);
        for (int32_t v = 0; v < n; ++v) {
            triangle[v] = origins[v].triangle + index_base;
            for (int k = 0; k < 3; ++k)
                barycentric[3 * v + k] = origins[v].weights[k];
        }
    });
}

} // extern "C"

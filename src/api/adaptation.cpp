// Adaptation: sfa_smooth, sfa_adapt.
#include "api/analysis_settings.hpp"

#include "adapt/smooth.hpp"
#include "fields/transfer.hpp"

#include <utility>

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_smooth(sfa_surface *s, int32_t iterations)
{
    return call(s, "sfa_smooth", [&] {
        require(iterations >= 0, "iterations must be >= 0");
        require_mesh(s);
        // Work on a copy of the positions and fields; commit only when every sweep succeeded.
        TriMesh mesh = s->mesh;
        std::vector<VertexField> fields = s->fields;
        for (int32_t sweep = 0; sweep < iterations; ++sweep) {
            std::vector<Vec3> moved = smoothing_sweep(mesh, current_analysis(s, mesh));
            fields = fields_at_moved_vertices(mesh, moved, fields);
            mesh.pos.swap(moved);
        }
        s->mesh.pos.swap(mesh.pos);
        s->fields.swap(fields);
    });
}

SFA_EXPORT int sfa_adapt(sfa_surface *s)
{
    return call(s, "sfa_adapt", [&] {
        require_mesh(s);
        fail(Status::internal, "not implemented yet: the full adaptation (paper §3-§4) comes in a later release");
    });
}

} // extern "C"

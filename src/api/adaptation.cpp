// Adaptation: sfa_smooth, sfa_adapt.
#include "api/boundary.hpp"

#include "adapt/adapt.hpp"
#include "adapt/smooth_surface.hpp"
#include "mesh/invariants.hpp"

#include <algorithm>
#include <string>
#include <utility>

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_smooth(sfa_surface *s, int32_t iterations)
{
    return call(s, "sfa_smooth", [&] {
        require(iterations >= 0, "iterations must be >= 0");
        require_mesh(s);
        const SmoothSettings settings = smooth_settings(s->params);
        // Sweeps move vertices only: work on the handle's mesh with its positions saved (the
        // connectivity is not copied, a step of a flow calls this on every step), and on a
        // copy of the fields; if anything fails, the positions go back.
        TriMesh &mesh = s->mesh;
        const std::vector<Vec3> saved_positions = mesh.pos;
        std::vector<VertexField> fields = s->fields;
        SmoothResult result;
        try {
            result = smooth_surface(mesh, fields, settings, iterations, s->near_sheet, s->analysis_workspace,
                                    s->components);
        } catch (...) {
            std::copy(saved_positions.begin(), saved_positions.end(), mesh.pos.begin()); // same size: no allocation
            throw;
        }
        s->fields.swap(fields);
        s->seconds_spent += result.seconds;
        s->volume_correction = result.volume_correction;
    });
}

SFA_EXPORT int sfa_adapt(sfa_surface *s)
{
    return call(s, "sfa_adapt", [&] {
        require_mesh(s);
        const AdaptSettings settings = adapt_settings(s->params, s->mean_edge_length_at_set);

        // Work on copies; the velocities travel as one more field. Commit only at the end.
        TriMesh mesh = s->mesh;
        std::vector<VertexField> data = s->fields;
        const bool has_velocity = !s->velocity.empty();
        if (has_velocity) {
            VertexField velocity{3, std::vector<double>(3 * s->velocity.size())};
            for (size_t v = 0; v < s->velocity.size(); ++v)
                for (int c = 0; c < 3; ++c)
                    velocity.values[3 * v + c] = s->velocity[v][c];
            data.push_back(std::move(velocity));
        }
        std::vector<char> near_sheet;
        Components components = s->components;
        const AdaptCounts counts = adapt_surface(mesh, data, settings, near_sheet, s->analysis_workspace, components);
        const std::string broken = invariant_violation(mesh);
        if (!broken.empty())
            fail(Status::internal, ("the adapted mesh is broken (" + broken + "); the surface is unchanged").c_str());

        std::vector<Vec3> velocity;
        if (has_velocity) {
            velocity.resize(mesh.pos.size());
            for (size_t v = 0; v < velocity.size(); ++v)
                velocity[v] = Vec3(data.back().values.data() + 3 * v);
            data.pop_back();
        }
        s->mesh = std::move(mesh);
        s->fields.swap(data);
        s->velocity.swap(velocity);
        s->near_sheet.swap(near_sheet);
        std::swap(s->components, components);
        s->seconds_spent += counts.seconds;
        s->volume_correction = counts.volume_correction;
    });
}

} // extern "C"

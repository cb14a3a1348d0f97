// SPDX-License-Identifier: BSD-3-Clause
// Adaptation: sfa_smooth, sfa_adapt.
#include "api/boundary.hpp"

#include "adapt/adapt.hpp"
#include "adapt/smooth_surface.hpp"
#include "mesh/invariants.hpp"

#include <algorithm>
#include <string>
#include <utility>

using namespace sfa;

namespace {

// A copy of what the host keeps on the surface, in the form smoothing and adaptation carry
// it: the velocities travel as the last vertex field.
SurfaceData carried_data(const sfa_surface *s)
{
    SurfaceData data{s->fields, s->size_field, s->face_fields, s->constraints, {}};
    if (!s->velocity.empty()) {
        VertexField velocity{3, std::vector<double>(3 * s->velocity.size())};
        for (size_t v = 0; v < s->velocity.size(); ++v)
            for (int c = 0; c < 3; ++c)
                velocity.values[3 * v + c] = s->velocity[v][c];
        data.fields.push_back(std::move(velocity));
    }
    return data;
}

// Takes the carried data back into the handle: allocates first, then commits without
// throwing, so that a failure leaves the handle as it was.
void commit(sfa_surface *s, SurfaceData &data)
{
    std::vector<Vec3> velocity;
    if (!s->velocity.empty()) {
        const VertexField &carried = data.fields.back();
        velocity.resize(carried.values.size() / 3);
        for (size_t v = 0; v < velocity.size(); ++v)
            velocity[v] = Vec3(carried.values.data() + 3 * v);
        data.fields.pop_back();
    }
    s->fields.swap(data.fields);
    s->velocity.swap(velocity);
    s->size_field.swap(data.size);
    s->face_fields.swap(data.face_fields);
    std::swap(s->constraints, data.constraints);
}

} // namespace

extern "C" {

SFA_EXPORT int sfa_smooth(sfa_surface *s, int32_t iterations)
{
    return call(s, "sfa_smooth", [&] {
        require(iterations >= 0, "iterations must be >= 0");
        require_mesh(s);
        const SmoothSettings settings = smooth_settings(s->params);
        // Sweeps move vertices only: work on the handle's mesh with its positions saved (the
        // connectivity is not copied, a step of a flow calls this on every step), and on a
        // copy of the host's data; if anything fails, the positions go back.
        TriMesh &mesh = s->mesh;
        std::vector<Vec3> saved_positions = mesh.pos;
        SurfaceData data = carried_data(s);
        SmoothResult result;
        std::vector<Vec3> after;
        try {
            result = smooth_surface(mesh, data, settings, iterations, s->near_sheet, s->analysis_workspace,
                                    s->components);
            after = mesh.pos;
            commit(s, data);
        } catch (...) {
            std::copy(saved_positions.begin(), saved_positions.end(), mesh.pos.begin()); // same size: no allocation
            throw;
        }
        // The origins: the connectivity is the handle's, the positions were saved.
        s->origins.valid = true;
        s->origins.same_connectivity = true;
        s->origins.before = TriMesh(); // only its positions: the handle's mesh has the rest
        s->origins.before.pos.swap(saved_positions);
        s->origins.hints.clear();
        s->origins.after.swap(after);
        s->seconds_spent += result.seconds;
        s->volume_correction = result.volume_correction;
        s->volume_left = result.volume_left;
    });
}

SFA_EXPORT int sfa_adapt(sfa_surface *s)
{
    return call(s, "sfa_adapt", [&] {
        require_mesh(s);
        const AdaptSettings settings = adapt_settings(s->params, s->mean_edge_length_at_set);

        // Work on copies. Commit only at the end.
        TriMesh mesh = s->mesh;
        SurfaceData data = carried_data(s);
        std::vector<char> near_sheet;
        Components components = s->components;
        const AdaptCounts counts = adapt_surface(mesh, data, settings, near_sheet, s->analysis_workspace, components);
        const std::string broken = invariant_violation(mesh);
        if (!broken.empty())
            fail(Status::internal, ("the adapted mesh is broken (" + broken + "); the surface is unchanged").c_str());

        std::vector<Vec3> after = mesh.pos;
        commit(s, data);
        // The mesh as it was stays, for the origins.
        std::swap(s->origins.before, s->mesh);
        s->mesh = std::move(mesh);
        s->origins.valid = true;
        s->origins.same_connectivity = false;
        s->origins.hints.swap(data.origin_hints);
        s->origins.after.swap(after);
        s->counts_set_by = "sfa_adapt";
        s->near_sheet.swap(near_sheet);
        s->collision_blocks = BlockPartition();
        std::swap(s->components, components);
        s->seconds_spent += counts.seconds;
        s->volume_correction = counts.volume_correction;
        s->volume_left = counts.volume_left;
        s->topology = counts.topology;
    });
}

} // extern "C"

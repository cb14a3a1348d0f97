// Adaptation: sfa_smooth, sfa_adapt.
#include "api/analysis_settings.hpp"

#include "adapt/adapt.hpp"
#include "adapt/smooth.hpp"
#include "adapt/volume.hpp"
#include "fields/transfer.hpp"
#include "geometry/measures.hpp"
#include "mesh/invariants.hpp"

#include <algorithm>
#include <string>
#include <utility>

using namespace sfa;

namespace {
// Smoothing sweeps per pass: two let the vertices settle around what repair changed.
constexpr int smoothing_sweeps_per_pass = 2;
} // namespace

extern "C" {

SFA_EXPORT int sfa_smooth(sfa_surface *s, int32_t iterations)
{
    return call(s, "sfa_smooth", [&] {
        require(iterations >= 0, "iterations must be >= 0");
        require_mesh(s);
        // Sweeps move vertices only: work on the handle's mesh with its positions saved (the
        // connectivity is not copied, a step of a flow calls this on every step), and on a
        // copy of the fields; if anything fails, the positions go back.
        TriMesh &mesh = s->mesh;
        const std::vector<Vec3> saved_positions = mesh.pos;
        std::vector<VertexField> fields = s->fields;
        PhaseTimes seconds;
        try {
            const double volume = enclosed_volume(mesh);
            const bool closed = mesh.is_closed();
            // The last adaptation's findings where there was one (a flow adapts every few
            // steps, and a sheet thins slowly), else this surface's own.
            CrossingGuard guard;
            CrossingGuard *const guarded = s->params.get(Param::crossing_guard) != 0 ? &guard : nullptr;
            if (guarded)
                guard = timed(seconds.analysis, [&] {
                    return CrossingGuard(s->near_sheet.size() == mesh.pos.size() ? s->near_sheet
                                                                                 : near_facing_sheet(mesh));
                });
            const FeatureThresholds thresholds = feature_thresholds(s->params);
            const MetricBounds bounds = metric_bounds(s->params);
            SurfaceAnalysis &analysis = s->analysis_workspace;
            for (int32_t sweep = 0; sweep < iterations; ++sweep) {
                timed(seconds.analysis, [&] { analyze_surface(mesh, thresholds, bounds, analysis); });
                PhaseClock clock(seconds.smoothing);
                std::vector<Vec3> moved = smoothing_sweep(mesh, analysis, s->params.get(Param::denoise), guarded);
                fields = fields_at_moved_vertices(mesh, moved, fields);
                mesh.pos.swap(moved);
                if (closed)
                    restore_enclosed_volume(mesh, analysis.features.rank, volume);
            }
        } catch (...) {
            std::copy(saved_positions.begin(), saved_positions.end(), mesh.pos.begin()); // same size: no allocation
            throw;
        }
        s->fields.swap(fields);
        s->seconds_spent += seconds;
    });
}

SFA_EXPORT int sfa_adapt(sfa_surface *s)
{
    return call(s, "sfa_adapt", [&] {
        require_mesh(s);
        const Parameters &p = s->params;
        const double edge_length = p.get(Param::edge_length) > 0 ? p.get(Param::edge_length) : s->mean_edge_length_at_set;
        const AdaptSettings settings{feature_thresholds(p), metric_bounds(p), p.get(Param::flip_dihedral_angle) * radians,
                                     repair_settings(p, edge_length), static_cast<int>(p.get(Param::adapt_passes)),
                                     smoothing_sweeps_per_pass,
                                     p.get(Param::denoise),
                                     p.get(Param::crossing_guard) != 0};

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
        const AdaptCounts counts = adapt_surface(mesh, data, settings, near_sheet, s->analysis_workspace);
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
        s->seconds_spent += counts.seconds;
    });
}

} // extern "C"

// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/smooth_surface.hpp"

#include "adapt/carried_face_fields.hpp"
#include "adapt/size_field.hpp"
#include "adapt/smooth.hpp"
#include "adapt/volume.hpp"
#include "fields/carried_fields.hpp"

#include <algorithm>

namespace sfa {

SmoothResult smooth_surface(TriMesh &mesh, SurfaceData &data, const SmoothSettings &settings,
                            int32_t sweeps, const std::vector<char> &near_sheet, SurfaceAnalysis &workspace,
                            const Components &components)
{
    SmoothResult result;
    PhaseTimes &seconds = result.seconds;
    // Each component keeps its own volume (the connectivity does not change).
    const std::vector<double> volumes = component_volumes(mesh, components.of_vertex, components.count);
    CrossingGuard guard;
    if (settings.crossing_guard)
        guard = timed(seconds.analysis, [&] {
            return CrossingGuard(near_sheet.size() == mesh.pos.size() ? near_sheet : near_facing_sheet(mesh));
        });
    const SizeAsField size(mesh, data, 0); // interpolated as it is
    MeshEdit edit(mesh);
    CarriedFields carried_fields(data.fields);
    edit.attach(carried_fields);
    const CarriedFaceFields face_fields(edit, data.face_fields); // remapped by overlap
    const CarriedConstraints constraints(mesh, data.constraints); // nothing changes them here
    SurfaceAnalysis &analysis = workspace;
    for (int32_t sweep = 0; sweep < sweeps; ++sweep) {
        timed(seconds.analysis, [&] {
            analyze_surface(mesh, settings.features, settings.metric, analysis);
            constraints.impose_on(analysis.features.rank);
        });
        if (settings.crossing_guard)
            guard.watch_features(analysis.features.rank);
        PhaseClock clock(seconds.smoothing);
        std::vector<Vec3> moved =
            smoothing_sweep(mesh, analysis, settings.denoise, settings.crossing_guard ? &guard : nullptr);
        edit.move(moved);
        const VolumeRestoration restored = restore_enclosed_volumes(
            edit, analysis.features.rank, components.of_vertex, volumes, components.closed, settings.volume_correction,
            settings.crossing_guard ? &guard : nullptr);
        result.volume_correction = std::max(result.volume_correction, restored.largest_change);
        // Sweep after sweep, what one left uncorrected stays: the volumes are the call's.
        result.volume_left = std::max(result.volume_left, restored.largest_left);
    }
    return result;
}

} // namespace sfa

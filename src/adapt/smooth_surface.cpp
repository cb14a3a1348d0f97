#include "adapt/smooth_surface.hpp"

#include "adapt/smooth.hpp"
#include "adapt/volume.hpp"
#include "fields/carried_fields.hpp"
#include "geometry/measures.hpp"

namespace sfa {

PhaseTimes smooth_surface(TriMesh &mesh, std::vector<VertexField> &fields, const SmoothSettings &settings,
                          int32_t sweeps, const std::vector<char> &near_sheet, SurfaceAnalysis &workspace)
{
    PhaseTimes seconds;
    const double volume = enclosed_volume(mesh);
    const bool closed = mesh.is_closed();
    CrossingGuard guard;
    if (settings.crossing_guard)
        guard = timed(seconds.analysis, [&] {
            return CrossingGuard(near_sheet.size() == mesh.pos.size() ? near_sheet : near_facing_sheet(mesh));
        });
    MeshEdit edit(mesh);
    CarriedFields carried_fields(fields);
    edit.attach(carried_fields);
    SurfaceAnalysis &analysis = workspace;
    for (int32_t sweep = 0; sweep < sweeps; ++sweep) {
        timed(seconds.analysis, [&] { analyze_surface(mesh, settings.features, settings.metric, analysis); });
        PhaseClock clock(seconds.smoothing);
        std::vector<Vec3> moved =
            smoothing_sweep(mesh, analysis, settings.denoise, settings.crossing_guard ? &guard : nullptr);
        edit.move(moved);
        if (closed)
            restore_enclosed_volume(mesh, analysis.features.rank, volume);
    }
    return seconds;
}

} // namespace sfa

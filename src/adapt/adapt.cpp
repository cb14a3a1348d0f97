#include "adapt/adapt.hpp"

#include "adapt/carried_features.hpp"
#include "adapt/contract.hpp"
#include "adapt/flip.hpp"
#include "adapt/smooth.hpp"
#include "adapt/split.hpp"
#include "adapt/volume.hpp"
#include "fields/carried_fields.hpp"
#include "geometry/guard_listener.hpp"
#include "geometry/measures.hpp"
#include "geometry/tracked_analysis.hpp"

namespace sfa {
namespace {
constexpr double settled_fraction = 1e-2;
} // namespace

AdaptCounts adapt_surface(TriMesh &mesh, std::vector<VertexField> &fields, const AdaptSettings &settings,
                          std::vector<char> &near_sheet, SurfaceAnalysis &workspace)
{
    AdaptCounts counts;
    PhaseTimes &seconds = counts.seconds;
    // Features are detected once; the geometry is analysed in full where every vertex has
    // moved (at the start and after each sweep). After splitting, contraction and flipping
    // only the vertices whose fans changed are analysed anew (tracked_analysis.hpp): the
    // same result as a full analysis, for a fraction of its cost.
    SurfaceAnalysis &geometry = workspace;
    timed(seconds.analysis, [&] { analyze_surface(mesh, settings.features, settings.metric, geometry); });

    // Everything that lives on the mesh follows every change of the edit.
    MeshEdit edit(mesh);
    CarriedFields carried_fields(fields);
    CarriedFeatures features(geometry.features);
    TrackedAnalysis tracked(geometry, mesh);
    edit.attach(carried_fields);
    edit.attach(features);
    edit.attach(tracked);
    // Where the surface is thinner than an edge, no step may carry it through itself.
    CrossingGuard guard;
    GuardListener guard_listener(guard);
    if (settings.crossing_guard) {
        guard = timed(seconds.analysis, [&] { return CrossingGuard(near_facing_sheet(mesh)); });
        edit.attach(guard_listener);
    }
    const PassContext context{edit, features, settings.crossing_guard ? &guard : nullptr};

    const auto analyse_all = [&] {
        PhaseClock clock(seconds.analysis);
        analyze_geometry(mesh, settings.metric, geometry);
        geometry.features = features.as_features(mesh);
        tracked.mark_current();
    };
    const auto analyse_changed = [&] {
        PhaseClock clock(seconds.analysis);
        tracked.update(mesh, settings.metric);
        geometry.features = features.as_features(mesh);
    };
    const bool closed = mesh.is_closed();
    const double volume = enclosed_volume(mesh);
    while (counts.passes < settings.max_passes) {
        if (++counts.passes > 1)
            analyse_all(); // the last pass's sweeps moved every vertex
        // Repair first (§4): the density the desired edge length asks for, and no extreme
        // angles; then optimization (§3) of the repaired mesh.
        const int32_t splits = timed(seconds.repair, [&] { return splitting_pass(context, settings.repair); });
        analyse_changed();
        const int32_t contractions = timed(seconds.repair, [&] {
            const int32_t made = contraction_pass(context, geometry, settings.repair);
            edit.compact();
            return made;
        });
        analyse_changed();
        const int32_t flips = timed(seconds.flipping, [&] { return flipping_pass(context, geometry, settings.flip); });
        analyse_changed();
        for (int sweep = 0; sweep < settings.smoothing_sweeps; ++sweep) {
            if (sweep > 0)
                analyse_all();
            PhaseClock clock(seconds.smoothing);
            std::vector<Vec3> moved =
                smoothing_sweep(mesh, geometry, settings.denoise, settings.crossing_guard ? &guard : nullptr);
            edit.move(moved);
        }
        counts.splits += splits;
        counts.contractions += contractions;
        counts.flips += flips;
        // Settled: after the first pass or two, the changes of a pass dwindle to a few edges
        // in a thousand (on a dynamic surface, the second pass of a call changes about 0.5 %
        // of the vertices, the later ones each half of that), and every pass costs four
        // analyses and two sweeps of the whole mesh. The next call (a dynamic surface is
        // adapted every few steps) picks up what is left.
        if (splits + contractions + flips <= settled_fraction * mesh.num_vertices())
            break;
    }
    if (closed) {
        // The offset moves vertices along their normals, not over the surface: their fields
        // stay with them.
        PhaseClock clock(seconds.smoothing);
        restore_enclosed_volume(mesh, features.ranks(), volume);
    }
    // New vertices and triangles were appended where they were made: put neighbours next
    // to each other in memory again, for every loop until the next adaptation. Only what
    // outlives the call follows.
    if (counts.splits + counts.contractions > 0) {
        PhaseClock clock(seconds.repair);
        edit.detach(tracked);
        edit.detach(features);
        edit.order_for_locality();
    }
    near_sheet = settings.crossing_guard ? guard.watched() : std::vector<char>();
    return counts;
}

} // namespace sfa

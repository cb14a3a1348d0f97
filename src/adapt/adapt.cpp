#include "adapt/adapt.hpp"

#include "adapt/carried_features.hpp"

#include "adapt/contract.hpp"
#include "adapt/smooth.hpp"
#include "adapt/split.hpp"
#include "adapt/volume.hpp"
#include "fields/transfer.hpp"
#include "geometry/measures.hpp"
#include "mesh/locality_order.hpp"

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
    // only the vertices whose fans changed are analysed anew (update_geometry): the same
    // result as a full analysis, for a fraction of its cost.
    SurfaceAnalysis &geometry = workspace;
    timed(seconds.analysis, [&] { analyze_surface(mesh, settings.features, settings.metric, geometry); });
    CarriedFeatures features(geometry.features);
    std::vector<char> changed;
    const auto analyse_all = [&] {
        PhaseClock clock(seconds.analysis);
        analyze_geometry(mesh, settings.metric, geometry);
        geometry.features = features.as_features(mesh);
    };
    const auto analyse_changed = [&] {
        PhaseClock clock(seconds.analysis);
        update_geometry(mesh, changed, settings.metric, geometry);
        geometry.features = features.as_features(mesh);
        changed.assign(mesh.pos.size(), 0);
    };
    // Where the surface is thinner than an edge, no step may carry it through itself.
    CrossingGuard guard;
    CrossingGuard *const guarded = settings.crossing_guard ? &guard : nullptr;
    if (guarded)
        guard = timed(seconds.analysis, [&] { return CrossingGuard(near_facing_sheet(mesh)); });
    const bool closed = mesh.is_closed();
    const double volume = enclosed_volume(mesh);
    while (counts.passes < settings.max_passes) {
        if (++counts.passes > 1)
            analyse_all(); // the last pass's sweeps moved every vertex
        changed.assign(mesh.pos.size(), 0);
        // Repair first (§4): the density the desired edge length asks for, and no extreme
        // angles; then optimization (§3) of the repaired mesh.
        const int32_t splits = timed(seconds.repair, [&] {
            return splitting_pass(mesh, settings.repair, features, fields, changed, guarded);
        });
        analyse_changed();
        const int32_t contractions = timed(seconds.repair, [&] {
            return contraction_pass(mesh, geometry, settings.repair, features, fields, changed, guarded);
        });
        analyse_changed();
        const int32_t flips = timed(seconds.flipping, [&] {
            const FlipSettings flip_settings{settings.metric, settings.flip_max_dihedral};
            return flipping_pass(mesh, geometry, flip_settings, &changed, guarded);
        });
        analyse_changed();
        for (int sweep = 0; sweep < settings.smoothing_sweeps; ++sweep) {
            if (sweep > 0)
                analyse_all();
            PhaseClock clock(seconds.smoothing);
            std::vector<Vec3> moved = smoothing_sweep(mesh, geometry, settings.denoise, guarded);
            fields = fields_at_moved_vertices(mesh, moved, fields);
            mesh.pos.swap(moved);
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
        PhaseClock clock(seconds.smoothing);
        restore_enclosed_volume(mesh, features.rank, volume);
    }
    // New vertices and triangles were appended where they were made: put neighbours next
    // to each other in memory again, for every loop until the next adaptation.
    if (counts.splits + counts.contractions > 0) {
        PhaseClock clock(seconds.repair);
        const std::vector<int32_t> vertex_map = order_for_locality(mesh);
        renumber_fields(fields, vertex_map);
        if (guarded)
            guard.renumber(vertex_map);
    }
    near_sheet = guarded ? guard.watched() : std::vector<char>();
    return counts;
}

} // namespace sfa

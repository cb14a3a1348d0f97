#include "adapt/adapt.hpp"

#include "adapt/carried_features.hpp"

#include "adapt/contract.hpp"
#include "adapt/smooth.hpp"
#include "adapt/split.hpp"
#include "adapt/volume.hpp"
#include "fields/transfer.hpp"
#include "geometry/measures.hpp"

namespace sfa {
namespace {
constexpr double settled_fraction = 2e-3;
} // namespace

AdaptCounts adapt_surface(TriMesh &mesh, std::vector<VertexField> &fields, const AdaptSettings &settings)
{
    AdaptCounts counts;
    CarriedFeatures features(analyze_surface(mesh, settings.features, settings.metric).features);
    // The geometry of the mesh as it now is, with the carried features.
    const auto analysis = [&] {
        SurfaceAnalysis a = analyze_geometry(mesh, settings.metric);
        a.features = features.as_features(mesh);
        return a;
    };
    const bool closed = mesh.is_closed();
    const double volume = enclosed_volume(mesh);
    while (counts.passes < settings.max_passes) {
        ++counts.passes;
        // Repair first (§4): the density the desired edge length asks for, and no extreme
        // angles; then optimization (§3) of the repaired mesh.
        const int32_t splits = splitting_pass(mesh, settings.repair, features, fields);
        const int32_t contractions = contraction_pass(mesh, analysis(), settings.repair, features, fields);
        const int32_t flips = flipping_pass(mesh, analysis(), FlipSettings{settings.metric, settings.flip_max_dihedral});
        for (int sweep = 0; sweep < settings.smoothing_sweeps; ++sweep) {
            std::vector<Vec3> moved = smoothing_sweep(mesh, analysis());
            fields = fields_at_moved_vertices(mesh, moved, fields);
            mesh.pos.swap(moved);
        }
        counts.splits += splits;
        counts.contractions += contractions;
        counts.flips += flips;
        // Settled: after the first passes, the changes of a pass dwindle to a few edges
        // that flip or split back and forth (a few in ten thousand); the next call (a
        // dynamic surface is adapted every few steps) picks up what is left.
        if (splits + contractions + flips <= settled_fraction * mesh.num_vertices())
            break;
    }
    if (closed)
        restore_enclosed_volume(mesh, features.rank, volume);
    return counts;
}

} // namespace sfa

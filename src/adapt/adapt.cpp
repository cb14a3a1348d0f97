// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/adapt.hpp"

#include "adapt/carried_face_fields.hpp"
#include "adapt/carried_features.hpp"
#include "adapt/contract.hpp"
#include "adapt/flip.hpp"
#include "adapt/size_field.hpp"
#include "adapt/smooth.hpp"
#include "adapt/split.hpp"
#include "adapt/thin_sheet_sizes.hpp"
#include "adapt/topology_change.hpp"
#include "adapt/volume.hpp"
#include "fields/carried_fields.hpp"
#include "fields/vertex_origins.hpp"
#include "geometry/guard_listener.hpp"
#include "geometry/tracked_analysis.hpp"
#include "mesh/vertex_labels.hpp"

namespace sfa {
namespace {

constexpr double settled_fraction = 1e-2;

// One sfa_adapt call: the edit, and everything attached to it that follows its changes.
class Adaptation {
public:
    // `size`: the graded desired length of every vertex, the last of data.fields (or null).
    // `origin_hints`: per vertex, a triangle of the mesh as the call found it.
    // `near_sheet`: near_facing_sheet(mesh) if the crossing guard is on.
    Adaptation(TriMesh &mesh, SurfaceData &data, const std::vector<double> *size, const AdaptSettings &settings,
               SurfaceAnalysis &workspace, const Components &components, std::vector<int32_t> origin_hints,
               std::vector<char> near_sheet, PhaseTimes &seconds)
        : mesh_(mesh), settings_(settings), seconds_(seconds), geometry_(workspace), edit_(mesh),
          carried_fields_(data.fields), face_fields_(edit_, data.face_fields), origins_(std::move(origin_hints)),
          size_(size),
          constraints_(mesh, data.constraints), features_(detected_features()), tracked_(geometry_, mesh),
          guard_listener_(guard_), closed_(components.closed), component_of_(components.of_vertex),
          volumes_(component_volumes(mesh, components.of_vertex, components.count))
    {
        edit_.attach(carried_fields_);
        edit_.attach(origins_);
        if (!data.constraints.empty())
            edit_.attach(constraints_);
        edit_.attach(features_);
        edit_.attach(tracked_);
        edit_.attach(component_of_);
        // Where the surface is thinner than an edge, no step may carry it through itself.
        if (settings.crossing_guard) {
            guard_ = CrossingGuard(std::move(near_sheet));
            guard_.watch_features(features_.ranks());
            edit_.attach(guard_listener_);
        }
    }

    // Split, contract, flip, then smooth; returns the number of splits, contractions and
    // flips it made, and adds them to `counts`.
    int32_t pass(AdaptCounts &counts);

    // Each closed component's enclosed volume back and, if the connectivity changed, the
    // locality order; the vertices the guard watched, numbered as the mesh is now.
    std::vector<char> finish(AdaptCounts &counts);
    // A triangle of the mesh the call found near each vertex (vertex_origins.hpp).
    const std::vector<int32_t> &origin_hints() const { return origins_.hints(); }
    // What the host pinned, numbered as the mesh is now.
    Constraints constraints() const { return constraints_.as_host(mesh_); }
    // The components of the mesh as it is now, numbered and indexed.
    Components components() const
    {
        Components components;
        components.count = static_cast<int32_t>(closed_.size());
        components.of_vertex = component_of_.labels();
        components.closed = closed_;
        index_components(mesh_, components);
        return components;
    }

private:
    // The crossing guard, or null when it is off.
    CrossingGuard *guard() { return settings_.crossing_guard ? &guard_ : nullptr; }

    // Features are detected once, at the start, where the geometry is analysed in full.
    // After every split, contraction, flip and sweep only the vertices whose fans changed
    // are analysed anew (tracked_analysis.hpp): the same result as a full analysis, for a
    // fraction of its cost (a sweep leaves the settled fans alone). Fixed vertices are
    // carried as corners.
    const Features &detected_features()
    {
        timed(seconds_.analysis, [&] { analyze_surface(mesh_, settings_.features, settings_.metric, geometry_); });
        constraints_.impose_on(geometry_.features.rank);
        return geometry_.features;
    }
    void analyse_changed()
    {
        PhaseClock clock(seconds_.analysis);
        tracked_.update(mesh_, settings_.metric);
        geometry_.features = features_.as_features(mesh_);
    }

    TriMesh &mesh_;
    const AdaptSettings &settings_;
    PhaseTimes &seconds_;
    SurfaceAnalysis &geometry_;
    MeshEdit edit_;
    CarriedFields carried_fields_;
    CarriedFaceFields face_fields_;
    OriginHints origins_;
    const std::vector<double> *size_;
    CarriedConstraints constraints_; // before features_, which it shapes
    CarriedFeatures features_;
    TrackedAnalysis tracked_;
    CrossingGuard guard_;
    GuardListener guard_listener_;
    // Each component keeps its own volume: the components as the call found them, followed
    // through every change (a vertex's component never changes: no change of topology).
    const std::vector<char> closed_;
    VertexLabels component_of_;
    const std::vector<double> volumes_;
};

int32_t Adaptation::pass(AdaptCounts &counts)
{
    if (++counts.passes > 1)
        analyse_changed(); // the last pass's sweeps
    const PassContext context{edit_, features_, guard(), constraints_, size_};
    // Repair first (§4): the density the desired edge length asks for, and no extreme
    // angles; then optimization (§3) of the repaired mesh.
    const int32_t splits = timed(seconds_.repair, [&] { return splitting_pass(context, geometry_, settings_.repair); });
    analyse_changed();
    const int32_t contractions = timed(seconds_.repair, [&] {
        const int32_t made = contraction_pass(context, geometry_, settings_.repair, counts.clearance_tests);
        edit_.compact();
        return made;
    });
    analyse_changed();
    const int32_t flips = timed(seconds_.flipping, [&] { return flipping_pass(context, geometry_, settings_.flip); });
    analyse_changed();
    for (int sweep = 0; sweep < settings_.smoothing_sweeps; ++sweep) {
        if (sweep > 0)
            analyse_changed();
        PhaseClock clock(seconds_.smoothing);
        std::vector<Vec3> moved = smoothing_sweep(mesh_, geometry_, settings_.denoise, guard());
        edit_.move(moved);
    }
    counts.splits += splits;
    counts.contractions += contractions;
    counts.flips += flips;
    return splits + contractions + flips;
}

std::vector<char> Adaptation::finish(AdaptCounts &counts)
{
    {
        // The offsets move vertices along their normals, not over the surface: their fields
        // stay with them.
        PhaseClock clock(seconds_.smoothing);
        const VolumeRestoration restored = restore_enclosed_volumes(
            edit_, features_.ranks(), component_of_.labels(), volumes_, closed_, settings_.volume_correction, guard());
        counts.volume_correction = restored.largest_change;
        counts.volume_left = restored.largest_left;
    }
    // New vertices and triangles were appended where they were made: put neighbours next
    // to each other in memory again, for every loop until the next adaptation. Only what
    // outlives the call follows.
    if (counts.splits + counts.contractions > 0) {
        PhaseClock clock(seconds_.repair);
        edit_.detach(tracked_);
        edit_.detach(features_);
        edit_.order_for_locality();
    }
    return settings_.crossing_guard ? guard_.watched() : std::vector<char>();
}

} // namespace

AdaptCounts adapt_surface(TriMesh &mesh, SurfaceData &data, const AdaptSettings &settings,
                          std::vector<char> &near_sheet, SurfaceAnalysis &workspace, Components &components)
{
    AdaptCounts counts;
    std::vector<int32_t> origin_hints = OriginHints(mesh).hints();
    if (settings.topology_change) {
        PhaseClock clock(counts.seconds.repair);
        counts.topology = change_topology(mesh, data, components, settings.merge_distance,
                                          settings.repair.desired_length, origin_hints);
    }
    // The vertices near a facing sheet, for the crossing guard and the finer sizes there.
    std::vector<char> near_facing;
    if (settings.crossing_guard || settings.thin_sheet_edge_ratio < 1)
        near_facing = timed(counts.seconds.analysis, [&] { return near_facing_sheet(mesh); });
    const ThinSheetSizes thin_sheets(mesh, data, near_facing, settings.thin_sheet_edge_ratio,
                                     settings.repair.desired_length);
    const SizeAsField size(mesh, data, settings.size_gradation);
    Adaptation adaptation(mesh, data, size.values(), settings, workspace, components, std::move(origin_hints),
                          settings.crossing_guard ? std::move(near_facing) : std::vector<char>(), counts.seconds);
    while (counts.passes < settings.max_passes) {
        // Settled: after the first pass or two, the changes of a pass dwindle to a few edges
        // in a thousand (on a dynamic surface, the second pass of a call changes about 0.5 %
        // of the vertices, the later ones each half of that), and every pass costs four
        // analyses and two sweeps of the whole mesh. The next call (a dynamic surface is
        // adapted every few steps) picks up what is left.
        if (adaptation.pass(counts) <= settled_fraction * mesh.num_vertices())
            break;
    }
    near_sheet = adaptation.finish(counts);
    components = adaptation.components();
    data.origin_hints = adaptation.origin_hints();
    if (!data.constraints.empty())
        data.constraints = adaptation.constraints();
    return counts;
}

} // namespace sfa

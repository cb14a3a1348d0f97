// SPDX-License-Identifier: BSD-3-Clause
// The host's size field (sfa_set_size_field): a desired edge length l per vertex, in place
// of the one global l of §4.3, from which every threshold of mesh repair is derived. An
// edge's l is the mean of its ends'. Before an adaptation uses them the sizes are graded,
// so that the mesh can follow them without slivers where they jump: along any path over
// the mesh, l may grow by at most (gradation - 1) times the distance travelled,
//     l_v <= l_w + (gradation - 1) |x_v - x_w|,
// so neighbouring edges of the desired length differ by at most the factor `gradation`
// (MMG's hgrad has the same meaning). Grading only ever lowers a size: where the host
// asks for fine edges it gets them, and the coarse side starts coarsening a short way off.
#pragma once

#include "adapt/settings.hpp"
#include "adapt/surface_data.hpp"
#include "mesh/tri_mesh.hpp"

#include <vector>

namespace sfa {

// The smallest sizes not above `size` that satisfy the gradation bound over the mesh's
// edges: l_v = min over w of (size_w + (gradation - 1) d(v, w)), d the length of the
// shortest path of edges, by Dijkstra's algorithm from every vertex at once (each vertex
// is settled once: O(n log n)).
std::vector<double> graded_sizes(const TriMesh &mesh, std::vector<double> size, double gradation);

// For as long as it lives, the size field of `data` (if it has one) travels as the last of
// data.fields, interpolated like any vertex field; then it is data.size again. With
// `gradation` > 0 it is graded first (sfa_adapt; the grading stays: it only lowers sizes,
// and grading a graded field changes nothing); smoothing carries it as it is (0).
class SizeAsField {
public:
    SizeAsField(const TriMesh &mesh, SurfaceData &data, double gradation) : data_(data), sized_(!data.size.empty())
    {
        if (sized_)
            data.fields.push_back(
                {1, gradation > 0 ? graded_sizes(mesh, std::move(data.size), gradation) : std::move(data.size)});
    }
    ~SizeAsField()
    {
        if (!sized_)
            return;
        data_.size.swap(data_.fields.back().values);
        data_.fields.pop_back();
    }
    SizeAsField(const SizeAsField &) = delete;
    SizeAsField &operator=(const SizeAsField &) = delete;

    // The desired length of every vertex as the edit carries it, or null without a size
    // field (a reference that stays valid: carried_fields.hpp).
    const std::vector<double> *values() const { return sized_ ? &data_.fields.back().values : nullptr; }

private:
    SurfaceData &data_;
    const bool sized_;
};

// The thresholds of `settings` for the desired length l instead of its own: every length
// scales with l, the ratios and angles stay.
RepairSettings repair_at_length(const RepairSettings &settings, double l);

// The thresholds for one edge: those of the global l, or of the edge's own l where a size
// field is set.
class LocalRepair {
public:
    // `size`: per vertex (graded), or null for the global l of `settings`.
    LocalRepair(const RepairSettings &settings, const std::vector<double> *size) : settings_(settings), size_(size) {}

    RepairSettings at_edge(const TriMesh &mesh, int32_t h) const
    {
        if (!size_)
            return settings_;
        return repair_at_length(settings_, ((*size_)[mesh.tail(h)] + (*size_)[mesh.head(h)]) / 2);
    }
private:
    const RepairSettings &settings_;
    const std::vector<double> *size_;
};

} // namespace sfa

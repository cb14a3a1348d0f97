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
#include "mesh/tri_mesh.hpp"

#include <vector>

namespace sfa {

// The smallest sizes not above `size` that satisfy the gradation bound over the mesh's
// edges: l_v = min over w of (size_w + (gradation - 1) d(v, w)), d the length of the
// shortest path of edges, by Dijkstra's algorithm from every vertex at once (each vertex
// is settled once: O(n log n)).
std::vector<double> graded_sizes(const TriMesh &mesh, std::vector<double> size, double gradation);

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

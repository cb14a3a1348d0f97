// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/tracked_analysis.hpp"

namespace sfa {

void TrackedAnalysis::update(const TriMesh &mesh, const MetricBounds &bounds)
{
    update_geometry(mesh, changed_.marks(), bounds, analysis_);
    changed_.clear();
}

void TrackedAnalysis::renumber(const Renumbering &renumbering)
{
    changed_.renumber(renumbering);
    if (renumbering.keeps_order) {
        renumber_vertices(analysis_, renumbering.vertex_map); // in place
        return;
    }
    renumbering.apply_to_vertices(analysis_.quadric);
    renumbering.apply_to_vertices(analysis_.eigen);
    renumbering.apply_to_vertices(analysis_.metric);
}

} // namespace sfa

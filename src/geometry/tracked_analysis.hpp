// SPDX-License-Identifier: BSD-3-Clause
// The partial re-analysis as a listener of an edit: it hears which vertices' fans each
// split, contraction, flip or sweep changed, keeps the analysis's per-vertex entries
// numbered as the mesh through compaction, and brings the geometry up to date for the
// marked vertices only (update_geometry): the same result as a full analysis, for a
// fraction of its cost.
#pragma once

#include "geometry/analysis.hpp"
#include "mesh/changed_vertices.hpp"

namespace sfa {

class TrackedAnalysis : public EditListener {
public:
    // `analysis` must be the analysis of `mesh` as it is now.
    TrackedAnalysis(SurfaceAnalysis &analysis, const TriMesh &mesh) : analysis_(analysis), changed_(mesh.num_vertices()) {}

    const SurfaceAnalysis &analysis() const { return analysis_; }
    // The geometry of the vertices marked since the last call analysed anew; features are
    // left as they are.
    void update(const TriMesh &mesh, const MetricBounds &bounds);

    void split(const TriMesh &mesh, const SplitChange &change) override { changed_.split(mesh, change); }
    void collapse(const TriMesh &mesh, const CollapseChange &change) override { changed_.collapse(mesh, change); }
    void flip(const TriMesh &mesh, const FlipChange &change) override { changed_.flip(mesh, change); }
    void move(const TriMesh &mesh, const MoveChange &change) override { changed_.move(mesh, change); }
    void renumber(const Renumbering &renumbering) override;

private:
    SurfaceAnalysis &analysis_;
    ChangedVertices changed_;
};

} // namespace sfa

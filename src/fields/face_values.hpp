// SPDX-License-Identifier: BSD-3-Clause
// Values living on the triangles: ncomp densities per unit area per triangle (what host
// face fields, such as a surfactant concentration, will be), carried through every change
// of an edit as a conservative remap by overlap (geometry/overlap.hpp), each change local
// to its own fan, so that each keeps the integral of every component over the faces it
// changes exactly (to round-off), and with it the integral over every connected component:
// - a split triangle's halves share its integral in proportion to their areas (they are
//   exactly its overlap);
// - a flipped pair's new faces take the old pair's densities by overlap, in a chart normal
//   to the pair (the quad's outline does not change);
// - a contraction's surviving faces around the kept vertex take, by overlap, the densities
//   of the faces that were around the edge, in a chart normal to those;
// - a smoothing sweep remaps vertex by vertex in index order: v's fan with v where it was
//   onto its fan with v where it goes, the other corners where the sweep has put them so
//   far (Gauss-Seidel inside this listener only; the mesh moves at once);
// - an offset (the volume correction, off the surface) leaves each face its own integral.
// A fan that turns over in its chart is shared by area instead: conservative, but smeared
// to its mean (shared_remaps() counts them). Compaction and renumbering move the values
// with their triangles. A host's own motion of the surface is not an edit: it leaves the
// densities as they are.
#pragma once

#include "geometry/overlap.hpp"
#include "mesh/mesh_edit.hpp"

#include <utility>
#include <vector>

namespace sfa {

class FaceValues : public EditListener {
public:
    // values[ncomp * t + c]: component c on triangle t.
    FaceValues(int32_t ncomp, std::vector<double> values) : ncomp_(ncomp), values_(std::move(values)) {}

    int32_t components() const { return ncomp_; }
    double value(int32_t t, int32_t c) const { return values_[static_cast<size_t>(ncomp_) * t + c]; }
    const std::vector<double> &values() const { return values_; }
    // The values, moved out (the listener is done with).
    std::vector<double> take_values() { return std::move(values_); }
    // How many remaps of a fan fell back to sharing by area (RemapPath::shared).
    int64_t shared_remaps() const { return shared_remaps_; }

    void split(const TriMesh &mesh, const SplitChange &change) override;
    void flip(const TriMesh &mesh, const FlipChange &change) override;
    void before_collapse(const TriMesh &mesh, int32_t h) override;
    void collapse(const TriMesh &mesh, const CollapseChange &change) override;
    void move(const TriMesh &mesh, const MoveChange &change) override;
    void offset(const TriMesh &mesh, const std::vector<Vec3> &positions) override;
    void renumber(const Renumbering &renumbering) override
    {
        renumbering.apply(values_, renumbering.triangle_map, static_cast<size_t>(ncomp_));
    }

private:
    double &at(int32_t t, int32_t c) { return values_[static_cast<size_t>(ncomp_) * t + c]; }
    // Remembers face t, with these corners, as one of the old faces of the fan to remap.
    void add_old(int32_t t, const Corners &corners);
    // Remaps the old faces onto faces_ (with corners new_corners_) in the chart normal to
    // `normal`, and stores the result on faces_.
    void remap_fan(const Vec3 &normal);

    int32_t ncomp_;
    std::vector<double> values_;
    int64_t shared_remaps_ = 0;
    // The fan being remapped; kept between changes so that their storage is reused.
    std::vector<Corners> old_corners_, new_corners_;
    std::vector<double> old_values_, new_values_;
    std::vector<int32_t> faces_;
    Vec3 collapse_normal_ = Vec3::Zero(); // of the faces around a contracted edge, before
    std::vector<Vec3> sweep_;             // the positions of a sweep so far
};

} // namespace sfa

// Values living on the triangles: ncomp densities per unit area per triangle (what host
// face fields, such as a surfactant concentration, will be), carried through every change
// of an edit so that each change keeps the integral of every component over the faces it
// changes: a split triangle's halves share its integral in proportion to their areas, a
// flipped pair's new faces share the pair's integral, and a contraction's surviving faces
// around the merged vertex take the integral the faces around the edge had (every density
// there scaled by one factor). Compaction and renumbering move the values with their
// triangles.
#pragma once

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

    void split(const TriMesh &mesh, const SplitChange &change) override;
    void flip(const TriMesh &mesh, const FlipChange &change) override;
    void before_collapse(const TriMesh &mesh, int32_t h) override;
    void collapse(const TriMesh &mesh, const CollapseChange &change) override;
    void renumber(const Renumbering &renumbering) override
    {
        renumbering.apply(values_, renumbering.triangle_map, static_cast<size_t>(ncomp_));
    }

private:
    double &at(int32_t t, int32_t c) { return values_[static_cast<size_t>(ncomp_) * t + c]; }

    int32_t ncomp_;
    std::vector<double> values_;
    std::vector<double> integral_before_; // per component, over the faces around a contracted edge
};

} // namespace sfa

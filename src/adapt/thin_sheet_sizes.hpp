// SPDX-License-Identifier: BSD-3-Clause
// Finer edges where a sheet is thinner than an edge (SFA_PARAM_THIN_SHEET_EDGE_RATIO). There
// the two sides of the sheet come nearer than their edges, and a triangle spanning the
// sheet's rim must bend round something smaller than itself: its angles collapse, and the
// shape error it makes stays on the surface after the sheet has opened up again (the
// vortex flow with T = 6, doc/flows.md). Asking for shorter edges there lets the mesh
// follow the sheet as it thins. The vertices are those the crossing guard watches for a
// facing sheet (near_facing_sheet), found anyway.
#pragma once

#include "adapt/surface_data.hpp"
#include "mesh/tri_mesh.hpp"

#include <algorithm>
#include <vector>

namespace sfa {

// For as long as it lives, data.size holds the sizes the adaptation asks for: the host's
// size field, or l everywhere without one, times `ratio` at the vertices near a facing sheet
// (near_sheet[v] != 0). The host's own field travels meanwhile as the last of data.fields,
// carried through the changes like any vertex field, and is data.size again afterwards;
// without one, data.size is empty again. With `ratio` 1, or no vertex near a facing sheet,
// it does nothing.
class ThinSheetSizes {
public:
    ThinSheetSizes(const TriMesh &mesh, SurfaceData &data, const std::vector<char> &near_sheet, double ratio,
                   double l)
        : data_(data),
          active_(ratio < 1 && std::any_of(near_sheet.begin(), near_sheet.end(), [](char c) { return c != 0; })),
          host_sized_(!data.size.empty())
    {
        if (!active_)
            return;
        std::vector<double> asked = host_sized_ ? data.size : std::vector<double>(mesh.pos.size(), l);
        for (size_t v = 0; v < asked.size(); ++v)
            if (near_sheet[v])
                asked[v] *= ratio;
        if (host_sized_)
            data.fields.push_back({1, std::move(data.size)});
        data.size = std::move(asked);
    }
    ~ThinSheetSizes()
    {
        if (!active_)
            return;
        if (host_sized_) {
            data_.size.swap(data_.fields.back().values);
            data_.fields.pop_back();
        } else {
            data_.size.clear();
        }
    }
    ThinSheetSizes(const ThinSheetSizes &) = delete;
    ThinSheetSizes &operator=(const ThinSheetSizes &) = delete;

private:
    SurfaceData &data_;
    const bool active_, host_sized_;
};

} // namespace sfa

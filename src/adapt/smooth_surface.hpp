// SPDX-License-Identifier: BSD-3-Clause
// Smoothing alone (sfa_smooth): sweeps of anisotropic vertex redistribution (§3.2) with
// the connectivity unchanged, so that host arrays stay valid.
#pragma once

#include "adapt/phase_times.hpp"
#include "adapt/settings.hpp"
#include "adapt/surface_data.hpp"
#include "mesh/components.hpp"

#include <vector>

namespace sfa {

struct SmoothResult {
    PhaseTimes seconds;
    // The largest relative volume change of a closed component that a sweep made
    // (restore_enclosed_volumes), and the correction took back if it was on.
    double volume_correction = 0;
    // The largest relative volume change of a closed component the correction left
    // (restore_enclosed_volumes' largest_left), over the sweeps.
    double volume_left = 0;
};

// `sweeps` times: the surface analysed, one sweep (smoothing_sweep) made through an edit
// that carries the host's data (the size field interpolated as a field), and each closed
// component's enclosed volume restored. Fixed vertices are corners (constraints.hpp). With the
// crossing guard, the vertices watched are those of `near_sheet` if it has one mark per
// vertex (the last adaptation's findings: a flow adapts every few steps, and a sheet thins
// slowly), else this surface's own. The analyses are made in `workspace` (as for
// adapt_surface); `components` are the mesh's.
SmoothResult smooth_surface(TriMesh &mesh, SurfaceData &data, const SmoothSettings &settings,
                            int32_t sweeps, const std::vector<char> &near_sheet, SurfaceAnalysis &workspace,
                            const Components &components);

} // namespace sfa

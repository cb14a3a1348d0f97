// Smoothing alone (sfa_smooth): sweeps of anisotropic vertex redistribution (§3.2) with
// the connectivity unchanged, so that host arrays stay valid.
#pragma once

#include "adapt/phase_times.hpp"
#include "adapt/settings.hpp"
#include "fields/vertex_fields.hpp"

#include <vector>

namespace sfa {

// `sweeps` times: the surface analysed, one sweep (smoothing_sweep) made through an edit
// that carries the fields, and a closed surface's enclosed volume restored. With the
// crossing guard, the vertices watched are those of `near_sheet` if it has one mark per
// vertex (the last adaptation's findings: a flow adapts every few steps, and a sheet thins
// slowly), else this surface's own. The analyses are made in `workspace` (as for
// adapt_surface). Returns the seconds of each phase.
PhaseTimes smooth_surface(TriMesh &mesh, std::vector<VertexField> &fields, const SmoothSettings &settings,
                          int32_t sweeps, const std::vector<char> &near_sheet, SurfaceAnalysis &workspace);

} // namespace sfa

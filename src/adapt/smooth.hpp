// Anisotropic vertex redistribution (paper §3.2).
#pragma once

#include "geometry/analysis.hpp"

#include <vector>

namespace sfa {

// One Jacobi sweep: every new position from the old ones and one analysis of the old
// surface. A smooth vertex moves in its tangent plane towards equal metric edge lengths
// and is lifted onto the surface fitted to its neighbours (its motion in the primary
// space); a ridge vertex moves along its ridge; corners stay. Connectivity never changes.
// Returns the new positions. The enclosed volume is the caller's to restore
// (restore_enclosed_volume): motion along the fitted surface still changes it a little (a
// jittered unit sphere gains 3e-4 in 20 sweeps as its vertices even out).
std::vector<Vec3> smoothing_sweep(const TriMesh &mesh, const SurfaceAnalysis &analysis);

} // namespace sfa

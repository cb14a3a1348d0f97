// Anisotropic vertex redistribution (paper §3.2) with a volume-conserving correction.
#pragma once

#include "geometry/analysis.hpp"

#include <vector>

namespace sfa {

// One Jacobi sweep: every new position from the old ones and one analysis of the old
// surface. Connectivity never changes. Returns the new positions.
std::vector<Vec3> smoothing_sweep(const TriMesh &mesh, const SurfaceAnalysis &analysis);

} // namespace sfa

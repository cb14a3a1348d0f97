// SPDX-License-Identifier: BSD-3-Clause
// Anisotropic vertex redistribution (paper §3.2).
#pragma once

#include "geometry/analysis.hpp"
#include "geometry/crossing_guard.hpp"

#include <vector>

namespace sfa {

// One Jacobi sweep: every new position from the old ones and one analysis of the old
// surface. A smooth vertex moves in its tangent plane towards equal metric edge lengths
// and is lifted onto the surface fitted to its neighbours (its motion in the primary
// space); a ridge vertex moves along its ridge; corners stay. Connectivity never changes.
// Returns the new positions. The enclosed volume is the caller's to restore
// (restore_enclosed_volume): motion along the fitted surface still changes it a little (a
// jittered unit sphere gains 3e-4 in 20 sweeps as its vertices even out).
//
// Denoising (§5.1, §5.2.2; SFA_PARAM_DENOISE): with weight w in (0, 1] a smooth vertex
// also moves along its normal n by (w / 4) n.(U_v - mean of U_q over its neighbours q),
// U the umbrella vector (mean of the neighbours minus the vertex): a Jacobi step of
// bi-Laplacian normal diffusion. Noise from vertex to vertex is damped by up to half per
// sweep, while a smooth surface, whose umbrella vectors vary slowly, stays where it is
// (the plain umbrella step would shrink every curved region, and volume restoration would
// then round the body off). The caller's volume restoration gives back the volume the
// noise took with it.
//
// A move that folds a face, or turns it from the side the surface faces at a smooth corner
// (surface_side.hpp), is not made (the face's corners stay); with a guard, nor one that
// would carry a face through a watched face.
std::vector<Vec3> smoothing_sweep(const TriMesh &mesh, const SurfaceAnalysis &analysis, double denoise = 0,
                                  CrossingGuard *guard = nullptr);

} // namespace sfa

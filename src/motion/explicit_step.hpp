// SPDX-License-Identifier: BSD-3-Clause
// One explicit step with the host's per-vertex velocities (sfa_move), cut so that no
// triangle folds.
#pragma once

#include "mesh/tri_mesh.hpp"
#include "motion/fold_time.hpp"

#include <vector>

namespace sfa {

struct Step {
    std::vector<Vec3> positions; // the vertices after the step
    double dt_taken;
};

// The shortest step the fold control may cut a step dt to: 1e-12 dt. A surface that
// shrinks to a point (a bubble under v = -x) has its fold ahead by a time that each step
// halves, and went on for hundreds of steps, each SFA_OK, while the host's time stood
// still: t + dt_taken == t once dt_taken < 1.1e-16 t, i.e. from below 1e-12 dt when the
// host is some 10^4 steps into its run. Finishing dt at 1e-12 of it per step would take
// 10^12 steps: that is no step, and the call says so.
inline constexpr double min_step_fraction = 1e-12;

// Throws Error(Status::numeric) naming `fold`'s triangle (from index_base) if the step
// the fold control allows, `allowed`, is below min_step_fraction of `dt`.
void require_step_at_least(const Fold &fold, double allowed, double dt, int32_t index_base);

// dt_taken = min(dt, safety * first fold time). Throws Error(Status::numeric) if that is
// less than min_step_fraction dt, or if that step would still leave a triangle flat or
// folded once rounded (the fold is closer than round-off can resolve), or would leave the
// coordinate range (coordinate_range.hpp). Messages count vertices and triangles from
// index_base, as the host does.
Step explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety,
                   int32_t index_base);

// x + dt v for every vertex.
std::vector<Vec3> displaced(const std::vector<Vec3> &pos, const std::vector<Vec3> &velocity, double dt);

// Throws Error(Status::numeric) if `moved`, the positions after a step of dt_taken, are
// not a surface the library can go on with: first if a vertex is outside the coordinate
// range or the surface spans less than it (then the fold test could not be trusted: its
// products overflow or underflow), then naming the first triangle that `moved` leaves flat
// or folded (the analytic fold time is exact, the rounded positions need not be).
void require_valid_step(const TriMesh &mesh, const std::vector<Vec3> &moved, double dt_taken, int32_t index_base);

} // namespace sfa

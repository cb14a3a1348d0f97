// SPDX-License-Identifier: BSD-3-Clause
// Motion that never lets the surface touch itself (SFA_PARAM_COLLISION_SAFE_MOTION): the
// explicit and Runge-Kutta steps of sfa_move and sfa_advect, cut further so that no two
// triangles that share no vertex meet during the step (geometry/collision_time.hpp).
#pragma once

#include "motion/rk4_step.hpp"

namespace sfa {

// Pairs closer than this fraction of their longest edge cannot be let approach any more:
// each cut step halves a closing gap at most, so a pair that keeps closing reaches it
// within about twenty calls, and the call fails instead of creeping on forever.
constexpr double stuck_gap_ratio = 1e-6;

// explicit_step, cut to the collision-free time. Throws Error(Status::numeric) naming the
// two triangles (numbered from index_base) that stop the step when they are closer than
// stuck_gap_ratio of their size and still closing.
Step collision_safe_explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety,
                                  int32_t index_base);

// rk4_step, retried with shorter steps until its displacement, seen as linear motion over
// the step, is collision-free; throws as collision_safe_explicit_step, `t` naming the time.
Step collision_safe_rk4_step(const TriMesh &mesh, const VelocityField &field, double t, double dt, double safety,
                             int32_t index_base);

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// Motion that never lets the surface touch itself (SFA_PARAM_COLLISION_SAFE_MOTION): the
// explicit and Runge-Kutta steps of sfa_move and sfa_advect, cut further so that no two
// triangles that share no vertex meet during the step (geometry/collision_time.hpp).
#pragma once

#include "geometry/block_partition.hpp"
#include "motion/rk4_step.hpp"

namespace sfa {

// Pairs closer than this fraction of their longest edge cannot be let approach any more:
// each cut step halves a closing gap at most, so a pair that keeps closing reaches it
// within about twenty calls, and the call fails instead of creeping on forever.
constexpr double stuck_gap_ratio = 1e-6;

// With contact on (SFA_PARAM_TOPOLOGY_CHANGE), two triangles nearer than this fraction of
// their longest edge that would limit the step are in contact: sheets that near are one
// sheet to the mesh, and where sfa_adapt could not merge them (a sheet folded flat onto
// itself, its two layers a ring or two apart) a cut step would only halve their gap call
// after call until it failed (vortex T = 6, at t = 5.70, 3.6e-9 apart). At a hundredth,
// two drops pressed together needed some ten more cut steps for each ring of triangles
// that came to touch.
constexpr double contact_gap_ratio = 5e-2;

// At most this many rounds of joining contacts into zones; contacts left after them limit
// the step as any other pair.
constexpr int max_contact_rounds = 32;

// explicit_step, cut to the collision-free time. Throws Error(Status::numeric) naming the
// two triangles (numbered from index_base) that stop the step when they are closer than
// stuck_gap_ratio of their size and still closing, or that touch within rounding and
// would be rounded through each other by the step's positions. With `contact`, the
// corners of the triangles in contact instead move together: each group of corners that
// contacts join (an impact zone, Bridson, Fedkiw and Anderson 2002, §7.4) takes the mean
// of its velocities, so that it moves as one (an inelastic contact, without rotation).
// With `blocks`, the search for pairs deals the triangles into blocks as it holds them, or
// it comes to hold them (geometry/block_partition.hpp): the caller keeps it while the
// triangles stay the same.
Step collision_safe_explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety,
                                  int32_t index_base, bool contact = false, BlockPartition *blocks = nullptr);

// rk4_step, retried with shorter steps until its displacement, seen as linear motion over
// the step, is collision-free; throws as collision_safe_explicit_step, `t` naming the time.
// With `contact` and `blocks`, as in collision_safe_explicit_step.
Step collision_safe_rk4_step(const TriMesh &mesh, const VelocityField &field, double t, double dt, double safety,
                             int32_t index_base, bool contact = false, BlockPartition *blocks = nullptr);

} // namespace sfa

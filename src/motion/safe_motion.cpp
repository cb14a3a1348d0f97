// SPDX-License-Identifier: BSD-3-Clause
#include "motion/safe_motion.hpp"

#include "mesh/error.hpp"
#include "geometry/collision_time.hpp"

#include <algorithm>
#include <cstdio>

namespace sfa {
namespace {

// Throws if the pair that limits the step is too close to let it approach any further.
// `when` says when the step starts.
void require_room(const Approach &a, const char *when, int32_t index_base)
{
    if (!(a.gap < stuck_gap_ratio * a.size))
        return;
    char message[300];
    std::snprintf(message, sizeof message,
                  "triangles %d and %d are %.3g apart (%.2g of their size) and closing at %.3g %s: the surface "
                  "would touch itself within %.3g, and the step cannot advance without that",
                  a.first + index_base, a.second + index_base, a.gap, a.gap / a.size, a.closing, when,
                  a.closing > 0 ? a.gap / a.closing : 0.0);
    throw Error(Status::numeric, message);
}

std::vector<Vec3> mean_velocity(const TriMesh &mesh, const Step &step)
{
    std::vector<Vec3> velocity(step.positions.size());
    for (size_t v = 0; v < velocity.size(); ++v)
        velocity[v] = (step.positions[v] - mesh.pos[v]) / step.dt_taken;
    return velocity;
}

} // namespace

Step collision_safe_explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety,
                                  int32_t index_base)
{
    Step step = explicit_step(mesh, velocity, dt, safety, index_base);
    const Approach a = first_approach(mesh, velocity, step.dt_taken);
    if (a.time >= step.dt_taken)
        return step;
    require_room(a, "at the start of the step", index_base);
    step.dt_taken = a.time;
    step.positions = displaced(mesh.pos, velocity, step.dt_taken);
    require_valid_step(mesh, step.positions, step.dt_taken, index_base);
    return step;
}

Step collision_safe_rk4_step(const TriMesh &mesh, const VelocityField &field, double t, double dt, double safety,
                             int32_t index_base)
{
    // The RK4 mean velocity changes with the step only at higher order, so a step a little
    // shorter than the collision-free time of the last try is nearly always free.
    constexpr int max_tries = 40;
    double h = dt;
    for (int attempt = 0; attempt < max_tries; ++attempt) {
        Step step = rk4_step(mesh, field, t, h, safety, index_base);
        const Approach a = first_approach(mesh, mean_velocity(mesh, step), step.dt_taken);
        if (a.time >= step.dt_taken)
            return step;
        char when[40];
        std::snprintf(when, sizeof when, "at t = %g", t);
        require_room(a, when, index_base);
        h = std::min(a.time, 0.9 * step.dt_taken);
    }
    char message[200];
    std::snprintf(message, sizeof message,
                  "no Runge-Kutta step from t = %g keeps the surface from touching itself (tried down to dt = %g)", t, h);
    throw Error(Status::numeric, message);
}

} // namespace sfa

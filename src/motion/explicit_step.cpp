// SPDX-License-Identifier: BSD-3-Clause
#include "motion/explicit_step.hpp"

#include "mesh/coordinate_range.hpp"
#include "mesh/error.hpp"
#include "mesh/parallel.hpp"
#include "motion/fold_time.hpp"

#include <algorithm>
#include <cstdio>

namespace sfa {

std::vector<Vec3> displaced(const std::vector<Vec3> &pos, const std::vector<Vec3> &velocity, double dt)
{
    const int32_t n = static_cast<int32_t>(pos.size());
    std::vector<Vec3> out(n);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v)
        out[v] = pos[v] + dt * velocity[v];
    return out;
}

Step explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety,
                   int32_t index_base)
{
    Step step;
    const Fold fold = first_fold(mesh, velocity);
    step.dt_taken = std::min(dt, safety * fold.time);
    require_step_at_least(fold, step.dt_taken, dt, index_base);
    step.positions = displaced(mesh.pos, velocity, step.dt_taken);
    require_valid_step(mesh, step.positions, step.dt_taken, index_base);
    return step;
}

void require_step_at_least(const Fold &fold, double allowed, double dt, int32_t index_base)
{
    if (allowed >= min_step_fraction * dt)
        return;
    char message[400];
    std::snprintf(message, sizeof message,
                  "triangle %d turns over %g time units from now along these velocities, so the fold control allows "
                  "a step of only %g, less than %g of the step of %g asked: the surface cannot advance past the "
                  "collapse of that triangle (as when a bubble shrinks to a point); nothing moved",
                  fold.triangle + index_base, fold.time, allowed, min_step_fraction, dt);
    throw Error(Status::numeric, message);
}

void require_valid_step(const TriMesh &mesh, const std::vector<Vec3> &moved, double dt_taken, int32_t index_base)
{
    char message[400];
    const int32_t outside = first_out_of_range(moved);
    if (outside >= 0) {
        if (outside < mesh.num_vertices())
            std::snprintf(message, sizeof message,
                          "the step of %g would carry vertex %d to (%g, %g, %g), outside the range the library "
                          "computes in (%s); nothing moved",
                          dt_taken, outside + index_base, moved[outside].x(), moved[outside].y(), moved[outside].z(),
                          coordinate_range_text());
        else
            std::snprintf(message, sizeof message,
                          "the step of %g would shrink the surface to a span of %g (the diagonal of its bounding "
                          "box), outside the range the library computes in (%s); nothing moved",
                          dt_taken, extent_of(moved), coordinate_range_text());
        throw Error(Status::numeric, message);
    }
    const int32_t folded = first_folded_triangle(mesh, moved);
    if (folded < 0)
        return;
    std::snprintf(message, sizeof message,
                  "the velocities fold triangle %d within round-off: even the largest safe step, %g, leaves it flat "
                  "or turned over",
                  folded + index_base, dt_taken);
    throw Error(Status::numeric, message);
}

} // namespace sfa

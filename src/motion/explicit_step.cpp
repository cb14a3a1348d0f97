#include "motion/explicit_step.hpp"

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

Step explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety)
{
    Step step;
    step.dt_taken = std::min(dt, safety * first_fold_time(mesh, velocity));
    step.positions = displaced(mesh.pos, velocity, step.dt_taken);
    require_no_fold(mesh, step.positions, step.dt_taken);
    return step;
}

void require_no_fold(const TriMesh &mesh, const std::vector<Vec3> &moved, double dt_taken)
{
    const int32_t folded = first_folded_triangle(mesh, moved);
    if (folded < 0)
        return;
    char message[220];
    std::snprintf(message, sizeof message,
                  "the velocities fold triangle %d within round-off: even the largest safe step, %g, leaves it flat "
                  "or turned over",
                  folded, dt_taken);
    throw Error(Status::numeric, message);
}

} // namespace sfa

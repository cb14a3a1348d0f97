#include "motion/explicit_step.hpp"

#include "mesh/error.hpp"
#include "motion/fold_time.hpp"

#include <algorithm>
#include <cstdio>

namespace sfa {

std::vector<Vec3> displaced(const std::vector<Vec3> &pos, const std::vector<Vec3> &velocity, double dt)
{
    std::vector<Vec3> out(pos.size());
    for (size_t v = 0; v < pos.size(); ++v)
        out[v] = pos[v] + dt * velocity[v];
    return out;
}

Step explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety)
{
    Step step;
    step.dt_taken = std::min(dt, safety * first_fold_time(mesh, velocity));
    step.positions = displaced(mesh.pos, velocity, step.dt_taken);
    if (step.dt_taken < dt && step.positions == mesh.pos) {
        char message[200];
        std::snprintf(message, sizeof message,
                      "the velocities fold a triangle at once: the largest safe step, %g, moves no vertex",
                      step.dt_taken);
        throw Error(Status::numeric, message);
    }
    return step;
}

} // namespace sfa

// One explicit step with the host's per-vertex velocities (sfa_move), cut so that no
// triangle folds.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace sfa {

struct Step {
    std::vector<Vec3> positions; // the vertices after the step
    double dt_taken;
};

// dt_taken = min(dt, safety * first fold time). Throws Error(Status::numeric) if that
// step is too small to move any vertex.
Step explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety);

// x + dt v for every vertex.
std::vector<Vec3> displaced(const std::vector<Vec3> &pos, const std::vector<Vec3> &velocity, double dt);

} // namespace sfa

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
// step would still leave a triangle flat or folded once rounded (the fold is closer than
// round-off can resolve).
Step explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety);

// x + dt v for every vertex.
std::vector<Vec3> displaced(const std::vector<Vec3> &pos, const std::vector<Vec3> &velocity, double dt);

// Throws Error(Status::numeric) naming the first triangle that `moved` leaves flat or
// folded: the analytic fold time is exact, the rounded positions need not be.
void require_no_fold(const TriMesh &mesh, const std::vector<Vec3> &moved, double dt_taken);

} // namespace sfa

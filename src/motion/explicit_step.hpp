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
// round-off can resolve), or would leave the coordinate range (coordinate_range.hpp).
// Messages count vertices and triangles from index_base, as the host does.
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

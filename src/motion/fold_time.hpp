// Fold control for explicit motion (paper §5.2, after Jiao's time-step control): under
// linear motion x(t) = x + t v, the normal of a triangle is a quadratic in t, and the
// triangle turns over when that normal stops pointing along its starting direction.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace sfa {

// The earliest t > 0 at which n(0).n(t) = 0 for some triangle, or +infinity if no
// triangle ever turns over along these velocities.
double first_fold_time(const TriMesh &mesh, const std::vector<Vec3> &velocity);

// The first triangle (0-based) whose normal at `moved` positions no longer points along
// its normal at mesh.pos (flat or turned over, also by round-off), or -1 if none.
int32_t first_folded_triangle(const TriMesh &mesh, const std::vector<Vec3> &moved);

// The smallest positive root of c0 + c1 t + c2 t^2 with c0 > 0, or +infinity.
double first_positive_root(double c0, double c1, double c2);

} // namespace sfa

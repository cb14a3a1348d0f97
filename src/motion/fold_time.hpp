// SPDX-License-Identifier: BSD-3-Clause
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

struct Fold {
    double time;      // as first_fold_time
    int32_t triangle; // the triangle that folds then (the lowest of a tie), or -1 if none does
};
// The same, and which triangle folds first.
Fold first_fold(const TriMesh &mesh, const std::vector<Vec3> &velocity);

// The fold time of one triangle with edges e1, e2 (from corner 0) whose corners' velocities
// differ from corner 0's by d1, d2. Computed with the edges and the velocity differences
// scaled by powers of two to about 1, which is exact: the same time to the last bit as
// without (where that neither overflows nor underflows), for triangles and velocities of
// any size. 0 where it cannot be told (a flat triangle, velocity differences that overflow).
double triangle_fold_time(const Vec3 &e1, const Vec3 &e2, const Vec3 &d1, const Vec3 &d2);

// Whether triangle t's normal at `moved` positions no longer points along its normal at
// mesh.pos: flat or turned over, also by round-off, and also when it was flat already.
bool turned_over(const TriMesh &mesh, const std::vector<Vec3> &moved, int32_t t);

// The first triangle (0-based) that `moved` leaves turned over, or -1 if none.
int32_t first_folded_triangle(const TriMesh &mesh, const std::vector<Vec3> &moved);

// Whether triangle t has a corner that `moved` puts somewhere else and is turned over
// there: what a move folded (first_folded_moved_triangle).
bool move_folded(const TriMesh &mesh, const std::vector<Vec3> &moved, int32_t t);

// The first triangle (0-based, or -1) for which move_folded: what a move folded, and not
// a triangle that was flat before it and did not move (no move of other vertices unfolds
// that one, so a caller that stops the corners of what this reports would otherwise stop
// them forever). Stopping the corners of the triangle reported (moved[v] =
// mesh.pos[v]) leaves one vertex fewer that moves, so a loop doing that ends within the
// number of vertices.
int32_t first_folded_moved_triangle(const TriMesh &mesh, const std::vector<Vec3> &moved);

// The smallest positive root of c0 + c1 t + c2 t^2 with c0 > 0, or +infinity.
double first_positive_root(double c0, double c1, double c2);

} // namespace sfa

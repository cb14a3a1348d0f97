// SPDX-License-Identifier: BSD-3-Clause
// Where a point lies over a mesh: the corners of a triangle and barycentric weights. Every
// vertex attribute that is interpolated (host fields, velocities) is carried through an
// operation that moves, creates or merges a vertex with the stencil of its new position
// over the mesh as it was: the triangle it lies over (the one where its smallest
// barycentric coordinate is largest), so that a field linear on a flat region stays
// exactly linear.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <limits>

namespace sfa {

struct Stencil {
    Triangle corners; // {-1, -1, -1}: none (the point lies over no face it was given)
    Eigen::Vector3d weights;
};

// Barycentric coordinates of the projection of x onto the plane of (a, b, c).
Eigen::Vector3d barycentric(const Vec3 &x, const Vec3 &a, const Vec3 &b, const Vec3 &c);

// The stencil of x over the triangle, among those for_each_face visits, that x lies over.
// Allocates nothing, so it may run inside parallel loops.
template <class ForEachFace>
Stencil stencil_over(const TriMesh &mesh, const Vec3 &x, ForEachFace &&for_each_face)
{
    Stencil best{{-1, -1, -1}, Eigen::Vector3d::Zero()};
    double best_min = -std::numeric_limits<double>::infinity();
    for_each_face([&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        const Eigen::Vector3d w = barycentric(x, mesh.pos[t[0]], mesh.pos[t[1]], mesh.pos[t[2]]);
        if (w.allFinite() && w.minCoeff() > best_min) {
            best_min = w.minCoeff();
            best = {t, w};
        }
    });
    return best;
}

} // namespace sfa

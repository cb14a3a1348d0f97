// SPDX-License-Identifier: BSD-3-Clause
// The quadric error metric of Garland and Heckbert, used to place a new or merged vertex
// (§4.1, §4.2): the sum over nearby faces of area * (squared distance to the face's plane).
#pragma once

#include "mesh/tri_mesh.hpp"

#include <cmath>

namespace sfa {

// The point x + t * direction minimizing the quadric error of the faces that for_each_face
// visits (it calls its argument with each face index). A smooth surface's new vertex, put
// on a chord, moves this way back towards the surface the faces around it describe. That
// takes a shift of about a sagitta, k L^2 / 8 for a chord of length L on curvature k: an
// eighth of L even where one edge turns the surface by a radian. A shift beyond max_shift
// means the faces describe no single smooth sheet (a cusp, or the two sides of a filament
// thinner than an edge, where the minimum may lie beyond the other side): x stays.
// Splitting and contraction allow max_shift_ratio times the edge's length: twice the
// sagitta of an edge that turns the surface by a radian.
inline constexpr double max_shift_ratio = 0.25;
template <class ForEachFace>
Vec3 quadric_error_minimum_along(const TriMesh &mesh, ForEachFace &&for_each_face, const Vec3 &x, const Vec3 &direction,
                                 double max_shift)
{
    // error(t) = sum area (n.(x + t d - c))^2 with n the unit normal and c a corner:
    // minimal at t = -sum area (n.d)(n.(x - c)) / sum area (n.d)^2.
    double numerator = 0, denominator = 0;
    for_each_face([&](int32_t f) {
        const Triangle &c = mesh.tri[f];
        const Vec3 twice_area = (mesh.pos[c[1]] - mesh.pos[c[0]]).cross(mesh.pos[c[2]] - mesh.pos[c[0]]);
        const double norm = twice_area.norm();
        if (!(norm > 0)) // flat, or NaN
            return;
        const Vec3 n = twice_area / norm;
        const double along = n.dot(direction);
        numerator += norm * along * n.dot(x - mesh.pos[c[0]]);
        denominator += norm * along * along;
    });
    if (!(denominator > 0))
        return x;
    const double shift = -numerator / denominator;
    return std::abs(shift) <= max_shift ? Vec3(x + shift * direction) : x;
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
// The quadric metric tensor of §2.2: A = N^T W N over the faces incident on a vertex,
// with the face areas as weights W, and its eigen-analysis.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <cmath>
#include <vector>

namespace sfa {

using Mat3 = Eigen::Matrix3d;

// Eigenvalues lambda1 >= lambda2 >= lambda3 >= 0 and unit eigenvectors, column i of
// `vectors` for values[i]. e1 spans the primary space of a smooth vertex (its normal);
// e2, e3 span its null space (tangent plane), e3 along the minimum curvature direction.
struct QuadricEigen {
    Eigen::Vector3d values;
    Mat3 vectors;
    Vec3 e(int i) const { return vectors.col(i); }
};

// Unit normal times area (half the cross product of two edges) of triangle t, and of every
// triangle.
inline Vec3 face_area_vector(const TriMesh &mesh, int32_t t)
{
    const Triangle &c = mesh.tri[t];
    return 0.5 * (mesh.pos[c[1]] - mesh.pos[c[0]]).cross(mesh.pos[c[2]] - mesh.pos[c[0]]);
}
std::vector<Vec3> face_area_vectors(const TriMesh &mesh);

// One face's term of the quadric: area n n^T = a a^T / |a| for its area vector a; zero for
// a flat face, which has no normal and no weight.
Mat3 face_quadric(const Vec3 &area_vector);

// w = a / sqrt|a| for an area vector a (zero for a flat face), so that the face's quadric
// term is w w^T: one square root per face. And for every face.
inline Vec3 weighted_normal(const Vec3 &area_vector)
{
    const double area = area_vector.norm();
    return !(area > 0) ? Vec3::Zero() : Vec3(area_vector / std::sqrt(area));
}
std::vector<Vec3> weighted_normals(const std::vector<Vec3> &area_vectors);

// A_v = sum over the faces t around v of area_t n_t n_t^T = sum w_t w_t^T, with
// weighted(t) = w_t: the six distinct entries, summed around the fan.
template <class Weighted>
Mat3 vertex_quadric(const TriMesh &mesh, int32_t v, Weighted &&weighted)
{
    double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
    mesh.for_each_outgoing(v, [&](int32_t h) {
        const Vec3 w = weighted(TriMesh::face(h));
        xx += w.x() * w.x();
        xy += w.x() * w.y();
        xz += w.x() * w.z();
        yy += w.y() * w.y();
        yz += w.y() * w.z();
        zz += w.z() * w.z();
    });
    Mat3 quadric;
    quadric << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    return quadric;
}

// The eigen-decomposition, eigenvalues decreasing.
QuadricEigen decompose(const Mat3 &quadric);

} // namespace sfa

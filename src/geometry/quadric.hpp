// The quadric metric tensor of §2.2: A = N^T W N over the faces incident on a vertex,
// with the face areas as weights W, and its eigen-analysis.
#pragma once

#include "mesh/tri_mesh.hpp"

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

// Per face: unit normal times area (half the cross product of two edges).
std::vector<Vec3> face_area_vectors(const TriMesh &mesh);

// One face's term of the quadric: area n n^T = a a^T / |a| for its area vector a; zero for
// a flat face, which has no normal and no weight.
Mat3 face_quadric(const Vec3 &area_vector);

// A_v = sum over the faces t around v of area_t n_t n_t^T = sum a_t a_t^T / |a_t|,
// with a_t the face's area vector.
std::vector<Mat3> vertex_quadrics(const TriMesh &mesh, const std::vector<Vec3> &area_vectors);

// The eigen-decomposition, eigenvalues decreasing.
QuadricEigen decompose(const Mat3 &quadric);

} // namespace sfa

// Carrying host fields through the operations that move, create or merge vertices: a
// vertex at a new position takes the barycentric interpolation of the old values in the
// old triangle its position lies over (the one where its smallest barycentric coordinate
// is largest), so that a field linear on a flat region stays exactly linear.
#pragma once

#include "fields/vertex_fields.hpp"
#include "mesh/tri_mesh.hpp"

#include <limits>
#include <vector>

namespace sfa {

// Where a value comes from: corners of an old triangle and barycentric weights.
struct Stencil {
    Triangle corners;
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

// The fields' value at the stencil, into vertex v (which may be one of its corners).
void set_interpolated(std::vector<VertexField> &fields, int32_t v, const Stencil &stencil);

// Appends a vertex with the fields' value at the stencil.
void append_interpolated(std::vector<VertexField> &fields, const Stencil &stencil);

// Renumbers after compaction or reordering: vertex v's values go to vertex_map[v], or away
// if it is -1.
void renumber_fields(std::vector<VertexField> &fields, const std::vector<int32_t> &vertex_map);

// The fields after every vertex moved to moved[v] at once (a smoothing sweep), each from
// its old star; vertices that did not move keep their values.
std::vector<VertexField> fields_at_moved_vertices(const TriMesh &old_mesh, const std::vector<Vec3> &moved,
                                                  const std::vector<VertexField> &fields);

} // namespace sfa

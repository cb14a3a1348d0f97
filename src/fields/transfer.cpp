#include "fields/transfer.hpp"

#include "mesh/parallel.hpp"

#include <algorithm>
#include <limits>

namespace sfa {
namespace {

// Barycentric coordinates of the projection of x onto the plane of (a, b, c).
Eigen::Vector3d barycentric(const Vec3 &x, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    const Vec3 normal = (b - a).cross(c - a);
    const double twice_area = normal.squaredNorm();
    const double wa = (c - b).cross(x - b).dot(normal) / twice_area;
    const double wb = (a - c).cross(x - c).dot(normal) / twice_area;
    return Eigen::Vector3d(wa, wb, 1 - wa - wb);
}

} // namespace

std::vector<VertexField> fields_at_moved_vertices(const TriMesh &old_mesh, const std::vector<Vec3> &moved,
                                                  const std::vector<VertexField> &fields)
{
    std::vector<VertexField> out = fields;
    if (fields.empty())
        return out;
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < old_mesh.num_vertices(); ++v) {
        if (moved[v] == old_mesh.pos[v])
            continue;
        int32_t best_face = -1;
        Eigen::Vector3d best_weights;
        double best_min = -std::numeric_limits<double>::infinity();
        old_mesh.for_each_outgoing(v, [&](int32_t h) {
            const Triangle &t = old_mesh.tri[TriMesh::face(h)];
            const Eigen::Vector3d w =
                barycentric(moved[v], old_mesh.pos[t[0]], old_mesh.pos[t[1]], old_mesh.pos[t[2]]);
            if (w.minCoeff() > best_min) {
                best_min = w.minCoeff();
                best_face = TriMesh::face(h);
                best_weights = w;
            }
        });
        const Triangle &t = old_mesh.tri[best_face];
        for (size_t f = 0; f < fields.size(); ++f) {
            const int32_t ncomp = fields[f].ncomp;
            for (int32_t c = 0; c < ncomp; ++c) {
                double value = 0;
                for (int k = 0; k < 3; ++k)
                    value += best_weights[k] * fields[f].values[static_cast<size_t>(ncomp) * t[k] + c];
                out[f].values[static_cast<size_t>(ncomp) * v + c] = value;
            }
        }
    }
    return out;
}

} // namespace sfa

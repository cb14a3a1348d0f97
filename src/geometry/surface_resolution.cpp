// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/surface_resolution.hpp"

#include "geometry/distance.hpp"
#include "geometry/measures.hpp"
#include "geometry/quadric.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace sfa {
namespace {

constexpr size_t max_visits = 512;

// More than a right angle, by more than round-off: a right-angled crease (a machined
// part's edge) has normals exactly square to each other.
bool facing_apart(const Vec3 &p, const Vec3 &q) { return p.dot(q) < -1e-9; }

// Whether triangle q comes within `radius` of `point`. Most triangles a walk meets have a
// corner that near, or none within their own size of it; the closest point settles the
// rest.
bool within(const TriMesh &mesh, int32_t q, const Vec3 &point, double radius)
{
    const Triangle &c = mesh.tri[q];
    const Vec3 &a = mesh.pos[c[0]], &b = mesh.pos[c[1]], &d = mesh.pos[c[2]];
    const double nearest_corner2 =
        std::min({(a - point).squaredNorm(), (b - point).squaredNorm(), (d - point).squaredNorm()});
    if (nearest_corner2 <= radius * radius)
        return true;
    // Every point of q lies within its longest edge of each corner.
    const double reach =
        radius + std::sqrt(std::max({(b - a).squaredNorm(), (d - b).squaredNorm(), (a - d).squaredNorm()}));
    if (nearest_corner2 > reach * reach)
        return false;
    return (closest_point_on_triangle(point, a, b, d) - point).norm() <= radius;
}

// Whether the walk from triangle t (above) reaches two triangles facing apart. Two normals
// within 45 degrees of t's are at most 90 degrees apart, so only those beyond that cone
// are compared with the others: on a smooth surface, none.
bool turns_within_its_size(const TriMesh &mesh, const std::vector<Vec3> &normal, int32_t t,
                           std::vector<int32_t> &visited)
{
    const Triangle &corners = mesh.tri[t];
    const Vec3 &a = mesh.pos[corners[0]], &b = mesh.pos[corners[1]], &c = mesh.pos[corners[2]];
    const Vec3 centroid = (a + b + c) / 3;
    const double radius = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const double cone = std::sqrt(0.5); // cos 45 degrees
    bool all_in_cone = true;
    visited.assign(1, t);
    for (size_t i = 0; i < visited.size() && visited.size() < max_visits; ++i)
        for (int k = 0; k < 3; ++k) {
            const int32_t twin = mesh.opp[3 * visited[i] + k];
            if (twin < 0)
                continue;
            const int32_t next = TriMesh::face(twin);
            if (std::find(visited.begin(), visited.end(), next) != visited.end())
                continue;
            if (!within(mesh, next, centroid, radius))
                continue;
            const bool in_cone = normal[t].dot(normal[next]) >= cone;
            if (!(all_in_cone && in_cone))
                for (int32_t seen : visited)
                    if (facing_apart(normal[seen], normal[next]))
                        return true;
            all_in_cone = all_in_cone && in_cone;
            visited.push_back(next);
        }
    return false;
}

} // namespace

std::vector<char> unresolved_triangles(const TriMesh &mesh)
{
    const int32_t n = mesh.num_triangles();
    std::vector<Vec3> normal(n);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t t = 0; t < n; ++t)
        normal[t] = face_area_vector(mesh, t).normalized();
    std::vector<char> unresolved(n, 0);
    std::vector<int32_t> visited;
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 256) firstprivate(visited)
    for (int32_t t = 0; t < n; ++t)
        unresolved[t] = turns_within_its_size(mesh, normal, t, visited);
    return unresolved;
}

ResolvedAngles resolved_angles(const TriMesh &mesh, const std::vector<char> &unresolved)
{
    // The areas summed in a fixed order: the same for any threads.
    const Eigen::Vector2d area = ordered_sum(mesh.num_triangles(), Eigen::Vector2d::Zero().eval(), [&](int32_t t) {
        const double size = face_area_vector(mesh, t).norm();
        return Eigen::Vector2d(size, unresolved[t] ? size : 0);
    });
    const double smallest = angle_range(mesh, &unresolved).min_degrees;
    return {area[0] > 0 ? area[1] / area[0] : 0, std::isinf(smallest) ? 180 : smallest};
}

} // namespace sfa

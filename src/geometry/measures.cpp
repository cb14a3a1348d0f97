#include "geometry/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sfa {

namespace {
constexpr double degrees_per_radian = 180.0 / 3.14159265358979323846;

// Angle between two vectors, accurate also for angles near 0 and 180 degrees.
double angle_between(const Vec3 &u, const Vec3 &w) { return std::atan2(u.cross(w).norm(), u.dot(w)); }
} // namespace

double enclosed_volume(const TriMesh &mesh) { return enclosed_volume(mesh, mesh.pos); }

double enclosed_volume(const TriMesh &mesh, const std::vector<Vec3> &positions)
{
    double six_volume = 0;
    for (const Triangle &t : mesh.tri)
        six_volume += positions[t[0]].dot(positions[t[1]].cross(positions[t[2]]));
    return six_volume / 6;
}

Vec3 volume_gradient(const TriMesh &mesh, int32_t v)
{
    Vec3 gradient = Vec3::Zero();
    mesh.for_each_outgoing(v, [&](int32_t h) {
        const Triangle &t = mesh.tri[TriMesh::face(h)];
        const int k = h % 3; // v is corner k
        gradient += mesh.pos[t[(k + 1) % 3]].cross(mesh.pos[t[(k + 2) % 3]]);
    });
    return gradient / 6;
}

double surface_area(const TriMesh &mesh)
{
    double twice_area = 0;
    for (const Triangle &t : mesh.tri)
        twice_area += (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]).norm();
    return twice_area / 2;
}

AngleRange angle_range(const TriMesh &mesh)
{
    AngleRange range{std::numeric_limits<double>::infinity(), 0};
    for (const Triangle &t : mesh.tri) {
        for (int k = 0; k < 3; ++k) {
            const Vec3 &corner = mesh.pos[t[k]];
            const double angle =
                angle_between(mesh.pos[t[(k + 1) % 3]] - corner, mesh.pos[t[(k + 2) % 3]] - corner);
            range.min_degrees = std::min(range.min_degrees, angle);
            range.max_degrees = std::max(range.max_degrees, angle);
        }
    }
    range.min_degrees *= degrees_per_radian;
    range.max_degrees *= degrees_per_radian;
    return range;
}

EdgeLengths edge_lengths(const TriMesh &mesh)
{
    EdgeLengths lengths{std::numeric_limits<double>::infinity(), 0, 0};
    double sum = 0;
    long count = 0;
    const int32_t num_halfedges = 3 * mesh.num_triangles();
    for (int32_t h = 0; h < num_halfedges; ++h) {
        if (mesh.opp[h] >= 0 && mesh.opp[h] < h)
            continue; // interior edges once, from their first half-edge
        const double length = (mesh.pos[mesh.head(h)] - mesh.pos[mesh.tail(h)]).norm();
        lengths.min = std::min(lengths.min, length);
        lengths.max = std::max(lengths.max, length);
        sum += length;
        ++count;
    }
    lengths.mean = count ? sum / static_cast<double>(count) : 0;
    return lengths;
}

double max_aspect_ratio(const TriMesh &mesh)
{
    double worst = 0;
    for (const Triangle &t : mesh.tri) {
        const Vec3 &a = mesh.pos[t[0]], &b = mesh.pos[t[1]], &c = mesh.pos[t[2]];
        const double la = (c - b).norm(), lb = (a - c).norm(), lc = (b - a).norm();
        const double twice_area = (b - a).cross(c - a).norm();
        // R = la lb lc / (4 A), r = A / s with s the half perimeter: R / (2r) = la lb lc s / (8 A^2).
        const double half_perimeter = (la + lb + lc) / 2;
        const double ratio = twice_area > 0 ? la * lb * lc * half_perimeter / (2 * twice_area * twice_area)
                                            : std::numeric_limits<double>::infinity();
        worst = std::max(worst, ratio);
    }
    return worst;
}

double max_normal_turn_degrees(const TriMesh &mesh)
{
    double largest = 0;
    for (int32_t h = 0; h < 3 * mesh.num_triangles(); ++h) {
        const int32_t twin = mesh.opp[h];
        if (twin < h)
            continue; // boundary, or seen from the other side
        const auto normal = [&](int32_t t) {
            const Triangle &c = mesh.tri[t];
            return Vec3((mesh.pos[c[1]] - mesh.pos[c[0]]).cross(mesh.pos[c[2]] - mesh.pos[c[0]]));
        };
        largest = std::max(largest, angle_between(normal(TriMesh::face(h)), normal(TriMesh::face(twin))));
    }
    return largest * degrees_per_radian;
}

} // namespace sfa

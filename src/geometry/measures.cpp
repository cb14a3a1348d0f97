// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/measures.hpp"

#include "geometry/angles.hpp"
#include "mesh/components.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace sfa {
namespace {

// Angle between two vectors, accurate also for angles near 0 and 180 degrees.
double angle_between(const Vec3 &u, const Vec3 &w) { return std::atan2(u.cross(w).norm(), u.dot(w)); }
} // namespace

double enclosed_volume(const TriMesh &mesh) { return enclosed_volume(mesh, connected_components(mesh)); }

double enclosed_volume(const TriMesh &mesh, const Components &components)
{
    const std::vector<Vec3> &positions = mesh.pos;
    std::vector<Vec3> about = component_centres(positions, components.of_vertex, components.count);
    for (int32_t c = 0; c < components.count; ++c)
        if (!components.closed[c])
            about[c] = Vec3::Zero(); // an open component's sum is the one about the origin
    return ordered_sum(mesh.num_triangles(), 0.0, [&](int32_t k) {
               const Triangle &t = mesh.tri[k];
               const Vec3 &o = about[components.of_vertex[t[0]]];
               return (positions[t[0]] - o).dot((positions[t[1]] - o).cross(positions[t[2]] - o));
           }) /
           6;
}

std::vector<Vec3> component_centres(const std::vector<Vec3> &positions, const std::vector<int32_t> &label,
                                    int32_t count)
{
    // Each component's bounding box, reduced in parallel (a volume step calls this several
    // times, and as one loop it kept the second core idle): a bound is one of the
    // coordinates, the same in any order.
    const double inf = std::numeric_limits<double>::infinity();
    using Bounds = std::array<Vec3, 2>;
    const std::vector<Bounds> bounds = ordered_group_reduce(
        static_cast<int32_t>(positions.size()), count, Bounds{Vec3::Constant(inf), Vec3::Constant(-inf)},
        [&](int32_t v) { return label[v]; }, [&](int32_t v) { return Bounds{positions[v], positions[v]}; },
        [](const Bounds &a, const Bounds &b) { return Bounds{a[0].cwiseMin(b[0]), a[1].cwiseMax(b[1])}; });
    std::vector<Vec3> centre(count, Vec3::Zero());
    for (int32_t c = 0; c < count; ++c)
        if (const Vec3 &low = bounds[c][0], &high = bounds[c][1]; low.x() <= high.x())
            centre[c] = low + (high - low) / 2; // not (low + high) / 2: no overflow
    return centre;
}

Vec3 volume_gradient(const TriMesh &mesh, int32_t v)
{
    Vec3 gradient = Vec3::Zero();
    const Vec3 &p = mesh.pos[v];
    mesh.for_each_outgoing(v, [&](int32_t h) {
        const Triangle &t = mesh.tri[TriMesh::face(h)];
        const int k = h % 3; // v is corner k
        gradient += (mesh.pos[t[(k + 1) % 3]] - p).cross(mesh.pos[t[(k + 2) % 3]] - p);
    });
    return gradient / 6;
}

double surface_area(const TriMesh &mesh)
{
    return ordered_sum(mesh.num_triangles(), 0.0, [&](int32_t k) {
               const Triangle &t = mesh.tri[k];
               return (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]).norm();
           }) /
           2;
}

AngleRange angle_range(const TriMesh &mesh, const std::vector<char> *left_out)
{
    // The angles' arc tangents are what took the time (13 ms for 193k triangles on two
    // cores): so a first pass finds the largest and smallest cosine of any corner, and a
    // second takes the arc tangent only of the corners whose cosine is within 1e-12 of
    // either. Rounding can put two cosines in the other order than their angles only where
    // the angles differ by a few units in the last place, when the cosines differ by far
    // less than that margin. A corner whose cosine is not finite (an edge of zero length,
    // or lengths whose squares underflow) counts in neither extreme and is always taken.
    // So the extremes are those of every corner's arc tangent, to the last bit. Minima and
    // maxima are exact: the same for any number of threads.
    const auto corner_cos = [](const Vec3 &u, const Vec3 &w) {
        return u.dot(w) / std::sqrt(u.squaredNorm() * w.squaredNorm());
    };
    const auto for_each_corner = [&](int32_t k, auto &&visit) {
        if (left_out && (*left_out)[k])
            return;
        const Triangle &t = mesh.tri[k];
        for (int i = 0; i < 3; ++i) {
            const Vec3 &corner = mesh.pos[t[i]];
            visit(mesh.pos[t[(i + 1) % 3]] - corner, mesh.pos[t[(i + 2) % 3]] - corner);
        }
    };
    double most_cos = -2, least_cos = 2;
#pragma omp parallel for num_threads(loop_threads()) schedule(static) reduction(max : most_cos) reduction(min : least_cos)
    for (int32_t k = 0; k < mesh.num_triangles(); ++k)
        for_each_corner(k, [&](const Vec3 &u, const Vec3 &w) {
            if (const double c = corner_cos(u, w); std::isfinite(c)) {
                most_cos = std::max(most_cos, c);
                least_cos = std::min(least_cos, c);
            }
        });
    constexpr double margin = 1e-12;
    double smallest = std::numeric_limits<double>::infinity(), largest = 0;
#pragma omp parallel for num_threads(loop_threads()) schedule(static) reduction(min : smallest) reduction(max : largest)
    for (int32_t k = 0; k < mesh.num_triangles(); ++k)
        for_each_corner(k, [&](const Vec3 &u, const Vec3 &w) {
            const double c = corner_cos(u, w);
            const bool unknown = !std::isfinite(c);
            if (unknown || c >= most_cos - margin)
                smallest = std::min(smallest, angle_between(u, w));
            if (unknown || c <= least_cos + margin)
                largest = std::max(largest, angle_between(u, w));
        });
    return AngleRange{smallest * degrees_per_radian, largest * degrees_per_radian};
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
    // Each face's normal and its length once, then one dot product per edge: the edge with
    // the smallest cosine (ties: the lowest half-edge, so the same for any number of
    // threads), without an arc tangent per edge; then its angle, accurately. A flat
    // triangle has no normal and turns nothing.
    std::vector<Vec3> normal(mesh.tri.size());
    std::vector<double> length(mesh.tri.size());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t t = 0; t < mesh.num_triangles(); ++t) {
        const Triangle &c = mesh.tri[t];
        normal[t] = (mesh.pos[c[1]] - mesh.pos[c[0]]).cross(mesh.pos[c[2]] - mesh.pos[c[0]]);
        length[t] = normal[t].norm();
    }
    double smallest_cos = 2;
    int32_t sharpest = -1;
#pragma omp parallel num_threads(loop_threads())
    {
        double local_cos = 2;
        int32_t local_edge = -1;
#pragma omp for schedule(static) nowait
        for (int32_t h = 0; h < 3 * mesh.num_triangles(); ++h) {
            const int32_t twin = mesh.opp[h];
            if (twin < h)
                continue; // boundary, or seen from the other side
            const int32_t f = TriMesh::face(h), g = TriMesh::face(twin);
            const double lengths = length[f] * length[g];
            const double cosine = lengths > 0 ? normal[f].dot(normal[g]) / lengths : 1.0;
            if (cosine < local_cos) {
                local_cos = cosine;
                local_edge = h;
            }
        }
#pragma omp critical
        if (local_edge >= 0 && (local_cos < smallest_cos || (local_cos == smallest_cos && local_edge < sharpest))) {
            smallest_cos = local_cos;
            sharpest = local_edge;
        }
    }
    if (sharpest < 0)
        return 0; // no interior edge
    return angle_between(normal[TriMesh::face(sharpest)], normal[TriMesh::face(mesh.opp[sharpest])]) *
           degrees_per_radian;
}

} // namespace sfa

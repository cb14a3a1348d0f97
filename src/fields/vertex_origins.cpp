// SPDX-License-Identifier: BSD-3-Clause
#include "fields/vertex_origins.hpp"

#include "mesh/error.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

namespace sfa {
namespace {

// A barycentric coordinate above -over_tolerance counts as >= 0 when deciding whether x
// lies over a triangle: rounding leaves a point on an edge a little outside one or both of
// its triangles. A point stopped that far outside is at most 1e-14 of the triangle's
// height away from it, and is then placed on the edge.
constexpr double over_tolerance = 1e-14;

// The walk remembers this many of the triangles it went through last, and does not go
// back to them: where x lies over no triangle (beyond a ridge, or outside a convex corner,
// as a point of a sphere is outside its polyhedron), crossing the most negative edge would
// go to and fro, or round the corner's fan.
constexpr int recent_size = 16;

// w0 and w1 clamped into the triangle (NaN counts as 0) and completed with
// w2 = 1 - (w0 + w1), so that all three are in [0, 1] and w0 + w1 + w2, added left to
// right, is exactly 1: for s = w0 + w1 (rounded) in [0, 1], s + (1 - s) rounds to 1 (the
// difference is exact for s >= 1/2, and below that off by at most 2^-54, which the sum
// rounds away), and clamping w1 to 1 - w0 keeps s <= 1.
Eigen::Vector3d summing_to_one(double w0, double w1)
{
    w0 = w0 > 0 ? (w0 < 1 ? w0 : 1) : 0;
    const double rest = 1 - w0;
    w1 = w1 > 0 ? (w1 < rest ? w1 : rest) : 0;
    return Eigen::Vector3d(w0, w1, 1 - (w0 + w1));
}

// x over one triangle: where it is over the plane (for the walk) and where its closest
// point is (for the answer).
struct Placement {
    Eigen::Vector3d projected; // barycentric coordinates of x projected onto the plane; NaN if degenerate
    Eigen::Vector3d weights;   // of x's closest point on the triangle (summing_to_one's rules)
    double distance2;          // from x to that point, squared
};

// The closest point to x of edge p-q (corners i and j), if nearer than the placement's.
void closer_on_edge(const Vec3 &p, const Vec3 &q, int i, int j, const Vec3 &x, Placement &out)
{
    const Vec3 d = q - p;
    const double length2 = d.squaredNorm();
    double t = length2 > 0 ? (x - p).dot(d) / length2 : 0;
    t = t > 0 ? (t < 1 ? t : 1) : 0; // NaN: 0
    const double distance2 = (x - (p + t * d)).squaredNorm();
    if (distance2 < out.distance2) {
        out.weights = Eigen::Vector3d::Zero();
        out.weights[i] = 1 - t; // (1 - t) + t rounds to 1 (summing_to_one)
        out.weights[j] = t;
        out.distance2 = distance2;
    }
}

Placement place(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &x)
{
    // A vertex that stayed where it was is that corner, exactly (its data unchanged).
    if (x == a)
        return {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 0, 0), 0};
    if (x == b)
        return {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 1, 0), 0};
    if (x == c)
        return {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, 1), 0};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Placement out{Eigen::Vector3d::Constant(nan), Eigen::Vector3d(1, 0, 0), std::numeric_limits<double>::infinity()};
    // As barycentric() (mesh/stencil.hpp), with the normal kept for the height.
    const Vec3 normal = (b - a).cross(c - a);
    const double twice_area2 = normal.squaredNorm();
    if (twice_area2 > 0) {
        const double wa = (c - b).cross(x - b).dot(normal) / twice_area2;
        const double wb = (a - c).cross(x - c).dot(normal) / twice_area2;
        out.projected = Eigen::Vector3d(wa, wb, 1 - wa - wb);
        if (wa >= 0 && wb >= 0 && out.projected[2] >= 0) {
            // Over the triangle: the closest point is the projection.
            const double height = (x - a).dot(normal);
            out.weights = summing_to_one(wa, wb);
            out.distance2 = height * height / twice_area2;
            return out;
        }
    }
    // Outside: the closest point is on an edge whose line has x on its far side (a
    // negative coordinate opposite): where it is a corner, x is beyond one of the corner's
    // two edges at least. A degenerate triangle: any edge.
    const Eigen::Vector3d &w = out.projected;
    if (!(w[2] >= 0))
        closer_on_edge(a, b, 0, 1, x, out);
    if (!(w[0] >= 0))
        closer_on_edge(b, c, 1, 2, x, out);
    if (!(w[1] >= 0))
        closer_on_edge(c, a, 2, 0, x, out);
    return out;
}

} // namespace

void OriginHints::reset(const TriMesh &before)
{
    const int32_t n = before.num_vertices();
    hints_.resize(n);
    for (int32_t v = 0; v < n; ++v)
        hints_[v] = before.v2h[v] >= 0 ? TriMesh::face(before.v2h[v]) : -1;
}

void OriginHints::split(const TriMesh &mesh, const SplitChange &change)
{
    const SplitRecord &r = change.record;
    if (r.vertex >= static_cast<int32_t>(hints_.size()))
        hints_.resize(r.vertex + 1, -1); // amortized: the vector grows by doubling
    const Vec3 &x = mesh.pos[r.vertex];
    hints_[r.vertex] =
        (x - mesh.pos[r.a]).squaredNorm() <= (x - mesh.pos[r.b]).squaredNorm() ? hints_[r.a] : hints_[r.b];
}

void OriginHints::before_collapse(const TriMesh &mesh, int32_t h)
{
    gone_was_ = mesh.pos[mesh.tail(h)];
    keep_was_ = mesh.pos[mesh.head(h)];
}

void OriginHints::collapse(const TriMesh &mesh, const CollapseChange &change)
{
    const CollapseRecord &r = change.record;
    const Vec3 &x = mesh.pos[r.keep];
    if ((x - gone_was_).squaredNorm() < (x - keep_was_).squaredNorm())
        hints_[r.keep] = hints_[r.gone];
}

void OriginHints::renumber(const Renumbering &renumbering)
{
    const std::vector<int32_t> &map = renumbering.vertex_map;
    if (!renumbering.keeps_order) {
        renumbering.apply_to_vertices(hints_);
        return;
    }
    // Compaction: new numbers never exceed old ones, so in place, front to back.
    size_t count = 0;
    for (size_t old = 0; old < map.size(); ++old)
        if (map[old] >= 0) {
            hints_[map[old]] = hints_[old];
            ++count;
        }
    hints_.resize(count);
}

VertexOrigin locate_origin(const TriMesh &before_topology, const std::vector<Vec3> &before_positions, int32_t hint,
                           const Vec3 &x, int32_t max_steps)
{
    VertexOrigin best{-1, Eigen::Vector3d::Zero()};
    if (hint < 0 || hint >= before_topology.num_triangles())
        return best;
    double best_distance2 = std::numeric_limits<double>::infinity();
    int32_t recent[recent_size];
    int32_t visited = 0;
    int32_t t = hint;
    for (int32_t step = 0; step < std::max(max_steps, 1); ++step) {
        const Triangle &corners = before_topology.tri[t];
        if (corners[0] < 0)
            break; // dead: the mesh as it was had not been compacted
        const Placement p =
            place(before_positions[corners[0]], before_positions[corners[1]], before_positions[corners[2]], x);
        if (best.triangle < 0 || p.distance2 <= best_distance2) {
            best = {t, p.weights};
            best_distance2 = p.distance2;
        }
        recent[visited++ % recent_size] = t;
        const Eigen::Vector3d &w = p.projected;
        if (w[0] >= -over_tolerance && w[1] >= -over_tolerance && w[2] >= -over_tolerance)
            break; // x lies over t (never true for a degenerate triangle: NaN)
        // The corners by coordinate, most negative first (a degenerate triangle's in order).
        int order[3] = {0, 1, 2};
        if (w[order[1]] < w[order[0]])
            std::swap(order[0], order[1]);
        if (w[order[2]] < w[order[1]])
            std::swap(order[1], order[2]);
        if (w[order[1]] < w[order[0]])
            std::swap(order[0], order[1]);
        int32_t next = -1;
        for (int k : order) {
            if (w[k] >= -over_tolerance)
                break; // x is on the triangle's side of the edges left
            const int32_t twin = before_topology.opp[3 * t + (k + 1) % 3]; // the edge opposite corner k
            if (twin < 0)
                continue; // the boundary
            const int32_t across = TriMesh::face(twin);
            int32_t *const seen = recent + std::min(visited, recent_size);
            if (std::find(recent, seen, across) != seen)
                continue; // back the way it came
            next = across;
            break;
        }
        if (next < 0)
            break;
        t = next;
    }
    return best;
}

std::vector<VertexOrigin> locate_origins(const TriMesh &before_topology, const std::vector<Vec3> &before_positions,
                                         const std::vector<int32_t> &hints, const std::vector<Vec3> &positions)
{
    if (hints.size() != positions.size())
        throw Error(Status::internal, "vertex origins: " + std::to_string(hints.size()) + " hints for " +
                                          std::to_string(positions.size()) + " vertices");
    const int32_t n = static_cast<int32_t>(positions.size());
    std::vector<VertexOrigin> origins(n);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v)
        origins[v] = locate_origin(before_topology, before_positions, hints[v], positions[v]);
    return origins;
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/surgery.hpp"

#include <algorithm>
#include <limits>

namespace sfa {
namespace {

// The hole the two triangles of h's edge leave, as the surrounding surface runs round it:
// for h = a -> b in (a, b, c) and its twin in (b, a, d), the surface keeps c -> b, b -> d,
// d -> a and a -> c.
std::array<int32_t, 4> hole_of_edge(const TriMesh &mesh, int32_t h)
{
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    const int32_t c = mesh.head(TriMesh::next(h)), d = mesh.head(TriMesh::next(mesh.opp[h]));
    return {c, b, d, a};
}

bool adjacent(const TriMesh &mesh, int32_t v, int32_t w)
{
    bool found = false;
    mesh.for_each_neighbour(v, [&](int32_t x, int32_t) { found = found || x == w; });
    return found;
}

} // namespace

bool plan_zipper(const TriMesh &mesh, int32_t h1, int32_t h2, ZipperPlan &plan)
{
    if (mesh.opp[h1] < 0 || mesh.opp[h2] < 0)
        return false;
    const std::array<int32_t, 4> p = hole_of_edge(mesh, h1), q = hole_of_edge(mesh, h2);
    std::array<int32_t, 8> corners;
    std::copy(p.begin(), p.end(), corners.begin());
    std::copy(q.begin(), q.end(), corners.begin() + 4);
    std::sort(corners.begin(), corners.end());
    if (std::adjacent_find(corners.begin(), corners.end()) != corners.end())
        return false;
    for (int32_t v : p)
        for (int32_t w : q)
            if (adjacent(mesh, v, w))
                return false;

    // The surface keeps p[i] -> p[i+1] and q[j] -> q[j+1]; the tube runs each the other
    // way. Rung i joins p[i] to q[(k - i) mod 4]: the holes face each other, so one is
    // walked backwards while the other is walked forwards.
    int best = 0;
    double shortest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
        double sum = 0;
        for (int i = 0; i < 4; ++i)
            sum += (mesh.pos[p[i]] - mesh.pos[q[(k - i + 4) % 4]]).squaredNorm();
        if (sum < shortest) {
            shortest = sum;
            best = k;
        }
    }
    for (int i = 0; i < 4; ++i) {
        const int32_t p0 = p[i], p1 = p[(i + 1) % 4];
        const int32_t q0 = q[(best - i + 4) % 4], q1 = q[(best - i + 3) % 4];
        plan.tube[2 * i] = {p1, p0, q0};
        plan.tube[2 * i + 1] = {p1, q0, q1};
    }
    plan.removed = {TriMesh::face(h1), TriMesh::face(mesh.opp[h1]), TriMesh::face(h2), TriMesh::face(mesh.opp[h2])};
    return true;
}

bool plan_pinch(const TriMesh &mesh, int32_t a, int32_t b, int32_t c, PinchPlan &plan)
{
    plan.loop = {a, b, c};
    plan.left.clear();
    const int32_t corners[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
        const int32_t v = corners[k], to = corners[(k + 1) % 3], from = corners[(k + 2) % 3];
        const int32_t start = mesh.halfedge(v, to);
        if (start < 0 || mesh.is_boundary_vertex(v))
            return false;
        // From v -> to counter-clockwise up to v -> from: the left side. The loop's third
        // corner may not be the first step (a triangle v, to, from) nor be missed.
        int32_t h = start;
        int32_t steps = 0;
        const int32_t bound = static_cast<int32_t>(mesh.tri.size());
        while (mesh.head(h) != from) {
            if (mesh.head(TriMesh::next(h)) == from && h == start)
                return false; // (v, to, from) is a triangle
            plan.left.push_back(TriMesh::face(h));
            h = mesh.rotate_ccw(h);
            if (h == start || ++steps > bound)
                return false;
        }
        // The right side must not be a single triangle (v, from, to) either.
        if (mesh.head(TriMesh::next(h)) == to)
            return false;
    }
    std::sort(plan.left.begin(), plan.left.end());
    plan.left.erase(std::unique(plan.left.begin(), plan.left.end()), plan.left.end());
    return true;
}

} // namespace sfa

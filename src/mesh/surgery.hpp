// SPDX-License-Identifier: BSD-3-Clause
// The two changes of topology (adapt/topology_change.hpp), planned on the mesh as it is:
// which triangles go, which come, which corners are renamed. Connectivity only: whether
// the result crosses itself is the caller's to check (with the exact predicates), and
// the caller applies a plan to the triangle list and rebuilds the adjacency.
//
// - A zipper (Brochu & Bridson 2009, "Robust topological operations for dynamic explicit
//   surfaces", §5: merging) joins two sheets at two of their edges: the two triangles of
//   each edge go, which leaves two holes bounded by four edges each, and a tube of eight
//   triangles joins the holes. Two bubbles become one, or a sheet gains a handle.
// - A pinch cuts the surface along a loop of three edges that is not a triangle (a neck
//   that contraction has thinned to three vertices around): the loop's corners are
//   doubled, the triangles on one side take the copies, and each side's hole is closed by
//   a triangle. One drop becomes two, or a handle is cut.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <array>
#include <vector>

namespace sfa {

struct ZipperPlan {
    std::array<int32_t, 4> removed; // the two triangles of each edge
    std::array<Triangle, 8> tube;   // oriented as the surface around the holes
};

// The zipper of the edges of h1 and h2 (half-edges of edges with two triangles each).
// False where the result would not be a manifold: the eight corners of the four triangles
// must be distinct (the edges are more than a triangle apart), and no edge may join a
// corner of one hole to a corner of the other (the tube adds those). Of the four ways to
// join the holes, the one with the shortest sum of squared rung lengths is taken.
bool plan_zipper(const TriMesh &mesh, int32_t h1, int32_t h2, ZipperPlan &plan);

struct PinchPlan {
    std::array<int32_t, 3> loop; // a, b, c: edges a-b, b-c, c-a, no triangle a-b-c
    // The triangles around a, b and c on the left of the loop a -> b -> c (a's from a -> b
    // counter-clockwise to a -> c, and so on): they take the copies of the corners.
    std::vector<int32_t> left;
};

// The pinch along a, b, c (pairwise joined by edges, none on a boundary). False where
// a-b-c is a triangle of either orientation, or a fan does not meet the loop's other two
// corners once each (the loop would not cut it in two).
bool plan_pinch(const TriMesh &mesh, int32_t a, int32_t b, int32_t c, PinchPlan &plan);

// A triangle of the left side with the loop's corners replaced by their copies.
inline Triangle with_copies(const PinchPlan &plan, Triangle t, const std::array<int32_t, 3> &copies)
{
    for (int32_t &v : t)
        for (int k = 0; k < 3; ++k)
            if (v == plan.loop[k]) {
                v = copies[k];
                break;
            }
    return t;
}

// The triangles that close the two sides: the left side's with the copies a2, b2, c2 of
// a, b, c, then the right side's.
inline std::array<Triangle, 2> pinch_caps(const PinchPlan &plan, const std::array<int32_t, 3> &copies)
{
    const auto &[a, b, c] = plan.loop;
    return {Triangle{copies[0], copies[2], copies[1]}, Triangle{a, b, c}};
}

} // namespace sfa

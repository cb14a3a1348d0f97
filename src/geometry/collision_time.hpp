// SPDX-License-Identifier: BSD-3-Clause
// How long every vertex may move along x + t v before two triangles that share no vertex
// could meet: for collision-safe motion (motion/safe_motion) and for the volume
// correction's larger offsets (adapt/volume). Conservative by construction: a pair is let
// move only as long as a plane that separates the two triangles at the start, moving along
// its normal at one speed, still separates them; a triangle, the hull of its corners,
// stays on its side of a plane exactly as long as its corners do, which under linear
// motion is a linear condition in t. This is the separating-plane certificate of
// conservative advancement. The plane is the one that lets the pair move longest among
// the separating-axis theorem's candidates for two triangles (the two face normals and
// the nine cross products of their edges), the planes square to a face through one of
// its edges (two triangles side by side in one sheet), and the plane square to the line
// of their centres. A pair that no such plane lets move the whole step gets a second
// chance: its distance is measured as it moves (additive continuous collision detection),
// which lets layers slide along each other a hair apart, as they do at a cusp, where a
// plane fixed at the start is soon crossed by their turning.
#pragma once

#include "geometry/block_partition.hpp"
#include "mesh/tri_mesh.hpp"

#include <limits>
#include <utility>
#include <vector>

namespace sfa {

// Pairs of triangles by their numbers.
using TrianglePairs = std::vector<std::pair<int32_t, int32_t>>;

// The pair of triangles that limits a step.
struct Approach {
    double time = std::numeric_limits<double>::infinity(); // how long the pair may move
    int32_t first = -1, second = -1;                        // the two triangles, 0-based
    double gap = 0;     // their separation, along the plane's normal, at the start
    double closing = 0; // the speed at which that separation shrinks (the corners' fastest)
    double size = 0;    // the longest edge of the two
};

// The largest t <= dt (and the pair that sets it, if t < dt) for which no two triangles
// that share no vertex come closer than half their start separation, certified either
// across a plane that separates them (each may take a quarter of the gap) or, for a pair
// that plane would stop early, by measuring their distance as they move (additive
// continuous collision detection, collision_time.cpp). A pair that touches at the start
// (within round-off) may slide along its plane of contact or open, not close; pairs that
// already meet have no such plane and are not limited. The pairs are found by
// their swept boxes over [0, dt] (swept_pairs.hpp); the result does not depend on the
// number of threads. With `among`, only the pairs of which one triangle at least is in it
// (distinct triangles) are looked at. Otherwise, with `kept`, the triangles are dealt into
// blocks as it holds them, or it comes to hold them (block_partition.hpp; for a caller whose
// triangles stay the same between searches). With `within_rounding`, the pairs too near at
// the start for a separating plane to certify them in floating point (or that meet
// already) are added to it: nothing keeps x + t v, rounded corner by corner, from carrying
// one of them through the other, so the caller checks them exactly once it has the
// positions (a soak finding: a uniform translation by 140 carried two triangles 1e-14 apart
// through each other).
Approach first_approach(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt,
                        const std::vector<int32_t> *among = nullptr, BlockPartition *kept = nullptr,
                        TrianglePairs *within_rounding = nullptr);

// The same, except that a pair nearer than contact_gap times its size (its longest edge)
// that would limit the step is put into `contacts` (sorted by its triangles) instead of
// limiting it: motion/safe_motion moves the two together. `among`, `kept` and
// `within_rounding` as for first_approach.
Approach first_approach_with_contacts(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt,
                                      double contact_gap, std::vector<Approach> &contacts,
                                      const std::vector<int32_t> *among = nullptr, BlockPartition *kept = nullptr,
                                      TrianglePairs *within_rounding = nullptr);

} // namespace sfa

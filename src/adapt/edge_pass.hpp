// SPDX-License-Identifier: BSD-3-Clause
// The pattern that splitting (§4.1), contraction (§4.2) and flipping (§3.3) share, written
// once: every edge is judged in parallel on the mesh as the pass finds it; the candidates
// are put in the operation's order (the paper's: longest first, shortest first, largest
// opposite angle first), ties by their vertices so that the result never depends on the
// order they were found in; then they are applied one by one, greedily, each judged again
// only if an earlier change of the pass touched what its verdict read.
#pragma once

#include "adapt/carried_features.hpp"
#include "adapt/constraints.hpp"
#include "geometry/crossing_guard.hpp"
#include "mesh/changed_vertices.hpp"
#include "mesh/mesh_edit.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

namespace sfa {

// What every pass of an adaptation works with: the edit through which it changes the mesh
// (with every attribute and observer attached), the features carried through the call, the
// crossing guard if it is on (null otherwise), what the host pinned, and the desired edge
// length of every vertex where the host set a size field (graded, size_field.hpp; null:
// the one global l).
struct PassContext {
    MeshEdit &edit;
    const CarriedFeatures &features;
    const CrossingGuard *guard;
    const CarriedConstraints &constraints;
    const std::vector<double> *size;
};

// For each vertex, the first (lowest) of the candidates `ends` (each with ends a and b) that
// has an end within `reach` edges of it, or the number of candidates if none has. A
// candidate's own ends count it; those of a vertex no longer in the mesh are not looked at.
template <class Candidate>
std::vector<int32_t> earliest_candidate_near(const TriMesh &mesh, const std::vector<Candidate> &ends, int32_t reach)
{
    const int32_t n = mesh.num_vertices(), count = static_cast<int32_t>(ends.size());
    std::vector<int32_t> earliest(n, count), spread(n);
    for (int32_t k = count - 1; k >= 0; --k)
        earliest[ends[k].a] = earliest[ends[k].b] = k;
    // An edge further each round: the least over the neighbours.
    for (int32_t round = 0; round < reach; ++round) {
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int32_t v = 0; v < n; ++v) {
            spread[v] = earliest[v];
            if (mesh.v2h[v] >= 0)
                mesh.for_each_neighbour(v, [&](int32_t w, int32_t) { spread[v] = std::min(spread[v], earliest[w]); });
        }
        earliest.swap(spread);
    }
    return earliest;
}

// Runs one pass of `operation`, which supplies:
//   struct Plan;                        what its full check found (where a merged vertex goes, say)
//   static constexpr bool plans_ahead;  true: the full check is made in parallel before
//                                       the serial phase (a costly check), for every
//                                       candidate but those an earlier one lies near:
//   static constexpr int32_t changes_reach;  (with plans_ahead) how many edges from a
//                                       candidate's ends the change an earlier candidate
//                                       makes at its own ends can change this one's verdict
//   bool wanted(int32_t h, double &order) const;
//       the first judgement, in parallel, of h: a boundary half-edge or the lower half of
//       an interior edge; a smaller order goes first
//   int32_t locate(int32_t a, int32_t b) const;
//       the edge a-b's half-edge as the mesh now is, or -1 if it is gone
//   bool plan(int32_t h, Plan &plan) const;
//       the full check on the mesh as it now is (in parallel when plans_ahead)
//   bool may_have_changed(int32_t h, const ChangedVertices &changed) const;
//       true if a change since the pass began (the fans marked in `changed`) can have
//       changed the verdict on h: then it is judged again
//   bool apply(MeshEdit &edit, int32_t h, const Plan &plan);
//       the change, through the edit; false if refused at the last moment
// Returns the number of changes made. Nothing in the parallel phases may throw.
template <class Operation>
int32_t run_edge_pass(MeshEdit &edit, Operation &operation)
{
    const TriMesh &mesh = edit.mesh();
    const int32_t halfedges = 3 * mesh.num_triangles();
    std::vector<char> wanted(halfedges, 0);
    std::vector<double> order(halfedges);
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 1024)
    for (int32_t h = 0; h < halfedges; ++h)
        if (mesh.opp[h] < 0 || mesh.opp[h] > h) // each edge once
            wanted[h] = operation.wanted(h, order[h]);

    struct Candidate {
        double order;
        int32_t a, b;
    };
    std::vector<Candidate> candidates;
    for (int32_t h = 0; h < halfedges; ++h)
        if (wanted[h])
            candidates.push_back({order[h], mesh.tail(h), mesh.head(h)});
    std::sort(candidates.begin(), candidates.end(), [](const Candidate &x, const Candidate &y) {
        return std::tie(x.order, x.a, x.b) < std::tie(y.order, y.a, y.b);
    });

    const int32_t count = static_cast<int32_t>(candidates.size());
    std::vector<typename Operation::Plan> plans(count);
    // The verdict of each candidate's full check: 1 or 0, or not_planned. Without
    // plans_ahead, `wanted` was the whole verdict.
    constexpr int8_t not_planned = -1;
    std::vector<int8_t> planned(count, 1);
    if constexpr (Operation::plans_ahead) {
        // A candidate with an earlier one within changes_reach edges is nearly always
        // judged again in the serial phase, once that one is made: its plan ahead would be
        // thrown away. (Contraction on Enright: of 139k candidates, 91.5k were planned again,
        // every one with an earlier candidate within three edges, and only 0.4k others had
        // one.) So it is planned there only. Finding them looks at every vertex: where the
        // candidates are few (fewer than one in 16 vertices), all are planned ahead.
        const bool few = static_cast<int64_t>(count) * 16 < mesh.num_vertices();
        const std::vector<int32_t> earliest =
            few ? std::vector<int32_t>() : earliest_candidate_near(mesh, candidates, Operation::changes_reach);
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 64)
        for (int32_t k = 0; k < count; ++k) {
            if (!few && (earliest[candidates[k].a] < k || earliest[candidates[k].b] < k)) {
                planned[k] = not_planned;
                continue;
            }
            const int32_t h = operation.locate(candidates[k].a, candidates[k].b);
            planned[k] = h >= 0 && operation.plan(h, plans[k]);
        }
    }

    edit.begin_changes();
    ChangedVertices changed(mesh.num_vertices());
    const Attached listening(edit, changed);
    int32_t applied = 0;
    for (int32_t k = 0; k < count; ++k) {
        const int32_t h = operation.locate(candidates[k].a, candidates[k].b);
        if (h < 0)
            continue;
        bool allowed = planned[k] == 1;
        if (planned[k] == not_planned || operation.may_have_changed(h, changed))
            allowed = operation.plan(h, plans[k]);
        if (allowed && operation.apply(edit, h, plans[k]))
            ++applied;
    }
    return applied;
}

} // namespace sfa

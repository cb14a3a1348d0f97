// SPDX-License-Identifier: BSD-3-Clause
// Unit test of run_edge_pass (edge_pass.hpp): it plans candidates ahead, in parallel, on the
// mesh as the pass found it, and plans one again at its turn only where an earlier change
// may have changed its verdict (may_have_changed), or where an earlier candidate lies within
// changes_reach. The pass must make exactly the changes that planning each candidate at
// its own turn makes, for any number of threads.
#include "adapt/edge_pass.hpp"
#include "mesh/edge_collapse.hpp"
#include "mesh/validate.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstddef>
#include <setjmp.h>
#include <tuple>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

using namespace sfa;

namespace {

// Contracts an edge (near its midpoint) where it is shorter than `ratio` times the mean of
// the other edges at its two ends: a verdict that reads both ends' fans, which the
// contractions of nearby edges change, so that many candidates of a pass must be planned
// again after earlier ones.
class ShortEdges {
public:
    struct Plan {
        Vec3 merged = Vec3::Zero();
    };
    static constexpr bool plans_ahead = true;
    // Less than the verdict reads: may_have_changed must catch what earlier changes reach.
    static constexpr int32_t changes_reach = 0;

    ShortEdges(const TriMesh &mesh, double ratio) : mesh_(mesh), ratio_(ratio) {}

    bool wanted(int32_t h, double &order) const
    {
        if (!short_enough(h))
            return false;
        order = length(mesh_.tail(h), mesh_.head(h));
        return true;
    }
    int32_t locate(int32_t a, int32_t b) const
    {
        if (is_dead_vertex(mesh_, a) || is_dead_vertex(mesh_, b))
            return -1;
        const int32_t h = mesh_.halfedge(a, b);
        return h >= 0 ? h : mesh_.halfedge(b, a);
    }
    bool plan(int32_t h, Plan &plan) const
    {
        if (!short_enough(h) || !collapse_keeps_manifold(mesh_, h))
            return false;
        // The midpoint drawn a tenth of the way to the mean of the ends' neighbours: a
        // plan that any change around the ends changes, not only the verdict near its
        // threshold.
        const int32_t a = mesh_.tail(h), b = mesh_.head(h);
        const Vec3 midpoint = (mesh_.pos[a] + mesh_.pos[b]) / 2;
        Vec3 sum = Vec3::Zero();
        int count = 0;
        for (int32_t end : {a, b})
            mesh_.for_each_neighbour(end, [&](int32_t w, int32_t) {
                sum += mesh_.pos[w];
                ++count;
            });
        plan.merged = midpoint + 0.1 * (sum / count - midpoint);
        return true;
    }
    // A contraction marks the kept vertex and its neighbours: the verdict read the ends
    // and their neighbours.
    bool may_have_changed(int32_t h, const ChangedVertices &changed) const
    {
        bool marked = false;
        for (int32_t end : {mesh_.tail(h), mesh_.head(h)}) {
            marked = marked || changed[end];
            mesh_.for_each_neighbour(end, [&](int32_t w, int32_t) { marked = marked || changed[w]; });
        }
        return marked;
    }
    bool apply(MeshEdit &edit, int32_t h, const Plan &plan)
    {
        edit.collapse(h, plan.merged);
        return true;
    }

private:
    double length(int32_t a, int32_t b) const { return (mesh_.pos[b] - mesh_.pos[a]).norm(); }
    bool short_enough(int32_t h) const
    {
        const int32_t a = mesh_.tail(h), b = mesh_.head(h);
        double sum = 0;
        int count = 0;
        for (int32_t end : {a, b})
            mesh_.for_each_neighbour(end, [&](int32_t w, int32_t) {
                if (w != a && w != b) {
                    sum += length(end, w);
                    ++count;
                }
            });
        return count > 0 && length(a, b) < ratio_ * sum / count;
    }

    const TriMesh &mesh_;
    const double ratio_;
};

// The pass as edge_pass.hpp defines it, without its shortcuts: every edge judged on the
// mesh as the pass finds it, the candidates in order, each planned at its turn.
int32_t planned_at_every_turn(MeshEdit &edit, ShortEdges &operation)
{
    const TriMesh &mesh = edit.mesh();
    struct Candidate {
        double order;
        int32_t a, b;
    };
    std::vector<Candidate> candidates;
    for (int32_t h = 0; h < 3 * mesh.num_triangles(); ++h)
        if (double order = 0; (mesh.opp[h] < 0 || mesh.opp[h] > h) && operation.wanted(h, order))
            candidates.push_back({order, mesh.tail(h), mesh.head(h)});
    std::sort(candidates.begin(), candidates.end(), [](const Candidate &x, const Candidate &y) {
        return std::tie(x.order, x.a, x.b) < std::tie(y.order, y.a, y.b);
    });
    edit.begin_changes();
    int32_t applied = 0;
    for (const Candidate &c : candidates) {
        ShortEdges::Plan plan;
        const int32_t h = operation.locate(c.a, c.b);
        if (h >= 0 && operation.plan(h, plan) && operation.apply(edit, h, plan))
            ++applied;
    }
    return applied;
}

// A jittered sphere after one pass of ShortEdges, compacted (run_edge_pass's, or with
// `reference` planned_at_every_turn's); `made`: its contractions.
TriMesh after_pass(bool reference, int threads, int32_t &made)
{
    sfa_mesh_data sphere = shape_jittered_icosphere(4, 1.0, 0.45, 7);
    TriMesh mesh = validated_mesh(MeshInput{sphere.nverts, sphere.xyz, sphere.ntris, sphere.tris, 0, false});
    mesh_free(&sphere);
    const ThreadLimit limit(threads);
    MeshEdit edit(mesh);
    ShortEdges operation(mesh, 0.8);
    made = reference ? planned_at_every_turn(edit, operation) : run_edge_pass(edit, operation);
    edit.compact();
    return mesh;
}

void plans_made_ahead_make_the_changes_of_planning_at_every_turn(void **)
{
    int32_t expected_count = 0;
    const TriMesh expected = after_pass(true, 1, expected_count);
    // Enough contractions, near each other, for many plans made ahead to be overtaken.
    assert_true(expected_count > 200);
    for (int threads : {1, 2, 3}) {
        int32_t count = 0;
        const TriMesh mesh = after_pass(false, threads, count);
        assert_int_equal(count, expected_count);
        assert_true(mesh.tri == expected.tri);
        assert_true(mesh.pos == expected.pos);
    }
}

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(plans_made_ahead_make_the_changes_of_planning_at_every_turn),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

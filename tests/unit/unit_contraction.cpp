// SPDX-License-Identifier: BSD-3-Clause
// Unit test of the contraction's rule for two feature vertices (contract.cpp,
// merged_position): they merge only where they count as one feature. Nearer than r l they
// do anywhere; the ends of a needle at a cusp (needle_at_cusp: nearer than 2 r l, an angle
// below theta_s opposite) only where both are near a facing sheet, not on a CAD model's
// features.
#include "adapt/contract.hpp"
#include "adapt/edge_pass.hpp"
#include "adapt/settings.hpp"
#include "geometry/guard_listener.hpp"
#include "mesh/validate.hpp"

#include <cstdarg>
#include <cstddef>
#include <deque>
#include <setjmp.h>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

using namespace sfa;

namespace {

// A flat 6 x 6 grid of unit cells whose vertex (3, 3) has slid to 0.15 of the way from
// (2, 3): the edge between them (0.15 l at l = 1, more than r l = 0.1) is the short edge of
// two needles of 8.5 and 4.6 degrees, whose longest edges exceed l, so that no criterion
// of §4.2 asks for its contraction. Both ends are ridge vertices of different curves (the
// edge is no ridge edge). Returns the number of contractions of one pass, with every
// vertex watched by the crossing guard as near a facing sheet, or only the features.
int32_t contractions_of_the_needle(bool near_sheet, int32_t &vertices_left)
{
    sfa_mesh_data grid = shape_grid(6, 6, 1.0);
    const int32_t a = 3 * 7 + 2, b = 3 * 7 + 3;
    grid.xyz[3 * b] = 2.15;
    TriMesh mesh = validated_mesh(MeshInput{grid.nverts, grid.xyz, grid.ntris, grid.tris, 0, false});
    mesh_free(&grid);

    const Parameters parameters;
    SurfaceAnalysis geometry = analyze_surface(mesh, feature_thresholds(parameters), metric_bounds(parameters));
    Features features;
    features.rank.assign(mesh.pos.size(), 0);
    features.rank[a] = features.rank[b] = 1;
    features.ridge_halfedge.assign(mesh.opp.size(), 0);
    CarriedFeatures carried(features);

    CrossingGuard guard(std::vector<char>(mesh.pos.size(), near_sheet ? 1 : 0));
    guard.watch_features(features.rank);
    GuardListener listener(guard);
    MeshEdit edit(mesh);
    edit.attach(carried);
    edit.attach(listener);
    const CarriedConstraints no_constraints;
    const PassContext context{edit, carried, &guard, no_constraints, nullptr};
    int64_t clearance_tests = 0;
    const int32_t made = contraction_pass(context, geometry, repair_settings(parameters, 1.0), clearance_tests);
    edit.compact();
    vertices_left = mesh.num_vertices();
    return made;
}

void the_ends_of_a_needle_merge_near_a_facing_sheet_only(void **)
{
    int32_t left = 0;
    assert_int_equal(contractions_of_the_needle(true, left), 1);
    assert_int_equal(left, 48);
    assert_int_equal(contractions_of_the_needle(false, left), 0);
    assert_int_equal(left, 49);
}

// earliest_candidate_near (edge_pass.hpp), which decides which contraction candidates are
// planned ahead, against a search of each candidate's surroundings edge by edge.
void earliest_candidate_near_finds_the_first_within_reach(void **)
{
    sfa_mesh_data grid = shape_grid(8, 8, 1.0);
    const TriMesh mesh = validated_mesh(MeshInput{grid.nverts, grid.xyz, grid.ntris, grid.tris, 0, false});
    mesh_free(&grid);
    struct Ends {
        int32_t a, b;
    };
    const std::vector<Ends> candidates = {{40, 41}, {10, 11}, {12, 21}, {70, 71}, {41, 42}};
    const int32_t n = mesh.num_vertices(), count = static_cast<int32_t>(candidates.size());
    for (int32_t reach = 0; reach <= 3; ++reach) {
        const std::vector<int32_t> earliest = earliest_candidate_near(mesh, candidates, reach);
        std::vector<int32_t> expected(n, count);
        for (int32_t k = count - 1; k >= 0; --k) {
            std::vector<int32_t> hops(n, -1);
            std::deque<int32_t> queue = {candidates[k].a, candidates[k].b};
            hops[candidates[k].a] = hops[candidates[k].b] = 0;
            while (!queue.empty()) {
                const int32_t v = queue.front();
                queue.pop_front();
                expected[v] = k;
                if (hops[v] < reach)
                    mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
                        if (hops[w] < 0) {
                            hops[w] = hops[v] + 1;
                            queue.push_back(w);
                        }
                    });
            }
        }
        for (int32_t v = 0; v < n; ++v)
            if (earliest[v] != expected[v])
                fail_msg("reach %d, vertex %d: %d, expected %d", reach, v, earliest[v], expected[v]);
    }
}

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_ends_of_a_needle_merge_near_a_facing_sheet_only),
        cmocka_unit_test(earliest_candidate_near_finds_the_first_within_reach),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

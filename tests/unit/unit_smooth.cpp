// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the smoothing sweep's re-check of its own moves (§3.2): a move that folds a
// triangle is not made, and the re-check ends also where a triangle was flat before any
// move (it used to stop that triangle's corners again and again, for ever), and the
// crossing guard's re-check asks again a face whose corners it stopped.
#include "adapt/settings.hpp"
#include "adapt/smooth.hpp"
#include "geometry/crossing_guard.hpp"
#include "geometry/self_intersection.hpp"
#include "mesh/validate.hpp"
#include "motion/fold_time.hpp"

#include <cstdarg>
#include <cstddef>
#include <setjmp.h>
#include <unistd.h>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "mesh_formats.h"
#include "support/shapes.h"
}

using namespace sfa;

namespace {

const FeatureThresholds default_thresholds = feature_thresholds(Parameters());
const MetricBounds default_bounds = metric_bounds(Parameters());

TriMesh jittered_sphere()
{
    sfa_mesh_data m = shape_jittered_icosphere(2, 1.0, 0.3, 11);
    TriMesh mesh = validated_mesh(MeshInput{m.nverts, m.xyz, m.ntris, m.tris, 0, false});
    mesh_free(&m);
    return mesh;
}

void a_triangle_flat_before_the_sweep_does_not_stop_it(void **)
{
    // A hang ends the program (SIGALRM) instead of stalling the run.
    alarm(60);
    TriMesh mesh = jittered_sphere();
    // Vertex c onto vertex a: the two triangles on edge (a, c) are exactly flat before any
    // move, as a collapsed bubble's are. No move of other vertices unfolds them.
    const int32_t a = mesh.tri[0][0], c = mesh.tri[0][2];
    mesh.pos[c] = mesh.pos[a];
    std::vector<int32_t> flat;
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        if ((mesh.pos[mesh.tri[t][1]] - mesh.pos[mesh.tri[t][0]])
                .cross(mesh.pos[mesh.tri[t][2]] - mesh.pos[mesh.tri[t][0]])
                .squaredNorm() == 0)
            flat.push_back(t);
    assert_int_equal(flat.size(), 2);

    const SurfaceAnalysis analysis = analyze_surface(mesh, default_thresholds, default_bounds);
    const std::vector<Vec3> moved = smoothing_sweep(mesh, analysis);
    alarm(0);

    // The flat triangles' corners stay; the rest of the surface is smoothed, and no triangle
    // that moved is folded.
    for (int32_t t : flat)
        for (int32_t v : mesh.tri[t])
            assert_true(moved[v] == mesh.pos[v]);
    int32_t moving = 0;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        moving += moved[v] != mesh.pos[v];
    print_message("%d of %d vertices moved\n", moving, mesh.num_vertices());
    assert_true(moving > mesh.num_vertices() / 2);
    assert_int_equal(first_folded_moved_triangle(mesh, moved), -1);
}

void only_moved_triangles_count_as_folds(void **)
{
    TriMesh mesh = jittered_sphere();
    const int32_t a = mesh.tri[0][0], c = mesh.tri[0][2];
    mesh.pos[c] = mesh.pos[a];
    std::vector<Vec3> moved = mesh.pos;
    // Nothing moved: the flat triangles are flat, but no move folded them.
    assert_int_equal(first_folded_triangle(mesh, moved), 0);
    assert_int_equal(first_folded_moved_triangle(mesh, moved), -1);
    // A vertex of triangle 0 moves: now it counts.
    moved[mesh.tri[0][1]] += Vec3(1e-3, 0, 0);
    assert_int_equal(first_folded_moved_triangle(mesh, moved), 0);
}

// A face whose corners the re-check stops is back where it was: a face that moved and was
// asked only against where that one would have gone may meet it there. Part of a pleat of
// the vortex flow (T = 6, topology change, t = 5.895), thinner than an edge: the sweep
// carried two faces through two others (4 crossing pairs) until such a face was asked
// again.
void a_face_stopped_where_it_was_is_asked_again(void **)
{
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(mesh_file_read("tests/unit/data/pleat-before-a-sweep.obj", &m, nullptr, err, sizeof err), 0);
    TriMesh mesh = validated_mesh(MeshInput{m.nverts, m.xyz, m.ntris, m.tris, 0, false});
    mesh_free(&m);
    const SurfaceAnalysis analysis = analyze_surface(mesh, default_thresholds, default_bounds);
    CrossingGuard guard(near_facing_sheet(mesh));
    guard.watch_features(analysis.features.rank);
    assert_int_equal(self_intersection_count(mesh), 0);
    const std::vector<Vec3> before = mesh.pos;
    mesh.pos = smoothing_sweep(mesh, analysis, 0, &guard);
    assert_true(mesh.pos != before); // the sweep still smooths
    assert_int_equal(self_intersection_count(mesh), 0);
}

// Sweeps leave a fan near its equilibrium where it is (smooth.cpp, settled_imbalance):
// a jittered sphere settles, after which a sweep moves nothing; a vertex pushed a fifth of
// an edge along the surface moves back, and only the fans that contain it are looked at
// again. (Without the rule the Jacobi iteration only converges: every sweep moves every
// vertex a little, and lifts it onto a fitted quadric.)
void a_settled_fan_stays_where_it_is(void **)
{
    TriMesh mesh = jittered_sphere();
    int32_t sweeps = 0;
    for (;; ++sweeps) {
        assert_true(sweeps < 50);
        const std::vector<Vec3> moved =
            smoothing_sweep(mesh, analyze_surface(mesh, default_thresholds, default_bounds));
        if (moved == mesh.pos)
            break;
        mesh.pos = moved;
    }
    print_message("settled after %d sweeps\n", sweeps);

    const int32_t pushed = 0;
    Vec3 along = Vec3::Zero();
    double edge = 0;
    int32_t valence = 0;
    mesh.for_each_neighbour(pushed, [&](int32_t w, int32_t) {
        if (valence == 0)
            along = mesh.pos[w] - mesh.pos[pushed];
        edge += (mesh.pos[w] - mesh.pos[pushed]).norm();
        ++valence;
    });
    const Vec3 settled = mesh.pos[pushed];
    mesh.pos[pushed] = (settled + 0.2 * edge / valence * along.normalized()).normalized(); // still on the sphere
    const double pushed_by = (mesh.pos[pushed] - settled).norm();
    const std::vector<Vec3> moved = smoothing_sweep(mesh, analyze_surface(mesh, default_thresholds, default_bounds));
    assert_true((moved[pushed] - settled).norm() < 0.5 * pushed_by);
    std::vector<char> in_a_fan_with_it(mesh.num_vertices(), 0);
    in_a_fan_with_it[pushed] = 1;
    mesh.for_each_neighbour(pushed, [&](int32_t w, int32_t) { in_a_fan_with_it[w] = 1; });
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        if (!in_a_fan_with_it[v])
            assert_true(moved[v] == mesh.pos[v]);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_triangle_flat_before_the_sweep_does_not_stop_it),
        cmocka_unit_test(only_moved_triangles_count_as_folds),
        cmocka_unit_test(a_face_stopped_where_it_was_is_asked_again),
        cmocka_unit_test(a_settled_fan_stays_where_it_is),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of the crossing guard: which vertices it watches (those near a facing sheet), which
// faces it reports as passing through a watched one, and, through the public API, that no
// smoothing or adaptation carries a surface in a violent flow through itself.
#include "geometry/crossing_guard.hpp"
#include "mesh/validate.hpp"
#include "surfadapt.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdlib>
#include <setjmp.h>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "icosphere.h"
#include "support/shapes.h"
}

using namespace sfa;

namespace {

TriMesh box_mesh(double thickness)
{
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, thickness};
    sfa_mesh_data box = shape_box(8, lo, hi);
    TriMesh mesh = validated_mesh(MeshInput{box.nverts, box.xyz, box.ntris, box.tris, 0, false});
    mesh_free(&box);
    return mesh;
}

int32_t count(const std::vector<char> &marks)
{
    int32_t n = 0;
    for (char m : marks)
        n += m != 0;
    return n;
}

void a_sheet_thinner_than_an_edge_is_watched_a_thick_body_is_not(void **)
{
    // Edges of 1/8 on the large faces: a slab 1/50 thick has its two large faces nearer
    // than an edge, facing away from each other.
    const TriMesh slab = box_mesh(0.02);
    const std::vector<char> thin = near_facing_sheet(slab);
    assert_int_equal(thin.size(), slab.pos.size());
    for (int32_t v = 0; v < slab.num_vertices(); ++v)
        if (slab.pos[v].x() > 0.2 && slab.pos[v].x() < 0.8 && slab.pos[v].y() > 0.2 && slab.pos[v].y() < 0.8)
            assert_true(thin[v]); // the middle of both large faces

    // The unit cube's opposite faces are eight edges apart; adjacent faces meet at right
    // angles (their normals do not face each other).
    assert_int_equal(count(near_facing_sheet(box_mesh(1))), 0);
}

// The rule of near_facing_sheet by brute force, on a sphere whose one side is pressed flat
// (two sheets facing each other nearer than an edge there, a smooth surface elsewhere):
// of every two vertices that are not neighbours, whose normals
// point against each other and that are nearer than the sum of their longest edges, one
// at least is watched. The search looks only near vertices whose normals may face; this
// checks that it leaves out none of them.
void every_two_vertices_whose_fans_may_meet_are_watched(void **)
{
    const double centre[3] = {0, 0, 0};
    int32_t nverts = 0, ntris = 0;
    double *xyz = nullptr;
    int32_t *tris = nullptr;
    assert_int_equal(geodesic_sphere(40, 1, centre, &nverts, &xyz, &ntris, &tris), 0);
    for (int32_t v = 0; v < nverts; ++v) // x > 0.55 pressed to a hundredth, x < 0.3 a sphere
        xyz[3 * v + 2] *= std::clamp(1 - (xyz[3 * v] - 0.3) / 0.25, 0.01, 1.0);
    const TriMesh mesh = validated_mesh(MeshInput{nverts, xyz, ntris, tris, 0, false});
    std::free(xyz);
    std::free(tris);
    const int32_t n = mesh.num_vertices();
    std::vector<Vec3> normal(n, Vec3::Zero());
    std::vector<double> reach(n, 0);
    for (int32_t v = 0; v < n; ++v)
        mesh.for_each_outgoing(v, [&](int32_t h) {
            const Triangle &t = mesh.tri[TriMesh::face(h)];
            normal[v] += (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]);
            reach[v] = std::max(reach[v], (mesh.pos[mesh.head(h)] - mesh.pos[v]).norm());
        });
    const std::vector<char> watched = near_facing_sheet(mesh);
    int32_t pairs = 0;
    for (int32_t v = 0; v < n; ++v)
        for (int32_t w = v + 1; w < n; ++w) {
            if (!(normal[v].dot(normal[w]) < 0) || !((mesh.pos[w] - mesh.pos[v]).norm() < reach[v] + reach[w]))
                continue;
            bool neighbours = false;
            mesh.for_each_neighbour(v, [&](int32_t u, int32_t) { neighbours = neighbours || u == w; });
            if (neighbours)
                continue;
            ++pairs;
            if (!watched[v] && !watched[w])
                fail_msg("vertices %d and %d may meet, but neither is watched", v, w);
        }
    print_message("%d pairs of vertices may meet; %d of %d vertices watched\n", pairs, count(watched), n);
    assert_true(pairs > 100);
    assert_true(count(watched) < n / 2); // the sphere's side is not
}

// The face of the plane z = `z` whose centre is nearest to the middle of the slab.
int32_t middle_face_at(const TriMesh &mesh, double z)
{
    int32_t best = -1;
    double best_distance = 1e300;
    for (int32_t f = 0; f < mesh.num_triangles(); ++f) {
        const Triangle &t = mesh.tri[f];
        if (mesh.pos[t[0]].z() != z || mesh.pos[t[1]].z() != z || mesh.pos[t[2]].z() != z)
            continue;
        const Vec3 centre = (mesh.pos[t[0]] + mesh.pos[t[1]] + mesh.pos[t[2]]) / 3;
        const double distance = (centre - Vec3(0.5, 0.5, z)).norm();
        if (distance < best_distance) {
            best = f;
            best_distance = distance;
        }
    }
    return best;
}

void a_face_moved_through_the_other_side_of_a_sheet_crosses_it(void **)
{
    TriMesh slab = box_mesh(0.02);
    CrossingGuard guard(near_facing_sheet(slab));
    guard.index_faces(slab, slab.pos);
    const Triangle t = slab.tri[middle_face_at(slab, 0.02)];
    const auto lowered = [&](double dz) { // one corner
        Vec3 at[3] = {slab.pos[t[0]] - Vec3(0, 0, dz), slab.pos[t[1]], slab.pos[t[2]]};
        return guard.crosses(slab, slab.pos, t, at);
    };
    assert_false(lowered(0));     // as it is: meets only faces it shares a vertex with
    assert_false(lowered(0.015)); // still above the bottom
    assert_true(lowered(0.03));   // through the bottom

    // A face an operation moved far is found where it is now once entered again.
    const int32_t g = middle_face_at(slab, 0);
    Vec3 centre = Vec3::Zero();
    for (int32_t v : slab.tri[g]) {
        slab.pos[v].z() = 5;
        centre += slab.pos[v] / 3;
    }
    const Vec3 piercing[3] = {centre - Vec3(0, 0, 0.01), centre + Vec3(0.01, 0, 0.01), centre + Vec3(-0.01, 0, 0.01)};
    assert_false(guard.crosses(slab, slab.pos, t, piercing));
    guard.refresh(slab, slab.pos, g);
    assert_true(guard.crosses(slab, slab.pos, t, piercing));
}

// faces_meeting compares each pair once where crosses() asks from each face: both must name
// the same faces. The slab's top is pushed down in a ring of waves, so that some of its
// faces pass through the bottom and others only come near it; every other face asks.
void faces_meeting_names_the_faces_crosses_finds(void **)
{
    const TriMesh slab = box_mesh(0.02);
    CrossingGuard guard(near_facing_sheet(slab));
    std::vector<Vec3> moved = slab.pos;
    for (Vec3 &p : moved)
        if (p.z() == 0.02)
            p.z() -= 0.03 * std::max(0.0, std::sin(40 * (p - Vec3(0.5, 0.5, 0)).norm()));
    const std::vector<int32_t> listed = guard.list_faces(slab, moved);
    std::vector<char> asking(listed.size());
    for (size_t m = 0; m < listed.size(); ++m)
        asking[m] = m % 2;
    const std::vector<char> met = guard.faces_meeting(slab, moved, asking);
    assert_true(guard.index_faces(slab, moved) == listed);
    int32_t meeting = 0;
    for (size_t m = 0; m < listed.size(); ++m) {
        const Triangle &t = slab.tri[listed[m]];
        const Vec3 at[3] = {moved[t[0]], moved[t[1]], moved[t[2]]};
        const bool crosses = asking[m] && guard.crosses(slab, moved, t, at);
        if (static_cast<bool>(met[m]) != crosses)
            fail_msg("face %d: faces_meeting says %d, crosses() %d", listed[m], met[m], crosses);
        meeting += crosses;
    }
    print_message("%d of %zu listed faces meet another\n", meeting, listed.size());
    assert_true(meeting > 10 && meeting < static_cast<int32_t>(listed.size()) / 2 - 10); // some of those asking do not
}

// faces_meeting keeps the pairs it compared for its next call (a sweep's check, then the
// volume offsets' a hair further): after a move within its margin (a thousandth of each
// face's size) it compares only those, after a larger one it looks again, and either way
// it names what a new guard names. The slab is pressed to a hundred-thousandth of its
// width, its top and bottom nearer than the margin but apart; then one vertex of the top
// is pushed through the bottom by less than the margin, and the same vertex by more.
void faces_meeting_after_a_small_move_names_what_a_new_guard_names(void **)
{
    TriMesh slab = box_mesh(0.02);
    for (Vec3 &p : slab.pos)
        p.z() *= 5e-4;
    const auto all_of = [](size_t n) { return std::vector<char>(n, 1); };
    CrossingGuard guard(near_facing_sheet(slab));
    const size_t listed = guard.list_faces(slab, slab.pos).size();
    assert_int_equal(count(guard.faces_meeting(slab, slab.pos, all_of(listed))), 0);

    int32_t middle = 0;
    for (int32_t v = 0; v < slab.num_vertices(); ++v)
        if (slab.pos[v].z() > 0 &&
            (slab.pos[v] - Vec3(0.5, 0.5, 0)).norm() < (slab.pos[middle] - Vec3(0.5, 0.5, 0)).norm())
            middle = v;
    for (const double push : {5e-5, 1e-2}) {
        std::vector<Vec3> moved = slab.pos;
        moved[middle].z() -= push;
        assert_int_equal(guard.list_faces(slab, moved).size(), listed);
        const std::vector<char> met = guard.faces_meeting(slab, moved, all_of(listed));
        CrossingGuard fresh(near_facing_sheet(slab));
        fresh.list_faces(slab, moved);
        assert_true(met == fresh.faces_meeting(slab, moved, all_of(listed)));
        // The pushed vertex's fan meets the bottom, and so the bottom's faces it crosses.
        print_message("pushed by %g: %d faces meet another\n", push, count(met));
        assert_true(count(met) >= 6);
    }
}

void watched_vertices_follow_the_numbering(void **)
{
    CrossingGuard guard(std::vector<char>{0, 1, 0, 1});
    guard.add_vertex_between(0, 3); // 4
    guard.renumber({-1, 2, 0, -1, 1}); // 1 -> 2, 2 -> 0, 4 -> 1; 0 and 3 gone
    assert_int_equal(guard.watched().size(), 3);
    assert_false(guard.watches(0));
    assert_true(guard.watches(1));
    assert_true(guard.watches(2));
}

// A feature is watched, but is no vertex near a facing sheet; a new vertex is near a sheet
// where an end of its edge is, else watched where an end is.
void features_are_watched_but_not_near_a_sheet(void **)
{
    CrossingGuard guard(std::vector<char>{0, 1, 0, 0});
    guard.watch_features({1, 1, 0, 0});
    assert_true(guard.watches(0) && !guard.near_sheet(0));
    assert_true(guard.watches(1) && guard.near_sheet(1));
    assert_false(guard.watches(2));
    guard.add_vertex_between(0, 1); // 4
    guard.add_vertex_between(0, 2); // 5
    guard.add_vertex_between(2, 3); // 6
    assert_true(guard.near_sheet(4));
    assert_true(guard.watches(5) && !guard.near_sheet(5));
    assert_false(guard.watches(6));
}

constexpr double pi = 3.14159265358979323846;

// The vortex flow of period 6 (paper §5.2.3), as a host would evaluate it.
void vortex_velocity(void *, int32_t n, const double *xyz, double t, double *vel)
{
    const double m = std::cos(pi * t / 6);
    const auto sq = [](double x) { return x * x; };
    for (int32_t i = 0; i < n; ++i) {
        const double x = pi * xyz[3 * i], y = pi * xyz[3 * i + 1], z = pi * xyz[3 * i + 2];
        vel[3 * i] = m * sq(std::sin(x)) * (std::sin(2 * z) - std::sin(2 * y));
        vel[3 * i + 1] = m * sq(std::sin(y)) * (std::sin(2 * x) - std::sin(2 * z));
        vel[3 * i + 2] = m * sq(std::sin(z)) * (std::sin(2 * y) - std::sin(2 * x));
    }
}

double crossings(const sfa_surface *s)
{
    double count = -1;
    assert_int_equal(sfa_measure(s, SFA_MEASURE_SELF_INTERSECTIONS, &count), SFA_OK);
    return count;
}

void remeshing_never_carries_a_thin_filament_through_itself(void **)
{
    // A coarse sphere (1,442 vertices) through the vortex of period 6 with the flows'
    // schedule: its filaments become far thinner than an edge. In the last quarter of the
    // period, as they fold back, remeshing without the guard crossed the surface in
    // several calls. Advection itself may bring two sheets nearer than the mesh can tell
    // apart (that is the flow's doing); no smoothing or adaptation may add a crossing.
    const double centre[3] = {0.5, 0.75, 0.5};
    int32_t nverts = 0, ntris = 0;
    double *xyz = nullptr;
    int32_t *tris = nullptr;
    assert_int_equal(geodesic_sphere(12, 0.15, centre, &nverts, &xyz, &ntris, &tris), 0);
    sfa_surface *s = nullptr;
    assert_int_equal(sfa_create(&s), SFA_OK);
    assert_int_equal(sfa_set_mesh(s, nverts, xyz, ntris, tris, 0), SFA_OK);
    std::free(xyz);
    std::free(tris);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_ADAPT_PASSES, 1), SFA_OK);
    const double dt = 0.015;
    double t = 0;
    for (int step = 1; step <= 400; ++step) {
        int substeps = 0;
        while (t < step * dt - 1e-12) {
            double taken = 0;
            assert_int_equal(sfa_advect(s, vortex_velocity, nullptr, t, step * dt - t, &taken), SFA_OK);
            t += taken;
            ++substeps;
        }
        const bool watch = step > 300;
        const double before = watch ? crossings(s) : 0;
        const bool adapt = step % 4 == 0 || substeps > 2;
        assert_int_equal(adapt ? sfa_adapt(s) : sfa_smooth(s, 1), SFA_OK);
        if (watch && crossings(s) > before)
            fail_msg("step %d: %s took the crossings from %g to %g", step, adapt ? "sfa_adapt" : "sfa_smooth", before,
                     crossings(s));
    }
    sfa_destroy(s);
}

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_sheet_thinner_than_an_edge_is_watched_a_thick_body_is_not),
        cmocka_unit_test(every_two_vertices_whose_fans_may_meet_are_watched),
        cmocka_unit_test(a_face_moved_through_the_other_side_of_a_sheet_crosses_it),
        cmocka_unit_test(faces_meeting_names_the_faces_crosses_finds),
        cmocka_unit_test(faces_meeting_after_a_small_move_names_what_a_new_guard_names),
        cmocka_unit_test(watched_vertices_follow_the_numbering),
        cmocka_unit_test(features_are_watched_but_not_near_a_sheet),
        cmocka_unit_test(remeshing_never_carries_a_thin_filament_through_itself),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

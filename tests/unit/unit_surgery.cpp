// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the two changes of topology (mesh/surgery.hpp), on connectivity alone: a
// zipper of two closed bodies leaves one closed manifold (Euler characteristic 2), a pinch
// of a waist three edges round leaves two, and both refuse what would not be a manifold.
#include "mesh/components.hpp"
#include "mesh/invariants.hpp"
#include "mesh/surgery.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <setjmp.h>
#include <string>

extern "C" {
#include <cmocka.h>
}

using namespace sfa;

namespace {

// An octahedron of radius r about c, outward.
void add_octahedron(TriMesh &mesh, const Vec3 &c, double r)
{
    const int32_t o = mesh.num_vertices();
    for (const Vec3 &d : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)})
        mesh.pos.push_back(c + r * d);
    const int32_t faces[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (const auto &f : faces)
        mesh.tri.push_back({o + f[0], o + f[1], o + f[2]});
}

// A triangular tube of rings at z = 0, 1, 2 (three vertices each), closed by an apex below
// and above: the middle ring is a loop of three edges that is no triangle.
TriMesh waisted_tube()
{
    TriMesh mesh;
    for (int ring = 0; ring < 3; ++ring)
        for (int k = 0; k < 3; ++k) {
            const double angle = 2 * 3.14159265358979 * k / 3;
            mesh.pos.emplace_back(std::cos(angle), std::sin(angle), ring);
        }
    mesh.pos.emplace_back(0, 0, -1); // 9: below
    mesh.pos.emplace_back(0, 0, 3);  // 10: above
    for (int ring = 0; ring < 2; ++ring)
        for (int k = 0; k < 3; ++k) {
            const int32_t a = 3 * ring + k, b = 3 * ring + (k + 1) % 3;
            mesh.tri.push_back({a, b, b + 3});
            mesh.tri.push_back({a, b + 3, a + 3});
        }
    for (int k = 0; k < 3; ++k) {
        mesh.tri.push_back({(k + 1) % 3, k, 9});
        mesh.tri.push_back({6 + k, 6 + (k + 1) % 3, 10});
    }
    build_adjacency(mesh);
    return mesh;
}

int32_t euler_characteristic(const TriMesh &mesh)
{
    // A closed triangle mesh has 3 F / 2 edges.
    return mesh.num_vertices() - 3 * mesh.num_triangles() / 2 + mesh.num_triangles();
}

// The plan applied as the caller of surgery.hpp applies it, adjacency rebuilt.
TriMesh zipped(const TriMesh &mesh, const ZipperPlan &plan)
{
    TriMesh out;
    out.pos = mesh.pos;
    for (int32_t f = 0; f < mesh.num_triangles(); ++f)
        if (std::find(plan.removed.begin(), plan.removed.end(), f) == plan.removed.end())
            out.tri.push_back(mesh.tri[f]);
    out.tri.insert(out.tri.end(), plan.tube.begin(), plan.tube.end());
    build_adjacency(out);
    return out;
}

TriMesh pinched(const TriMesh &mesh, const PinchPlan &plan)
{
    TriMesh out;
    out.pos = mesh.pos;
    const std::array<int32_t, 3> copies = {mesh.num_vertices(), mesh.num_vertices() + 1, mesh.num_vertices() + 2};
    for (int32_t v : plan.loop)
        out.pos.push_back(mesh.pos[v]);
    for (int32_t f = 0; f < mesh.num_triangles(); ++f) {
        const bool left = std::binary_search(plan.left.begin(), plan.left.end(), f);
        out.tri.push_back(left ? with_copies(plan, mesh.tri[f], copies) : mesh.tri[f]);
    }
    for (const Triangle &cap : pinch_caps(plan, copies))
        out.tri.push_back(cap);
    build_adjacency(out);
    return out;
}

void zipping_two_bodies_makes_one_closed_manifold(void **)
{
    TriMesh mesh;
    add_octahedron(mesh, Vec3(-1.05, 0, 0), 1);
    add_octahedron(mesh, Vec3(1.05, 0, 0), 1);
    build_adjacency(mesh);
    // An edge at the left body's +x corner (0-2) and one at the right body's -x corner (7-8).
    const int32_t h1 = mesh.halfedge(0, 2), h2 = mesh.halfedge(7, 8);
    assert_true(h1 >= 0 && h2 >= 0);
    ZipperPlan plan;
    assert_true(plan_zipper(mesh, h1, h2, plan));
    const TriMesh out = zipped(mesh, plan);
    assert_string_equal(invariant_violation(out).c_str(), "");
    assert_true(out.is_closed());
    assert_int_equal(connected_components(out).count, 1);
    assert_int_equal(euler_characteristic(out), 2); // one sphere: the two became one
}

void a_zipper_of_edges_a_triangle_apart_is_refused(void **)
{
    TriMesh mesh;
    add_octahedron(mesh, Vec3::Zero(), 1);
    build_adjacency(mesh);
    ZipperPlan plan;
    // On one octahedron every two edges' triangles share a corner or are joined by an edge.
    for (int32_t h1 = 0; h1 < 24; ++h1)
        for (int32_t h2 = 0; h2 < 24; ++h2)
            assert_false(plan_zipper(mesh, h1, h2, plan));
}

void pinching_a_waist_makes_two_closed_bodies(void **)
{
    const TriMesh mesh = waisted_tube();
    assert_string_equal(invariant_violation(mesh).c_str(), "");
    PinchPlan plan;
    assert_true(plan_pinch(mesh, 3, 4, 5, plan));
    const TriMesh out = pinched(mesh, plan);
    assert_string_equal(invariant_violation(out).c_str(), "");
    assert_true(out.is_closed());
    const Components components = connected_components(out);
    assert_int_equal(components.count, 2);
    assert_int_equal(euler_characteristic(out), 4); // two spheres
    // The loop's reverse cuts the same way, the other side taking the copies.
    assert_true(plan_pinch(mesh, 3, 5, 4, plan));
    assert_string_equal(invariant_violation(pinched(mesh, plan)).c_str(), "");
}

void a_loop_that_is_a_triangle_is_not_pinched(void **)
{
    const TriMesh mesh = waisted_tube();
    PinchPlan plan;
    // 0, 1, 9 is a triangle (the bottom cap) in one orientation, 1, 0, 9 in the other.
    assert_false(plan_pinch(mesh, 0, 1, 9, plan));
    assert_false(plan_pinch(mesh, 1, 0, 9, plan));
    // 0, 1, 5 are not pairwise joined (0 and 5 share no edge).
    assert_false(plan_pinch(mesh, 0, 1, 5, plan));
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(zipping_two_bodies_makes_one_closed_manifold),
        cmocka_unit_test(a_zipper_of_edges_a_triangle_apart_is_refused),
        cmocka_unit_test(pinching_a_waist_makes_two_closed_bodies),
        cmocka_unit_test(a_loop_that_is_a_triangle_is_not_pinched),
    };
    return cmocka_run_group_tests_name("unit_surgery", tests, nullptr, nullptr);
}

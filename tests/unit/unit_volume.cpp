// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the volume correction (adapt/volume): each closed component gets its own
// volume back, and with the crossing guard the offset does not carry one side of the
// surface through the other where the two nearly touch (a soak finding: a coarse box,
// sheared, whose fold had two faces 1.7e-8 apart at edge length 4.5e-5; an offset of
// 3e-8 crossed them); where an offset would fold triangles or bring two sheets together,
// their corners are held and the rest of the component takes the volume back (the soak's
// first finding: whole components were left with their volume changed).
#include "adapt/volume.hpp"
#include "geometry/crossing_guard.hpp"
#include "geometry/self_intersection.hpp"
#include "mesh/components.hpp"
#include "mesh/validate.hpp"

#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <setjmp.h>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

using namespace sfa;

namespace {

constexpr double pi = 3.14159265358979323846;

// A sphere bent into a ring whose two rounded tips nearly meet: the unit sphere's z runs
// along an arc of radius 1 through +-(pi - gap / 2), its x and y become the tube's cross
// section of radius 0.1. The tips, `gap` apart, face each other.
TriMesh croissant(double gap)
{
    sfa_mesh_data m = shape_icosphere(4, 1.0);
    const double reach = pi - gap / 2;
    for (int32_t v = 0; v < m.nverts; ++v) {
        double *p = m.xyz + 3 * v;
        const double angle = reach * p[2], radius = 1 + 0.1 * p[0], height = -0.1 * p[1]; // keeps the outward orientation
        p[0] = radius * std::cos(angle);
        p[1] = radius * std::sin(angle);
        p[2] = height;
    }
    TriMesh mesh = validated_mesh(MeshInput{m.nverts, m.xyz, m.ntris, m.tris, 0, false});
    mesh_free(&m);
    return mesh;
}

struct Correction {
    int32_t crossings;
    double volume, wanted;
    VolumeRestoration restoration;
};

// Asks the croissant for `growth` more volume, with or without the guard.
Correction grow(double gap, double growth, bool guarded)
{
    TriMesh mesh = croissant(gap);
    const Components components = connected_components(mesh);
    assert_int_equal(components.count, 1);
    assert_int_equal(self_intersection_count(mesh), 0);
    std::vector<double> volume = component_volumes(mesh, components.of_vertex, components.count);
    const double wanted = volume[0] * (1 + growth);
    volume[0] = wanted;
    const std::vector<int8_t> smooth(mesh.num_vertices(), 0);
    CrossingGuard guard(near_facing_sheet(mesh));
    MeshEdit edit(mesh);
    const VolumeRestoration restoration =
        restore_enclosed_volumes(edit, smooth, components.of_vertex, volume, components.closed, true,
                                 guarded ? &guard : nullptr);
    return {self_intersection_count(mesh), component_volumes(mesh, components.of_vertex, 1)[0], wanted,
            restoration};
}

// Growth 1e-4 moves the surface out by about 5e-6, far less than a hundredth of the tube's
// thickness, so only the guard looks at the tips 1e-6 apart.
constexpr double tip_gap = 1e-6, growth = 1e-4;

void without_the_guard_the_offset_carries_the_tips_through_each_other(void **)
{
    const Correction c = grow(tip_gap, growth, false);
    assert_true(c.crossings > 0);
    assert_true(std::abs(c.volume - c.wanted) <= 1e-12 * std::abs(c.wanted));
}

void with_the_guard_the_tips_stay_apart_and_the_volume_comes_back(void **)
{
    const Correction c = grow(tip_gap, growth, true);
    assert_int_equal(c.crossings, 0);
    // The tips' corners are held; the rest of the surface takes the volume back.
    assert_true(std::abs(c.volume - c.wanted) <= 1e-12 * std::abs(c.wanted));
    assert_true(c.restoration.largest_change > 0.9 * growth);
    assert_true(c.restoration.largest_left == 0);
}

void tips_far_apart_are_offset_as_before(void **)
{
    const Correction guarded = grow(0.5, growth, true), plain = grow(0.5, growth, false);
    assert_int_equal(guarded.crossings, 0);
    assert_true(guarded.volume == plain.volume);
}

// Growth 0.1 moves the surface out by about 5e-3, more than a hundredth of the tube's
// thickness: the offset is certified, and it would bring the tips, 1e-3 apart, together.
// The corners of the triangles it brings together are held, and the rest of the tube
// takes the volume back (the whole component used to be left as it was, its volume 10 %
// short).
void a_large_offset_holds_the_tips_it_would_bring_together(void **)
{
    for (const bool guarded : {false, true}) {
        const Correction c = grow(1e-3, 0.1, guarded);
        assert_int_equal(c.crossings, 0);
        assert_true(std::abs(c.volume - c.wanted) <= 1e-12 * std::abs(c.wanted));
        assert_true(c.restoration.largest_left == 0);
    }
}

// A sphere with one vertex pushed in to `depth` of the radius: a narrow dimple, concave
// around its bottom. Given `more` volume, the offset moves every vertex out along
// its normal; around the bottom the normals converge, and a large enough offset turns the
// dimple's triangles over.
Correction grow_dimpled(double depth, double more)
{
    sfa_mesh_data m = shape_icosphere(3, 1.0);
    for (int k = 0; k < 3; ++k)
        m.xyz[k] *= depth;
    TriMesh mesh = validated_mesh(MeshInput{m.nverts, m.xyz, m.ntris, m.tris, 0, false});
    mesh_free(&m);
    const Components components = connected_components(mesh);
    std::vector<double> volume = component_volumes(mesh, components.of_vertex, components.count);
    const double wanted = volume[0] * (1 + more);
    volume[0] = wanted;
    const std::vector<int8_t> smooth(mesh.num_vertices(), 0);
    MeshEdit edit(mesh);
    const VolumeRestoration restoration =
        restore_enclosed_volumes(edit, smooth, components.of_vertex, volume, components.closed, true);
    return {self_intersection_count(mesh), component_volumes(mesh, components.of_vertex, 1)[0], wanted,
            restoration};
}

// A dimple half the radius deep, given 30 % more volume: the corners of the triangles the
// offset would turn over are held, and the rest of the sphere takes the volume back (the
// whole sphere used to be left as it was, 23 % short).
void an_offset_that_would_fold_the_dimple_holds_its_bottom(void **)
{
    const Correction c = grow_dimpled(0.5, 0.3);
    assert_int_equal(c.crossings, 0);
    assert_true(std::abs(c.volume - c.wanted) <= 1e-12 * std::abs(c.wanted));
    assert_true(c.restoration.largest_left == 0);
}

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(without_the_guard_the_offset_carries_the_tips_through_each_other),
        cmocka_unit_test(with_the_guard_the_tips_stay_apart_and_the_volume_comes_back),
        cmocka_unit_test(tips_far_apart_are_offset_as_before),
        cmocka_unit_test(a_large_offset_holds_the_tips_it_would_bring_together),
        cmocka_unit_test(an_offset_that_would_fold_the_dimple_holds_its_bottom),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

// SPDX-License-Identifier: BSD-3-Clause
// Measures that find their answer among all the mesh's pairs or corners by a shortcut, against
// looking at every one: the self-intersection count (SFA_MEASURE_SELF_INTERSECTIONS) and the
// range of the triangles' angles (SFA_MEASURE_MIN_ANGLE, _MAX_ANGLE), on two drops passing
// through each other, their vertices jittered so that each also folds through itself, at the
// origin, far from it and from tiny to huge, and on flat patches with degenerate corners.
#include "numbers.hpp" // before cmocka.h, which redefines what <random> needs

#include "geometry/angles.hpp"
#include "geometry/measures.hpp"
#include "geometry/self_intersection.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <limits>
#include <setjmp.h>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

using namespace sfa;

namespace {

int32_t every_pair_compared(const TriMesh &mesh)
{
    int32_t count = 0;
    for (int32_t s = 0; s < mesh.num_triangles(); ++s)
        for (int32_t t = s + 1; t < mesh.num_triangles(); ++t) {
            const Triangle &p = mesh.tri[s], &q = mesh.tri[t];
            count += !share_a_vertex(p, q) && triangles_intersect(mesh.pos[p[0]], mesh.pos[p[1]], mesh.pos[p[2]],
                                                                  mesh.pos[q[0]], mesh.pos[q[1]], mesh.pos[q[2]]);
        }
    return count;
}

// Every corner's angle by its arc tangent, as angle_range's answer must be to the last bit.
AngleRange every_corner_measured(const TriMesh &mesh)
{
    AngleRange range{std::numeric_limits<double>::infinity(), 0};
    for (const Triangle &t : mesh.tri)
        for (int i = 0; i < 3; ++i) {
            const Vec3 u = mesh.pos[t[(i + 1) % 3]] - mesh.pos[t[i]], w = mesh.pos[t[(i + 2) % 3]] - mesh.pos[t[i]];
            const double angle = std::atan2(u.cross(w).norm(), u.dot(w));
            range.min_degrees = std::min(range.min_degrees, angle);
            range.max_degrees = std::max(range.max_degrees, angle);
        }
    range.min_degrees *= degrees_per_radian;
    range.max_degrees *= degrees_per_radian;
    return range;
}

void expect_every_corners_range(const TriMesh &mesh, const char *what)
{
    const AngleRange found = angle_range(mesh), expected = every_corner_measured(mesh);
    if (found.min_degrees != expected.min_degrees || found.max_degrees != expected.max_degrees)
        fail_msg("%s: angles %.17g to %.17g, every corner gives %.17g to %.17g", what, found.min_degrees,
                 found.max_degrees, expected.min_degrees, expected.max_degrees);
}

void every_crossing_pair_is_counted_at_any_place_and_scale(void **)
{
    Numbers rng{20261205};
    sfa_mesh_data drops = shape_two_icospheres(3, 1, 1.2); // 2 x 1280 triangles, overlapping
    const double places[][2] = {{0, 1}, {0, 1e-12}, {0, 1e12}, {1e8, 1}, {-3e5, 1e-3}, {1e20, 1e15}}; // offset, scale
    for (const auto &[offset, scale] : places) {
        std::vector<double> xyz(drops.xyz, drops.xyz + 3 * drops.nverts);
        for (double &x : xyz)
            x = offset + scale * (x + rng.uniform(-0.04, 0.04)); // edges are about 0.1
        const TriMesh mesh = validated_mesh(MeshInput{drops.nverts, xyz.data(), drops.ntris, drops.tris, 0, false});
        expect_every_corners_range(mesh, "two jittered drops");
        const int32_t expected = every_pair_compared(mesh);
        if (self_intersection_count(mesh) != expected || expected < 100)
            fail_msg("offset %g, scale %g: %d crossing pairs counted, %d by every pair", offset, scale,
                     self_intersection_count(mesh), expected);
    }
    mesh_free(&drops);
}

// A flat patch whose corners include every degenerate case: a zero-length edge (no angle,
// whose cosine is not a number), a corner on the segment between two others (0 and 180
// degrees), needles down to a millionth of a degree, and an edge whose squared length
// underflows next to ordinary ones.
void the_angle_range_is_every_corners_to_the_last_bit(void **)
{
    const int n = 12;
    sfa_mesh_data grid = shape_grid(n, n, 1.0); // vertex (i, j) at (i, j, 0)
    struct Case {
        const char *what;
        int i, j;    // the vertex moved
        double x, y; // to here, in cells
    };
    const Case cases[] = {{"a zero-length edge", 5, 5, 6, 5},
                          {"a corner on its opposite edge", 5, 5, 5.5, 5.5},
                          {"a needle of 1e-6 degrees", 5, 5, 6 - 1e-8, 5 + 1e-8},
                          {"an edge of 1e-160", 1, 0, 1e-160, 0},
                          {"nothing degenerate", 5, 5, 5.3, 4.8}};
    // Degenerate triangles cannot be given to sfa_set_mesh, but motion and smoothing can
    // make them: the positions are changed after the mesh is built.
    const TriMesh flat = validated_mesh(MeshInput{grid.nverts, grid.xyz, grid.ntris, grid.tris, 0, false});
    // At 1e-170 every squared length underflows: no corner's cosine is finite.
    for (const double scale : {1.0, 1e-40, 1e40, 1e-170})
        for (const Case &c : cases) {
            TriMesh mesh = flat;
            mesh.pos[c.j * (n + 1) + c.i] = Vec3(c.x, c.y, 0);
            for (Vec3 &p : mesh.pos)
                p *= scale;
            expect_every_corners_range(mesh, c.what);
        }
    // Right angles and angles of 45 degrees moved by round-off: corners whose cosines and
    // arc tangents may round into different orders.
    Numbers rng{20261205};
    for (int trial = 0; trial < 200; ++trial) {
        TriMesh mesh = flat;
        for (Vec3 &p : mesh.pos)
            p += Vec3(rng.uniform(-1e-14, 1e-14), rng.uniform(-1e-14, 1e-14), 0);
        expect_every_corners_range(mesh, "a grid moved by round-off");
    }
    mesh_free(&grid);
}

// Two needles whose cosines round into the other order than their angles: the first has
// the smaller angle (9.0000004e-6 radians against 9.0000142e-6) but also the smaller
// cosine (found by a search over random needles). Only the margin keeps the first. A third
// triangle has a corner of about 40 degrees whose cosine is infinite (one edge's squared
// length underflows, the dot and cross products do not): it must not hide the needles.
void a_smallest_angle_whose_cosine_rounds_below_anothers_is_found(void **)
{
    const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0, 9, 0, 0, 10, 0, 0, 9, 1, 0};
    const int32_t tris[] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    TriMesh mesh = validated_mesh(MeshInput{9, xyz, 3, tris, 0, false});
    mesh.pos = {Vec3::Zero(), Vec3(1.6363769295683315, 0, 0), Vec3(1.6953992434200678, 1.5258593832687479e-05, 0),
                Vec3::Zero(), Vec3(0.92116500017075897, 0, 0), Vec3(0.66008686566476882, 5.9407911446108217e-06, 0),
                Vec3::Zero(), Vec3(1e-170, 1e-171, 0), Vec3(1e10, 1e10, 0)};
    expect_every_corners_range(mesh, "two needles and a corner of no finite cosine");
    assert_true(angle_range(mesh).min_degrees < 9.000001e-6 * degrees_per_radian);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_crossing_pair_is_counted_at_any_place_and_scale),
        cmocka_unit_test(the_angle_range_is_every_corners_to_the_last_bit),
        cmocka_unit_test(a_smallest_angle_whose_cosine_rounds_below_anothers_is_found),
    };
    return cmocka_run_group_tests_name("unit_measures", tests, nullptr, nullptr);
}

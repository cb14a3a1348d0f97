// SPDX-License-Identifier: BSD-3-Clause
// The self-intersection count (SFA_MEASURE_SELF_INTERSECTIONS) against every pair of
// triangles compared exactly: two drops passing through each other, their vertices
// jittered so that each also folds through itself, at the origin, far from it, and
// from tiny to huge.
#include "numbers.hpp" // before cmocka.h, which redefines what <random> needs

#include "geometry/self_intersection.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/validate.hpp"

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
        const int32_t expected = every_pair_compared(mesh);
        if (self_intersection_count(mesh) != expected || expected < 100)
            fail_msg("offset %g, scale %g: %d crossing pairs counted, %d by every pair", offset, scale,
                     self_intersection_count(mesh), expected);
    }
    mesh_free(&drops);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_crossing_pair_is_counted_at_any_place_and_scale),
    };
    return cmocka_run_group_tests_name("unit_self_intersection", tests, nullptr, nullptr);
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of the angular index of a vertex's fan (geometry/fan_sectors.hpp) and of what it
// is for (issue 18): the check that a contraction's faces pass through none around the
// ends' neighbours makes O(valence) exact triangle tests, not O(valence^2), on a cone
// whose apex and base centre neighbour every rim vertex.
#include "adapt/adapt.hpp"
#include "adapt/settings.hpp"
#include "geometry/measures.hpp"
#include "mesh/components.hpp"
#include "geometry/fan_sectors.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/validate.hpp"
#include "surfadapt.h"

#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <random>
#include <setjmp.h>
#include <set>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

using namespace sfa;

namespace {

// A closed cone: the apex (0) over a rim of n vertices at height 0, closed by the rim's
// centre (n + 1), both of valence n (as bench/bench_valence.c).
void cone(int n, std::vector<double> &xyz, std::vector<int32_t> &tris, double height = 1)
{
    xyz = {0, 0, height};
    for (int i = 0; i < n; ++i) {
        const double a = 2 * 3.14159265358979323846 * i / n;
        xyz.insert(xyz.end(), {std::cos(a), std::sin(a), 0});
    }
    xyz.insert(xyz.end(), {0, 0, 0});
    tris.clear();
    for (int i = 0; i < n; ++i) {
        const int32_t a = 1 + i, b = 1 + (i + 1) % n;
        tris.insert(tris.end(), {0, a, b, n + 1, b, a});
    }
}

// Every face of the fan a random triangle meets is among the candidates, whenever the
// index answers (apex of a steep and of a flat cone, base centre, triangles near the axis
// and with a corner on it).
void candidates_hold_every_face_met(void **)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.2, 1.2);
    int answered = 0, met = 0;
    for (double height : {1.0, 0.05}) {
        std::vector<double> xyz;
        std::vector<int32_t> tris;
        cone(200, xyz, tris, height);
        const TriMesh mesh = validated_mesh(
            MeshInput{static_cast<int32_t>(xyz.size() / 3), xyz.data(), static_cast<int32_t>(tris.size() / 3),
                      tris.data(), 0, false});
        for (int32_t hub : {0, 201}) {
            FanSectors fan;
            assert_true(fan.build(mesh, hub));
            for (int trial = 0; trial < 4000; ++trial) {
                Vec3 p[3];
                for (Vec3 &q : p)
                    q = Vec3(unit(random), unit(random), unit(random) * height);
                if (trial % 2 == 0)
                    p[0] = Vec3(0, 0, trial % 4 == 0 ? 0.0 : -0.5); // a corner on the axis
                else
                    p[1] = p[0] + 0.05 * (p[1] - p[0]), p[2] = p[0] + 0.05 * (p[2] - p[0]); // small
                std::set<int32_t> candidates;
                if (!fan.for_each_candidate(p, [&](int32_t f) { candidates.insert(f); }))
                    continue;
                ++answered;
                mesh.for_each_outgoing(hub, [&](int32_t h) {
                    const Triangle &t = mesh.tri[TriMesh::face(h)];
                    if (triangles_intersect(p[0], p[1], p[2], mesh.pos[t[0]], mesh.pos[t[1]], mesh.pos[t[2]])) {
                        ++met;
                        assert_true(candidates.count(TriMesh::face(h)) == 1);
                    }
                });
            }
        }
    }
    assert_true(answered > 8000); // the filter is used, not passed over
    assert_true(met > 1000);      // and was tested where it matters
}

// The fan an edge of a sphere would have contracted (as a contraction check indexes it
// where a vertex of high valence is contracted): every face around either end but the two
// of the edge, and every one of them a random triangle meets among the candidates. (The
// apex of the cone contracted into a rim vertex has no star-shaped fan in projection: the
// two faces down to the base centre fold over the rest, and the index is refused.)
void merged_fan_holds_every_moved_face_met(void **)
{
    std::vector<double> xyz;
    std::vector<int32_t> tris;
    cone(200, xyz, tris);
    const TriMesh cone_mesh = validated_mesh(MeshInput{static_cast<int32_t>(xyz.size() / 3), xyz.data(),
                                                       static_cast<int32_t>(tris.size() / 3), tris.data(), 0,
                                                       false});
    FanSectors fan;
    assert_false(fan.build_merged(cone_mesh, cone_mesh.halfedge(0, 1), Vec3(0.5, 0, 0.5)));

    sfa_mesh_data sphere = shape_icosphere(2, 1);
    const TriMesh mesh = validated_mesh(MeshInput{sphere.nverts, sphere.xyz, sphere.ntris, sphere.tris, 0, false});
    const int32_t h = mesh.v2h[0], ea = mesh.tail(h), eb = mesh.head(h);
    const Vec3 merged = (mesh.pos[ea] + mesh.pos[eb]) / 2;
    assert_true(fan.build_merged(mesh, h, merged));
    int32_t expected = -2; // the edge's two faces are around both ends
    mesh.for_each_outgoing(ea, [&](int32_t) { ++expected; });
    mesh.for_each_outgoing(eb, [&](int32_t) { ++expected; });
    assert_int_equal(fan.size(), expected - 2);
    std::vector<int32_t> moved;
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        const bool has_a = t[0] == ea || t[1] == ea || t[2] == ea, has_b = t[0] == eb || t[1] == eb || t[2] == eb;
        if (!(has_a && has_b))
            moved.push_back(f);
    });
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.2, 1.2);
    int answered = 0, met = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        Vec3 p[3];
        for (Vec3 &q : p)
            q = Vec3(unit(random), unit(random), unit(random));
        if (trial % 2 == 0)
            p[0] = merged + Vec3(0.5, 0, 0); // a corner outside the merged vertex
        else
            p[0] = merged + 0.1 * p[0], p[1] = p[0] + 0.05 * (p[1] - p[0]), p[2] = p[0] + 0.05 * (p[2] - p[0]);
        std::set<int32_t> candidates;
        if (!fan.for_each_candidate(p, [&](int32_t f) { candidates.insert(f); }))
            continue;
        ++answered;
        for (int32_t f : moved) {
            Vec3 q[3];
            for (int k = 0; k < 3; ++k)
                q[k] = mesh.tri[f][k] == ea || mesh.tri[f][k] == eb ? merged : mesh.pos[mesh.tri[f][k]];
            if (triangles_intersect(p[0], p[1], p[2], q[0], q[1], q[2])) {
                ++met;
                assert_true(candidates.count(f) == 1);
            }
        }
    }
    print_message("merged fan: %d of 4000 answered, %d faces met\n", answered, met);
    assert_true(answered > 2000);
    assert_true(met > 200);
    mesh_free(&sphere);
}

// The adaptation of the cone of valence 1000 (as sfa_adapt makes it): about 5 n
// contraction checks, each of which read the apex's and the base centre's whole fans
// before (27 n^2 = 2.7e7 triangle tests).
void cone_clearance_tests_grow_linearly(void **)
{
    const int n = 1000;
    std::vector<double> xyz;
    std::vector<int32_t> tris;
    cone(n, xyz, tris);
    TriMesh mesh = validated_mesh(MeshInput{n + 2, xyz.data(), 2 * n, tris.data(), 0, false});
    const AdaptSettings settings = adapt_settings(Parameters(), edge_lengths(mesh).mean);
    SurfaceData data;
    std::vector<char> near_sheet;
    SurfaceAnalysis workspace;
    Components components = connected_components(mesh);
    const AdaptCounts counts = adapt_surface(mesh, data, settings, near_sheet, workspace, components);
    print_message("%lld triangle tests for valence %d\n", static_cast<long long>(counts.clearance_tests), n);
    assert_true(counts.contractions > n);
    assert_true(counts.clearance_tests > 0);
    assert_true(counts.clearance_tests < 1000 * n); // before: 27 n^2
}

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(candidates_hold_every_face_met),
        cmocka_unit_test(merged_fan_holds_every_moved_face_met),
        cmocka_unit_test(cone_clearance_tests_grow_linearly),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

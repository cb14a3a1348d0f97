// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of `surfadapt repair` (apps/surfadapt/repair.cpp) on random polygon soups:
// vertices on a coarse lattice (so that many coincide or are collinear), faces of 1 to 8
// corners, some indices out of range, repeated faces, faces turned round. Whatever comes
// in, what comes out uses only vertices it has, every one of them, no triangle twice and
// none with a repeated corner; and when the report leaves nothing for the user, the
// library accepts the result.
#include "repair.hpp"
#include "surfadapt.h"

#include <algorithm>
#include <array>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <setjmp.h>
#include <string>
#include <vector>

extern "C" {
#include <cmocka.h>
}

namespace {

// A fixed sequence, the same on every machine.
struct Random {
    uint64_t state;
    uint32_t next()
    {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<uint32_t>(state >> 33);
    }
    int below(int n) { return static_cast<int>(next() % static_cast<uint32_t>(n)); }
};

PolygonMesh random_soup(Random &r)
{
    PolygonMesh mesh;
    const int nverts = 3 + r.below(30);
    for (int v = 0; v < 3 * nverts; ++v)
        mesh.xyz.push_back(r.below(4)); // a 4 x 4 x 4 lattice: coincident and collinear corners
    const int nfaces = 1 + r.below(40);
    for (int f = 0; f < nfaces; ++f) {
        mesh.face_start.push_back(static_cast<int32_t>(mesh.indices.size()));
        const int corners = 1 + r.below(8);
        for (int k = 0; k < corners; ++k)
            mesh.indices.push_back(r.below(nverts + 1) - (r.below(50) == 0 ? nverts + 2 : 0));
    }
    mesh.face_start.push_back(static_cast<int32_t>(mesh.indices.size()));
    return mesh;
}

void output_is_consistent(const TriangleSoup &out)
{
    const auto nverts = static_cast<int32_t>(out.xyz.size() / 3);
    assert_int_equal(out.tris.size() % 3, 0);
    std::vector<char> used(static_cast<size_t>(nverts), 0);
    std::vector<std::array<int32_t, 3>> sorted;
    for (size_t t = 0; t < out.tris.size(); t += 3) {
        std::array<int32_t, 3> corners{out.tris[t], out.tris[t + 1], out.tris[t + 2]};
        for (const int32_t v : corners) {
            assert_true(v >= 0 && v < nverts);
            used[v] = 1;
        }
        std::sort(corners.begin(), corners.end());
        assert_true(corners[0] != corners[1] && corners[1] != corners[2]);
        sorted.push_back(corners);
    }
    assert_true(std::all_of(used.begin(), used.end(), [](char u) { return u != 0; }));
    std::sort(sorted.begin(), sorted.end());
    assert_true(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
}

void random_soups_come_out_consistent(void **)
{
    Random r{12345};
    int accepted = 0, left_for_the_user = 0, empty = 0;
    for (int round = 0; round < 20000; ++round) {
        const PolygonMesh in = random_soup(r);
        TriangleSoup out;
        const RepairReport report = repair_mesh(in, out);
        output_is_consistent(out);
        if (out.tris.empty()) {
            ++empty;
            continue;
        }
        if (report.non_orientable_components > 0 || report.edges_with_many_faces_left > 0) {
            ++left_for_the_user;
            continue;
        }
        sfa_surface *s = nullptr;
        assert_int_equal(sfa_create(&s), SFA_OK);
        const int rc = sfa_set_mesh(s, static_cast<int32_t>(out.xyz.size() / 3), out.xyz.data(),
                                    static_cast<int32_t>(out.tris.size() / 3), out.tris.data(), 0);
        if (rc != SFA_OK)
            print_error("round %d: the library refuses a repair that left nothing: %s\n", round, sfa_last_error(s));
        assert_int_equal(rc, SFA_OK);
        sfa_destroy(s);
        ++accepted;
    }
    print_message("%d accepted, %d left for the user, %d empty\n", accepted, left_for_the_user, empty);
    assert_true(accepted > 1000);
}

// A polygon's fan from its first corner folds over where the polygon is concave; ear
// clipping gives triangles that all turn the polygon's way and cover its area once.
void a_concave_polygon_is_cut_into_its_own_area(void **)
{
    PolygonMesh comb;
    const double xy[][2] = {{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
    const int n = sizeof xy / sizeof xy[0];
    comb.face_start = {0, n};
    for (int i = 0; i < n; ++i) {
        comb.xyz.insert(comb.xyz.end(), {xy[i][0], xy[i][1], 0.0});
        comb.indices.push_back(i);
    }
    TriangleSoup out;
    const RepairReport report = repair_mesh(comb, out);
    assert_int_equal(report.polygons_clipped, 1);
    assert_int_equal(report.polygons_not_simple, 0);
    assert_int_equal(out.tris.size(), 3 * (n - 2));
    double area = 0;
    for (size_t t = 0; t < out.tris.size(); t += 3) {
        const double *a = &out.xyz[3 * out.tris[t]], *b = &out.xyz[3 * out.tris[t + 1]], *c = &out.xyz[3 * out.tris[t + 2]];
        const double twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        assert_true(twice > 0); // counter-clockwise, as the polygon
        area += twice / 2;
    }
    assert_true(area == 15 - 2 * 2); // the 5 x 3 block less its two notches of 1 x 2
}

// Repair changes only what is wrong: a sound fan stays the file's, and two bodies that only
// touch at a vertex given twice stay apart, with nothing reported.
void what_is_sound_is_kept_and_not_reported(void **)
{
    PolygonMesh mesh;
    // Two tetrahedra whose apexes (vertices 0 and 4) are at the same point, and a convex
    // quadrilateral apart from them.
    mesh.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, -1, 0, 0, 0, -1, 0, 0, 0, -1,
                5, 0, 0, 6, 0, 0, 6, 1, 0, 5, 1, 0};
    mesh.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 4, 5, 6, 4, 7, 5, 4, 6, 7, 5, 7, 6, 8, 9, 10, 11};
    for (int32_t f = 0; f <= 8; ++f)
        mesh.face_start.push_back(3 * f);
    mesh.face_start.push_back(28);
    TriangleSoup out;
    const RepairReport report = repair_mesh(mesh, out);
    for (const std::string &line : report.lines())
        print_error("reported: %s\n", line.c_str());
    assert_int_equal(report.changes(), 0);
    assert_int_equal(out.xyz.size(), 3 * 12);
    const std::vector<int32_t> quad(out.tris.end() - 6, out.tris.end());
    assert_true((quad == std::vector<int32_t>{8, 9, 10, 8, 10, 11})); // the fan from its first corner
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(random_soups_come_out_consistent),
        cmocka_unit_test(a_concave_polygon_is_cut_into_its_own_area),
        cmocka_unit_test(what_is_sound_is_kept_and_not_reported),
    };
    return cmocka_run_group_tests_name("unit_repair", tests, nullptr, nullptr);
}

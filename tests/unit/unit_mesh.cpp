// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the mesh core: adjacency, one-ring walks, the invariant checker, and the
// edge flip, split and contraction with compaction, and the renumbering for locality.
#include "mesh/compact.hpp"
#include "mesh/edge_collapse.hpp"
#include "mesh/edge_flip.hpp"
#include "mesh/edge_split.hpp"
#include "mesh/invariants.hpp"
#include "mesh/locality_order.hpp"
#include "mesh/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstring>
#include <string>
#include <setjmp.h>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

using namespace sfa;

namespace {

// A unit cube, triangles counter-clockwise from outside.
const double cube_xyz[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
const int32_t cube_tris[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                             1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

// A flat 3x3-vertex grid patch: open, 8 triangles.
std::vector<double> grid_xyz()
{
    std::vector<double> xyz;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            xyz.insert(xyz.end(), {double(i), double(j), 0.0});
    return xyz;
}
std::vector<int32_t> grid_tris()
{
    std::vector<int32_t> tris;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const int32_t a = 3 * j + i, b = a + 1, c = a + 4, d = a + 3;
            tris.insert(tris.end(), {a, b, c, a, c, d});
        }
    return tris;
}

TriMesh cube() { return validated_mesh(MeshInput{8, cube_xyz, 12, cube_tris, 0, false}); }

TriMesh grid()
{
    static const std::vector<double> xyz = grid_xyz();
    static const std::vector<int32_t> tris = grid_tris();
    return validated_mesh(MeshInput{9, xyz.data(), 8, tris.data(), 0, false});
}

void closed_mesh_has_every_twin(void **)
{
    const TriMesh mesh = cube();
    assert_string_equal(invariant_violation(mesh).c_str(), "");
    for (int32_t h = 0; h < 36; ++h) {
        assert_true(mesh.opp[h] >= 0);
        assert_int_equal(mesh.opp[mesh.opp[h]], h);
        assert_int_equal(mesh.tail(mesh.opp[h]), mesh.head(h));
    }
}

void one_ring_walk_visits_every_triangle_once(void **)
{
    for (const TriMesh &mesh : {cube(), grid()}) {
        std::vector<int32_t> valence(mesh.num_vertices(), 0);
        for (const Triangle &t : mesh.tri)
            for (int32_t v : t)
                ++valence[v];
        for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
            std::vector<int32_t> faces;
            mesh.for_each_outgoing(v, [&](int32_t h) {
                assert_int_equal(mesh.tail(h), v);
                faces.push_back(TriMesh::face(h));
            });
            assert_int_equal(static_cast<int>(faces.size()), valence[v]);
        }
    }
}

void boundary_vertices_start_at_their_boundary_halfedge(void **)
{
    const TriMesh mesh = grid();
    assert_string_equal(invariant_violation(mesh).c_str(), "");
    int boundary = 0;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        boundary += mesh.is_boundary_vertex(v);
    assert_int_equal(boundary, 8); // all but the centre vertex 4
    assert_false(mesh.is_boundary_vertex(4));
}

void checker_names_a_broken_twin(void **)
{
    TriMesh mesh = cube();
    mesh.opp[mesh.opp[0]] = 5;
    assert_string_not_equal(invariant_violation(mesh).c_str(), "");
}

void checker_names_a_bad_vertex_halfedge(void **)
{
    TriMesh mesh = cube();
    mesh.v2h[3] = mesh.v2h[4];
    const std::string message = invariant_violation(mesh);
    assert_non_null(std::strstr(message.c_str(), "vertex 3"));
}

void checker_names_a_non_finite_position(void **)
{
    TriMesh mesh = cube();
    mesh.pos[6].y() = NAN;
    assert_non_null(std::strstr(invariant_violation(mesh).c_str(), "vertex 6"));
}

void build_adjacency_matches_validation(void **)
{
    const TriMesh validated = cube();
    TriMesh rebuilt;
    rebuilt.pos = validated.pos;
    rebuilt.tri = validated.tri;
    build_adjacency(rebuilt);
    assert_true(rebuilt.opp == validated.opp);
    assert_true(rebuilt.v2h == validated.v2h);
}

// Triangles as sorted rotations, so that two meshes with the same faces compare equal.
std::vector<Triangle> canonical_triangles(const TriMesh &mesh)
{
    std::vector<Triangle> faces;
    for (Triangle t : mesh.tri) {
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        faces.push_back(t);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

void flips_keep_every_invariant_and_undo_themselves(void **)
{
    for (TriMesh mesh : {cube(), grid()}) {
        const int32_t halfedges = 3 * mesh.num_triangles();
        // Several rounds of flips in a scrambled order reach many configurations.
        for (int round = 0; round < 5; ++round)
            for (int32_t k = 0; k < halfedges; ++k) {
                const int32_t h = (7 * k + round) % halfedges;
                if (!flip_keeps_manifold(mesh, h))
                    continue;
                const std::vector<Triangle> before = canonical_triangles(mesh);
                const FlipQuad quad = flip_quad(mesh, h);
                std::vector<std::array<int32_t, 2>> ends(halfedges);
                for (int32_t e = 0; e < halfedges; ++e)
                    ends[e] = {mesh.tail(e), mesh.head(e)};

                const FlipMoves moves = flip_edge(mesh, h);
                assert_string_equal(invariant_violation(mesh).c_str(), "");
                assert_int_equal(mesh.tail(h), quad.q);
                assert_int_equal(mesh.head(h), quad.p);
                for (int i = 0; i < 4; ++i) {
                    assert_int_equal(mesh.tail(moves.to[i]), ends[moves.from[i]][0]);
                    assert_int_equal(mesh.head(moves.to[i]), ends[moves.from[i]][1]);
                }
                // Flipping the new edge back restores the same triangles.
                assert_true(flip_keeps_manifold(mesh, h));
                flip_edge(mesh, h);
                assert_string_equal(invariant_violation(mesh).c_str(), "");
                assert_true(canonical_triangles(mesh) == before);
                flip_edge(mesh, h);
            }
    }
}

void flips_never_make_a_duplicate_edge_or_cross_a_boundary(void **)
{
    // A tetrahedron: flipping any edge would join two vertices that are already joined.
    const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const int32_t tris[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
    const TriMesh tetrahedron = validated_mesh(MeshInput{4, xyz, 4, tris, 0, false});
    for (int32_t h = 0; h < 12; ++h)
        assert_false(flip_keeps_manifold(tetrahedron, h));
    const TriMesh patch = grid();
    for (int32_t h = 0; h < 3 * patch.num_triangles(); ++h)
        if (patch.opp[h] < 0)
            assert_false(flip_keeps_manifold(patch, h));
}

TriMesh mesh_of(const sfa_mesh_data &m) { return validated_mesh(MeshInput{m.nverts, m.xyz, m.ntris, m.tris, 0, false}); }

int32_t euler_characteristic(const TriMesh &mesh)
{
    int32_t edges = 0;
    for (int32_t h = 0; h < 3 * mesh.num_triangles(); ++h)
        edges += mesh.opp[h] < 0 || mesh.opp[h] > h;
    return mesh.num_vertices() - edges + mesh.num_triangles();
}

void splits_keep_every_invariant(void **)
{
    sfa_mesh_data sphere = shape_icosphere(1, 1.0);
    for (TriMesh mesh : {cube(), grid(), mesh_of(sphere)}) {
        const int32_t euler = euler_characteristic(mesh);
        shapes_rng rng = rng_seed(3);
        for (int k = 0; k < 60; ++k) {
            const int32_t h = static_cast<int32_t>(rng_next(&rng) % (3 * mesh.tri.size()));
            const int32_t vertices = mesh.num_vertices(), triangles = mesh.num_triangles();
            const int32_t a = mesh.tail(h), b = mesh.head(h);
            const bool interior = mesh.opp[h] >= 0;
            const Vec3 middle = (mesh.pos[a] + mesh.pos[b]) / 2;
            const int32_t m = split_edge(mesh, h, middle).vertex;
            assert_string_equal(invariant_violation(mesh).c_str(), "");
            assert_int_equal(m, vertices);
            assert_int_equal(mesh.num_triangles(), triangles + (interior ? 2 : 1));
            assert_int_equal(mesh.tail(h), a);
            assert_int_equal(mesh.head(h), m);
            assert_true(mesh.pos[m] == middle);
            assert_int_equal(mesh.is_boundary_vertex(m), !interior);
            assert_int_equal(euler_characteristic(mesh), euler);
        }
    }
    mesh_free(&sphere);
}

// Mean |a - b| over the edges (a, b): how far apart in memory neighbours are.
double mean_index_gap(const TriMesh &mesh)
{
    double sum = 0;
    for (int32_t h = 0; h < 3 * mesh.num_triangles(); ++h)
        sum += std::abs(mesh.tail(h) - mesh.head(h));
    return sum / (3 * mesh.num_triangles());
}

void locality_order_keeps_the_surface_and_brings_neighbours_close(void **)
{
    // An icosphere (and an open grid) with its vertices and triangles shuffled, as a
    // mesh adapted through a flow has them.
    sfa_mesh_data sphere = shape_icosphere(5, 1.0), plane = shape_grid(40, 30, 0.1);
    for (sfa_mesh_data *shape : {&sphere, &plane}) {
        const int32_t n = shape->nverts, m = shape->ntris;
        std::vector<int32_t> shuffle(n);
        for (int32_t v = 0; v < n; ++v)
            shuffle[v] = v;
        shapes_rng rng = rng_seed(11);
        for (int32_t v = n - 1; v > 0; --v)
            std::swap(shuffle[v], shuffle[rng_next(&rng) % (v + 1)]);
        std::vector<double> xyz(3 * n);
        std::vector<int32_t> tris(3 * m);
        for (int32_t v = 0; v < n; ++v)
            std::copy(shape->xyz + 3 * v, shape->xyz + 3 * v + 3, xyz.begin() + 3 * shuffle[v]);
        for (int32_t t = 0; t < m; ++t)
            for (int i = 0; i < 3; ++i)
                tris[3 * ((t * 7919) % m) + i] = shuffle[shape->tris[3 * t + i]];
        const TriMesh before = validated_mesh(MeshInput{n, xyz.data(), m, tris.data(), 0, false});
        TriMesh after = before;
        const std::vector<int32_t> map = order_for_locality(after).vertex_map;

        assert_string_equal(invariant_violation(after).c_str(), "");
        std::vector<char> hit(n, 0);
        for (int32_t v = 0; v < n; ++v) {
            hit[map[v]] = 1;
            assert_true(after.pos[map[v]] == before.pos[v]);
        }
        assert_int_equal(std::count(hit.begin(), hit.end(), 1), n); // a permutation
        // The same triangles, corners in the same cyclic order.
        std::vector<Triangle> renamed, kept(after.tri);
        for (const Triangle &c : before.tri)
            renamed.push_back({map[c[0]], map[c[1]], map[c[2]]});
        std::sort(renamed.begin(), renamed.end());
        std::sort(kept.begin(), kept.end());
        assert_true(renamed == kept);
        print_message("%d vertices: mean index gap along edges %.0f -> %.0f\n", n, mean_index_gap(before),
                      mean_index_gap(after));
        assert_true(mean_index_gap(after) < mean_index_gap(before) / 10);
    }
    mesh_free(&sphere);
    mesh_free(&plane);
}

void contractions_keep_every_invariant_and_the_topology(void **)
{
    sfa_mesh_data sphere = shape_icosphere(2, 1.0), patch = shape_grid(6, 5, 0.1);
    for (TriMesh mesh : {mesh_of(sphere), mesh_of(patch)}) {
        const int32_t euler = euler_characteristic(mesh);
        shapes_rng rng = rng_seed(11);
        int collapses = 0;
        for (int attempt = 0; attempt < 4000 && mesh.num_vertices() > 8; ++attempt) {
            const int32_t h = static_cast<int32_t>(rng_next(&rng) % (3 * mesh.tri.size()));
            if (!collapse_keeps_manifold(mesh, h))
                continue;
            const int32_t keep = mesh.head(h), gone = mesh.tail(h);
            const Vec3 target = mesh.pos[keep];
            collapse_edge(mesh, h, target);
            const std::vector<int32_t> renumber = compact(mesh).vertex_map;
            assert_int_equal(renumber[gone], -1);
            assert_true(mesh.pos[renumber[keep]] == target);
            assert_string_equal(invariant_violation(mesh).c_str(), "");
            assert_int_equal(euler_characteristic(mesh), euler);
            ++collapses;
        }
        assert_true(collapses > 20);
    }
    mesh_free(&sphere);
    mesh_free(&patch);
}

void contractions_that_would_break_the_surface_are_refused(void **)
{
    // A tetrahedron cannot lose an edge (the opposite vertices would keep two neighbours).
    const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const int32_t tris[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
    const TriMesh tetrahedron = validated_mesh(MeshInput{4, xyz, 4, tris, 0, false});
    for (int32_t h = 0; h < 12; ++h)
        assert_false(collapse_keeps_manifold(tetrahedron, h));
    // An interior edge between two boundary vertices would pinch an open surface.
    const TriMesh patch = grid();
    for (int32_t h = 0; h < 3 * patch.num_triangles(); ++h)
        if (patch.opp[h] >= 0 && patch.is_boundary_vertex(patch.tail(h)) && patch.is_boundary_vertex(patch.head(h)))
            assert_false(collapse_keeps_manifold(patch, h));
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(closed_mesh_has_every_twin),
        cmocka_unit_test(one_ring_walk_visits_every_triangle_once),
        cmocka_unit_test(boundary_vertices_start_at_their_boundary_halfedge),
        cmocka_unit_test(checker_names_a_broken_twin),
        cmocka_unit_test(checker_names_a_bad_vertex_halfedge),
        cmocka_unit_test(checker_names_a_non_finite_position),
        cmocka_unit_test(build_adjacency_matches_validation),
        cmocka_unit_test(flips_keep_every_invariant_and_undo_themselves),
        cmocka_unit_test(flips_never_make_a_duplicate_edge_or_cross_a_boundary),
        cmocka_unit_test(splits_keep_every_invariant),
        cmocka_unit_test(contractions_keep_every_invariant_and_the_topology),
        cmocka_unit_test(contractions_that_would_break_the_surface_are_refused),
        cmocka_unit_test(locality_order_keeps_the_surface_and_brings_neighbours_close),
    };
    return cmocka_run_group_tests_name("unit_mesh", tests, nullptr, nullptr);
}

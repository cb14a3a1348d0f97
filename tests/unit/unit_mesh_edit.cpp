// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the edit mechanism (mesh/mesh_edit.hpp): through random sequences of
// splits, contractions, flips, moves, compactions and renumberings, every listener keeps
// what it carries right: edge flags stay on the same vertex pairs, a linear field stays
// exactly linear, per-triangle values keep their integral where the surface is flat, and
// every vertex whose fan changed is reported.
#include "fields/carried_fields.hpp"
#include "fields/face_values.hpp"
#include "mesh/changed_vertices.hpp"
#include "mesh/halfedge_flags.hpp"
#include "mesh/invariants.hpp"
#include "mesh/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <map>
#include <set>
#include <setjmp.h>
#include <utility>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

#include "assert_near.hpp"

using namespace sfa;

namespace {

TriMesh mesh_of(const sfa_mesh_data &m) { return validated_mesh(MeshInput{m.nverts, m.xyz, m.ntris, m.tris, 0, false}); }

bool alive(const TriMesh &mesh, int32_t h) { return mesh.tri[TriMesh::face(h)][0] >= 0; }

// True if flipping h keeps both faces facing up (z > 0): the quad is convex.
bool flip_stays_flat(const TriMesh &mesh, int32_t h)
{
    const FlipQuad q = flip_quad(mesh, h);
    const auto up = [&](int32_t x, int32_t y, int32_t z) {
        return (mesh.pos[y] - mesh.pos[x]).cross(mesh.pos[z] - mesh.pos[x]).z() > 0;
    };
    return up(q.q, q.p, q.a) && up(q.p, q.q, q.b);
}

// True if contracting h onto its head keeps every surviving face facing up (z > 0).
bool collapse_stays_flat(const TriMesh &mesh, int32_t h)
{
    const int32_t gone = mesh.tail(h), keep = mesh.head(h);
    bool up = true;
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        Triangle t = mesh.tri[f];
        if (std::count(t.begin(), t.end(), gone) + std::count(t.begin(), t.end(), keep) == 2)
            return; // dies
        for (int32_t &c : t)
            c = c == gone ? keep : c;
        up = up && (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]).z() > 1e-12;
    });
    return up;
}

// `steps` random changes through `edit`: splits at edge midpoints, contractions onto the
// kept vertex, flips of unflagged edges (`may_flip`), a compaction every 16 steps; then a
// compaction and the locality order. check() after every change.
template <class MayFlip, class Check>
void random_edits(MeshEdit &edit, uint64_t seed, int steps, MayFlip &&may_flip, Check &&check,
                  bool keep_flat = false)
{
    const TriMesh &mesh = edit.mesh();
    shapes_rng rng = rng_seed(seed);
    for (int step = 0; step < steps; ++step) {
        const int32_t h = static_cast<int32_t>(rng_next(&rng) % (3 * mesh.tri.size()));
        if (!alive(mesh, h))
            continue;
        switch (rng_next(&rng) % 3) {
        case 0: edit.split(h, (mesh.pos[mesh.tail(h)] + mesh.pos[mesh.head(h)]) / 2); break;
        case 1:
            if (!collapse_keeps_manifold(mesh, h) || (keep_flat && !collapse_stays_flat(mesh, h)))
                continue;
            edit.collapse(h, mesh.pos[mesh.head(h)]);
            break;
        case 2:
            if (!flip_keeps_manifold(mesh, h) || !may_flip(h) || (keep_flat && !flip_stays_flat(mesh, h)))
                continue;
            edit.flip(h);
            break;
        }
        check();
        if (step % 16 == 15) {
            edit.compact();
            check();
        }
    }
    edit.compact();
    edit.order_for_locality();
    assert_string_equal(invariant_violation(mesh).c_str(), "");
    check();
}

using Pair = std::pair<int32_t, int32_t>;
Pair pair_of(int32_t a, int32_t b) { return {std::min(a, b), std::max(a, b)}; }

// The rules of HalfedgeFlags said on vertex pairs instead of half-edges: a split edge's
// halves keep its flag, a contracted vertex's flagged edges become the kept vertex's.
class FlaggedPairs : public EditListener {
public:
    std::set<Pair> pairs;
    void split(const TriMesh &, const SplitChange &change) override
    {
        const SplitRecord &r = change.record;
        if (pairs.erase(pair_of(r.a, r.b))) {
            pairs.insert(pair_of(r.a, r.vertex));
            pairs.insert(pair_of(r.vertex, r.b));
        }
    }
    void collapse(const TriMesh &, const CollapseChange &change) override
    {
        const int32_t gone = change.record.gone, keep = change.record.keep;
        std::set<Pair> moved;
        for (const Pair &p : pairs)
            if (p.first == gone || p.second == gone) {
                const int32_t other = p.first == gone ? p.second : p.first;
                if (other != keep)
                    moved.insert(pair_of(keep, other));
            } else
                moved.insert(p);
        pairs.swap(moved);
    }
    void renumber(const Renumbering &r) override
    {
        std::set<Pair> renamed;
        for (const Pair &p : pairs)
            renamed.insert(pair_of(r.vertex_map[p.first], r.vertex_map[p.second]));
        pairs.swap(renamed);
    }
};

void edge_flags_stay_on_the_same_vertex_pairs(void **)
{
    sfa_mesh_data sphere = shape_icosphere(2, 1.0), plane = shape_grid(9, 7, 0.1);
    for (const sfa_mesh_data *shape : {&sphere, &plane}) {
        TriMesh mesh = mesh_of(*shape);
        // Every third edge flagged, and every boundary edge.
        std::vector<char> initial(mesh.opp.size(), 0);
        FlaggedPairs expected;
        for (int32_t h = 0; h < static_cast<int32_t>(mesh.opp.size()); ++h)
            if (mesh.opp[h] < 0 || (mesh.opp[h] > h && h % 3 == 0)) {
                initial[h] = 1;
                if (mesh.opp[h] >= 0)
                    initial[mesh.opp[h]] = 1;
                expected.pairs.insert(pair_of(mesh.tail(h), mesh.head(h)));
            }
        MeshEdit edit(mesh);
        HalfedgeFlags flags(initial);
        edit.attach(flags);
        edit.attach(expected);
        int32_t checks = 0;
        random_edits(
            edit, 7, 600, [&](int32_t h) { return !flags[h]; },
            [&] {
                for (int32_t h = 0; h < static_cast<int32_t>(mesh.opp.size()); ++h)
                    if (alive(mesh, h))
                        assert_int_equal(flags[h], expected.pairs.count(pair_of(mesh.tail(h), mesh.head(h))));
                ++checks;
            });
        assert_true(checks > 100);
    }
    mesh_free(&sphere);
    mesh_free(&plane);
}

double linear(const Vec3 &p) { return 1 + 2 * p.x() - 3 * p.y(); }

void a_linear_field_stays_linear_through_every_change(void **)
{
    sfa_mesh_data plane = shape_grid(12, 10, 0.1);
    TriMesh mesh = mesh_of(plane);
    std::vector<VertexField> fields{{2, std::vector<double>(2 * mesh.pos.size())}};
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        fields[0].values[2 * v] = linear(mesh.pos[v]);
        fields[0].values[2 * v + 1] = -linear(mesh.pos[v]);
    }
    MeshEdit edit(mesh);
    CarriedFields carried(fields);
    edit.attach(carried);
    const auto check = [&] {
        assert_int_equal(fields[0].values.size(), 2 * mesh.pos.size());
        for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
            if (is_dead_vertex(mesh, v))
                continue;
            assert_near(fields[0].values[2 * v], linear(mesh.pos[v]), 1e-12);
            assert_near(fields[0].values[2 * v + 1], -linear(mesh.pos[v]), 1e-12);
        }
    };
    random_edits(edit, 3, 400, [](int32_t) { return true; }, check, true);
    // A sweep: every vertex slides within the plane, a little.
    shapes_rng rng = rng_seed(5);
    std::vector<Vec3> moved = mesh.pos;
    for (Vec3 &p : moved)
        p += 0.01 * Vec3(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, 0);
    edit.move(moved);
    check();
    mesh_free(&plane);
}

Vec3 face_normal(const TriMesh &mesh, int32_t t)
{
    const Triangle &c = mesh.tri[t];
    return 0.5 * (mesh.pos[c[1]] - mesh.pos[c[0]]).cross(mesh.pos[c[2]] - mesh.pos[c[0]]);
}

double total(const TriMesh &mesh, const FaceValues &values, int component)
{
    double sum = 0;
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        if (mesh.tri[t][0] >= 0)
            sum += values.value(t, component) * face_normal(mesh, t).norm();
    return sum;
}

void face_values_keep_their_integral_on_a_flat_surface(void **)
{
    sfa_mesh_data plane = shape_grid(12, 10, 0.1);
    TriMesh mesh = mesh_of(plane);
    std::vector<double> density(2 * mesh.tri.size());
    shapes_rng rng = rng_seed(9);
    for (double &d : density)
        d = rng_uniform(&rng);
    MeshEdit edit(mesh);
    FaceValues values(2, density);
    edit.attach(values);
    const double before[2] = {total(mesh, values, 0), total(mesh, values, 1)};
    // Splits, flips of convex quads and contractions of interior edges onto the end they keep
    // (which may fold a face: its area still counts).
    int32_t changes = 0;
    for (int step = 0; step < 600; ++step) {
        const int32_t h = static_cast<int32_t>(rng_next(&rng) % (3 * mesh.tri.size()));
        if (!alive(mesh, h))
            continue;
        if (step % 3 == 0)
            edit.split(h, (mesh.pos[mesh.tail(h)] + mesh.pos[mesh.head(h)]) / 2);
        else if (step % 3 == 1 && flip_keeps_manifold(mesh, h) && flip_stays_flat(mesh, h))
            edit.flip(h);
        else if (step % 3 == 2 && collapse_keeps_manifold(mesh, h) && !mesh.is_boundary_vertex(mesh.tail(h)) &&
                 !mesh.is_boundary_vertex(mesh.head(h)))
            edit.collapse(h, mesh.pos[mesh.head(h)]);
        else
            continue;
        ++changes;
        for (int c = 0; c < 2; ++c)
            assert_near(total(mesh, values, c), before[c], 1e-12 * std::abs(before[c]));
    }
    edit.compact();
    edit.order_for_locality();
    for (int c = 0; c < 2; ++c)
        assert_near(total(mesh, values, c), before[c], 1e-12 * std::abs(before[c]));
    assert_true(changes > 300);
    mesh_free(&plane);
}

// Each face around v, as its sorted corners and their positions.
std::vector<std::vector<double>> fan_signature(const TriMesh &mesh, int32_t v)
{
    std::vector<std::vector<double>> fan;
    mesh.for_each_outgoing(v, [&](int32_t h) {
        Triangle t = mesh.tri[TriMesh::face(h)];
        std::sort(t.begin(), t.end());
        std::vector<double> face;
        for (int32_t c : t)
            face.insert(face.end(), {double(c), mesh.pos[c].x(), mesh.pos[c].y(), mesh.pos[c].z()});
        fan.push_back(face);
    });
    std::sort(fan.begin(), fan.end());
    return fan;
}

struct RenumberingSeen : EditListener {
    bool seen = false;
    void renumber(const Renumbering &) override { seen = true; }
};

void every_vertex_whose_fan_changed_is_marked(void **)
{
    sfa_mesh_data sphere = shape_icosphere(2, 1.0), plane = shape_grid(8, 6, 0.1);
    for (const sfa_mesh_data *shape : {&sphere, &plane}) {
        TriMesh mesh = mesh_of(*shape);
        MeshEdit edit(mesh);
        ChangedVertices changed(mesh.num_vertices());
        RenumberingSeen renumbered;
        edit.attach(changed);
        edit.attach(renumbered);
        std::vector<std::vector<std::vector<double>>> before;
        const auto remember = [&] {
            before.assign(mesh.pos.size(), {});
            for (int32_t v = 0; v < mesh.num_vertices(); ++v)
                if (!is_dead_vertex(mesh, v))
                    before[v] = fan_signature(mesh, v);
            changed.clear();
        };
        remember();
        int32_t marked = 0;
        random_edits(
            edit, 11, 300, [](int32_t) { return true; },
            [&] {
                if (!renumbered.seen)
                    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
                        if (is_dead_vertex(mesh, v))
                            continue;
                        if (v < static_cast<int32_t>(before.size()) && fan_signature(mesh, v) == before[v])
                            continue;
                        assert_true(changed[v]); // new, or its fan changed
                        ++marked;
                    }
                renumbered.seen = false;
                remember();
            });
        assert_true(marked > 300);
    }
    mesh_free(&sphere);
    mesh_free(&plane);
}

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(edge_flags_stay_on_the_same_vertex_pairs),
        cmocka_unit_test(a_linear_field_stays_linear_through_every_change),
        cmocka_unit_test(face_values_keep_their_integral_on_a_flat_surface),
        cmocka_unit_test(every_vertex_whose_fan_changed_is_marked),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

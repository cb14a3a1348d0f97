// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the vertex origins (fields/vertex_origins.hpp): through random splits,
// contractions, flips, sweeps, offsets, compactions and the locality order of an edit with
// OriginHints attached, every vertex of a flat plane is reproduced by its origin over the
// mesh as it was (to 1e-12), from a hint a few triangles away; on a sphere a linear
// function carried by the origins is off by O(h^2) (a quarter when h halves); a vertex that
// stayed where it was is its old corner, exactly; on one triangle the origin is the
// closest point; and the walk is bounded (far points, convex corners, facing sheets, a
// walk longer than its bound).
#include "fields/vertex_origins.hpp"
#include "mesh/invariants.hpp"
#include "mesh/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <setjmp.h>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

using namespace sfa;

namespace {

TriMesh mesh_of(const sfa_mesh_data &m) { return validated_mesh(MeshInput{m.nverts, m.xyz, m.ntris, m.tris, 0, false}); }

bool alive(const TriMesh &mesh, int32_t h) { return mesh.tri[TriMesh::face(h)][0] >= 0; }

Vec3 point_of(const TriMesh &mesh, const std::vector<Vec3> &positions, const VertexOrigin &o)
{
    Vec3 x = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
        x += o.weights[k] * positions[mesh.tri[o.triangle][k]];
    return x;
}

double distance_to(const TriMesh &before, const VertexOrigin &o, const Vec3 &x)
{
    return (point_of(before, before.pos, o) - x).norm();
}

// The distance from x to the triangle (a, b, c), found as simply as possible: to the
// projection onto the plane if that is inside, else to the nearest of the three edges.
double distance_to_triangle(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &x)
{
    const Eigen::Vector3d w = barycentric(x, a, b, c);
    if (w.minCoeff() >= 0)
        return (x - (w[0] * a + w[1] * b + w[2] * c)).norm();
    const Vec3 *corners[4] = {&a, &b, &c, &a};
    double nearest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        const Vec3 &p = *corners[k], &q = *corners[k + 1];
        const double t = std::clamp((x - p).dot(q - p) / (q - p).squaredNorm(), 0.0, 1.0);
        nearest = std::min(nearest, (x - (p + t * (q - p))).norm());
    }
    return nearest;
}

// A valid origin: a triangle of the mesh as it was, weights in [0, 1] adding up to 1
// exactly (left to right).
void assert_valid(const TriMesh &before, const VertexOrigin &o)
{
    assert_true(o.triangle >= 0 && o.triangle < before.num_triangles());
    for (int k = 0; k < 3; ++k)
        assert_true(o.weights[k] >= 0 && o.weights[k] <= 1);
    assert_true(o.weights[0] + o.weights[1] + o.weights[2] == 1.0);
}

// The unit square of n x n cells with its interior vertices moved by up to 0.3 of a cell
// in x and y (the boundary stays straight, so the mesh as it was covers the square).
TriMesh jittered_plane(int n, uint64_t seed)
{
    sfa_mesh_data grid = shape_grid(n, n, 1.0 / n);
    TriMesh mesh = mesh_of(grid);
    mesh_free(&grid);
    shapes_rng rng = rng_seed(seed);
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        if (!mesh.is_boundary_vertex(v))
            mesh.pos[v] += 0.6 / n * Vec3(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, 0);
    return mesh;
}

// For each vertex, the vertex of the mesh as it was that it still is (it never moved and
// was never merged), or -1: new, moved or merged.
class Unmoved : public EditListener {
public:
    explicit Unmoved(int32_t n) : was_(n)
    {
        for (int32_t v = 0; v < n; ++v)
            was_[v] = v;
    }
    const std::vector<int32_t> &was() const { return was_; }
    void split(const TriMesh &mesh, const SplitChange &) override { was_.resize(mesh.pos.size(), -1); }
    void collapse(const TriMesh &, const CollapseChange &change) override { was_[change.record.keep] = -1; }
    void move(const TriMesh &mesh, const MoveChange &change) override { moved(mesh, change.positions); }
    void offset(const TriMesh &mesh, const std::vector<Vec3> &positions) override { moved(mesh, positions); }
    void renumber(const Renumbering &renumbering) override { renumbering.apply_to_vertices(was_); }

private:
    void moved(const TriMesh &mesh, const std::vector<Vec3> &positions)
    {
        for (int32_t v = 0; v < mesh.num_vertices(); ++v)
            if (positions[v] != mesh.pos[v])
                was_[v] = -1;
    }
    std::vector<int32_t> was_;
};

// True if every face around the edge of h that survives contracting it to `position`
// faces up (z > 0): the plane stays a valid triangulation.
bool collapse_stays_flat(const TriMesh &mesh, int32_t h, const Vec3 &position)
{
    const int32_t gone = mesh.tail(h), keep = mesh.head(h);
    bool up = true;
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        if (std::count(t.begin(), t.end(), gone) + std::count(t.begin(), t.end(), keep) == 2)
            return; // dies
        Vec3 p[3];
        for (int k = 0; k < 3; ++k)
            p[k] = t[k] == gone || t[k] == keep ? position : mesh.pos[t[k]];
        up = up && (p[1] - p[0]).cross(p[2] - p[0]).z() > 1e-12;
    });
    return up;
}

bool flip_stays_flat(const TriMesh &mesh, int32_t h)
{
    const FlipQuad q = flip_quad(mesh, h);
    const auto up = [&](int32_t x, int32_t y, int32_t z) {
        return (mesh.pos[y] - mesh.pos[x]).cross(mesh.pos[z] - mesh.pos[x]).z() > 1e-12;
    };
    return up(q.q, q.p, q.a) && up(q.p, q.q, q.b);
}

// How a surface is edited: where points go (onto the surface), how far a sweep moves a
// vertex, whether the plane must stay a valid triangulation.
struct Surface {
    bool flat;
    double edge; // the mean edge length
};

Vec3 onto(const Surface &s, const Vec3 &x) { return s.flat ? x : x.normalized(); }

struct EditCounts {
    int32_t splits = 0, collapses = 0, flips = 0, sweeps = 0;
};

// Where sweeps move nothing, so that some vertices stay where they were.
bool still(const Surface &s, const Vec3 &x) { return s.flat ? x.x() < 0.25 : x.z() > 0.6; }

// A sweep: about two thirds of the vertices outside the still region move, by up to a third of an edge (on the plane
// an interior vertex moves towards a random convex combination of its neighbours, so it
// stays inside the square; on the sphere in a random direction, then back onto it).
void sweep(MeshEdit &edit, const Surface &s, shapes_rng &rng)
{
    const TriMesh &mesh = edit.mesh();
    std::vector<Vec3> moved = mesh.pos;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        if (is_dead_vertex(mesh, v) || rng_uniform(&rng) < 0.35 || (s.flat && mesh.is_boundary_vertex(v)) ||
            still(s, mesh.pos[v]))
            continue;
        if (s.flat) {
            Vec3 target = Vec3::Zero();
            double total = 0;
            mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
                const double weight = rng_uniform(&rng);
                target += weight * mesh.pos[w];
                total += weight;
            });
            moved[v] += rng_uniform(&rng) / 3 * (target / total - mesh.pos[v]);
        } else {
            const Vec3 d(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5);
            moved[v] = (mesh.pos[v] + s.edge / 3 * d).normalized();
        }
    }
    edit.move(moved);
}

// `steps` random changes: splits at a random point of the edge's middle half, contractions
// to a random point of the edge, flips, a sweep every 64 steps and a compaction every 32;
// then an offset (the volume correction: a little off the sphere; within the plane), a
// compaction and the locality order.
EditCounts random_edits(MeshEdit &edit, const Surface &s, uint64_t seed, int steps)
{
    const TriMesh &mesh = edit.mesh();
    shapes_rng rng = rng_seed(seed);
    EditCounts counts;
    for (int step = 0; step < steps; ++step) {
        if (step % 64 == 63) {
            sweep(edit, s, rng);
            ++counts.sweeps;
        }
        if (step % 32 == 31)
            edit.compact();
        const int32_t h = static_cast<int32_t>(rng_next(&rng) % (3 * mesh.tri.size()));
        if (!alive(mesh, h))
            continue;
        const Vec3 a = mesh.pos[mesh.tail(h)], b = mesh.pos[mesh.head(h)];
        switch (rng_next(&rng) % 3) {
        case 0:
            edit.split(h, onto(s, a + (0.25 + 0.5 * rng_uniform(&rng)) * (b - a)));
            ++counts.splits;
            break;
        case 1: {
            const Vec3 position = onto(s, a + rng_uniform(&rng) * (b - a));
            if (!collapse_keeps_manifold(mesh, h) || (s.flat && !collapse_stays_flat(mesh, h, position)))
                continue;
            edit.collapse(h, position);
            ++counts.collapses;
            break;
        }
        case 2:
            if (!flip_keeps_manifold(mesh, h) || (s.flat && !flip_stays_flat(mesh, h)))
                continue;
            edit.flip(h);
            ++counts.flips;
            break;
        }
    }
    std::vector<Vec3> offset = mesh.pos;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        if (is_dead_vertex(mesh, v) || v % 3 != 0)
            continue;
        if (s.flat && !mesh.is_boundary_vertex(v))
            offset[v] += 1e-3 * s.edge * Vec3(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, 0);
        else if (!s.flat)
            offset[v] *= 1 + 1e-2 * s.edge * s.edge;
    }
    edit.offset(offset);
    edit.compact();
    edit.order_for_locality();
    assert_string_equal(invariant_violation(mesh).c_str(), "");
    return counts;
}

// The fewest walk steps from its hint that reproduce x to 1e-12 over the plane, or
// `limit` + 1 if none up to `limit` do.
int32_t steps_needed(const TriMesh &before, int32_t hint, const Vec3 &x, int32_t limit)
{
    for (int32_t steps = 1; steps <= limit; ++steps) {
        const VertexOrigin o = locate_origin(before, before.pos, hint, x, steps);
        if ((point_of(before, before.pos, o) - x).norm() <= 1e-12)
            return steps;
    }
    return limit + 1;
}

void a_flat_plane_is_reproduced_through_every_change(void **)
{
    for (uint64_t seed : {1, 2, 3}) {
        TriMesh mesh = jittered_plane(16, seed);
        const TriMesh before = mesh;
        const Surface plane{true, 1.0 / 16};
        MeshEdit edit(mesh);
        OriginHints hints(mesh);
        Unmoved unmoved(mesh.num_vertices());
        edit.attach(hints);
        edit.attach(unmoved);
        const EditCounts counts = random_edits(edit, plane, 10 + seed, 1500);
        assert_true(counts.splits > 200 && counts.collapses > 100 && counts.flips > 100 && counts.sweeps > 20);
        assert_int_equal(hints.hints().size(), mesh.pos.size());

        const std::vector<VertexOrigin> origins = locate_origins(before, before.pos, hints.hints(), mesh.pos);
        int32_t stayed = 0, far = 0, farthest = 0;
        for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
            assert_valid(before, origins[v]);
            const double error = (point_of(before, before.pos, origins[v]) - mesh.pos[v]).norm();
            if (error > 1e-12)
                fail_msg("seed %d, vertex %d: its origin is %g away", int(seed), v, error);
            stayed += unmoved.was()[v] >= 0;
            // The hints are near: a few triangles' walk finds the origin.
            const int32_t steps = steps_needed(before, hints.hints()[v], mesh.pos[v], 16);
            farthest = std::max(farthest, steps);
            far += steps > 8;
        }
        std::printf("plane, seed %d: %d vertices (%d stayed), %d splits, %d contractions, %d flips, %d sweeps; "
                    "walks of up to %d triangles, %d longer than 8\n",
                    int(seed), mesh.num_vertices(), stayed, counts.splits, counts.collapses, counts.flips,
                    counts.sweeps, farthest, far);
        assert_true(stayed > 20);
        assert_true(farthest <= 16);

        // Hints that are not followed through the edit are far: the same check fails.
        std::vector<int32_t> stale = hints.hints();
        std::reverse(stale.begin(), stale.end());
        int32_t lost = 0;
        for (int32_t v = 0; v < mesh.num_vertices(); ++v)
            lost += steps_needed(before, stale[v], mesh.pos[v], 16) > 16;
        assert_true(lost > mesh.num_vertices() / 4);
    }
}

// The error of f(x) = a.x + b carried by the origins (sum of w_k f(corner k)) over the
// vertices of a jittered icosphere of 20 4^k triangles after random changes that keep
// every vertex on the sphere (largest and root mean square), and the mesh's mean edge.
struct LinearError {
    double max_error, rms_error, edge;
};

LinearError linear_error_on_a_sphere(int k, uint64_t seed)
{
    sfa_mesh_data sphere = shape_jittered_icosphere(k, 1.0, 0.25, seed);
    TriMesh mesh = mesh_of(sphere);
    const double edge = mesh_mean_edge_length(&sphere);
    mesh_free(&sphere);
    const TriMesh before = mesh;
    MeshEdit edit(mesh);
    OriginHints hints(mesh);
    Unmoved unmoved(mesh.num_vertices());
    edit.attach(hints);
    edit.attach(unmoved);
    const EditCounts counts = random_edits(edit, Surface{false, edge}, seed, before.num_triangles() / 2);
    assert_true(counts.splits > 0 && counts.collapses > 0 && counts.flips > 0 && counts.sweeps > 0);

    const Vec3 a(0.3, -0.5, 0.8);
    const double b = 0.25;
    const auto f = [&](const Vec3 &x) { return a.dot(x) + b; };
    const std::vector<VertexOrigin> origins = locate_origins(before, before.pos, hints.hints(), mesh.pos);
    double max_error = 0, sum_squares = 0;
    int32_t stayed = 0, not_nearest = 0;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        const VertexOrigin &o = origins[v];
        assert_valid(before, o);
        double carried = 0;
        for (int c = 0; c < 3; ++c)
            carried += o.weights[c] * f(before.pos[before.tri[o.triangle][c]]);
        const double error = std::abs(carried - f(mesh.pos[v]));
        max_error = std::max(max_error, error);
        sum_squares += error * error;
        stayed += unmoved.was()[v] >= 0;
        // The hints are near: a short walk finds the same triangle.
        assert_int_equal(locate_origin(before, before.pos, hints.hints()[v], mesh.pos[v], 16).triangle, o.triangle);
        if (k > 4)
            continue; // the brute force below is quadratic
        // The origin is the nearest point of the sphere as it was, or nearly: where x lies
        // over two triangles (across an edge that is nearly flat, or a little concave
        // where the jitter made it so), the walk stops at the first it reaches.
        double nearest = std::numeric_limits<double>::infinity();
        for (const Triangle &t : before.tri)
            nearest = std::min(nearest, distance_to_triangle(before.pos[t[0]], before.pos[t[1]], before.pos[t[2]], mesh.pos[v]));
        const double found = distance_to(before, o, mesh.pos[v]);
        if (found > 1.001 * nearest + 1e-12)
            fail_msg("icosphere %d, vertex %d: origin %g away, the nearest triangle %g", k, v, found, nearest);
        not_nearest += found > nearest + 1e-12;
    }
    assert_true(stayed > mesh.num_vertices() / 20);
    const double rms_error = std::sqrt(sum_squares / mesh.num_vertices());
    std::printf("sphere %d: %d vertices, h = %.4f, error of a linear function: largest %.3e (%.3f h^2), "
                "rms %.3e (%.3f h^2)",
                k, mesh.num_vertices(), edge, max_error, max_error / (edge * edge), rms_error, rms_error / (edge * edge));
    if (k <= 4)
        std::printf("; %d origins not on the nearest triangle", not_nearest);
    std::printf("\n");
    return {max_error, rms_error, edge};
}

void a_linear_function_on_a_sphere_is_carried_to_second_order(void **)
{
    LinearError e[3];
    for (int level = 0; level < 3; ++level)
        e[level] = linear_error_on_a_sphere(3 + level, 21 + level);
    for (int level = 0; level < 3; ++level)
        assert_true(e[level].max_error < 0.5 * e[level].edge * e[level].edge); // |a| about 1, a unit sphere
    for (int level = 0; level < 2; ++level) {
        const double h_ratio = e[level].edge / e[level + 1].edge;
        const double max_ratio = e[level].max_error / e[level + 1].max_error;
        const double rms_ratio = e[level].rms_error / e[level + 1].rms_error;
        std::printf("h %.2f times smaller: the error %.2f times smaller (largest), %.2f (rms)\n", h_ratio,
                    max_ratio, rms_ratio);
        assert_true(h_ratio > 1.9 && h_ratio < 2.1);
        // h^2: 4 (h: 2). The largest error is that of the largest triangle: noisier.
        assert_true(max_ratio > 3 && max_ratio < 5.5);
        assert_true(rms_ratio > 3.4 && rms_ratio < 4.6);
    }
}

// A vertex that stayed where it was (never moved nor merged; its fan may have changed) has
// its old self as origin: weight 1 on that corner, the position reproduced bit for bit.
void a_vertex_that_stayed_is_its_old_corner_exactly(void **)
{
    sfa_mesh_data sphere = shape_jittered_icosphere(3, 1.0, 0.25, 5);
    for (bool flat : {true, false}) {
        TriMesh mesh = flat ? jittered_plane(16, 4) : mesh_of(sphere);
        const TriMesh before = mesh;
        MeshEdit edit(mesh);
        OriginHints hints(mesh);
        Unmoved unmoved(mesh.num_vertices());
        edit.attach(hints);
        edit.attach(unmoved);
        random_edits(edit, Surface{flat, flat ? 1.0 / 16 : mesh_mean_edge_length(&sphere)}, 31, 600);
        const std::vector<VertexOrigin> origins = locate_origins(before, before.pos, hints.hints(), mesh.pos);
        int32_t stayed = 0;
        for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
            const int32_t was = unmoved.was()[v];
            if (was < 0)
                continue;
            ++stayed;
            const VertexOrigin &o = origins[v];
            const Triangle &corners = before.tri[o.triangle];
            const int k = static_cast<int>(std::find(corners.begin(), corners.end(), was) - corners.begin());
            assert_true(k < 3);
            assert_true(o.weights[k] == 1.0);
            assert_true(point_of(before, before.pos, o) == mesh.pos[v]);
        }
        std::printf("%s: %d stayed\n", flat ? "plane" : "sphere", stayed);
        assert_true(stayed > 30);
    }
    mesh_free(&sphere);
}

// On one triangle, the origin is x's closest point (the walk's choice of the nearest
// triangle rests on it): random points about random triangles, obtuse ones among them.
void the_origin_on_one_triangle_is_the_closest_point(void **)
{
    shapes_rng rng = rng_seed(17);
    const auto random_point = [&](double scale) -> Vec3 {
        return scale * Vec3(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5);
    };
    for (int trial = 0; trial < 2000; ++trial) {
        TriMesh one;
        one.pos = {random_point(1), random_point(1), random_point(1)};
        if (trial % 2)
            one.pos[2] = (one.pos[0] + one.pos[1]) / 2 + random_point(0.1); // obtuse, often very
        one.tri = {{0, 1, 2}};
        build_adjacency(one);
        const Vec3 x = random_point(3);
        const VertexOrigin o = locate_origin(one, one.pos, 0, x);
        assert_valid(one, o);
        assert_float_equal(distance_to(one, o, x), distance_to_triangle(one.pos[0], one.pos[1], one.pos[2], x), 1e-12);
    }
}

void the_walk_is_bounded(void **)
{
    // Just beyond the edge of a plane, from a hint at the far corner: the walk crosses the
    // plane and stops at the boundary, at the nearest point. Far beyond it, the
    // coordinates point along the boundary no more: it stops at the boundary, with the
    // nearest triangle it saw.
    const TriMesh plane = jittered_plane(16, 7);
    const VertexOrigin beyond = locate_origin(plane, plane.pos, 0, Vec3(1.001, 0.5, 0));
    assert_valid(plane, beyond);
    assert_true((point_of(plane, plane.pos, beyond) - Vec3(1, 0.5, 0)).norm() < 1e-12);
    const Vec3 far(5, 0.5, 3);
    const VertexOrigin far_beyond = locate_origin(plane, plane.pos, 0, far);
    assert_valid(plane, far_beyond);
    const Vec3 reached_edge = point_of(plane, plane.pos, far_beyond);
    assert_true(std::abs(reached_edge.x() - 1) < 1e-12 && reached_edge.z() == 0);
    assert_true(distance_to(plane, far_beyond, far) < distance_to(plane, locate_origin(plane, plane.pos, 0, far, 1), far));

    // A walk longer than its bound: it stops, with the nearest triangle it saw.
    sfa_mesh_data strip_data = shape_grid(400, 1, 0.01);
    const TriMesh strip = mesh_of(strip_data);
    mesh_free(&strip_data);
    const Vec3 end(3.995, 0.005, 0);
    const VertexOrigin cut = locate_origin(strip, strip.pos, 0, end, 100);
    assert_valid(strip, cut);
    const double from_hint = distance_to(strip, locate_origin(strip, strip.pos, 0, end, 1), end);
    const double reached = distance_to(strip, cut, end);
    assert_true(reached < from_hint - 0.3 && reached > 3.995 - 100 * 0.01); // two triangles per cell
    const VertexOrigin whole = locate_origin(strip, strip.pos, 0, end, 1000);
    assert_true(distance_to(strip, whole, end) < 1e-12);

    // Outside a convex corner, over none of its faces: round the fan and stop, at the corner.
    sfa_mesh_data ico_data = shape_icosahedron(1.0);
    const TriMesh ico = mesh_of(ico_data);
    mesh_free(&ico_data);
    const Vec3 over_corner = 1.5 * ico.pos[0];
    const VertexOrigin corner = locate_origin(ico, ico.pos, TriMesh::face(ico.v2h[0]), over_corner);
    assert_valid(ico, corner);
    assert_true((point_of(ico, ico.pos, corner) - ico.pos[0]).norm() < 1e-12);

    // A point off the edge between two faces, over neither (the to and fro at a ridge).
    const int32_t h = ico.v2h[0];
    const Vec3 off_edge = 1.2 * (ico.pos[ico.tail(h)] + ico.pos[ico.head(h)]) / 2;
    const VertexOrigin ridge = locate_origin(ico, ico.pos, TriMesh::face(h), off_edge);
    assert_valid(ico, ridge);
    assert_true((point_of(ico, ico.pos, ridge) - (ico.pos[ico.tail(h)] + ico.pos[ico.head(h)]) / 2).norm() < 1e-12);

    // Two facing sheets: from a hint on the upper one, the point nearer the lower sheet
    // stays on the upper (the walk only crosses edges).
    sfa_mesh_data lower = shape_grid(8, 8, 0.125), upper = shape_grid(8, 8, 0.125);
    const double up[3] = {0, 0, 0.01};
    mesh_translate(&upper, up);
    mesh_append(&lower, &upper);
    const TriMesh sheets = mesh_of(lower);
    const int32_t upper_first = upper.ntris;
    mesh_free(&lower);
    mesh_free(&upper);
    const VertexOrigin stays = locate_origin(sheets, sheets.pos, upper_first + 5, Vec3(0.4, 0.6, 0.001));
    assert_valid(sheets, stays);
    assert_true(stays.triangle >= upper_first);
    assert_true((point_of(sheets, sheets.pos, stays) - Vec3(0.4, 0.6, 0.01)).norm() < 1e-12);

    // No hint, no origin; a point that is not a number: the hint, with valid weights.
    assert_int_equal(locate_origin(plane, plane.pos, -1, far).triangle, -1);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    assert_valid(plane, locate_origin(plane, plane.pos, 3, Vec3(nan, 0, 0)));
}

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_flat_plane_is_reproduced_through_every_change),
        cmocka_unit_test(a_linear_function_on_a_sphere_is_carried_to_second_order),
        cmocka_unit_test(a_vertex_that_stayed_is_its_old_corner_exactly),
        cmocka_unit_test(the_origin_on_one_triangle_is_the_closest_point),
        cmocka_unit_test(the_walk_is_bounded),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

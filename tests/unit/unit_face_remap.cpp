// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the conservative remap by overlap (geometry/overlap.hpp) and of FaceValues
// (fields/face_values.hpp), which carries densities per unit area on the triangles through
// every change of an edit with it: the overlap of two triangles in known cases, slivers
// included; on a flat jittered plane, through random splits, flips, contractions and
// smoothing sweeps, the integrals of a constant and of linear densities kept to round-off,
// the constant kept constant, and a linear density smeared less than by the averaging the
// remap replaced; on a sphere whose vertices slide along it, the integrals kept and a
// constant within 1 %.
#include "fields/face_values.hpp"
#include "geometry/overlap.hpp"
#include "mesh/invariants.hpp"
#include "mesh/validate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <setjmp.h>
#include <tuple>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

#include "assert_near.hpp"

using namespace sfa;

namespace {

constexpr double pi = 3.14159265358979323846;

using Tri2 = std::array<ChartPoint, 3>;

double twice_area(const Tri2 &t) { return (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x); }
double overlap(const Tri2 &a, const Tri2 &b) { return overlap_area(a.data(), b.data()); }
Tri2 reversed(const Tri2 &t) { return {t[0], t[2], t[1]}; }

// Every orientation of either triangle and either order gives the same overlap.
void assert_overlap(const Tri2 &a, const Tri2 &b, double expected, double tolerance)
{
    for (const Tri2 &x : {a, reversed(a)})
        for (const Tri2 &y : {b, reversed(b)}) {
            assert_near(overlap(x, y), expected, tolerance);
            assert_near(overlap(y, x), expected, tolerance);
        }
}

void overlap_of_known_pairs(void **)
{
    const Tri2 big{{{0, 0}, {2, 0}, {0, 2}}};
    assert_overlap(big, big, 2, 1e-15);                             // identical
    assert_overlap(big, {{{3, 0}, {5, 0}, {3, 2}}}, 0, 0);          // disjoint
    assert_overlap(big, {{{2, 0}, {2, 2}, {0, 2}}}, 0, 1e-15);      // sharing an edge only
    assert_overlap(big, {{{0, 2}, {-1, 3}, {-1, 2}}}, 0, 1e-15);    // sharing a corner only
    assert_overlap(big, {{{0.2, 0.2}, {1, 0.2}, {0.2, 1}}}, 0.32, 1e-15); // one inside the other
    // Half of each: big and its mirror image about x = 1 meet in (0,0), (2,0), (1,1).
    assert_overlap(big, {{{0, 0}, {2, 0}, {2, 2}}}, 1, 1e-15);
    // The star of David: an equilateral triangle and its half-turn about the centre meet in
    // a hexagon of two thirds of its area.
    const double s = std::sqrt(3.0);
    const Tri2 up{{{-1, -1 / s}, {1, -1 / s}, {0, 2 / s}}}, down{{{1, 1 / s}, {-1, 1 / s}, {0, -2 / s}}};
    assert_overlap(up, down, 2.0 / 3.0 * 0.5 * twice_area(up), 1e-15);
    // Big below y = 1, a quadrilateral of 2 - 0.5: the other triangle's top edge lies on
    // y = 1 and its other edges pass outside big.
    assert_overlap(big, {{{-3, 1}, {1, -3}, {5, 1}}}, 1.5, 1e-15);
    // Big's corner cut off by x + y = 0.5.
    assert_overlap(big, {{{-1, -1}, {1.5, -1}, {-1, 1.5}}}, 0.125, 1e-15);
}

void overlap_of_slivers_and_degenerate_triangles(void **)
{
    const Tri2 big{{{0, 0}, {2, 0}, {0, 2}}};
    // A sliver inside: its own area. Round-off is relative to the triangles' size squared
    // (here 1), not to the sliver's area.
    const Tri2 sliver{{{0.1, 0.1}, {1.5, 0.1}, {0.8, 0.1 + 1e-9}}};
    assert_overlap(big, sliver, 0.5 * twice_area(sliver), 1e-15);
    // A sliver across an edge of big, tapering to a point outside: the three quarters of
    // it beyond the half-way width are inside.
    const Tri2 across{{{-1, 0.5}, {1, 0.5 + 1e-10}, {1, 0.5 - 1e-10}}};
    assert_overlap(big, across, 0.75 * 0.5 * std::abs(twice_area(across)), 1e-15);
    // Collinear, coincident or absurdly small corners: zero (and never NaN).
    const Tri2 degenerate[] = {
        {{{0.1, 0.1}, {0.5, 0.5}, {0.9, 0.9}}},
        {{{0.5, 0.5}, {0.5, 0.5}, {1, 0.2}}},
        {{{0.3, 0.3}, {0.3, 0.3}, {0.3, 0.3}}},
        {{{0, 0}, {1e-300, 0}, {0, 1e-300}}},
    };
    for (const Tri2 &d : degenerate) {
        assert_true(overlap(big, d) >= 0 && overlap(big, d) <= 1e-300);
        assert_true(overlap(d, big) >= 0 && overlap(d, big) <= 1e-300);
        assert_true(overlap(d, d) >= 0 && overlap(d, d) <= 1e-300);
    }
    // Two nearly identical slivers, each almost on the other's edges: between 0 and the area.
    shapes_rng rng = rng_seed(4);
    for (int k = 0; k < 10000; ++k) {
        const double e = std::pow(10.0, -16 * rng_uniform(&rng));
        const Tri2 a{{{0, 0}, {1, 0}, {rng_uniform(&rng), e}}};
        const Tri2 b{{{e * rng_uniform(&rng), 0}, {1, e * (rng_uniform(&rng) - 0.5)}, {rng_uniform(&rng), e}}};
        const double o = overlap(a, b);
        assert_true(std::isfinite(o) && o >= 0 && o <= 0.5 * std::min(std::abs(twice_area(a)), std::abs(twice_area(b))));
    }
}

// A triangle cut into four by its edge midpoints, and into three about an inner point:
// any triangle's overlap with it is the sum of its overlaps with the parts.
void overlap_adds_up_over_a_partition(void **)
{
    shapes_rng rng = rng_seed(8);
    const auto point = [&] { return ChartPoint{4 * rng_uniform(&rng) - 2, 4 * rng_uniform(&rng) - 2}; };
    const auto mid = [](ChartPoint a, ChartPoint b) { return ChartPoint{(a.x + b.x) / 2, (a.y + b.y) / 2}; };
    for (int k = 0; k < 2000; ++k) {
        const Tri2 t{point(), point(), point()}, x{point(), point(), point()};
        const ChartPoint ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
        const Tri2 fours[] = {{t[0], ab, ca}, {ab, t[1], bc}, {ca, bc, t[2]}, {ab, bc, ca}};
        const double w = rng_uniform(&rng), v = (1 - w) * rng_uniform(&rng);
        const ChartPoint inner{t[0].x + w * (t[1].x - t[0].x) + v * (t[2].x - t[0].x),
                               t[0].y + w * (t[1].y - t[0].y) + v * (t[2].y - t[0].y)};
        const Tri2 threes[] = {{t[0], t[1], inner}, {t[1], t[2], inner}, {t[2], t[0], inner}};
        double by_fours = 0, by_threes = 0;
        for (const Tri2 &part : fours)
            by_fours += overlap(x, part);
        for (const Tri2 &part : threes)
            by_threes += overlap(x, part);
        const double whole = overlap(x, t);
        assert_true(whole <= 0.5 * std::min(std::abs(twice_area(t)), std::abs(twice_area(x))));
        assert_near(by_fours, whole, 1e-14);
        assert_near(by_threes, whole, 1e-14);
    }
}

Vec3 area_vector(const Vec3 &a, const Vec3 &b, const Vec3 &c) { return 0.5 * (b - a).cross(c - a); }

// A fan of six triangles around a point of a tilted plane, and the same fan with the point
// moved: by overlap, a constant stays constant and the total is kept; turned over, the
// fan is shared by area, still conservatively.
void remap_of_a_fan(void **)
{
    const Vec3 normal = Vec3(1, -2, 3).normalized();
    const Vec3 u = normal.cross(Vec3::UnitX()).normalized(), w = normal.cross(u);
    const auto at = [&](double x, double y) -> Vec3 { return Vec3(0.3, 0.1, -0.2) + x * u + y * w; };
    const auto fan = [&](double cx, double cy) {
        std::vector<Corners> faces;
        for (int k = 0; k < 6; ++k) {
            const double a0 = k * pi / 3, a1 = (k + 1) * pi / 3;
            faces.push_back({at(cx, cy), at(std::cos(a0), std::sin(a0)), at(std::cos(a1), std::sin(a1))});
        }
        return faces;
    };
    const std::vector<Corners> before = fan(0, 0);
    std::vector<double> old_values(12), new_values(12);
    for (int k = 0; k < 6; ++k) {
        old_values[2 * k] = 3;
        old_values[2 * k + 1] = k - 2.5; // both signs
    }
    const auto total = [](const std::vector<Corners> &faces, const std::vector<double> &values, int c) {
        double sum = 0;
        for (size_t k = 0; k < faces.size(); ++k)
            sum += values[2 * k + c] * 0.5 * (faces[k][1] - faces[k][0]).cross(faces[k][2] - faces[k][0]).norm();
        return sum;
    };
    for (const auto &[cx, cy, path] : {std::tuple{0.3, -0.2, RemapPath::overlap}, std::tuple{1.5, 0.2, RemapPath::shared}}) {
        const std::vector<Corners> after = fan(cx, cy);
        assert_int_equal(static_cast<int>(remap_by_overlap(before.data(), old_values.data(), 6, after.data(),
                                                           new_values.data(), 6, 2, 5 * normal)),
                         static_cast<int>(path));
        for (int c = 0; c < 2; ++c)
            assert_near(total(after, new_values, c), total(before, old_values, c), 1e-14);
        for (int k = 0; k < 6; ++k)
            assert_near(new_values[2 * k], 3, path == RemapPath::overlap ? 1e-14 : 1.0);
    }
    // Onto itself: every value where it was.
    remap_by_overlap(before.data(), old_values.data(), 6, before.data(), new_values.data(), 6, 2, normal);
    for (int k = 0; k < 12; ++k)
        assert_near(new_values[k], old_values[k], 1e-14);
}

// A steep cap of three faces whose apex leans out past its base: seen along the fan's
// area-weighted normal (the base's) a face is turned over, but seen along a tilted normal
// none is, and the remap maps by overlap there. A constant stays one value on all faces.
void remap_of_a_leaning_cap(void **)
{
    const Vec3 a(1, 0, 0), b(-0.5, std::sqrt(0.75), 0), c(-0.5, -std::sqrt(0.75), 0);
    const auto cap = [&](const Vec3 &v) { return std::vector<Corners>{{v, a, b}, {v, b, c}, {v, c, a}}; };
    const std::vector<Corners> before = cap({1.3, 0, 1}), after = cap({1.2, 0.1, 1});
    Vec3 normal = Vec3::Zero();
    for (const std::vector<Corners> *fan : {&before, &after})
        for (const Corners &t : *fan)
            normal += area_vector(t[0], t[1], t[2]);
    assert_true(area_vector(before[2][0], before[2][1], before[2][2]).dot(normal) < 0);
    const std::vector<double> old_values{2, 2, 2};
    std::vector<double> new_values(3);
    assert_int_equal(static_cast<int>(remap_by_overlap(before.data(), old_values.data(), 3, after.data(),
                                                       new_values.data(), 3, 1, normal)),
                     static_cast<int>(RemapPath::overlap));
    double old_total = 0, new_total = 0;
    for (int k = 0; k < 3; ++k) {
        old_total += 2 * triangle_area(before[k][0], before[k][1], before[k][2]);
        new_total += new_values[k] * triangle_area(after[k][0], after[k][1], after[k][2]);
        assert_near(new_values[k], new_values[0], 1e-14);
    }
    assert_near(new_total, old_total, 1e-14 * old_total);
}

// ---------------------------------------------------------------- through edits

TriMesh mesh_of(const sfa_mesh_data &m) { return validated_mesh(MeshInput{m.nverts, m.xyz, m.ntris, m.tris, 0, false}); }

bool alive(const TriMesh &mesh, int32_t h) { return mesh.tri[TriMesh::face(h)][0] >= 0; }

double face_area(const TriMesh &mesh, int32_t t)
{
    const Triangle &c = mesh.tri[t];
    return area_vector(mesh.pos[c[0]], mesh.pos[c[1]], mesh.pos[c[2]]).norm();
}
Vec3 centroid(const TriMesh &mesh, int32_t t)
{
    const Triangle &c = mesh.tri[t];
    return (mesh.pos[c[0]] + mesh.pos[c[1]] + mesh.pos[c[2]]) / 3;
}

double total(const TriMesh &mesh, const std::vector<double> &values, int32_t ncomp, int32_t c)
{
    double sum = 0;
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        if (mesh.tri[t][0] >= 0)
            sum += values[static_cast<size_t>(ncomp) * t + c] * face_area(mesh, t);
    return sum;
}

// The surface the edits stay on: which way it faces at a point, how a point is put back
// onto it, and how well shaped a face the edits make must be.
struct Surface {
    Vec3 (*up)(const Vec3 &);
    Vec3 (*onto)(const Vec3 &);
    double min_quality; // of 4 sqrt(3) area / (sum of squared edge lengths): 1 if equilateral
};
constexpr double radius = 1.3;
// On the plane slivers down to about a degree are allowed. Thinner ones make the constant
// drift by more than 1e-12, and rightly: a split point that rounding puts off the edge
// changes the halves' total area from the sliver's, relatively, by its distance from the
// edge over the sliver's height (1e-17 / 1e-5), and the halves must share the sliver's
// integral exactly.
const Surface plane{[](const Vec3 &) -> Vec3 { return Vec3::UnitZ(); }, [](const Vec3 &p) { return p; }, 0.03};
// On the sphere the edits keep the faces well shaped, as adaptation does: a sliver lifted
// onto the sphere by a split, or folded by a flip, gains or loses a large part of its area,
// and a conserved density must then change as much.
const Surface sphere{[](const Vec3 &p) -> Vec3 { return p.normalized(); },
                     [](const Vec3 &p) -> Vec3 { return radius * p.normalized(); }, 0.3};

double quality(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    const double lengths = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    return lengths > 0 ? 4 * std::sqrt(3.0) * area_vector(a, b, c).norm() / lengths : 0;
}

// True if (a, b, c) faces up by more than a sliver's round-off, and is shaped well enough.
bool acceptable(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Surface &surface)
{
    const double lengths = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    return area_vector(a, b, c).dot(surface.up((a + b + c) / 3)) > 1e-9 * lengths &&
           quality(a, b, c) >= surface.min_quality;
}

// The faces a split of h at m would make: each face of the edge with either end replaced by m.
bool split_acceptable(const TriMesh &mesh, int32_t h, const Vec3 &m, const Surface &surface)
{
    bool ok = true;
    mesh.for_each_face_of_edge(h, [&](int32_t f) {
        for (int32_t end : {mesh.tail(h), mesh.head(h)}) {
            Corners t = {mesh.pos[mesh.tri[f][0]], mesh.pos[mesh.tri[f][1]], mesh.pos[mesh.tri[f][2]]};
            for (int k = 0; k < 3; ++k)
                if (mesh.tri[f][k] == end)
                    t[k] = m;
            ok = ok && acceptable(t[0], t[1], t[2], surface);
        }
    });
    return ok;
}

// Where faces must be well shaped, a flip must also make the pair better shaped, as a
// flipping pass's do (random flips back and forth would fold the sphere's quads each time).
bool flip_acceptable(const TriMesh &mesh, int32_t h, const Surface &surface)
{
    const FlipQuad q = flip_quad(mesh, h);
    const std::vector<Vec3> &p = mesh.pos;
    const bool better = surface.min_quality == 0 ||
                        std::min(quality(p[q.q], p[q.p], p[q.a]), quality(p[q.p], p[q.q], p[q.b])) >
                            std::min(quality(p[q.a], p[q.b], p[q.p]), quality(p[q.b], p[q.a], p[q.q]));
    return better && acceptable(p[q.q], p[q.p], p[q.a], surface) && acceptable(p[q.p], p[q.q], p[q.b], surface);
}

bool collapse_acceptable(const TriMesh &mesh, int32_t h, const Surface &surface)
{
    const int32_t gone = mesh.tail(h), keep = mesh.head(h);
    bool ok = true;
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        Triangle t = mesh.tri[f];
        if (std::count(t.begin(), t.end(), gone) + std::count(t.begin(), t.end(), keep) == 2)
            return; // dies
        for (int32_t &c : t)
            c = c == gone ? keep : c;
        ok = ok && acceptable(mesh.pos[t[0]], mesh.pos[t[1]], mesh.pos[t[2]], surface);
    });
    return ok;
}

// The sweep a smoothing pass might make: every interior vertex pushed by up to `reach`
// times its shortest edge in a random direction of the tangent plane, then back onto the
// surface. A vertex whose move would make a face of its fan unacceptable, with the
// vertices before it moved already (the order FaceValues remaps in), stays.
std::vector<Vec3> sweep(const TriMesh &mesh, shapes_rng &rng, double reach, const Surface &surface)
{
    std::vector<Vec3> moved = mesh.pos;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        if (is_dead_vertex(mesh, v) || mesh.is_boundary_vertex(v))
            continue;
        double shortest = INFINITY;
        mesh.for_each_outgoing(v, [&](int32_t g) { shortest = std::min(shortest, (moved[mesh.head(g)] - moved[v]).norm()); });
        const Vec3 n = surface.up(moved[v]);
        Vec3 d(rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5, rng_uniform(&rng) - 0.5);
        d -= d.dot(n) * n;
        const Vec3 was = moved[v];
        moved[v] = surface.onto(was + reach * shortest * rng_uniform(&rng) * d.normalized());
        bool ok = true;
        mesh.for_each_outgoing(v, [&](int32_t g) {
            const Triangle &t = mesh.tri[TriMesh::face(g)];
            ok = ok && acceptable(moved[t[0]], moved[t[1]], moved[t[2]], surface);
        });
        if (!ok)
            moved[v] = was;
    }
    return moved;
}

// The rules FaceValues had before the remap by overlap, to measure the remap against: a
// flipped pair both take the pair's mean density, a contraction's surviving faces are all
// scaled by one factor, a sweep leaves the densities as they are.
class AveragingFaceValues : public EditListener {
public:
    AveragingFaceValues(int32_t components, std::vector<double> initial) : ncomp_(components), values(std::move(initial)) {}
    void split(const TriMesh &mesh, const SplitChange &change) override
    {
        const SplitRecord &r = change.record;
        values.resize(static_cast<size_t>(ncomp_) * mesh.tri.size());
        const int32_t opposite[2] = {r.p, r.q};
        for (int side = 0; side < 2; ++side) {
            const int32_t kept = r.old_faces[side], made = r.new_faces[side];
            if (kept < 0)
                continue;
            const int32_t from = side == 0 ? r.a : r.b, to = side == 0 ? r.b : r.a;
            const double whole = area_vector(mesh.pos[from], mesh.pos[to], mesh.pos[opposite[side]]).norm();
            const double scale = whole / (face_area(mesh, kept) + face_area(mesh, made));
            for (int32_t c = 0; c < ncomp_; ++c)
                at(made, c) = at(kept, c) *= scale;
        }
    }
    void flip(const TriMesh &mesh, const FlipChange &change) override
    {
        const FlipQuad &q = change.quad;
        const std::vector<Vec3> &p = mesh.pos;
        const double old_areas[2] = {area_vector(p[q.a], p[q.b], p[q.p]).norm(), area_vector(p[q.b], p[q.a], p[q.q]).norm()};
        const double new_area = face_area(mesh, change.faces[0]) + face_area(mesh, change.faces[1]);
        for (int32_t c = 0; c < ncomp_; ++c)
            at(change.faces[0], c) = at(change.faces[1], c) =
                (at(change.faces[0], c) * old_areas[0] + at(change.faces[1], c) * old_areas[1]) / new_area;
    }
    void before_collapse(const TriMesh &mesh, int32_t h) override
    {
        before_.assign(ncomp_, 0);
        mesh.for_each_face_around_edge(h, [&](int32_t f) {
            for (int32_t c = 0; c < ncomp_; ++c)
                before_[c] += at(f, c) * face_area(mesh, f);
        });
    }
    void collapse(const TriMesh &mesh, const CollapseChange &change) override
    {
        std::vector<double> after(ncomp_, 0);
        mesh.for_each_outgoing(change.record.keep, [&](int32_t g) {
            for (int32_t c = 0; c < ncomp_; ++c)
                after[c] += at(TriMesh::face(g), c) * face_area(mesh, TriMesh::face(g));
        });
        mesh.for_each_outgoing(change.record.keep, [&](int32_t g) {
            for (int32_t c = 0; c < ncomp_; ++c)
                at(TriMesh::face(g), c) *= before_[c] / after[c];
        });
    }
    void renumber(const Renumbering &r) override { r.apply(values, r.triangle_map, static_cast<size_t>(ncomp_)); }

    int32_t ncomp_;
    std::vector<double> values;

private:
    double &at(int32_t t, int32_t c) { return values[static_cast<size_t>(ncomp_) * t + c]; }
    std::vector<double> before_;
};

// Densities given by functions of the position: their exact means over each face are their
// values at its centroid (they are linear).
constexpr int32_t ncomp = 3;
constexpr double constant = 1.5; // component 0
double density(const Vec3 &p, int32_t c)
{
    switch (c) {
    case 0: return constant;
    case 1: return 1 + 2 * p.x() - 3 * p.y();    // linear, of both signs over the region
    default: return 2 + p.x() + p.y() + p.z();   // linear and positive
    }
}

std::vector<double> exact_densities(const TriMesh &mesh)
{
    std::vector<double> values(static_cast<size_t>(ncomp) * mesh.num_triangles());
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        for (int32_t c = 0; c < ncomp; ++c)
            values[static_cast<size_t>(ncomp) * t + c] = density(centroid(mesh, t), c);
    return values;
}

// The area-weighted L1 distance of component c from its exact mean on each face.
double deviation(const TriMesh &mesh, const std::vector<double> &values, int32_t c)
{
    double sum = 0;
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        if (mesh.tri[t][0] >= 0)
            sum += std::abs(values[static_cast<size_t>(ncomp) * t + c] - density(centroid(mesh, t), c)) * face_area(mesh, t);
    return sum;
}

// Random splits (at the edge's midpoint put back onto the surface), flips and contractions
// of interior edges (onto the kept vertex) whose faces are acceptable, a compaction every
// 64 steps, and every `sweep_every` steps a sweep; check() after every change. Returns the
// number of changes.
template <class Check>
int32_t random_edits(MeshEdit &edit, uint64_t seed, int steps, int sweep_every, const Surface &surface, Check &&check)
{
    const TriMesh &mesh = edit.mesh();
    shapes_rng rng = rng_seed(seed);
    int32_t changes = 0;
    for (int step = 0; step < steps; ++step) {
        if (step % sweep_every == sweep_every - 1) {
            std::vector<Vec3> moved = sweep(mesh, rng, 0.3, surface);
            edit.move(moved);
        } else {
            const int32_t h = static_cast<int32_t>(rng_next(&rng) % (3 * mesh.tri.size()));
            if (!alive(mesh, h))
                continue;
            const bool interior = !mesh.is_boundary_vertex(mesh.tail(h)) && !mesh.is_boundary_vertex(mesh.head(h));
            const Vec3 middle = surface.onto((mesh.pos[mesh.tail(h)] + mesh.pos[mesh.head(h)]) / 2);
            switch (rng_next(&rng) % 3) {
            case 0:
                if (!split_acceptable(mesh, h, middle, surface))
                    continue;
                edit.split(h, middle);
                break;
            case 1:
                if (!interior || !collapse_keeps_manifold(mesh, h) || !collapse_acceptable(mesh, h, surface))
                    continue;
                edit.collapse(h, mesh.pos[mesh.head(h)]);
                break;
            case 2:
                if (!flip_keeps_manifold(mesh, h) || !flip_acceptable(mesh, h, surface))
                    continue;
                edit.flip(h);
                break;
            }
        }
        ++changes;
        check();
        if (step % 64 == 63) {
            edit.compact();
            check();
        }
    }
    edit.compact();
    edit.order_for_locality();
    assert_string_equal(invariant_violation(mesh).c_str(), "");
    check();
    return changes;
}

// The flat grid with its interior vertices moved at random by up to a third of a cell
// within the plane, so that no two faces are alike.
TriMesh jittered_plane(int nx, int ny, double h, uint64_t seed)
{
    sfa_mesh_data grid = shape_grid(nx, ny, h);
    TriMesh mesh = mesh_of(grid);
    mesh_free(&grid);
    shapes_rng rng = rng_seed(seed);
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        if (!mesh.is_boundary_vertex(v))
            mesh.pos[v] += h / 3 * Vec3(2 * rng_uniform(&rng) - 1, 2 * rng_uniform(&rng) - 1, 0);
    return mesh;
}

void on_a_plane_integrals_are_kept_and_a_constant_stays_constant(void **)
{
    TriMesh mesh = jittered_plane(14, 12, 0.1, 2);
    MeshEdit edit(mesh);
    FaceValues values(ncomp, exact_densities(mesh));
    edit.attach(values);
    double before[ncomp];
    for (int32_t c = 0; c < ncomp; ++c)
        before[c] = total(mesh, values.values(), ncomp, c);
    double worst_constant = 0;
    const int32_t changes = random_edits(
        edit, 21, 2000, 25, plane,
        [&] {
            for (int32_t c = 0; c < ncomp; ++c)
                assert_near(total(mesh, values.values(), ncomp, c), before[c], 1e-12 * std::abs(before[c]));
            for (int32_t t = 0; t < mesh.num_triangles(); ++t)
                if (mesh.tri[t][0] >= 0)
                    worst_constant = std::max(worst_constant, std::abs(values.value(t, 0) / constant - 1));
        });
    print_message("after %d changes: constant within %.3g\n", changes, worst_constant);
    assert_true(changes > 800);
    assert_true(worst_constant <= 1e-12);
    // Every fan was remapped by overlap: none turned over.
    assert_int_equal(values.shared_remaps(), 0);
}

// The same edits heard by the remap and by the averaging it replaced: the remap must smear
// a linear density less. Splits, flips and contractions only: the averaging has no rule for
// a sweep (it left the densities as they were, which does not keep the integral).
void on_a_plane_the_remap_smears_less_than_averaging(void **)
{
    TriMesh mesh = jittered_plane(14, 12, 0.1, 3);
    MeshEdit edit(mesh);
    FaceValues values(ncomp, exact_densities(mesh));
    AveragingFaceValues averaged(ncomp, exact_densities(mesh));
    edit.attach(values);
    edit.attach(averaged);
    random_edits(edit, 22, 1500, 1 << 30, plane, [] {});
    for (int32_t c = 1; c < ncomp; ++c) {
        const double remapped = deviation(mesh, values.values(), c), smeared = deviation(mesh, averaged.values, c);
        print_message("component %d: L1 deviation %.4g by overlap, %.4g averaged\n", c, remapped, smeared);
        assert_true(remapped < 0.9 * smeared);
    }
}

void on_a_sphere_integrals_are_kept_and_a_constant_stays_within_one_percent(void **)
{
    sfa_mesh_data shape = shape_jittered_icosphere(4, radius, 0.3, 17);
    TriMesh mesh = mesh_of(shape);
    mesh_free(&shape);
    MeshEdit edit(mesh);
    FaceValues values(ncomp, exact_densities(mesh));
    edit.attach(values);
    double before[ncomp];
    for (int32_t c = 0; c < ncomp; ++c)
        before[c] = total(mesh, values.values(), ncomp, c);
    double worst_constant = 0;
    const int32_t changes = random_edits(
        edit, 23, 1200, 20, sphere,
        [&] {
            for (int32_t c = 0; c < ncomp; ++c)
                assert_near(total(mesh, values.values(), ncomp, c), before[c], 1e-12 * std::abs(before[c]));
            for (int32_t t = 0; t < mesh.num_triangles(); ++t)
                if (mesh.tri[t][0] >= 0)
                    worst_constant = std::max(worst_constant, std::abs(values.value(t, 0) / constant - 1));
        });
    assert_true(changes > 300);
    print_message("after %d changes: constant within %.3g\n", changes, worst_constant);
    // Then sweeps alone, as a smoothing phase makes them.
    shapes_rng rng = rng_seed(5);
    for (int k = 0; k < 20; ++k) {
        std::vector<Vec3> moved = sweep(mesh, rng, 0.3, sphere);
        edit.move(moved);
        for (int32_t c = 0; c < ncomp; ++c)
            assert_near(total(mesh, values.values(), ncomp, c), before[c], 1e-12 * std::abs(before[c]));
        for (int32_t t = 0; t < mesh.num_triangles(); ++t)
            worst_constant = std::max(worst_constant, std::abs(values.value(t, 0) / constant - 1));
    }
    print_message("and 20 sweeps: constant within %.3g, %lld fans shared by area\n", worst_constant,
                  static_cast<long long>(values.shared_remaps()));
    assert_true(worst_constant < 0.01);
}

// The volume correction's offset: each face keeps its own integral.
void an_offset_keeps_each_face_integral(void **)
{
    sfa_mesh_data shape = shape_icosphere(2, 1.0);
    TriMesh mesh = mesh_of(shape);
    mesh_free(&shape);
    MeshEdit edit(mesh);
    FaceValues values(ncomp, exact_densities(mesh));
    edit.attach(values);
    std::vector<double> integrals(static_cast<size_t>(ncomp) * mesh.num_triangles());
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        for (int32_t c = 0; c < ncomp; ++c)
            integrals[static_cast<size_t>(ncomp) * t + c] = values.value(t, c) * face_area(mesh, t);
    std::vector<Vec3> moved = mesh.pos;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        moved[v] *= 1 + 0.01 * (v % 5);
    edit.offset(moved);
    for (int32_t t = 0; t < mesh.num_triangles(); ++t)
        for (int32_t c = 0; c < ncomp; ++c)
            assert_near(values.value(t, c) * face_area(mesh, t), integrals[static_cast<size_t>(ncomp) * t + c],
                               1e-14 * std::abs(integrals[static_cast<size_t>(ncomp) * t + c]));
}

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(overlap_of_known_pairs),
        cmocka_unit_test(overlap_of_slivers_and_degenerate_triangles),
        cmocka_unit_test(overlap_adds_up_over_a_partition),
        cmocka_unit_test(remap_of_a_fan),
        cmocka_unit_test(remap_of_a_leaning_cap),
        cmocka_unit_test(on_a_plane_integrals_are_kept_and_a_constant_stays_constant),
        cmocka_unit_test(on_a_plane_the_remap_smears_less_than_averaging),
        cmocka_unit_test(on_a_sphere_integrals_are_kept_and_a_constant_stays_within_one_percent),
        cmocka_unit_test(an_offset_keeps_each_face_integral),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

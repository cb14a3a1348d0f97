// Unit tests of the conservative remap by overlap (geometry/overlap.hpp): the overlap of two
// triangles in known cases, slivers and degenerate triangles included, and adding up over
// a partition; a fan remapped onto itself and onto the fan with its centre moved, flat or
// leaning, keeping its integral and a constant, or shared by area where it folds.
#include "geometry/overlap.hpp"

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

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(overlap_of_known_pairs),
        cmocka_unit_test(overlap_of_slivers_and_degenerate_triangles),
        cmocka_unit_test(overlap_adds_up_over_a_partition),
        cmocka_unit_test(remap_of_a_fan),
        cmocka_unit_test(remap_of_a_leaning_cap),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

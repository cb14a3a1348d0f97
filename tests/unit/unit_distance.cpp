// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of geometry/distance: the closest point of a triangle to a point and the
// distance between two triangles agree with a dense sampling of the triangles (never
// farther than the best sample, and within the sampling's spacing of it), on random
// configurations of every kind (a point near a corner, an edge or the face; triangles
// nearly parallel, crossed edges, slivers).
#include "geometry/distance.hpp"
#include "geometry/triangle_intersection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <setjmp.h>

extern "C" {
#include <cmocka.h>
}

#include "numbers.hpp"

using namespace sfa;

namespace {


constexpr int samples_per_edge = 60;

// Every point i/n a + j/n b + (n-i-j)/n c of the triangle.
template <class F> void for_each_sample(const Vec3 &a, const Vec3 &b, const Vec3 &c, F &&f)
{
    const int n = samples_per_edge;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j)
            f((i * a + j * b + (n - i - j) * c) / n);
}

double longest_edge(const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    return std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
}

void closest_point_on_a_triangle_beats_every_sample(void **)
{
    Numbers rng{3};
    for (int trial = 0; trial < 3000; ++trial) {
        const Vec3 a = rng.point(1), b = rng.point(1), c = trial % 5 ? rng.point(1) : Vec3((a + b) / 2 + rng.point(1e-3));
        const Vec3 p = rng.point(1.5);
        const Vec3 q = closest_point_on_triangle(p, a, b, c);
        double best = std::numeric_limits<double>::infinity();
        for_each_sample(a, b, c, [&](const Vec3 &x) { best = std::min(best, (p - x).norm()); });
        const double found = (p - q).norm(), spacing = longest_edge(a, b, c) / samples_per_edge;
        if (!(found <= best + 1e-12) || !(found >= best - spacing))
            fail_msg("trial %d: closest point at %.9g, the samples' best at %.9g", trial, found, best);
        // q lies on the triangle: its barycentric coordinates are in [0, 1].
        const Vec3 n = (b - a).cross(c - a);
        if (n.squaredNorm() > 1e-12) {
            const double u = (b - q).cross(c - q).dot(n) / n.squaredNorm(), v = (c - q).cross(a - q).dot(n) / n.squaredNorm();
            assert_true(u >= -1e-9 && v >= -1e-9 && u + v <= 1 + 1e-9);
            assert_true(std::abs((q - a).dot(n.normalized())) < 1e-9);
        }
    }
}

void triangle_distance_matches_the_samples(void **)
{
    Numbers rng{5};
    for (int trial = 0; trial < 600; ++trial) {
        Vec3 a[3], b[3];
        for (int k = 0; k < 3; ++k)
            a[k] = rng.point(1);
        const Vec3 shift(0, 0, rng.uniform(0.01, 1.5));
        for (int k = 0; k < 3; ++k) // every third pair nearly parallel to the first
            b[k] = trial % 3 ? rng.point(1) + shift : Vec3(a[k] + shift + rng.point(1e-3));
        if (triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]))
            continue; // not for triangles that meet
        const double found = triangle_distance(a, b);
        double best = std::numeric_limits<double>::infinity();
        for_each_sample(a[0], a[1], a[2], [&](const Vec3 &x) {
            best = std::min(best, (x - closest_point_on_triangle(x, b[0], b[1], b[2])).norm());
        });
        const double spacing = longest_edge(a[0], a[1], a[2]) / samples_per_edge;
        if (!(found <= best + 1e-12) || !(found >= best - spacing))
            fail_msg("trial %d: distance %.9g, the samples' best %.9g", trial, found, best);
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(closest_point_on_a_triangle_beats_every_sample),
        cmocka_unit_test(triangle_distance_matches_the_samples),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

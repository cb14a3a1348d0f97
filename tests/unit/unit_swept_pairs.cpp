// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the broad phase of collision-safe motion (geometry/swept_pairs.hpp): every
// pair of triangles that meets during the step is visited, each pair once and in order,
// from any number of threads; and where the whole surface travels several edge lengths in
// a step, comparing each block in the frame of its own motion visits far fewer pairs than
// boxes swept at rest would.
#include "geometry/swept_pairs.hpp"
#include "geometry/triangle_intersection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <set>
#include <setjmp.h>
#include <utility>

extern "C" {
#include <cmocka.h>
}

#include "numbers.hpp"

using namespace sfa;

namespace {

// Triangles (three corners each, no shared corners) and their corners' displacements.
struct Moving {
    std::vector<Vec3> x, d;
    int32_t count() const { return static_cast<int32_t>(x.size() / 3); }
    Vec3 at(int32_t t, int k, double time) const { return x[3 * t + k] + time * d[3 * t + k]; }
};

// A sheet of n x n cells, two triangles each, from `corner` along `across` and `up` (the
// whole sheet's sides), corners jittered.
void add_patch(Moving &m, int n, const Vec3 &corner, const Vec3 &across, const Vec3 &up, Numbers &rng)
{
    const Vec3 u = across / n, v = up / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3 a = corner + i * u + j * v, b = a + u, c = a + v, e = a + u + v;
            for (const Vec3 &p : {a, b, e, a, e, c})
                m.x.push_back(p + 0.05 * u.norm() * rng.point(1));
        }
}

// A unit square sheet of n x n cells at height z.
void add_sheet(Moving &m, int n, double z, Numbers &rng)
{
    add_patch(m, n, Vec3(0, 0, z), Vec3(1, 0, 0), Vec3(0, 1, 0), rng);
}

std::vector<SweptTriangle> swept(const Moving &m)
{
    std::vector<SweptTriangle> out(static_cast<size_t>(m.count()));
    for (int32_t t = 0; t < m.count(); ++t) {
        const Vec3 x[3] = {m.x[3 * t], m.x[3 * t + 1], m.x[3 * t + 2]};
        const Vec3 d[3] = {m.d[3 * t], m.d[3 * t + 1], m.d[3 * t + 2]};
        out[t] = swept_triangle({3 * t, 3 * t + 1, 3 * t + 2}, x, d);
    }
    return out;
}

// The visited pairs; fails on a pair out of order or visited twice.
std::set<std::pair<int32_t, int32_t>> visited_pairs(const Moving &m, BlockPartition *kept = nullptr)
{
    std::vector<std::vector<std::pair<int32_t, int32_t>>> by_thread(static_cast<size_t>(loop_threads()));
    for_each_pair_that_may_meet(
        swept(m), [&](int32_t s, int32_t t, int thread) { by_thread[static_cast<size_t>(thread)].push_back({s, t}); },
        kept);
    std::set<std::pair<int32_t, int32_t>> pairs;
    for (const auto &list : by_thread)
        for (const auto &p : list) {
            if (!(0 <= p.first && p.first < p.second && p.second < m.count()))
                fail_msg("pair (%d, %d) out of order or range", p.first, p.second);
            if (!pairs.insert(p).second)
                fail_msg("pair (%d, %d) visited twice", p.first, p.second);
        }
    return pairs;
}

bool meet_during_step(const Moving &m, int32_t s, int32_t t)
{
    for (int k = 0; k <= 32; ++k) {
        const double time = k / 32.0;
        if (triangles_intersect(m.at(s, 0, time), m.at(s, 1, time), m.at(s, 2, time), m.at(t, 0, time),
                                m.at(t, 1, time), m.at(t, 2, time)))
            return true;
    }
    return false;
}

// Two sheets, 0.03 apart, carried 0.5 (ten cells) by a swirl that turns them, the lower
// one rising through the upper one during the step; a few corners thrown far.
Moving crossing_sheets(Numbers &rng)
{
    Moving m;
    add_sheet(m, 20, 0, rng);
    add_sheet(m, 20, 0.03, rng);
    for (size_t c = 0; c < m.x.size(); ++c) {
        const Vec3 &p = m.x[c];
        Vec3 d = Vec3(0.5, 0.2 * std::sin(3 * p[0]), 0.1 * p[1]);
        if (c < m.x.size() / 2)
            d[2] += 0.06 * (0.5 + p[0]); // rises 0.03 to 0.09: through the upper sheet
        m.d.push_back(d);
    }
    for (int k = 0; k < 5; ++k)
        m.d[static_cast<size_t>(rng.pick(static_cast<int>(m.d.size())))] += rng.point(3);
    return m;
}

// Fails unless every two triangles that meet during the step are visited; how many meet.
int check_meeting_pairs_are_visited(const Moving &m, BlockPartition *kept = nullptr)
{
    const auto pairs = visited_pairs(m, kept);
    int meeting = 0;
    const std::vector<SweptTriangle> boxes = swept(m);
    for (int32_t s = 0; s < m.count(); ++s)
        for (int32_t t = s + 1; t < m.count(); ++t)
            if (boxes_overlap(swept_in_frame(boxes[s], Vec3::Zero()), swept_in_frame(boxes[t], Vec3::Zero())) &&
                meet_during_step(m, s, t)) {
                ++meeting;
                if (!pairs.count({s, t}))
                    fail_msg("triangles %d and %d meet during the step but were not visited", s, t);
            }
    return meeting;
}

void every_pair_that_meets_is_visited_once(void **)
{
    Numbers rng{5};
    const Moving m = crossing_sheets(rng);
    for (int threads = 1; threads <= 2; ++threads) {
        ThreadLimit limit(threads);
        const int meeting = check_meeting_pairs_are_visited(m);
        print_message("%d threads: %d pairs meet\n", threads, meeting);
        assert_true(meeting > 500);
    }
}

// A search may deal the triangles into blocks as an earlier one did (collision-safe motion
// keeps them between adaptations): with blocks made where the triangles were, far from
// where they are now (each thrown up to two sheets' widths away), every pair that meets is
// still visited. The blocks serve block_partition_searches searches, then are made anew.
void blocks_kept_from_elsewhere_still_visit_every_pair_that_meets(void **)
{
    Numbers rng{7};
    const Moving m = crossing_sheets(rng);
    Moving elsewhere = m;
    for (int32_t t = 0; t < m.count(); ++t) {
        const Vec3 throw_to = rng.point(2);
        for (int k = 0; k < 3; ++k)
            elsewhere.x[3 * t + k] += throw_to;
    }
    BlockPartition kept;
    visited_pairs(elsewhere, &kept);
    assert_int_equal(kept.triangles, m.count());
    const std::vector<int32_t> dealt = kept.order;
    for (int search = 2; search <= block_partition_searches; ++search) {
        const int meeting = check_meeting_pairs_are_visited(m, &kept);
        assert_true(meeting > 500);
        assert_int_equal(kept.searches, search);
        assert_true(kept.order == dealt); // the same blocks
    }
    visited_pairs(m, &kept);
    assert_int_equal(kept.searches, 1); // made anew, where the triangles are now
    assert_true(kept.order != dealt);
}

// Two sheets whose blocks are far apart at rest: a vertical one rushes through a resting
// horizontal one, three blocks (36 cells) in a step. The blocks near each other are found
// by the boxes they sweep at rest, which must hold the motion.
void sheets_that_rush_through_each_other_from_far_are_compared(void **)
{
    Numbers rng{11};
    Moving m;
    add_sheet(m, 10, 0, rng);
    m.d.assign(m.x.size(), Vec3::Zero());
    add_patch(m, 10, Vec3(3.5, 0, -0.5), Vec3(0, 1, 0), Vec3(0, 0, 1), rng);
    m.d.resize(m.x.size(), Vec3(-4.3, 0, 0));
    const int meeting = check_meeting_pairs_are_visited(m);
    print_message("%d pairs meet\n", meeting);
    assert_true(meeting > 50);
}

// A sheet whose halves move apart, one up and one down, as fast as a block is tall: in its
// block's frame (their mean motion, about none) its triangles sweep far, and the sheet
// above, in the next block, which the rising half passes through, is compared with them
// there. What a block's triangles reach in its frame must hold their motion in it.
void a_block_is_compared_with_all_its_triangles_reach_in_its_frame(void **)
{
    Numbers rng{13};
    Moving m;
    add_sheet(m, 10, 0, rng); // first, so that its block is the first and its frame the one used
    for (const Vec3 &p : m.x)
        m.d.push_back(Vec3(0, 0, p[1] < 0.5 ? 1.6 : -1.6));
    add_patch(m, 10, Vec3(0, 0, 1.3), Vec3(1, 0, 0), Vec3(0, 0.5, 0), rng);
    m.d.resize(m.x.size(), Vec3::Zero());
    const int meeting = check_meeting_pairs_are_visited(m);
    print_message("%d pairs meet\n", meeting);
    assert_true(meeting > 50);
}

// The same sheet moving as one, ten cells in a step: at rest each box is swept over ten
// cells and overlaps a strip of them; in the sheet's own frame it overlaps its neighbours.
void a_surface_moving_as_one_visits_its_neighbours_only(void **)
{
    Numbers rng{9};
    Moving m;
    add_sheet(m, 40, 0, rng);
    for (const Vec3 &p : m.x)
        m.d.push_back(Vec3(0.25, 0.1, 0.02) + 0.01 * Vec3(p[1], -p[0], 0));
    const auto pairs = visited_pairs(m);
    size_t at_rest = 0;
    const std::vector<SweptTriangle> s = swept(m);
    for (int32_t a = 0; a < m.count(); ++a)
        for (int32_t b = a + 1; b < m.count(); ++b)
            at_rest += boxes_overlap(swept_in_frame(s[a], Vec3::Zero()), swept_in_frame(s[b], Vec3::Zero()));
    print_message("%zu pairs visited, %zu boxes swept at rest overlap (%d triangles)\n", pairs.size(), at_rest,
                  m.count());
    assert_true(pairs.size() < at_rest / 4);
    assert_true(pairs.size() < 20 * static_cast<size_t>(m.count()));
}

// A sheet whose triangles share their corners, folded so that its two halves pass through
// each other during the step: no two triangles with a corner in common are visited (they
// are neighbours, the fold control's concern), and every other two that meet are.
void neighbours_are_not_visited(void **)
{
    constexpr int n = 24;
    std::vector<Vec3> x, d;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n;
            x.push_back(Vec3(u, v, 0.02 * std::cos(6 * u)));
            d.push_back(Vec3(0.3, 0, u > 0.5 ? -0.2 : 0.2) + 0.05 * Vec3(v, -u, 0)); // the halves cross
        }
    const auto corner = [](int i, int j) { return static_cast<int32_t>(i * (n + 1) + j); };
    std::vector<Triangle> tri;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            tri.push_back({corner(i, j), corner(i + 1, j), corner(i + 1, j + 1)});
            tri.push_back({corner(i, j), corner(i + 1, j + 1), corner(i, j + 1)});
        }
    // The second half of the sheet moved onto the first, so that they overlap.
    for (Vec3 &p : x)
        if (p.x() > 0.5)
            p = Vec3(p.x() - 0.5, p.y(), p.z() + 0.01);
    std::vector<SweptTriangle> swept;
    for (const Triangle &t : tri) {
        const Vec3 at[3] = {x[t[0]], x[t[1]], x[t[2]]}, by[3] = {d[t[0]], d[t[1]], d[t[2]]};
        swept.push_back(swept_triangle(t, at, by));
    }
    std::set<std::pair<int32_t, int32_t>> pairs;
    for_each_pair_that_may_meet(swept, [&](int32_t s, int32_t t, int) {
        if (share_a_vertex(tri[s], tri[t]))
            fail_msg("triangles %d and %d share a corner but were visited", s, t);
#pragma omp critical
        pairs.insert({s, t});
    });
    int meeting = 0;
    for (int32_t s = 0; s < static_cast<int32_t>(tri.size()); ++s)
        for (int32_t t = s + 1; t < static_cast<int32_t>(tri.size()); ++t) {
            if (share_a_vertex(tri[s], tri[t]))
                continue;
            bool meet = false;
            for (int k = 0; k <= 16 && !meet; ++k) {
                const double h = k / 16.0;
                const Triangle &p = tri[s], &q = tri[t];
                meet = triangles_intersect(x[p[0]] + h * d[p[0]], x[p[1]] + h * d[p[1]], x[p[2]] + h * d[p[2]],
                                           x[q[0]] + h * d[q[0]], x[q[1]] + h * d[q[1]], x[q[2]] + h * d[q[2]]);
            }
            if (meet) {
                ++meeting;
                if (!pairs.count({s, t}))
                    fail_msg("triangles %d and %d meet during the step but were not visited", s, t);
            }
        }
    print_message("%d pairs meet, %zu visited\n", meeting, pairs.size());
    assert_true(meeting > 100);
}

// Triangles apart from each other in a grid far from the origin, their boxes touching
// exactly (each cell's corners computed once), at rest: every two whose boxes touch are
// visited. The sweep compares the boxes in floats relative to the block, whose last
// place (about 1e-9 here) is far coarser than the boxes' widening for rounding (1e-14 of
// the coordinates): only a conversion that keeps their order keeps them touching.
void boxes_that_touch_far_from_the_origin_are_visited(void **)
{
    constexpr int n = 30;
    const double base = 1e4 + 0.1, h = 0.001;
    double at[n + 1];
    for (int i = 0; i <= n; ++i)
        at[i] = base + i * h;
    Moving m;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (const Vec3 &p : {Vec3(at[i], at[j], base), Vec3(at[i + 1], at[j], base), Vec3(at[i], at[j + 1], base)})
                m.x.push_back(p);
    m.d.assign(m.x.size(), Vec3::Zero());
    const auto pairs = visited_pairs(m);
    const std::vector<SweptTriangle> boxes = swept(m);
    int touching = 0;
    for (int32_t s = 0; s < m.count(); ++s)
        for (int32_t t = s + 1; t < m.count(); ++t)
            if (boxes_overlap(swept_in_frame(boxes[s], Vec3::Zero()), swept_in_frame(boxes[t], Vec3::Zero()))) {
                ++touching;
                if (!pairs.count({s, t}))
                    fail_msg("the boxes of triangles %d and %d touch but the pair was not visited", s, t);
            }
    assert_int_equal(touching, 4 * (n - 1) * (n - 1) + 2 * (n - 1)); // sides and corners
}

// The rows' floats keep the order of their doubles, whatever is subtracted from them
// first (the block's corner), so that boxes that overlap in doubles overlap in floats:
// through the floats' smallest and largest numbers and beyond their range.
void nearest_floats_keep_the_order(void **)
{
    Numbers rng{20261204};
    std::vector<double> values = {0.0, 1e-320, -1e-320, 1e-45, 0.1, -0.1, 3.4028234663852886e38, 3.5e38,
                                  -3.5e38, 1e300, -1e300, std::numeric_limits<double>::max(),
                                  -std::numeric_limits<double>::max()};
    for (int i = 0; i < 100000; ++i)
        values.push_back((i % 2 ? 1 : -1) * std::ldexp(rng.uniform(1, 2), static_cast<int>(rng.uniform(-160, 140))));
    for (int i = 0; i < 1000; ++i) // neighbouring doubles, which round to one float or two
        values.push_back(std::nextafter(0.1 + i * 1e-17, 1.0));
    std::sort(values.begin(), values.end());
    for (const double origin : {0.0, 0.1, -1e4, 1e30}) {
        float previous = -std::numeric_limits<float>::infinity();
        for (const double x : values) {
            const float f = detail::nearest_float(x - origin);
            if (!(f >= previous))
                fail_msg("%.17g - %g: %.9g comes before the float of a smaller double", x, origin, f);
            previous = f;
        }
    }
    assert_true(detail::nearest_float(1e300) == std::numeric_limits<float>::max());
}

// The blocks' numbering: distinct keys numbered in the order they first come, equal keys
// alike, through the table's growth (5,000 distinct keys, its first size 1,024), however
// many runs number them in parallel (a run's keys may all have come in an earlier run, or
// none of them).
void keys_are_numbered_in_order_of_first_coming(void **)
{
    std::vector<uint64_t> key;
    for (uint64_t round = 0; round < 3; ++round)
        for (uint64_t k = 0; k < 5000; ++k)
            key.push_back(k << 42 | (k % 7) << 21 | k); // distinct, as cell keys are
    for (int runs : {1, 2, 3, 7, 64}) {
        std::vector<int32_t> number;
        assert_int_equal(detail::number_by_key(key, number, runs), 5000);
        for (size_t i = 0; i < key.size(); ++i)
            if (number[i] != static_cast<int32_t>(i % 5000))
                fail_msg("%d runs: key %zu numbered %d, not %zu", runs, i, number[i], i % 5000);
    }
    const std::vector<uint64_t> few = {9, 9, 4};
    std::vector<int32_t> number;
    assert_int_equal(detail::number_by_key(few, number, 8), 2);
    assert_true(number == (std::vector<int32_t>{0, 0, 1}));
}

// The sweep's order: sort_spread_keys orders (key, index) pairs as std::sort does, ties by
// index, for keys spread evenly, keys with many ties, keys crowded into one bucket (which
// std::sort takes over), keys all one, and keys whose range overflows.
void spread_keys_sort_as_std_sort_does(void **)
{
    Numbers rng{20261203};
    const auto check = [](const char *what, const std::vector<double> &keys) {
        std::vector<std::pair<double, int32_t>> items, scratch;
        for (size_t i = 0; i < keys.size(); ++i)
            items.push_back({keys[i], static_cast<int32_t>(i)});
        std::vector<std::pair<double, int32_t>> expected = items;
        std::sort(expected.begin(), expected.end());
        std::vector<size_t> buckets;
        detail::sort_spread_keys(items, scratch, buckets);
        if (items != expected)
            fail_msg("%s: %zu keys not in std::sort's order", what, keys.size());
    };
    std::vector<double> even, ties, crowded, huge;
    for (int i = 0; i < 1000; ++i) {
        even.push_back(rng.uniform(-3, 5));
        ties.push_back(std::floor(rng.uniform(0, 400))); // about 2.5 a value
        crowded.push_back(i % 10 == 0 ? rng.uniform(0, 1e6) : rng.uniform(0, 1));
        huge.push_back(i % 2 ? rng.uniform(1e307, 1.7e308) : -rng.uniform(1e307, 1.7e308));
    }
    check("evenly spread", even);
    check("with ties", ties);
    check("crowded", crowded);
    check("all one", std::vector<double>(100, 0.25));
    check("overflowing range", huge);
    check("two", {1.0, -1.0});
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_pair_that_meets_is_visited_once),
        cmocka_unit_test(blocks_kept_from_elsewhere_still_visit_every_pair_that_meets),
        cmocka_unit_test(sheets_that_rush_through_each_other_from_far_are_compared),
        cmocka_unit_test(a_block_is_compared_with_all_its_triangles_reach_in_its_frame),
        cmocka_unit_test(a_surface_moving_as_one_visits_its_neighbours_only),
        cmocka_unit_test(neighbours_are_not_visited),
        cmocka_unit_test(boxes_that_touch_far_from_the_origin_are_visited),
        cmocka_unit_test(nearest_floats_keep_the_order),
        cmocka_unit_test(keys_are_numbered_in_order_of_first_coming),
        cmocka_unit_test(spread_keys_sort_as_std_sort_does),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}

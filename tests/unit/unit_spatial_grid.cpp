// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the spatial grid: it finds each pair of overlapping boxes exactly once, the
// pairs an all-pairs test finds, through its pair sweep and through its queries, built and
// added alike; and a query meets the points of its cells in the order of the cells and of
// the points. On random boxes in a compact box (the cells numbered densely), on boxes far
// apart (the cells hashed, some 2^21 cells apart, so that their keys coincide), on large
// boxes crowding few buckets, on boxes that all lie in one cell, and with boxes too large
// to enter in their cells, kept apart. The pair sweeps of box_pairs.hpp, over all boxes and
// over the pairs with a box of a subset, find the same pairs as all-pairs tests.
#include "geometry/box_pairs.hpp"
#include "geometry/spatial_grid.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <setjmp.h>
#include <utility>
#include <vector>

extern "C" {
#include <cmocka.h>
}

using namespace sfa;

namespace {

using Pairs = std::vector<std::pair<int32_t, int32_t>>;

// A fixed sequence of numbers in [0, 1), the same on every machine.
struct Numbers {
    uint64_t state;
    double next()
    {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state >> 11) / static_cast<double>(uint64_t{1} << 53);
    }
    Vec3 point() { return Vec3(next(), next(), next()); }
};

bool overlap(const Box &a, const Box &b)
{
    return (a[0] - b[1]).maxCoeff() <= 0 && (b[0] - a[1]).maxCoeff() <= 0;
}

Pairs all_pairs(const std::vector<Box> &boxes)
{
    Pairs pairs;
    for (int32_t s = 0; s < static_cast<int32_t>(boxes.size()); ++s)
        for (int32_t t = s + 1; t < static_cast<int32_t>(boxes.size()); ++t)
            if (overlap(boxes[s], boxes[t]))
                pairs.push_back({s, t});
    return pairs;
}

// Boxes of up to `largest` on a side, with their low corners in the box [0, 1] * spread.
std::vector<Box> random_boxes(int32_t count, double spread, double largest, uint64_t seed)
{
    Numbers numbers{seed};
    std::vector<Box> boxes(count);
    for (Box &box : boxes) {
        box[0] = numbers.point() * spread;
        box[1] = box[0] + numbers.point() * largest;
    }
    return boxes;
}

// Each pair of the pair sweep, where it counts: in the first cell both boxes cover.
Pairs pairs_by_sweep(const std::vector<Box> &boxes, const CellFrame &cells)
{
    SpatialGrid<int32_t> grid;
    grid.build(
        cells, static_cast<int32_t>(boxes.size()), [&](int32_t m) { return boxes[m]; },
        [](int32_t m, const GridCell &) { return m; });
    Pairs pairs;
    for (size_t b = 0; b < grid.bucket_count(); ++b)
        grid.for_each_pair_in_bucket(b, [&](int32_t s, int32_t t, uint64_t key) {
            assert_true(s < t);
            if (cell_key(first_shared_cell(grid.cells_of(s)[0], grid.cells_of(t)[0])) == key &&
                overlap(boxes[s], boxes[t]))
                pairs.push_back({s, t});
        });
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// Each pair met by the query of its first box, where it counts; the boxes from `built` on
// are added after the grid is built.
Pairs pairs_by_query(const std::vector<Box> &boxes, const CellFrame &cells, int32_t built)
{
    struct Entry {
        GridCell first;
        int32_t box;
    };
    SpatialGrid<Entry> grid;
    grid.build(
        cells, built, [&](int32_t m) { return boxes[m]; },
        [](int32_t m, const GridCell &first) { return Entry{first, m}; });
    for (int32_t m = built; m < static_cast<int32_t>(boxes.size()); ++m)
        grid.add(boxes[m][0], boxes[m][1], [&](const GridCell &first) { return Entry{first, m}; });
    Pairs pairs;
    for (int32_t s = 0; s < static_cast<int32_t>(boxes.size()); ++s) {
        const GridCell first = cells.cell_of(boxes[s][0]);
        grid.any_in_cells(first, cells.cell_of(boxes[s][1]), [&](const Entry &e, const GridCell &here) {
            if (e.box > s && same_cell(first_shared_cell(first, e.first), here) && overlap(boxes[s], boxes[e.box]))
                pairs.push_back({s, e.box});
            return false;
        });
    }
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

void assert_same_pairs(const Pairs &found, const Pairs &expected)
{
    assert_int_equal(found.size(), expected.size()); // a pair found twice would show here
    assert_true(found == expected);
}

void check_pairs(const std::vector<Box> &boxes, const CellFrame &cells)
{
    const Pairs expected = all_pairs(boxes);
    assert_true(!expected.empty());
    assert_same_pairs(pairs_by_sweep(boxes, cells), expected);
    const int32_t count = static_cast<int32_t>(boxes.size());
    for (const int32_t built : {count, count / 2, 0})
        assert_same_pairs(pairs_by_query(boxes, cells, built), expected);
}

void random_boxes_pair_up_as_all_pairs_find(void **)
{
    // Cells of 0.1 over a box of 1: densely numbered. Boxes up to three cells wide.
    check_pairs(random_boxes(600, 1.0, 0.3, 1), CellFrame{Vec3::Zero(), 0.1});
}

void boxes_far_apart_pair_up_as_all_pairs_find(void **)
{
    // Clusters 2^21 and 2^22 cells apart along each axis (their cells share keys), and a
    // few boxes scattered in between: the cells are hashed.
    std::vector<Box> boxes;
    const double cell = 0.1, apart = cell * static_cast<double>(uint64_t{1} << 21);
    for (const Vec3 &offset : {Vec3(0, 0, 0), Vec3(apart, 0, 0), Vec3(0, apart, 2 * apart), Vec3(apart, apart, apart)})
        for (Box box : random_boxes(150, 1.0, 0.3, 2)) {
            box[0] += offset;
            box[1] += offset;
            boxes.push_back(box);
        }
    for (const Box &box : random_boxes(40, 3 * apart, 0.3, 3))
        boxes.push_back(box);
    check_pairs(boxes, CellFrame{Vec3::Zero(), cell});
}

void large_boxes_in_few_buckets_pair_up_as_all_pairs_find(void **)
{
    // 30 boxes of up to six cells on a side in a box too large to number densely: a few
    // thousand entries in 32 buckets, each bucket shared by many cells.
    check_pairs(random_boxes(30, 1.0, 0.6, 6), CellFrame{Vec3::Zero(), 0.1});
}

void boxes_in_one_cell_pair_up_as_all_pairs_find(void **)
{
    check_pairs(random_boxes(80, 0.4, 0.5, 4), CellFrame{Vec3::Zero(), 1.0});
}

// Issue 18: a 100 x 100 grid with one corner pulled out 600 edges made the crossing guard
// enter the corner's faces in the cube of their extent in cells (645 MB; farther, memory
// ran out). Large boxes are kept apart: the entries are those of the small boxes alone, and
// queries, small and large, built and added, still meet every overlapping box once.
void large_boxes_are_kept_apart_and_still_met(void **)
{
    const CellFrame cells{Vec3::Zero(), 0.1};
    std::vector<Box> boxes = random_boxes(400, 1.0, 0.2, 7); // up to 3 cells a side
    // Boxes of 600 to 6000 cells on a side, one of them degenerate (a segment), and one of
    // 18 cells (just large) and one of 17 (just small) on one axis.
    boxes.push_back({Vec3(0.5, 0.5, 0.5), Vec3(60, 61, 62)});
    boxes.push_back({Vec3(-600, 0.3, 0.2), Vec3(0.4, 0.3, 0.25)});
    boxes.push_back({Vec3(0.05, 0.05, 0.05), Vec3(1.85, 0.1, 0.1)});
    boxes.push_back({Vec3(0.05, 0.05, 0.05), Vec3(1.75, 0.1, 0.1)});
    const int32_t count = static_cast<int32_t>(boxes.size());
    size_t small_entries = 0;
    for (int32_t m = 0; m < count; ++m) {
        const GridCell first = cells.cell_of(boxes[m][0]), last = cells.cell_of(boxes[m][1]);
        if (!spans_many_cells(first, last))
            small_entries += static_cast<size_t>((last[0] - first[0] + 1) * (last[1] - first[1] + 1) *
                                                 (last[2] - first[2] + 1));
    }
    SpatialGrid<int32_t> grid;
    grid.build(
        cells, count, [&](int32_t m) { return boxes[m]; }, [](int32_t m, const GridCell &) { return m; });
    assert_int_equal(grid.entry_count(), small_entries); // not the ~2e11 of the large boxes
    assert_true(grid.entry_count() < 27 * static_cast<size_t>(count));
    for (int32_t m = count - 4; m < count; ++m) // added alike
        grid.add(boxes[m][0], boxes[m][1], [&](const GridCell &) { return m; });
    assert_true(grid.entry_count() < 2 * 27 * static_cast<size_t>(count));

    const Pairs expected = all_pairs(boxes);
    for (const int32_t built : {count, count - 4, 0})
        assert_same_pairs(pairs_by_query(boxes, cells, built), expected);
}

// The points a query meets, in order, against those in its cells sorted by cell (i, then
// j, then k) and by number: the order the search for facing sheets depends on.
void check_point_order(const std::vector<Vec3> &points, const CellFrame &cells, const std::vector<Box> &queries)
{
    SpatialGrid<int32_t> grid;
    grid.build(
        cells, static_cast<int32_t>(points.size()), [&](int32_t v) { return Box{points[v], points[v]}; },
        [](int32_t v, const GridCell &) { return v; });
    for (const Box &query : queries) {
        const GridCell first = cells.cell_of(query[0]), last = cells.cell_of(query[1]);
        std::vector<std::pair<GridCell, int32_t>> expected;
        for (int32_t v = 0; v < static_cast<int32_t>(points.size()); ++v) {
            const GridCell c = cells.cell_of(points[v]);
            bool inside = true;
            for (int a = 0; a < 3; ++a)
                inside = inside && first[a] <= c[a] && c[a] <= last[a];
            if (inside)
                expected.push_back({c, v});
        }
        std::sort(expected.begin(), expected.end());
        std::vector<int32_t> met, met_by_cell;
        grid.any_built_in_cells(first, last, [&](int32_t v) {
            met.push_back(v);
            return false;
        });
        grid.any_in_cells(first, last, [&](int32_t v, const GridCell &here) {
            assert_true(same_cell(cells.cell_of(points[v]), here));
            met_by_cell.push_back(v);
            return false;
        });
        assert_int_equal(met.size(), expected.size());
        for (size_t k = 0; k < met.size(); ++k)
            assert_int_equal(met[k], expected[k].second);
        assert_true(met_by_cell == met);
        // A query stops where its visit says so.
        if (!met.empty()) {
            int32_t last_met = -1;
            assert_true(grid.any_built_in_cells(first, last, [&](int32_t v) {
                last_met = v;
                return v == met[met.size() / 2];
            }));
            assert_int_equal(last_met, met[met.size() / 2]);
        }
    }
}

void a_query_meets_points_cell_by_cell_in_their_order(void **)
{
    Numbers numbers{5};
    std::vector<Vec3> points(2000);
    for (Vec3 &p : points)
        p = numbers.point();
    std::vector<Box> queries;
    for (int q = 0; q < 60; ++q) {
        const Vec3 centre = numbers.point() * 1.2 - Vec3::Constant(0.1), half = numbers.point() * 0.15;
        queries.push_back({centre - half, centre + half});
    }
    check_point_order(points, CellFrame{Vec3::Zero(), 0.05}, queries); // densely numbered
    // Queries of more than 18 cells on an axis read the entries rather than the cells: in
    // a densely numbered grid (as the search for facing sheets always has), in the same
    // order.
    std::vector<Box> large_queries;
    for (int q = 0; q < 10; ++q) {
        const Vec3 centre = numbers.point(), half = numbers.point() * 0.3 + Vec3(0.5, 0, 0);
        large_queries.push_back({centre - half, centre + half});
    }
    check_point_order(points, CellFrame{Vec3::Zero(), 0.05}, large_queries);
    // One point far out: the box of the points is then hashed.
    points.push_back(Vec3(1e6, -3e5, 2e6));
    queries.push_back({points.back() - Vec3::Constant(0.1), points.back() + Vec3::Constant(0.1)});
    check_point_order(points, CellFrame{Vec3(-1, -3e5, -1), 0.05}, queries);
}

// A point whose cell number is no integer (NaN, from a coordinate that overflowed) or no
// int64_t (beyond 2^63 cells) was converted to int64_t anyway: undefined behaviour, which
// on x86 gave INT64_MIN for all of them. Now such numbers are clamped to +-2^52, NaN to
// the lowest, and a grid built of such boxes answers without reading out of its arrays.
void cells_of_non_finite_or_far_points_are_clamped(void **)
{
    const CellFrame frame{Vec3::Zero(), 1e-3};
    const int64_t last = int64_t{1} << 52;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const GridCell far = frame.cell_of(Vec3(1e300, -1e300, inf));
    assert_true(far[0] == last && far[1] == -last && far[2] == last);
    const GridCell lost = frame.cell_of(Vec3(nan, 0.0105, -inf));
    assert_true(lost[0] == -last && lost[1] == 10 && lost[2] == -last);
    // Near the limit, cells are still numbered exactly.
    const GridCell near_limit = CellFrame{Vec3::Zero(), 1}.cell_of(Vec3(4503599627370495.0, -4503599627370496.0, -0.5));
    assert_true(near_limit[0] == last - 1 && near_limit[1] == -last && near_limit[2] == -1);

    // A grid of a few ordinary boxes and one with a NaN corner: its pairs are the ordinary
    // ones' (the NaN box covers no cell on its NaN axis), and a query with a NaN corner
    // finds nothing and ends.
    std::vector<Box> boxes = {{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(0.5, 0.5, 0.5), Vec3(2, 2, 2)},
                              {Vec3(0, 0, 0), Vec3(nan, 1, 1)}};
    SpatialGrid<int32_t> grid;
    grid.build(
        CellFrame{Vec3::Zero(), 0.5}, 3, [&](int32_t m) { return boxes[m]; },
        [](int32_t m, const GridCell &) { return m; });
    int32_t pairs = 0;
    for (size_t b = 0; b < grid.bucket_count(); ++b)
        grid.for_each_pair_in_bucket(b, [&](int32_t s, int32_t t, uint64_t here) {
            if (cell_key(first_shared_cell(grid.cells_of(s)[0], grid.cells_of(t)[0])) == here)
                pairs += s == 0 && t == 1 ? 1 : 100;
        });
    assert_int_equal(pairs, 1);
    assert_false(grid.any_in_cells(grid.frame().cell_of(Vec3(nan, 0, 0)), grid.frame().cell_of(Vec3(nan, 1, 1)),
                                   [](int32_t, const GridCell &) { return true; }));
}

// The pairs a sweep of box_pairs.hpp reports, gathered from its threads and sorted.
template <class Sweep>
Pairs pairs_reported(Sweep &&sweep)
{
    std::vector<Pairs> per_thread(static_cast<size_t>(loop_threads()));
    sweep([&](int32_t s, int32_t t) { per_thread[static_cast<size_t>(thread_index())].push_back({s, t}); });
    Pairs pairs;
    for (const Pairs &list : per_thread)
        pairs.insert(pairs.end(), list.begin(), list.end());
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// The collision-safe motion's later rounds of contact look only at the pairs of the
// triangles around moved corners: they must be every overlapping pair with one of them, each
// once, large boxes and boxes with a NaN corner (which overlap nothing) among them.
void pairs_with_a_subset_are_all_pairs_with_one_of_it(void **)
{
    std::vector<Box> boxes = random_boxes(500, 1.0, 0.2, 8);
    boxes.push_back({Vec3(0.05, 0.05, 0.05), Vec3(40, 0.1, 0.1)}); // large
    const double nan = std::numeric_limits<double>::quiet_NaN();
    boxes.push_back({Vec3(nan, 0, 0), Vec3(1, 1, 1)});
    const int32_t count = static_cast<int32_t>(boxes.size());
    const Pairs every = all_pairs(boxes);
    assert_same_pairs(pairs_reported([&](auto visit) { for_each_overlapping_pair(boxes, 0.1, visit); }), every);

    // Among them a subset of one large box alone: a grid whose cells hold nothing (its
    // empty box of cells overflowed the dense numbering, caught by UBSan).
    std::vector<std::vector<int32_t>> subsets = {{}, {7}, {count - 2}, {count - 1}, {count - 1, 3}};
    std::vector<int32_t> every_third, all;
    for (int32_t m = 0; m < count; ++m) {
        all.push_back(m);
        if (m % 3 == 1)
            every_third.push_back(m);
    }
    subsets.push_back(every_third);
    subsets.push_back(all);
    for (const std::vector<int32_t> &some : subsets) {
        std::vector<char> in(static_cast<size_t>(count), 0);
        for (int32_t m : some)
            in[m] = 1;
        Pairs expected;
        for (const auto &[s, t] : every)
            if (in[s] || in[t])
                expected.push_back({s, t});
        assert_same_pairs(
            pairs_reported([&](auto visit) { for_each_overlapping_pair_with(boxes, some, 0.1, visit); }), expected);
    }
}

// The search for merge candidates compares only edges whose normal classes may face: the
// pairs it is given must be exactly the overlapping pairs of groups that may pair, large
// boxes (compared with all others outside the grid) among them, whether the boxes are
// numbered group by group (one run per group in a cell, as that search numbers them) or
// with their groups interleaved (a run per entry).
void pairs_across_groups_are_the_overlapping_pairs_of_groups_that_may_pair(void **)
{
    std::vector<Box> boxes = random_boxes(600, 1.0, 0.2, 9);
    boxes.push_back({Vec3(0.05, 0.05, 0.05), Vec3(40, 0.1, 0.1)}); // large
    const auto may_pair = [](int32_t a, int32_t b) { return a != b && (a + b) % 3 != 0; };
    const auto interleaved = [](int32_t s) { return s % 6 == 5 ? 4 : s % 6; }; // groups of unequal size
    const auto in_runs = [](int32_t s) { return s < 50 ? 0 : s < 300 ? 1 : s < 320 ? 2 : s < 500 ? 4 : 5; };
    // By place, in six slabs across x: most boxes overlap only boxes of their own slab or
    // of the next, and are left out of the grid before it is built.
    const auto by_place = [&](int32_t s) {
        return static_cast<int32_t>(std::clamp(std::floor(6 * boxes[s][0].x()), 0.0, 5.0));
    };
    for (const auto &group : {std::function<int32_t(int32_t)>(interleaved), std::function<int32_t(int32_t)>(in_runs),
                              std::function<int32_t(int32_t)>(by_place)}) {
        Pairs expected;
        for (const auto &[s, t] : all_pairs(boxes))
            if (may_pair(group(s), group(t)))
                expected.push_back({s, t});
        assert_true(expected.size() > 100 && expected.size() < all_pairs(boxes).size());
        assert_same_pairs(pairs_reported([&](auto visit) {
                              for_each_overlapping_pair_across(boxes, 6, group, may_pair, 0.1, visit);
                          }),
                          expected);
    }
}

// The grid's cells are made from the kept boxes' sizes: among many tiny boxes, a few as
// wide as nine callers' cells (not large to the caller) must still be in the grid's cells,
// not left out of them as too large.
void pairs_across_groups_among_boxes_of_very_different_sizes(void **)
{
    std::vector<Box> boxes = random_boxes(500, 1.0, 0.004, 21);
    for (const Box &wide : random_boxes(20, 1.0, 0.9, 22))
        boxes.push_back(wide);
    const auto may_pair = [](int32_t a, int32_t b) { return a != b && (a + b) % 3 != 0; };
    const auto group = [](int32_t s) { return s % 6; };
    Pairs expected;
    for (const auto &[s, t] : all_pairs(boxes))
        if (may_pair(group(s), group(t)))
            expected.push_back({s, t});
    assert_true(expected.size() > 100);
    assert_same_pairs(pairs_reported([&](auto visit) {
                          for_each_overlapping_pair_across(boxes, 6, group, may_pair, 0.1, visit);
                      }),
                      expected);
}

// The grid of the merge search holds only the boxes near a box of a group that pairs
// with theirs: two groups on either side of x = 0.5, pairing only with each other; boxes
// farther from it than two coarse cells are left out, and every box that overlaps one of
// the other group is kept.
void boxes_far_from_a_pairing_group_are_left_out(void **)
{
    const std::vector<Box> boxes = random_boxes(4000, 1.0, 0.01, 11);
    std::vector<int32_t> every(boxes.size());
    for (int32_t s = 0; s < static_cast<int32_t>(boxes.size()); ++s)
        every[s] = s;
    const auto side = [&](int32_t s) { return boxes[s][0].x() < 0.5 ? 0 : 1; };
    const auto may_pair = [](int a, int b) { return a != b; };
    const std::vector<int32_t> kept = detail::boxes_near_a_pairing_group(boxes, every, 2, side, may_pair, 0.05);
    const double coarse = std::max(0.05, 1.01 / std::cbrt(4.0 * 4000)); // as widened for the boxes' bounds
    std::vector<char> is_kept(boxes.size(), 0);
    for (int32_t s : kept) {
        is_kept[s] = 1;
        if (!(std::abs(boxes[s][0].x() - 0.5) < 2 * coarse + 0.01))
            fail_msg("box %d at x = %g is kept, far from the other group", s, boxes[s][0].x());
    }
    for (const auto &[s, t] : all_pairs(boxes))
        if (side(s) != side(t) && !(is_kept[s] && is_kept[t]))
            fail_msg("boxes %d and %d overlap across the groups but were left out", s, t);
    print_message("%zu of %zu boxes kept\n", kept.size(), boxes.size());
    assert_true(kept.size() < boxes.size() / 2);
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(random_boxes_pair_up_as_all_pairs_find),
        cmocka_unit_test(boxes_far_apart_pair_up_as_all_pairs_find),
        cmocka_unit_test(large_boxes_in_few_buckets_pair_up_as_all_pairs_find),
        cmocka_unit_test(boxes_in_one_cell_pair_up_as_all_pairs_find),
        cmocka_unit_test(large_boxes_are_kept_apart_and_still_met),
        cmocka_unit_test(a_query_meets_points_cell_by_cell_in_their_order),
        cmocka_unit_test(cells_of_non_finite_or_far_points_are_clamped),
        cmocka_unit_test(pairs_with_a_subset_are_all_pairs_with_one_of_it),
        cmocka_unit_test(pairs_across_groups_are_the_overlapping_pairs_of_groups_that_may_pair),
        cmocka_unit_test(pairs_across_groups_among_boxes_of_very_different_sizes),
        cmocka_unit_test(boxes_far_from_a_pairing_group_are_left_out),
    };
    return cmocka_run_group_tests_name("unit_spatial_grid", tests, nullptr, nullptr);
}

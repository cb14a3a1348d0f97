// SPDX-License-Identifier: BSD-3-Clause
// Every pair of overlapping boxes, each once: the broad phase of the self-intersection
// count and of collision-safe motion, and (of groups that may pair) of the merge search;
// and the boxes near one of a group that may pair with theirs, for the merge search and
// the crossing guard's search for facing sheets.
// Boxes of up to a few cells go into the uniform grid (spatial_grid.hpp); a box larger
// than that (large_span cells on an axis: a long triangle among short ones, a vertex
// thrown far in one step) would be entered in the cube of its size in cells, millions for
// one sliver, so it is compared with every other box instead. Time and memory then stay
// linear in the boxes, plus the number of large boxes times all boxes.
#pragma once

#include "geometry/spatial_grid.hpp"
#include "mesh/parallel.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace sfa {

using Box = std::array<Vec3, 2>; // lowest and highest corner

inline bool boxes_overlap(const Box &a, const Box &b)
{
    return (a[0] - b[1]).maxCoeff() <= 0 && (b[0] - a[1]).maxCoeff() <= 0;
}

namespace detail {

// The union of two boxes; one with a NaN corner (which overlaps nothing) adds nothing.
inline Box box_union(const Box &a, const Box &b)
{
    if (!(b[0].allFinite() && b[1].allFinite()))
        return a;
    if (!(a[0].allFinite() && a[1].allFinite()))
        return b;
    return {a[0].cwiseMin(b[0]), a[1].cwiseMax(b[1])};
}

// The boxes that go into a grid of cells `cell` wide (small), in increasing order, and
// those that would cover too many of its cells (large), compared with every box instead.
struct BoxesBySize {
    std::vector<int32_t> small, large;
    std::vector<char> is_large; // per box
};

inline BoxesBySize boxes_by_size(const std::vector<Box> &boxes, double cell)
{
    BoxesBySize by_size;
    by_size.is_large.assign(boxes.size(), 0);
    for (int32_t t = 0; t < static_cast<int32_t>(boxes.size()); ++t) {
        const bool fits = (boxes[t][1] - boxes[t][0]).maxCoeff() <= large_span * cell; // false for NaN
        (fits ? by_size.small : by_size.large).push_back(t);
        by_size.is_large[t] = !fits;
    }
    return by_size;
}

// The lowest corner of the small boxes (at least one).
inline Vec3 lowest_corner(const std::vector<Box> &boxes, const std::vector<int32_t> &small)
{
    Vec3 lowest = boxes[small[0]][0];
    for (int32_t t : small)
        lowest = lowest.cwiseMin(boxes[t][0]);
    return lowest;
}

// Calls visit(s, t), s < t, for every pair of overlapping boxes, one of them large, that
// may_pair(s, t) wants.
template <class MayPair, class Visit>
void pairs_with_large_boxes(const std::vector<Box> &boxes, const BoxesBySize &by_size, MayPair &&may_pair,
                            Visit &&visit, [[maybe_unused]] int threads)
{
    const int32_t n = static_cast<int32_t>(boxes.size());
    const int64_t count = static_cast<int64_t>(by_size.large.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (int64_t i = 0; i < count; ++i) {
        const int32_t s = by_size.large[static_cast<size_t>(i)];
        for (int32_t t = 0; t < n; ++t)
            if (t != s && !(by_size.is_large[t] && t < s) && may_pair(s, t) && boxes_overlap(boxes[s], boxes[t]))
                visit(std::min(s, t), std::max(s, t));
    }
}

// The boxes of `small` (finite boxes) that may overlap a box of a group theirs may pair
// with, `groups` (at most 128) numbered from 0: each coarse cell, at least `coarse` wide,
// holds the set of groups of the boxes that cover it, and a box is kept if a cell it
// covers holds a group that pairs with its own. Two boxes that overlap cover one cell
// together, so no pair is lost; on a smooth surface, whose normals turn little within a
// cell, most boxes are left out. The cells are an array over the boxes' bounds, widened
// where that would hold more than about four cells a box (boxes far apart), which keeps
// more boxes, not fewer; where the boxes cover more than 64 cells each on average, all
// are kept.
template <class Group, class MayPair>
std::vector<int32_t> boxes_near_a_pairing_group(const std::vector<Box> &boxes, const std::vector<int32_t> &small,
                                                int groups, Group &&group, MayPair &&may_pair, double coarse)
{
    struct Groups {
        uint64_t bits[2] = {0, 0};
        void add(int g) { bits[g >> 6] |= uint64_t{1} << (g & 63); }
        void add(const Groups &o) { bits[0] |= o.bits[0], bits[1] |= o.bits[1]; }
        // add(g) from a parallel loop: an atomic or, made only where the bit is not set yet
        // (most boxes of a cell are of one group). The order of the ors does not matter.
        void add_shared(int g)
        {
            uint64_t &word = bits[g >> 6];
            const uint64_t bit = uint64_t{1} << (g & 63);
            if (!(__atomic_load_n(&word, __ATOMIC_RELAXED) & bit))
                __atomic_fetch_or(&word, bit, __ATOMIC_RELAXED);
        }
        bool meets(const Groups &o) const { return (bits[0] & o.bits[0]) | (bits[1] & o.bits[1]); }
    };
    std::vector<Groups> pairing(static_cast<size_t>(groups));
    for (int a = 0; a < groups; ++a)
        for (int b = 0; b < groups; ++b)
            if (may_pair(a, b))
                pairing[static_cast<size_t>(a)].add(b);
    // Each step is a parallel loop (on Enright at t = 1.5, the serial loops left a thread
    // idle for 11 ms of the 27 ms of each call's merge search).
    const int32_t count = static_cast<int32_t>(small.size());
    const Vec3 none = Vec3::Constant(std::numeric_limits<double>::quiet_NaN()); // a union adds nothing to it
    const Box bounds = ordered_group_reduce(
        count, 1, Box{none, none}, [](int32_t) { return 0; }, [&](int32_t m) { return boxes[small[m]]; }, box_union)[0];
    const Vec3 &lowest = bounds[0], &highest = bounds[1];
    const double most_per_axis = std::cbrt(4.0 * static_cast<double>(small.size()));
    const double size = std::max(coarse, (highest - lowest).maxCoeff() / most_per_axis);
    if (!(size > 0 && std::isfinite(size)))
        return small; // bounds that overflow, or no extent to cut: no cells
    // A coordinate's cell is its distance from the lowest corner in cells, truncated: the
    // boxes are finite and at or above that corner, so this is the floor, at most
    // most_per_axis, and it never decreases as the coordinate grows, so two boxes that
    // overlap cover one cell together. (CellFrame::cell_of's range checks are not needed
    // here, and took a third of this search.)
    const double per_cell = 1 / size;
    const auto cell_on = [&](const Vec3 &p, int a) { return static_cast<int64_t>((p[a] - lowest[a]) * per_cell); };
    const int64_t plane = (cell_on(highest, 1) + 1) * (cell_on(highest, 2) + 1), row = cell_on(highest, 2) + 1;
    struct Span {
        int64_t first;     // the cell of the lowest corner, numbered in the array
        int32_t across[3]; // how many more cells the box covers on each axis
    };
    // Boxes that cover many cells would make this cost more than the search it spares:
    // past 64 cells a box on average, every box is kept.
    std::vector<Span> span(small.size());
    size_t covered = 0;
#pragma omp parallel for num_threads(loop_threads()) schedule(static) reduction(+ : covered)
    for (int32_t m = 0; m < count; ++m) {
        const Box &box = boxes[small[m]];
        int64_t low[3];
        for (int a = 0; a < 3; ++a) {
            low[a] = cell_on(box[0], a);
            span[m].across[a] = static_cast<int32_t>(cell_on(box[1], a) - low[a]);
        }
        span[m].first = low[0] * plane + low[1] * row + low[2];
        covered += static_cast<size_t>(span[m].across[0] + 1) * static_cast<size_t>(span[m].across[1] + 1) *
                   static_cast<size_t>(span[m].across[2] + 1);
    }
    if (covered > 64 * small.size())
        return small;
    std::vector<Groups> held(static_cast<size_t>((cell_on(highest, 0) + 1) * plane));
    const auto for_each_cell = [&](const Span &s, auto &&visit) {
        Groups *first = &held[static_cast<size_t>(s.first)];
        if ((s.across[0] | s.across[1] | s.across[2]) == 0) // most boxes
            return visit(*first);
        for (int32_t i = 0; i <= s.across[0]; ++i)
            for (int32_t j = 0; j <= s.across[1]; ++j) {
                Groups *cells = first + i * plane + j * row;
                for (int32_t k = 0; k <= s.across[2]; ++k)
                    visit(cells[k]);
            }
    };
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t m = 0; m < count; ++m) {
        const int g = static_cast<int>(group(small[m]));
        for_each_cell(span[m], [&](Groups &cell) { cell.add_shared(g); });
    }
    std::vector<int32_t> number; // in `kept`, in order
    const auto near_a_pairing_group = [&](int32_t m) {
        Groups around;
        for_each_cell(span[m], [&](const Groups &cell) { around.add(cell); });
        return around.meets(pairing[static_cast<size_t>(group(small[m]))]);
    };
    std::vector<int32_t> kept(static_cast<size_t>(number_kept(count, near_a_pairing_group, number)));
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t m = 0; m < count; ++m)
        if (number[m] >= 0)
            kept[number[m]] = small[m];
    return kept;
}

} // namespace detail

// Calls visit(s, t), s < t, once for every two overlapping boxes, from parallel loops of
// `threads` threads (visit may use thread_index() for its own scratch; called from a
// parallel loop of its own, pass 1: a nested loop would number its threads from 0 again).
// `cell` is the grid's cell size, about the size of a typical box. Boxes with a NaN corner
// overlap nothing.
template <class Visit>
void for_each_overlapping_pair(const std::vector<Box> &boxes, double cell, Visit &&visit,
                               [[maybe_unused]] int threads = loop_threads()) // unused without OpenMP
{
    const detail::BoxesBySize by_size = detail::boxes_by_size(boxes, cell);
    const std::vector<int32_t> &small = by_size.small;
    if (small.size() >= 2) {
        // Each entry carries what the pairs of its cell compare, so that a cell's pairs read
        // one contiguous run of memory instead of two scattered arrays per pair (the broad
        // phase of collision-safe motion spent most of its time waiting for those reads).
        struct Entry {
            Box box;
            GridCell first; // the cell of the box's lowest corner
            int32_t index;  // in `boxes`
        };
        SpatialGrid<Entry> grid; // entries in increasing order of index
        grid.build(CellFrame{detail::lowest_corner(boxes, small), cell}, static_cast<int32_t>(small.size()),
                   [&](int32_t m) { return boxes[small[m]]; },
                   [&](int32_t m, const GridCell &first) { return Entry{boxes[small[m]], first, small[m]}; });
        const int64_t buckets = static_cast<int64_t>(grid.bucket_count());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
        for (int64_t b = 0; b < buckets; ++b)
            grid.for_each_pair_in_bucket(static_cast<size_t>(b), [&](const Entry &m, const Entry &k, uint64_t here) {
                // Each pair once: in the first cell both boxes cover. Most pairs of a cell
                // do not overlap, which is the cheaper test.
                if (boxes_overlap(m.box, k.box) && cell_key(first_shared_cell(m.first, k.first)) == here)
                    visit(m.index, k.index);
            });
    }
    detail::pairs_with_large_boxes(boxes, by_size, [](int32_t, int32_t) { return true; }, visit, threads);
}

// Calls visit(s, t), s < t, once for every two overlapping boxes whose groups may pair
// (may_pair(group(s), group(t)), symmetric, false for one group; groups are ints from 0 to
// `groups` - 1, at most 128), from parallel loops as for_each_overlapping_pair; `cell`,
// about a typical box's size, is the coarse cells' width and the widest the grid's cells
// may be. For
// searches where most overlapping pairs are of groups that never pair: the boxes far from
// any box of a group that pairs with theirs are left out (boxes_near_a_pairing_group);
// the others are numbered group by group (a counting sort of the few kept), and the boxes
// of one group in a cell are one run of the cell's entries; two runs whose groups do not
// pair are passed over whole. An entry is then the box's number and group alone (8 bytes
// instead of 80: the few pairs compared read their boxes where they are), so that the
// grid's memory, written anew at each search, is a tenth.
template <class Group, class MayPair, class Visit>
void for_each_overlapping_pair_across(const std::vector<Box> &boxes, int groups, Group &&group, MayPair &&may_pair,
                                      double cell, Visit &&visit,
                                      [[maybe_unused]] int threads = loop_threads()) // unused without OpenMP
{
    const detail::BoxesBySize by_size = detail::boxes_by_size(boxes, cell);
    // Only the boxes near one of a group that pairs with theirs go into the grid: on
    // bench_topology's sphere, where no two edges face, a fifth fewer instructions and
    // 86-89 ms a call instead of 107-123. Coarse cells of one grid cell: on the vortex T =
    // 2 run's mesh at t = 1, whose spiral sheet turns within a few edges, they keep 12 % of
    // the merge search's edges where cells of four kept 63 %, for a fifth fewer
    // instructions a call (the sphere's take 5 % more than with cells of two).
    const std::vector<int32_t> near =
        by_size.small.size() < 2
            ? by_size.small
            : detail::boxes_near_a_pairing_group(boxes, by_size.small, groups, group, may_pair, cell);
    if (near.size() >= 2) {
        std::vector<int32_t> small(near.size()), first_of_group(static_cast<size_t>(groups) + 1, 0);
        for (int32_t s : near)
            ++first_of_group[static_cast<size_t>(group(s)) + 1];
        for (size_t g = 1; g <= static_cast<size_t>(groups); ++g)
            first_of_group[g] += first_of_group[g - 1];
        for (int32_t s : near)
            small[static_cast<size_t>(first_of_group[static_cast<size_t>(group(s))]++)] = s;
        // The grid's cells from the kept boxes, which lie where the surface turns and are
        // often smaller than the caller's mean (Enright at t = 1.5: half as wide): as wide
        // as their mean, which compares fewer pairs of a crowded cell (a quarter fewer
        // instructions there), but no box more than large_span - 1 cells across (a larger
        // one would be left out of the grid's cells), and no wider than the caller's.
        double extents = 0, widest = 0;
        for (int32_t s : small) {
            const double extent = (boxes[s][1] - boxes[s][0]).maxCoeff();
            extents += extent;
            widest = std::max(widest, extent);
        }
        const double mean = extents / static_cast<double>(small.size());
        double grid_cell = std::min(cell, std::max(mean, widest / (large_span - 1)));
        if (!(grid_cell > 0))
            grid_cell = cell; // points
        struct Entry {
            int32_t thing; // in `small`
            int32_t group;
        };
        SpatialGrid<Entry> grid; // entries in increasing order of thing, and so group by group
        grid.build(CellFrame{detail::lowest_corner(boxes, small), grid_cell}, static_cast<int32_t>(small.size()),
                   [&](int32_t m) { return boxes[small[m]]; },
                   [&](int32_t m, const GridCell &) { return Entry{m, static_cast<int32_t>(group(small[m]))}; });
        const int64_t buckets = static_cast<int64_t>(grid.bucket_count());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
        for (int64_t b = 0; b < buckets; ++b)
            grid.for_each_pair_across_runs(
                static_cast<size_t>(b), [](const Entry &m, const Entry &k) { return m.group == k.group; },
                [&](const Entry &m, const Entry &k) { return may_pair(m.group, k.group); },
                [&](const Entry &m, const Entry &k, uint64_t here) {
                    const int32_t s = small[m.thing], t = small[k.thing];
                    // Each pair once: in the first cell both boxes cover.
                    if (cell_key(first_shared_cell(grid.cells_of(m.thing)[0], grid.cells_of(k.thing)[0])) == here &&
                        boxes_overlap(boxes[s], boxes[t]))
                        visit(std::min(s, t), std::max(s, t));
                });
    }
    detail::pairs_with_large_boxes(
        boxes, by_size, [&](int32_t s, int32_t t) { return may_pair(group(s), group(t)); }, visit, threads);
}

// Calls visit(s, t), s < t, once for every two overlapping boxes of which one at least is
// in `some` (distinct indices), from parallel loops: only `some` goes into a grid, and
// every box asks it, which costs the boxes times the cells each covers instead of every
// pair of a crowded cell. `cell` as in for_each_overlapping_pair.
template <class Visit>
void for_each_overlapping_pair_with(const std::vector<Box> &boxes, const std::vector<int32_t> &some, double cell,
                                    Visit &&visit)
{
    if (some.empty())
        return;
    const int32_t n = static_cast<int32_t>(boxes.size());
    std::vector<char> in_some(static_cast<size_t>(n), 0);
    Vec3 lowest = Vec3::Constant(std::numeric_limits<double>::infinity());
    for (int32_t s : some) {
        in_some[s] = 1;
        lowest = lowest.cwiseMin(boxes[s][0]); // a NaN corner leaves it as it was
    }
    if (!lowest.allFinite())
        return; // every box of `some` has a NaN corner: they overlap nothing
    SpatialGrid<int32_t> grid; // entry m is box some[m]
    grid.build(CellFrame{lowest, cell}, static_cast<int32_t>(some.size()), [&](int32_t m) { return boxes[some[m]]; },
               [](int32_t m, const GridCell &) { return m; });
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 256)
    for (int32_t t = 0; t < n; ++t) {
        if (!(boxes[t][0].allFinite() && boxes[t][1].allFinite()))
            continue;
        const GridCell first = grid.frame().cell_of(boxes[t][0]), last = grid.frame().cell_of(boxes[t][1]);
        grid.any_in_cells(first, last, [&](int32_t m, const GridCell &here) {
            const int32_t s = some[m];
            // Two of `some` are met from both: counted from the lower. Each in one cell.
            if (s == t || (in_some[t] && s < t) || !same_cell(first_shared_cell(first, grid.cells_of(m)[0]), here))
                return false;
            if (boxes_overlap(boxes[s], boxes[t]))
                visit(std::min(s, t), std::max(s, t));
            return false;
        });
    }
}

} // namespace sfa

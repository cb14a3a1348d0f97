// SPDX-License-Identifier: BSD-3-Clause
// A uniform grid of cubic cells for finding what lies near what: the boxes of faces that a
// new face could meet (the crossing guard), the points near a vertex (the search for facing
// sheets), the pairs of triangles that could intersect (the self-intersection count).
//
// A thing is entered in every cell its box covers, into the bucket of that cell; the
// entries are counting-sorted bucket by bucket, so that a bucket is one contiguous run.
// Memory grows with the entries and the things, never with the volume of the box around
// them: where that box has at most 8 cells per thing (and 64 more), each of its cells has a
// bucket of its own, numbered i, then j, then k, as in a dense grid, so that neighbouring
// cells are neighbours in memory; in a larger box the cells are hashed into as many buckets
// as there are things, and each entry keeps its cell's key in an array of its own, so that
// the entries of other cells in a bucket are passed over without reading them. Things
// entered after that are chained in a hashed table of their own, leaving the sorted runs as
// they are.
//
// A query visits every cell its box covers, clamped to the cells that hold entries.
//
// Large boxes are kept apart (as box_pairs.hpp does for the pair sweep): a thing whose box
// spans more than large_span + 1 cells on an axis (a long triangle among short ones, a
// vertex thrown far in one step, a corner pulled out hundreds of edges) would be entered in
// the cube of its extent in cells, millions of entries for one sliver, and a query box that
// large would visit as many cells, empty or not. Such a thing is stored once, with its
// cells, and every query compares it with its own cells; such a query compares itself with
// every thing instead of walking cells. Memory then grows with the things and the entries
// of the small ones alone (at most (large_span + 2)^3 each), and a query costs at most that
// many cells or the number of things.
#pragma once

#include "mesh/parallel.hpp"
#include "mesh/tri_mesh.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <new>
#include <vector>

namespace sfa {

// A cell: its number on each axis.
using GridCell = std::array<int64_t, 3>;

// Cubic cells of one size, numbered from an origin.
struct CellFrame {
    Vec3 origin = Vec3::Zero();
    double size = 1;

    // A division, not a product with the inverse size: the two can round apart, and a
    // point's cell decides the order in which a search meets it.
    GridCell cell_of(const Vec3 &p) const
    {
        const Vec3 c = (p - origin) / size;
        return {cell_number(c[0]), cell_number(c[1]), cell_number(c[2])};
    }

    // The floor of a coordinate in cells. Beyond +-2^52 cells on an axis (where a double
    // has no fractions left; a surface spans far fewer) the cell is the last one, and NaN
    // (from a coordinate that overflowed) is the lowest: converting such a value to an
    // integer would be undefined behaviour. The differences of two cell numbers still fit
    // an int64_t. Within the range, truncating and stepping down below a negative fraction
    // is the floor, exactly, without std::floor (a library call, or some thirty
    // instructions, on processors without SSE4.1's rounding).
    static constexpr double max_cell = 4503599627370496.0; // 2^52
    static int64_t cell_number(double x)
    {
        if (!(x >= -max_cell)) // also NaN
            return -static_cast<int64_t>(max_cell);
        if (!(x <= max_cell))
            return static_cast<int64_t>(max_cell);
        const int64_t truncated = static_cast<int64_t>(x);
        return truncated - (static_cast<double>(truncated) > x);
    }
};

// Boxes of more than this many cells on an axis are large: kept out of the grid's cells and
// compared with everything instead (here and in box_pairs.hpp).
constexpr double large_span = 16;

// Whether a box from cell `first` to cell `last` is large: a box of at most large_span cells
// in extent covers at most large_span + 1 cells on an axis, however its ends round, so a
// box box_pairs.hpp enters in the grid is never kept apart by it.
inline bool spans_many_cells(const GridCell &first, const GridCell &last)
{
    constexpr int64_t most = static_cast<int64_t>(large_span) + 1;
    return last[0] - first[0] > most || last[1] - first[1] > most || last[2] - first[2] > most;
}

// Whether two cell ranges share a cell.
inline bool cells_meet(const GridCell &first, const GridCell &last, const std::array<GridCell, 2> &span)
{
    for (int a = 0; a < 3; ++a)
        if (span[0][a] > last[a] || first[a] > span[1][a] || span[0][a] > span[1][a])
            return false;
    return true;
}

// Axis by axis: std::array's == becomes a call to memcmp, too slow for an inner loop.
inline bool same_cell(const GridCell &a, const GridCell &b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

// A cell as one key, 21 bits per axis. Cells 2^21 apart on an axis share a key, and the
// grid takes them for one cell; a surface spans far fewer cells than that.
inline uint64_t cell_key(const GridCell &c)
{
    constexpr uint64_t mask = (uint64_t{1} << 21) - 1;
    return (static_cast<uint64_t>(c[0]) & mask) << 42 | (static_cast<uint64_t>(c[1]) & mask) << 21 |
           (static_cast<uint64_t>(c[2]) & mask);
}

// Where a pair of boxes, with their low corners in cells a and b, is reported. Each box is
// in every cell it covers, so two boxes that share cells meet in each of them; the pair
// counts once, in the first cell both cover: on each axis the larger of their first cells.
inline GridCell first_shared_cell(const GridCell &a, const GridCell &b)
{
    return {std::max(a[0], b[0]), std::max(a[1], b[1]), std::max(a[2], b[2])};
}

// Entries of type Item, each in one cell.
template <class Item>
class SpatialGrid {
public:
    const CellFrame &frame() const { return frame_; }
    // Whether build has been called: only then can things be added.
    bool built() const { return !added_head_.empty(); }
    bool empty() const { return sorted_size_ == 0 && large_.empty() && added_things_.empty(); }
    // The entries in cells, built and added: what the grid's memory grows with.
    size_t entry_count() const { return sorted_size_ + added_.size(); }

    // Replaces the contents by `count` things: thing m, of box box_of(m) ({lo, hi}), is
    // entered as item_of(m, first) in every cell its box covers, `first` being the cell of
    // lo, unless the box spans many cells (spans_many_cells): then it is kept apart, once.
    // In a cell, entries come in the order of m. Both are called in parallel.
    template <class BoxOf, class ItemOf>
    void build(const CellFrame &frame, int32_t count, BoxOf &&box_of, ItemOf &&item_of);

    // Enters one more thing, of box [lo, hi], as item_of(first) in every cell it covers.
    template <class ItemOf>
    void add(const Vec3 &lo, const Vec3 &hi, ItemOf &&item_of);

    // Calls visit(item, cell) for the things in the cells from `first` to `last`: first the
    // built ones, cells in the order of i, then j, then k, and in a cell in their order;
    // then the added ones, cell by cell, latest first. A thing is met in every cell of the
    // range it covers, but a large thing, or any thing when the range itself spans many
    // cells, is met once only, in the first cell of the range it covers
    // (first_shared_cell(first, its first cell)): after the cells' entries for a large
    // thing, in order of things, or, for a large range, in order of things alone. Callers
    // that count a thing in that cell only (as every caller does) see each thing once
    // either way. Stops at the first visit that returns true, and returns whether one did.
    template <class Visit>
    bool any_in_cells(const GridCell &first, const GridCell &last, Visit &&visit) const;
    // The same for the built things alone, calling visit(item). Densely numbered, the cells
    // of a column are one run of entries, read in one loop (not one per cell, whose ends a
    // processor cannot foresee); and visit is called from one place only, so that the
    // compiler can inline it. For a range spanning many cells, the entries are read in
    // their stored order, each thing at its first entry: for things of one cell each (the
    // points of the search for facing sheets) in a densely numbered grid, the same order as
    // cell by cell.
    template <class Visit>
    bool any_built_in_cells(const GridCell &first, const GridCell &last, Visit &&visit) const;

    // The first and the last cell of built thing m's box.
    const std::array<GridCell, 2> &cells_of(int32_t m) const { return spans_[m]; }

    size_t bucket_count() const { return bucket_start_.size() - 1; }
    // Calls visit(a, b, key) for every two built entries a and b, a before b, of one cell in
    // the bucket; key is the cell's. Large things are in no bucket (box_pairs.hpp compares
    // them with every box itself).
    template <class Visit>
    void for_each_pair_in_bucket(size_t bucket, Visit &&visit) const;
    // The same for the pairs of entries in two runs that may pair, passing over the others
    // unseen. A run is a longest stretch of consecutive entries of the bucket for which
    // same_run(its first, entry) holds; runs_may_pair(first of one run, first of a later
    // one) says whether the pairs of two runs are wanted (never those within a run). A
    // bucket's entries come in the order of things, so things numbered group by group make
    // one run per group and cell: where a cell holds few groups, most of its pairs cost
    // nothing.
    template <class SameRun, class RunsMayPair, class Visit>
    void for_each_pair_across_runs(size_t bucket, SameRun &&same_run, RunsMayPair &&runs_may_pair,
                                   Visit &&visit) const;

private:
    struct Added {
        int32_t thing; // in added_things_
        int32_t next;  // the next added entry in the same chain, or -1
        uint64_t key;
    };
    struct AddedThing {
        Item item;
        std::array<GridCell, 2> span;
    };

    static uint64_t hashed(uint64_t key, int shift) { return (key * 0x9E3779B97F4A7C15u) >> shift; } // Fibonacci
    // The bucket of the column (i, j)'s cell k is column_start(i, j) + k, masked: a column's
    // cells are consecutive buckets, in the dense numbering and the hashed one alike.
    uint64_t column_start(int64_t i, int64_t j) const
    {
        if (dense_)
            return static_cast<uint64_t>(((i - low_[0]) * dims_[1] + (j - low_[1])) * dims_[2] - low_[2]);
        return hashed(cell_key({i, j, 0}), bucket_shift_);
    }
    size_t bucket_of(const GridCell &c) const
    {
        return static_cast<size_t>((column_start(c[0], c[1]) + static_cast<uint64_t>(c[2])) & bucket_mask_);
    }
    // The key of a dense grid's bucket's one cell.
    uint64_t dense_key(size_t bucket) const
    {
        const int64_t plane = dims_[1] * dims_[2], n = static_cast<int64_t>(bucket);
        return cell_key({low_[0] + n / plane, low_[1] + n % plane / dims_[2], low_[2] + n % dims_[2]});
    }
    template <class Fn>
    static void for_each_cell(const GridCell &first, const GridCell &last, Fn &&fn)
    {
        for (int64_t i = first[0]; i <= last[0]; ++i)
            for (int64_t j = first[1]; j <= last[1]; ++j)
                for (int64_t k = first[2]; k <= last[2]; ++k)
                    fn(GridCell{i, j, k});
    }
    static void clamp(GridCell &first, GridCell &last, const GridCell &low, const GridCell &high)
    {
        for (int a = 0; a < 3; ++a) {
            first[a] = std::max(first[a], low[a]);
            last[a] = std::min(last[a], high[a]);
        }
    }
    static constexpr int64_t none_low = std::numeric_limits<int64_t>::max();
    static constexpr int64_t none_high = std::numeric_limits<int64_t>::min();

    CellFrame frame_;
    bool dense_ = false;
    int bucket_shift_ = 60, added_shift_ = 60;
    uint64_t bucket_mask_ = 15;
    // The cells of the built entries lie from low_ to high_ (dims_ on each axis), those of
    // the added ones from added_low_ to added_high_: a query goes no further.
    GridCell low_ = {none_low, none_low, none_low}, high_ = {none_high, none_high, none_high}, dims_ = {0, 0, 0};
    GridCell added_low_ = low_, added_high_ = high_;
    // Bucket b's built entries are sorted_[bucket_start_[b]] up to, not including,
    // sorted_[bucket_start_[b + 1]]; hashed, the keys of their cells are sorted_key_[...]
    // at the same places. The items are left uninitialised until the sort writes them (no
    // pass of zeros over them first).
    std::vector<uint32_t> bucket_start_ = {0};
    std::unique_ptr<Item[]> sorted_;
    size_t sorted_size_ = 0, sorted_room_ = 0;
    std::vector<uint64_t> sorted_key_;
    std::vector<int32_t> owner_; // the thing of each sorted entry
    std::vector<uint32_t> first_entry_; // a small built thing's first entry
    std::vector<int32_t> large_; // the large built things, in increasing order
    std::vector<Item> large_item_; // theirs
    std::vector<int32_t> added_head_; // by hashed cell key
    std::vector<Added> added_; // entries of small added things
    std::vector<AddedThing> added_things_; // every added thing once
    std::vector<int32_t> added_large_; // the large ones among them
    std::vector<std::array<GridCell, 2>> spans_; // the cells of each built thing's box
};

template <class Item>
template <class BoxOf, class ItemOf>
void SpatialGrid<Item>::build(const CellFrame &frame, int32_t count, BoxOf &&box_of, ItemOf &&item_of)
{
    frame_ = frame;
    spans_.resize(count);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t m = 0; m < count; ++m) {
        const auto box = box_of(m);
        spans_[m] = {frame_.cell_of(box[0]), frame_.cell_of(box[1])};
    }
    low_.fill(none_low);
    high_.fill(none_high);
    large_.clear();
    for (int32_t m = 0; m < count; ++m)
        if (spans_many_cells(spans_[m][0], spans_[m][1]))
            large_.push_back(m);
    large_item_.resize(large_.size());
    for (size_t l = 0; l < large_.size(); ++l)
        large_item_[l] = item_of(large_[l], spans_[large_[l]][0]);
    // The cells' entries are those of the small things.
    const auto small = [&](int32_t m) { return !spans_many_cells(spans_[m][0], spans_[m][1]); };
    for (int32_t m = 0; m < count; ++m)
        if (const std::array<GridCell, 2> &span = spans_[m]; small(m))
            for (int a = 0; a < 3; ++a) {
            low_[a] = std::min(low_[a], span[0][a]);
            high_[a] = std::max(high_[a], span[1][a]);
        }
    int bits = 4;
    while ((size_t{1} << bits) < static_cast<size_t>(count))
        ++bits;
    // In doubles: the box of a scattered few can have more cells than an integer holds.
    // Where every thing is large, no cell has an entry, and there is no box to number.
    const bool any_small = low_[0] <= high_[0];
    const double dense_limit = 8.0 * count + 64;
    double box_cells = any_small ? 1 : 0;
    for (int a = 0; a < 3 && any_small; ++a)
        box_cells *= static_cast<double>(high_[a]) - static_cast<double>(low_[a]) + 1;
    dense_ = any_small && box_cells <= dense_limit;
    size_t buckets;
    if (dense_) {
        for (int a = 0; a < 3; ++a)
            dims_[a] = high_[a] - low_[a] + 1;
        buckets = static_cast<size_t>(dims_[0] * dims_[1] * dims_[2]);
        bucket_mask_ = ~uint64_t{0};
    } else {
        buckets = size_t{1} << bits;
        bucket_shift_ = 64 - bits;
        bucket_mask_ = buckets - 1;
    }
    // A counting sort: the entries of each bucket counted, then placed from the bucket's
    // end, the last thing first, so that a bucket's entries come in the order of things.
    bucket_start_.assign(buckets + 1, 0);
    size_t entries = 0;
    for (int32_t m = 0; m < count; ++m)
        if (small(m))
            for_each_cell(spans_[m][0], spans_[m][1], [&](const GridCell &c) {
                if (++entries > std::numeric_limits<uint32_t>::max())
                    throw std::bad_alloc(); // more entries than memory could hold
                ++bucket_start_[bucket_of(c)];
            });
    for (size_t b = 1; b < buckets; ++b)
        bucket_start_[b] += bucket_start_[b - 1];
    bucket_start_[buckets] = static_cast<uint32_t>(entries);
    sorted_key_.resize(dense_ ? 0 : entries);
    owner_.resize(entries);
    first_entry_.assign(count, 0);
    for (int32_t m = count - 1; m >= 0; --m)
        if (small(m))
            for_each_cell(spans_[m][0], spans_[m][1], [&](const GridCell &c) {
                const uint32_t e = --bucket_start_[bucket_of(c)];
                owner_[e] = m;
                if (!dense_)
                    sorted_key_[e] = cell_key(c);
            });
    for (size_t e = entries; e-- > 0;)
        first_entry_[owner_[e]] = static_cast<uint32_t>(e);
    // Then the items, larger, in parallel.
    if (entries > sorted_room_) {
        sorted_.reset(new Item[entries]);
        sorted_room_ = entries;
    }
    sorted_size_ = entries;
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int64_t e = 0; e < static_cast<int64_t>(entries); ++e)
        sorted_[e] = item_of(owner_[e], spans_[owner_[e]][0]);
    added_shift_ = 64 - bits;
    added_head_.assign(size_t{1} << bits, -1);
    added_.clear();
    added_things_.clear();
    added_large_.clear();
    added_low_.fill(none_low);
    added_high_.fill(none_high);
}

template <class Item>
template <class ItemOf>
void SpatialGrid<Item>::add(const Vec3 &lo, const Vec3 &hi, ItemOf &&item_of)
{
    const GridCell first = frame_.cell_of(lo), last = frame_.cell_of(hi);
    const int32_t thing = static_cast<int32_t>(added_things_.size());
    added_things_.push_back({item_of(first), {first, last}});
    if (spans_many_cells(first, last)) {
        added_large_.push_back(thing);
        return;
    }
    for (int a = 0; a < 3; ++a) {
        added_low_[a] = std::min(added_low_[a], first[a]);
        added_high_[a] = std::max(added_high_[a], last[a]);
    }
    for_each_cell(first, last, [&](const GridCell &c) {
        const uint64_t key = cell_key(c);
        int32_t &head = added_head_[hashed(key, added_shift_)];
        added_.push_back({thing, head, key});
        head = static_cast<int32_t>(added_.size() - 1);
    });
}

template <class Item>
template <class Visit>
bool SpatialGrid<Item>::any_in_cells(const GridCell &first, const GridCell &last, Visit &&visit) const
{
    const auto once = [&](const Item &item, const std::array<GridCell, 2> &span) {
        return cells_meet(first, last, span) && visit(item, first_shared_cell(first, span[0]));
    };
    if (spans_many_cells(first, last)) { // every thing, each once
        for (size_t e = 0; e < sorted_size_; ++e)
            if (first_entry_[owner_[e]] == e && once(sorted_[e], spans_[owner_[e]]))
                return true;
        for (size_t l = 0; l < large_.size(); ++l)
            if (once(large_item_[l], spans_[large_[l]]))
                return true;
        for (size_t t = added_things_.size(); t-- > 0;)
            if (once(added_things_[t].item, added_things_[t].span))
                return true;
        return false;
    }
    GridCell a = first, b = last;
    clamp(a, b, low_, high_);
    for (int64_t i = a[0]; i <= b[0]; ++i)
        for (int64_t j = a[1]; j <= b[1]; ++j) {
            const uint64_t column = column_start(i, j);
            for (int64_t k = a[2]; k <= b[2]; ++k) {
                const GridCell c{i, j, k};
                const uint64_t key = cell_key(c);
                const size_t bucket = static_cast<size_t>((column + static_cast<uint64_t>(k)) & bucket_mask_);
                for (size_t e = bucket_start_[bucket]; e < bucket_start_[bucket + 1]; ++e)
                    if ((dense_ || sorted_key_[e] == key) && visit(sorted_[e], c))
                        return true;
            }
        }
    for (size_t l = 0; l < large_.size(); ++l)
        if (once(large_item_[l], spans_[large_[l]]))
            return true;
    a = first;
    b = last;
    clamp(a, b, added_low_, added_high_);
    for (int64_t i = a[0]; i <= b[0]; ++i)
        for (int64_t j = a[1]; j <= b[1]; ++j)
            for (int64_t k = a[2]; k <= b[2]; ++k) {
                const GridCell c{i, j, k};
                const uint64_t key = cell_key(c);
                for (int32_t e = added_head_[hashed(key, added_shift_)]; e >= 0; e = added_[e].next)
                    if (added_[e].key == key && visit(added_things_[added_[e].thing].item, c))
                        return true;
            }
    for (size_t l = added_large_.size(); l-- > 0;)
        if (once(added_things_[added_large_[l]].item, added_things_[added_large_[l]].span))
            return true;
    return false;
}

template <class Item>
template <class Visit>
bool SpatialGrid<Item>::any_built_in_cells(const GridCell &first, const GridCell &last, Visit &&visit) const
{
    if (spans_many_cells(first, last)) { // every thing, each once
        for (size_t e = 0; e < sorted_size_; ++e)
            if (first_entry_[owner_[e]] == e && cells_meet(first, last, spans_[owner_[e]]) && visit(sorted_[e]))
                return true;
        for (size_t l = 0; l < large_.size(); ++l)
            if (cells_meet(first, last, spans_[large_[l]]) && visit(large_item_[l]))
                return true;
        return false;
    }
    GridCell a = first, b = last;
    clamp(a, b, low_, high_);
    for (int64_t i = a[0]; i <= b[0]; ++i)
        for (int64_t j = a[1]; j <= b[1]; ++j) {
            const uint64_t column = column_start(i, j);
            // Dense: one run for the column; hashed: one per cell, its bucket's.
            for (int64_t k = a[2]; k <= b[2]; k = dense_ ? b[2] + 1 : k + 1) {
                const uint64_t end_k = static_cast<uint64_t>(dense_ ? b[2] : k);
                const size_t from = bucket_start_[(column + static_cast<uint64_t>(k)) & bucket_mask_];
                const size_t to = bucket_start_[((column + end_k) & bucket_mask_) + 1];
                const uint64_t key = cell_key({i, j, k});
                for (size_t e = from; e < to; ++e)
                    if ((dense_ || sorted_key_[e] == key) && visit(sorted_[e]))
                        return true;
            }
        }
    for (size_t l = 0; l < large_.size(); ++l)
        if (cells_meet(first, last, spans_[large_[l]]) && visit(large_item_[l]))
            return true;
    return false;
}

template <class Item>
template <class Visit>
void SpatialGrid<Item>::for_each_pair_in_bucket(size_t bucket, Visit &&visit) const
{
    if (dense_) { // one cell per bucket
        if (bucket_start_[bucket + 1] - bucket_start_[bucket] < 2)
            return;
        const uint64_t key = dense_key(bucket);
        for (size_t a = bucket_start_[bucket]; a < bucket_start_[bucket + 1]; ++a)
            for (size_t b = a + 1; b < bucket_start_[bucket + 1]; ++b)
                visit(sorted_[a], sorted_[b], key);
        return;
    }
    for (size_t a = bucket_start_[bucket]; a < bucket_start_[bucket + 1]; ++a)
        for (size_t b = a + 1; b < bucket_start_[bucket + 1]; ++b)
            if (sorted_key_[a] == sorted_key_[b])
                visit(sorted_[a], sorted_[b], sorted_key_[a]);
}

template <class Item>
template <class SameRun, class RunsMayPair, class Visit>
void SpatialGrid<Item>::for_each_pair_across_runs(size_t bucket, SameRun &&same_run, RunsMayPair &&runs_may_pair,
                                                  Visit &&visit) const
{
    const size_t begin = bucket_start_[bucket], end = bucket_start_[bucket + 1];
    if (end - begin < 2)
        return;
    const uint64_t key = dense_ ? dense_key(bucket) : 0;
    const auto end_of_run = [&](size_t first) {
        size_t e = first + 1;
        while (e < end && same_run(sorted_[first], sorted_[e]))
            ++e;
        return e;
    };
    for (size_t run = begin, run_end; run < end; run = run_end) {
        run_end = end_of_run(run);
        for (size_t other = run_end, other_end; other < end; other = other_end) {
            other_end = end_of_run(other);
            if (!runs_may_pair(sorted_[run], sorted_[other]))
                continue;
            for (size_t a = run; a < run_end; ++a)
                for (size_t b = other; b < other_end; ++b)
                    if (dense_)
                        visit(sorted_[a], sorted_[b], key);
                    else if (sorted_key_[a] == sorted_key_[b])
                        visit(sorted_[a], sorted_[b], sorted_key_[a]);
        }
    }
}

} // namespace sfa

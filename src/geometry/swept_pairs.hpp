// SPDX-License-Identifier: BSD-3-Clause
// The broad phase of collision-safe motion: every pair of triangles that may meet while
// their corners move in straight lines over a step. Two triangles that meet do so in every
// frame moving at a constant velocity, so a pair whose swept boxes are apart in any one
// such frame cannot meet. In the frame at rest a box is swept over the whole distance its
// triangle travels, which in the paper's flows is several edge lengths (Enright, dt =
// 0.015: about nine), so that each box overlaps the boxes of a long strip of the sheet. In
// a frame moving with the surface around it a box is swept only over what its triangle
// moves relative to its neighbours. So space is cut into blocks of a few edge lengths;
// each block's triangles are compared in the frame of their mean motion, with those of the
// blocks nearby that come within its reach in that frame. (Swept boxes at rest made the
// first 40 steps of collision-safe Enright 2.2 times as long as without them, boxes in
// each block's frame 1.5 times; unswept boxes, which would be unsafe, 1.35 times.)
#pragma once

#include "geometry/block_partition.hpp"
#include "geometry/box_pairs.hpp"
#include "mesh/fill_buffer.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace sfa {

// A triangle over a step: the box of its corners at the start, and the box of its
// corners' displacements over the step (each corner moves from x to x + d).
struct SweptTriangle {
    Box start, motion;
    Triangle corners; // two triangles that share one are neighbours, never compared
    double scale;     // the largest coordinate of the two boxes, for their rounding
};

// Triangle `corners`, whose corners at x move by d over the step.
inline SweptTriangle swept_triangle(const Triangle &corners, const Vec3 (&x)[3], const Vec3 (&d)[3])
{
    SweptTriangle s{{x[0], x[0]}, {d[0], d[0]}, corners, 0};
    for (int k = 1; k < 3; ++k) {
        s.start = {s.start[0].cwiseMin(x[k]), s.start[1].cwiseMax(x[k])};
        s.motion = {s.motion[0].cwiseMin(d[k]), s.motion[1].cwiseMax(d[k])};
    }
    s.scale = std::max({s.start[0].cwiseAbs().maxCoeff(), s.start[1].cwiseAbs().maxCoeff(),
                        s.motion[0].cwiseAbs().maxCoeff(), s.motion[1].cwiseAbs().maxCoeff()});
    return s;
}

// Triangle `corners` at rest at `pos`: for the broad phase's pairs of a surface that does
// not move (the crossing guard's faces_meeting, the self-intersection count).
inline SweptTriangle resting_triangle(const Triangle &corners, const std::vector<Vec3> &pos)
{
    const Vec3 x[3] = {pos[corners[0]], pos[corners[1]], pos[corners[2]]};
    const Vec3 still[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    return swept_triangle(corners, x, still);
}

// The box a triangle sweeps in the frame displaced by w over the step: its start box and
// its start box moved by its corners' displacements less w, widened by the rounding of
// the sums (a pair that touches within round-off must not fall between two boxes).
inline Box swept_in_frame(const SweptTriangle &t, const Vec3 &w)
{
    const Vec3 low = (t.motion[0] - w).cwiseMin(Vec3::Zero()), high = (t.motion[1] - w).cwiseMax(Vec3::Zero());
    const double rounding = 1e-14 * std::max(t.scale, w.cwiseAbs().maxCoeff());
    return {(t.start[0] + low).array() - rounding, (t.start[1] + high).array() + rounding};
}

namespace detail {

// Grows `into` to hold `box`, whose corners are numbers; `into` is none (NaN) until the
// first box.
inline void widen(Box &into, const Box &box)
{
    if (std::isnan(into[0][0])) {
        into = box;
        return;
    }
    into[0] = into[0].cwiseMin(box[0]);
    into[1] = into[1].cwiseMax(box[1]);
}

// The mean of the boxes' largest extents, of those without a NaN corner; 0 if none.
inline double mean_extent(const std::vector<Box> &boxes)
{
    double sum = 0;
    size_t count = 0;
    for (const Box &b : boxes)
        if (const double extent = (b[1] - b[0]).maxCoeff(); std::isfinite(extent)) {
            sum += extent;
            ++count;
        }
    return count ? sum / static_cast<double>(count) : 0;
}

// Distinct keys numbered from 0 in the order in which they are first asked for: a table
// hashed by key, kept at most half full.
class KeyNumbering {
public:
    int32_t count() const { return count_; }
    // The number of k, a new one if k is new.
    int32_t number_of(uint64_t k)
    {
        size_t at = slot_of(k);
        if (number_[at] >= 0)
            return number_[at];
        if (2 * (static_cast<size_t>(count_) + 1) > key_.size()) {
            std::vector<uint64_t> old_key(2 * key_.size());
            std::vector<int32_t> old_number(2 * key_.size(), -1);
            old_key.swap(key_);
            old_number.swap(number_);
            for (size_t j = 0; j < old_key.size(); ++j)
                if (old_number[j] >= 0) {
                    const size_t to = slot_of(old_key[j]);
                    key_[to] = old_key[j];
                    number_[to] = old_number[j];
                }
            at = slot_of(k);
        }
        key_[at] = k;
        return number_[at] = count_++;
    }

private:
    size_t slot_of(uint64_t k) const
    {
        const size_t mask = key_.size() - 1;
        size_t at = static_cast<size_t>((k * 0x9E3779B97F4A7C15u) >> 20) & mask; // Fibonacci hashing
        while (number_[at] >= 0 && key_[at] != k)
            at = (at + 1) & mask;
        return at;
    }

    std::vector<uint64_t> key_ = std::vector<uint64_t>(1024);
    std::vector<int32_t> number_ = std::vector<int32_t>(1024, -1); // -1: an empty slot
    int32_t count_ = 0;
};

// Numbers the distinct keys in the order in which they first come, and sets number[i] to
// that of key[i]; returns how many there are. The keys are cut into `runs` runs, numbered
// in parallel, each on its own; then each run's keys, in the order they first come in it,
// are numbered through one table, run after run, which is the order in which they first
// come in all, and each run's numbers are mapped to those. Consecutive equal keys are
// looked up once.
inline int32_t number_by_key(const std::vector<uint64_t> &key, std::vector<int32_t> &number, int runs)
{
    const size_t n = key.size();
    number.resize(n);
    runs = static_cast<int>(std::clamp<size_t>(n, 1, static_cast<size_t>(std::max(runs, 1))));
    const auto run_start = [&](int r) { return n * static_cast<size_t>(r) / static_cast<size_t>(runs); };
    std::vector<std::vector<uint64_t>> firsts(static_cast<size_t>(runs)); // each run's keys, as they first come
    LoopFailure failure;
#pragma omp parallel for num_threads(loop_threads()) schedule(static, 1)
    for (int r = 0; r < runs; ++r)
        failure.run([&] {
            KeyNumbering local;
            const size_t begin = run_start(r), end = run_start(r + 1);
            for (size_t i = begin; i < end; ++i) {
                if (i > begin && key[i] == key[i - 1]) {
                    number[i] = number[i - 1];
                    continue;
                }
                number[i] = local.number_of(key[i]);
                if (number[i] == static_cast<int32_t>(firsts[r].size()))
                    firsts[r].push_back(key[i]);
            }
        });
    failure.rethrow();
    KeyNumbering all;
    std::vector<std::vector<int32_t>> in_all(static_cast<size_t>(runs));
    for (int r = 0; r < runs; ++r)
        for (uint64_t k : firsts[r])
            in_all[r].push_back(all.number_of(k));
#pragma omp parallel for num_threads(loop_threads()) schedule(static, 1)
    for (int r = 1; r < runs; ++r) // the first run's numbers are already those of all
        for (size_t i = run_start(r), end = run_start(r + 1); i < end; ++i)
            number[i] = in_all[r][static_cast<size_t>(number[i])];
    return all.count();
}

// Sorts (key, index) pairs, entered in increasing order of index, by key and then index,
// as std::sort would; the keys must be finite. They are dealt into as many buckets as there
// are keys, by value (a monotonic function of the key, so that each bucket's keys precede
// the next one's), then insertion-sorted, which moves each key within its bucket only. A
// comparison sort mispredicts about half of its branches (on bench_collision's sphere,
// std::sort made a quarter of the search's mispredictions, and the search takes about 4 %
// less time without it). Keys that crowd into a few buckets (more than max_bucket in one)
// are left to std::sort instead, so that the cost stays O(n log n).
inline void sort_spread_keys(std::vector<std::pair<double, int32_t>> &items,
                             std::vector<std::pair<double, int32_t>> &scratch, std::vector<size_t> &bucket_start)
{
    constexpr size_t max_bucket = 32;
    const size_t n = items.size();
    if (n < 2)
        return;
    double least = items[0].first, largest = least;
    for (const auto &item : items) {
        least = std::min(least, item.first);
        largest = std::max(largest, item.first);
    }
    // Buckets per unit of key; none where the keys are all one, or their range or its
    // reciprocal overflows.
    const double range = largest - least, scale = static_cast<double>(n) / range;
    if (!(range > 0 && std::isfinite(range) && std::isfinite(scale))) {
        std::sort(items.begin(), items.end());
        return;
    }
    const auto bucket_of = [&](double key) { return std::min(n - 1, static_cast<size_t>((key - least) * scale)); };
    bucket_start.assign(n + 1, 0);
    for (const auto &item : items)
        ++bucket_start[bucket_of(item.first) + 1];
    size_t crowd = 0;
    for (size_t b = 0; b < n; ++b) {
        crowd = std::max(crowd, bucket_start[b + 1]);
        bucket_start[b + 1] += bucket_start[b];
    }
    if (crowd > max_bucket) {
        std::sort(items.begin(), items.end());
        return;
    }
    scratch.resize(n);
    for (const auto &item : items)
        scratch[bucket_start[bucket_of(item.first)]++] = item; // stable: ties stay in order of index
    for (size_t i = 1; i < n; ++i) {
        const std::pair<double, int32_t> item = scratch[i];
        size_t j = i;
        for (; j > 0 && item.first < scratch[j - 1].first; --j)
            scratch[j] = scratch[j - 1];
        scratch[j] = item;
    }
    items.swap(scratch);
}

// The float nearest to x, the largest one beyond their range. Non-decreasing in x, as
// the difference x - o is for any o: two boxes that overlap in doubles overlap in floats.
inline float nearest_float(double x)
{
    constexpr double largest = std::numeric_limits<float>::max();
    return static_cast<float>(std::clamp(x, -largest, largest));
}

} // namespace detail

// Blocks are this many times the mean size of a triangle's box: small enough that the
// surface in one moves nearly as one, large enough that few of its triangles lie near its
// faces (those are compared again, as guests of the neighbouring block). 8, 12 and 16 took
// the same time on Enright and vortex T = 2 (and 8 and 12 on bench_collision's sphere,
// 6 and 16 longer); 4 took 10 % longer.
constexpr double swept_pairs_block_size = 12;

namespace detail {

// Deals the triangles into blocks of swept_pairs_block_size times `edge` (a triangle's
// size), from the lowest corner of triangle first_finite's start box.
template <class Allocator>
BlockPartition deal_into_blocks(const std::vector<SweptTriangle, Allocator> &triangles, double edge,
                                int32_t first_finite)
{
    const int32_t n = static_cast<int32_t>(triangles.size());
    BlockPartition made;
    // Each triangle's block is that of its start box's lowest corner; the blocks numbered
    // in the order in which triangles first fall in them (neighbours in the mesh's order
    // are often in one block), and the triangles counting-sorted by block: less than half
    // the time of sorting them by key on bench_collision's sphere. Each block is cut into
    // eight octants, its parts, each a run of triangles in increasing order, so that a
    // neighbouring block gives its guests from the parts that can reach it alone.
    // A corner's half block comes from a product with the inverse size rather than
    // CellFrame::cell_of's division: any rule that gives each triangle one block will do.
    const Vec3 blocks_origin = triangles[first_finite].start[0];
    const double halves_per_length = 2 / (swept_pairs_block_size * edge);
    std::vector<uint64_t> key(static_cast<size_t>(n));
    std::vector<uint8_t> octant(static_cast<size_t>(n));
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t t = 0; t < n; ++t) {
        const Vec3 at = (triangles[t].start[0] - blocks_origin) * halves_per_length;
        GridCell half = {CellFrame::cell_number(at[0]), CellFrame::cell_number(at[1]), CellFrame::cell_number(at[2])},
                 block;
        octant[t] = static_cast<uint8_t>((half[0] & 1) | (half[1] & 1) << 1 | (half[2] & 1) << 2);
        for (int a = 0; a < 3; ++a)
            block[a] = half[a] >= 0 ? half[a] / 2 : -((1 - half[a]) / 2); // rounded down
        key[t] = cell_key(block);
    }
    std::vector<int32_t> block_of;
    made.blocks = detail::number_by_key(key, block_of, loop_threads());
    // Part p of block b is number 8 b + p; its triangles are order[part_start[8 b + p]] on.
    sort_into_parts(
        n, 8 * static_cast<size_t>(made.blocks),
        [&](int32_t t) { return 8 * static_cast<size_t>(block_of[t]) + octant[t]; }, loop_threads(),
        made.part_start, made.order);
    made.triangles = n;
    return made;
}

} // namespace detail

// Calls visit(s, t, thread), s < t, once for every two triangles that share no corner and
// whose swept boxes overlap in the frame of the block one of them lies in (so at least for
// every two that share no corner and can meet over the step), from parallel loops;
// `thread` is the calling thread's index for visit's own scratch. With `kept`, the blocks
// are those it holds if it deals as many triangles and has served fewer than
// block_partition_searches searches; otherwise they are made and it holds them.
template <class Allocator, class Visit>
void for_each_pair_that_may_meet(const std::vector<SweptTriangle, Allocator> &triangles, Visit &&visit,
                                 BlockPartition *kept = nullptr)
{
    using detail::nearest_float, detail::widen;
    const int32_t n = static_cast<int32_t>(triangles.size());
    if (n < 2)
        return;
    // The size of a triangle, or where every one is a point, of the way it moves: the mean
    // extent of the start boxes of an evenly spread sample of at least 4096 of them, which
    // sets the blocks' size alone (reading every triangle for it took a twentieth of the
    // search on collision-safe Enright, on one thread while the others waited).
    const int32_t stride = std::max(1, n / 4096);
    double edge = 0;
    size_t sized = 0;
    for (int32_t t = 0; t < n; t += stride)
        if (const double extent = (triangles[t].start[1] - triangles[t].start[0]).maxCoeff(); std::isfinite(extent)) {
            edge += extent;
            ++sized;
        }
    edge = sized ? edge / static_cast<double>(sized) : 0;
    if (!(edge > 0)) {
        std::vector<Box> at_rest_each(static_cast<size_t>(n));
        for (int32_t t = 0; t < n; ++t)
            at_rest_each[t] = swept_in_frame(triangles[t], Vec3::Zero());
        edge = detail::mean_extent(at_rest_each);
    }
    // The blocks' origin: any point will do, and the first triangle's corner with numbers
    // is near the others. A triangle without numbers in its boxes overlaps nothing.
    int32_t first_finite = 0;
    while (first_finite < n && !triangles[first_finite].start[0].allFinite())
        ++first_finite;
    if (!(edge > 0) || first_finite == n)
        return; // every triangle a point at rest, or every one NaN: none comes to meet another
    BlockPartition made;
    if (!(kept && kept->triangles == n && kept->searches < block_partition_searches)) {
        made = detail::deal_into_blocks(triangles, edge, first_finite);
        if (kept)
            *kept = std::move(made);
    }
    const BlockPartition &partition = kept ? *kept : made;
    if (kept)
        ++kept->searches;
    const int32_t blocks = partition.blocks;
    const std::vector<int32_t> &part_start = partition.part_start, &order = partition.order;
    const auto block_start = [&](int32_t b) { return part_start[8 * static_cast<size_t>(b)]; };

    // Each block's frame (its triangles' mean displacement); for each of its parts what
    // bounds its triangles' boxes in any frame: a swept triangle whose boxes are the unions
    // of theirs and whose scale is the largest (its corners unused; each of the triangles'
    // boxes swept in a frame lies in its box swept in that frame: swept_in_frame's sums,
    // each term no larger, the rounding no smaller); and, from these, the block's reach (a
    // box holding its triangles' boxes swept in its frame) and its box at rest, which finds
    // the blocks near it. (Each triangle's own boxes, swept twice more for these, took 1.2
    // G of collision-safe vortex T = 2's 78.7 G instructions; the parts' bounds are nearly
    // as tight: as many guests.)
    std::vector<Vec3> frame(static_cast<size_t>(blocks));
    std::vector<Box> reach(static_cast<size_t>(blocks)), at_rest(static_cast<size_t>(blocks));
    std::vector<SweptTriangle> around(8 * static_cast<size_t>(blocks));
    const Vec3 none = Vec3::Constant(std::numeric_limits<double>::quiet_NaN()); // a union adds nothing to it
#pragma omp parallel for num_threads(loop_threads()) schedule(static) if (blocks > 1)
    for (int32_t b = 0; b < blocks; ++b) {
        Vec3 sum = Vec3::Zero();
        for (int32_t i = block_start(b); i < block_start(b + 1); ++i)
            sum += (triangles[order[i]].motion[0] + triangles[order[i]].motion[1]) / 2;
        frame[b] = sum / (block_start(b + 1) - block_start(b));
        if (!frame[b].allFinite())
            frame[b] = Vec3::Zero();
        reach[b] = at_rest[b] = {none, none};
        for (size_t p = 8 * static_cast<size_t>(b); p < 8 * static_cast<size_t>(b) + 8; ++p) {
            around[p] = {{none, none}, {none, none}, {}, 0};
            for (int32_t i = part_start[p]; i < part_start[p + 1]; ++i) {
                const SweptTriangle &t = triangles[order[i]];
                // A triangle with a corner or a motion that is not a number overlaps
                // nothing and adds nothing (box_union's rule, tested once a triangle).
                if (!(t.start[0].allFinite() && t.start[1].allFinite() && t.motion[0].allFinite() &&
                      t.motion[1].allFinite()))
                    continue;
                widen(around[p].start, t.start);
                widen(around[p].motion, t.motion);
                around[p].scale = std::max(around[p].scale, t.scale);
            }
            if (std::isnan(around[p].start[0][0]))
                continue; // no triangle with numbers
            widen(reach[b], swept_in_frame(around[p], frame[b]));
            widen(at_rest[b], swept_in_frame(around[p], Vec3::Zero()));
        }
    }
    // Two triangles that can meet have overlapping boxes at rest, so their blocks have too.
    // A pair of different blocks is compared in the frame of the first (`after`: the
    // blocks after each one whose boxes at rest overlap its own).
    std::vector<std::pair<int32_t, int32_t>> near;
    if (blocks > 1) {
        std::vector<std::vector<std::pair<int32_t, int32_t>>> found(static_cast<size_t>(loop_threads()));
        LoopFailure failure;
        for_each_overlapping_pair(at_rest, detail::mean_extent(at_rest), [&](int32_t a, int32_t b) {
            failure.run([&] { found[static_cast<size_t>(thread_index())].push_back({a, b}); });
        });
        failure.rethrow();
        for (const auto &list : found)
            near.insert(near.end(), list.begin(), list.end());
        std::sort(near.begin(), near.end());
    }
    std::vector<size_t> after_start(static_cast<size_t>(blocks) + 1, 0);
    for (const auto &p : near)
        ++after_start[static_cast<size_t>(p.first) + 1];
    for (int32_t b = 0; b < blocks; ++b)
        after_start[b + 1] += after_start[b];

    // Block b's pairs, in its frame: its own triangles with each other and with the guests,
    // those of the blocks after it whose boxes swept in its frame reach into its own (two
    // guests are not its pair). A block holds a few hundred boxes, nearly all of them about
    // a triangle's size in its frame. They are cut into strips across the axis on which
    // their low corners spread second most, each box in every strip it covers, and in
    // each strip sorted along the axis of most spread; each box is compared with those
    // that follow it in its strip until one starts beyond its end (sweep and prune), and
    // a pair counts in the first strip both cover. Without the strips a box would be
    // compared with every box of a slab across the block, about forty on a sheet. (A grid
    // per block, which this replaced, made bench_collision's sphere 1.5 times as long.)
    struct Entry {
        Box box;
        int32_t triangle;
        bool own;         // block b's, not a guest
        Triangle corners; // the triangle's, read with its boxes
        int first_strip, last_strip;
    };
    // A box in the sweep, in floats relative to the lowest corner of the block's boxes
    // (nearest_float: boxes that overlap still do, and a few more may), which halves the
    // bytes a comparison reads and lets one four-lane comparison test both axes across the
    // sweep. The corners are four lanes too (the last twice), so that whether two
    // triangles share one is three lane-wise comparisons rather than nine (GCC's and
    // Clang's vector extension).
    using Lanes = int32_t __attribute__((vector_size(16)));
    using FloatLanes = float __attribute__((vector_size(16)));
    using HalfLanes = int64_t __attribute__((vector_size(16)));
    struct Row {
        FloatLanes across;   // low, low, -high, -high on the strip axis and the third
        float low, high;     // on the sweep axis
        int32_t flags;       // own_row: the block's triangle, not a guest; first_row: the first strip it covers
        Lanes corners;
    };
    constexpr int32_t own_row = 1, first_row = 2;
    struct Sweep {
        std::vector<std::pair<double, int32_t>> by_low, sorting; // (low on the sweep axis, entry)
        std::vector<size_t> bucket_start;
        std::vector<int32_t> strip_start, strip_fill;
        FillBuffer<Row> rows;          // strip by strip, each in order of low on the sweep axis
        std::vector<int32_t> triangle; // of each row
    };
    const auto compare_block = [&](int32_t b, std::vector<Entry> &entries, Sweep &sweep, int thread) {
        // The entries, with what the choice of axes needs summed as they come; a box with a
        // NaN corner overlaps nothing and is left out.
        entries.clear();
        Vec3 sum = Vec3::Zero(), square = Vec3::Zero(), extent = Vec3::Zero();
        Box bounds = {none, none};
        const auto enter = [&](const Box &box, int32_t t, bool own) {
            if (!(box[0].allFinite() && box[1].allFinite()))
                return;
            sum += box[0];
            square += box[0].cwiseAbs2();
            extent += box[1] - box[0];
            detail::widen(bounds, box);
            entries.push_back({box, t, own, triangles[t].corners, 0, 0});
        };
        for (int32_t i = block_start(b); i < block_start(b + 1); ++i)
            enter(swept_in_frame(triangles[order[i]], frame[b]), order[i], true);
        for (size_t p = after_start[b]; p < after_start[b + 1]; ++p) {
            const int32_t other = near[p].second;
            for (size_t q = 8 * static_cast<size_t>(other); q < 8 * static_cast<size_t>(other) + 8; ++q) {
                // Each of the part's boxes in this frame lies in this one (swept_in_frame's
                // sums, each term no larger; the rounding no smaller): most parts of a block
                // near at rest are not near in this frame.
                if (part_start[q] == part_start[q + 1] || !boxes_overlap(swept_in_frame(around[q], frame[b]), reach[b]))
                    continue;
                for (int32_t i = part_start[q]; i < part_start[q + 1]; ++i)
                    if (const Box box = swept_in_frame(triangles[order[i]], frame[b]); boxes_overlap(box, reach[b]))
                        enter(box, order[i], false);
            }
        }
        const double count = static_cast<double>(entries.size());
        if (count < 2)
            return;
        const Vec3 spread = square / count - (sum / count).cwiseAbs2();
        int axis[3];
        spread.maxCoeff(&axis[0]);
        axis[1] = (axis[0] + 1) % 3;
        axis[2] = (axis[0] + 2) % 3;
        if (spread[axis[2]] > spread[axis[1]])
            std::swap(axis[1], axis[2]);
        // Strips two boxes wide, at most max_strips (so that a box is entered that many times
        // at most). A box's strips are found once, by a product with their number per unit
        // of length (the divisions were 7 % of this search on vortex T = 2); where the range
        // or that number overflows, one strip.
        constexpr int max_strips = 16;
        const double low = bounds[0][axis[1]], range = bounds[1][axis[1]] - low;
        const double wanted = 2 * extent[axis[1]] / count;
        int strips = wanted > 0 ? static_cast<int>(std::clamp(std::ceil(range / wanted), 1.0, double{max_strips})) : 1;
        const double per_length = strips / range;
        if (!(std::isfinite(range) && std::isfinite(per_length)))
            strips = 1;
        const auto strip_of = [&](double x) { // monotonic in x
            return strips == 1 ? 0 : std::min(strips - 1, static_cast<int>((x - low) * per_length));
        };
        sweep.strip_start.assign(static_cast<size_t>(strips) + 1, 0);
        sweep.by_low.resize(entries.size());
        for (size_t e = 0; e < entries.size(); ++e) {
            Entry &entry = entries[e];
            entry.first_strip = strip_of(entry.box[0][axis[1]]);
            entry.last_strip = strip_of(entry.box[1][axis[1]]);
            for (int s = entry.first_strip; s <= entry.last_strip; ++s)
                ++sweep.strip_start[static_cast<size_t>(s) + 1];
            sweep.by_low[e] = {entry.box[0][axis[0]], static_cast<int32_t>(e)};
        }
        // Sorted once along the sweep axis, then dealt into the strips in that order.
        detail::sort_spread_keys(sweep.by_low, sweep.sorting, sweep.bucket_start);
        for (int s = 0; s < strips; ++s)
            sweep.strip_start[s + 1] += sweep.strip_start[s];
        sweep.strip_fill.assign(sweep.strip_start.begin(), sweep.strip_start.end() - 1);
        sweep.rows.resize(static_cast<size_t>(sweep.strip_start[strips]));
        sweep.triangle.resize(sweep.rows.size());
        const Vec3 origin = bounds[0];
        for (const auto &o : sweep.by_low) {
            const Entry &e = entries[static_cast<size_t>(o.second)];
            const Vec3 from = e.box[0] - origin, to = e.box[1] - origin;
            Row row{{nearest_float(from[axis[1]]), nearest_float(from[axis[2]]), -nearest_float(to[axis[1]]),
                     -nearest_float(to[axis[2]])},
                    nearest_float(from[axis[0]]), nearest_float(to[axis[0]]), 0,
                    Lanes{e.corners[0], e.corners[1], e.corners[2], e.corners[2]}};
            for (int s = e.first_strip; s <= e.last_strip; ++s) {
                const int32_t at = sweep.strip_fill[s]++;
                row.flags = (e.own ? own_row : 0) | (s == e.first_strip ? first_row : 0);
                sweep.rows[at] = row;
                sweep.triangle[at] = e.triangle;
            }
        }
        for (int s = 0; s < strips; ++s)
            for (int32_t i = sweep.strip_start[s], end = sweep.strip_start[s + 1]; i < end; ++i) {
                const Row a = sweep.rows[i];
                // c's box meets a's across the sweep when c.across <= limit, lane by lane.
                const FloatLanes limit = {-a.across[2], -a.across[3], -a.across[0], -a.across[1]};
                const Lanes a0 = Lanes{} + a.corners[0], a1 = Lanes{} + a.corners[1], a2 = Lanes{} + a.corners[2];
                for (int32_t j = i + 1; j < end && sweep.rows[j].low <= a.high; ++j) {
                    const Row &c = sweep.rows[j];
                    // One branch, nearly always not taken: & rather than &&, and the empty
                    // asm makes the compiler compute the whole condition before it branches
                    // (it split off a branch on the boxes, taken about half the time, and
                    // bench_collision's sphere took 5 to 8 % longer). Most pairs whose boxes
                    // overlap are neighbours in the mesh, sharing a corner. A pair counts
                    // in the first strip both cover, and not if both are guests.
                    const HalfLanes apart = reinterpret_cast<HalfLanes>(
                        (c.across > limit) | (c.corners == a0) | (c.corners == a1) | (c.corners == a2));
                    int pass = ((apart[0] | apart[1]) == 0) & ((a.flags | c.flags) == (own_row | first_row));
                    asm("" : "+r"(pass));
                    if (pass)
                        visit(std::min(sweep.triangle[i], sweep.triangle[j]),
                              std::max(sweep.triangle[i], sweep.triangle[j]), thread);
                }
            }
    };
    // A block's scratch grows with its boxes, and visit may allocate too.
    std::vector<Entry> entries;
    Sweep sweep;
    LoopFailure failure;
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 1) firstprivate(entries, sweep)
    for (int32_t b = 0; b < blocks; ++b)
        failure.run([&] { compare_block(b, entries, sweep, thread_index()); });
    failure.rethrow();
}

} // namespace sfa

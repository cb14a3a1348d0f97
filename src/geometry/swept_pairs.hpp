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

#include "geometry/box_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace sfa {

// A triangle over a step: the box of its corners at the start, and the box of its
// corners' displacements over the step (each corner moves from x to x + d).
struct SweptTriangle {
    Box start, motion;
};

// The box a triangle sweeps in the frame displaced by w over the step: its start box and
// its start box moved by its corners' displacements less w, widened by the rounding of
// the sums (a pair that touches within round-off must not fall between two boxes).
inline Box swept_in_frame(const SweptTriangle &t, const Vec3 &w)
{
    const Vec3 low = (t.motion[0] - w).cwiseMin(Vec3::Zero()), high = (t.motion[1] - w).cwiseMax(Vec3::Zero());
    const double rounding = 1e-14 * std::max({t.start[0].cwiseAbs().maxCoeff(), t.start[1].cwiseAbs().maxCoeff(),
                                              t.motion[0].cwiseAbs().maxCoeff(), t.motion[1].cwiseAbs().maxCoeff(),
                                              w.cwiseAbs().maxCoeff()});
    return {(t.start[0] + low).array() - rounding, (t.start[1] + high).array() + rounding};
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

} // namespace detail

// Blocks are this many times the mean size of a triangle's box: small enough that the
// surface in one moves nearly as one, large enough that few of its triangles lie near its
// faces (those are compared again, as guests of the neighbouring block). 8, 12 and 16 took
// the same time on Enright and vortex T = 2; 4 took 10 % longer.
constexpr double swept_pairs_block_size = 12;

// Calls visit(s, t, thread), s < t, once for every two triangles whose swept boxes overlap
// in the frame of the block one of them lies in (so at least for every two that can meet
// over the step), from parallel loops; `thread` is the calling thread's index for
// visit's own scratch.
template <class Visit>
void for_each_pair_that_may_meet(const std::vector<SweptTriangle> &triangles, Visit &&visit)
{
    using detail::box_union;
    const int32_t n = static_cast<int32_t>(triangles.size());
    if (n < 2)
        return;
    std::vector<Box> start(static_cast<size_t>(n)), at_rest_each(static_cast<size_t>(n));
    for (int32_t t = 0; t < n; ++t) {
        start[t] = triangles[t].start;
        at_rest_each[t] = swept_in_frame(triangles[t], Vec3::Zero());
    }
    // The size of a triangle, or where every one is a point, of the way it moves.
    double edge = detail::mean_extent(start);
    if (!(edge > 0))
        edge = detail::mean_extent(at_rest_each);
    Vec3 lowest = Vec3::Constant(std::numeric_limits<double>::infinity());
    for (const Box &b : start)
        lowest = lowest.cwiseMin(b[0]); // a NaN corner leaves it as it was
    if (!(edge > 0) || !lowest.allFinite())
        return; // every triangle a point at rest, or every one NaN: none comes to meet another
    // Each triangle's block is that of its start box's lowest corner; the blocks in the
    // order of their keys, each block's triangles in increasing order.
    const CellFrame blocks_frame{lowest, swept_pairs_block_size * edge};
    std::vector<std::pair<uint64_t, int32_t>> keyed(static_cast<size_t>(n));
    for (int32_t t = 0; t < n; ++t)
        keyed[t] = {cell_key(blocks_frame.cell_of(start[t][0])), t};
    std::sort(keyed.begin(), keyed.end());
    std::vector<int32_t> order(static_cast<size_t>(n)), block_start = {0};
    for (int32_t i = 0; i < n; ++i) {
        order[i] = keyed[i].second;
        if (i > 0 && keyed[i].first != keyed[i - 1].first)
            block_start.push_back(i);
    }
    block_start.push_back(n);
    const int32_t blocks = static_cast<int32_t>(block_start.size()) - 1;

    // Each block's frame (its triangles' mean displacement), the union of its triangles'
    // boxes swept in it, and the union swept at rest, which finds the blocks near it.
    std::vector<Vec3> frame(static_cast<size_t>(blocks));
    std::vector<Box> reach(static_cast<size_t>(blocks)), at_rest(static_cast<size_t>(blocks));
#pragma omp parallel for num_threads(loop_threads()) schedule(static) if (blocks > 1)
    for (int32_t b = 0; b < blocks; ++b) {
        Vec3 sum = Vec3::Zero();
        for (int32_t i = block_start[b]; i < block_start[b + 1]; ++i)
            sum += (triangles[order[i]].motion[0] + triangles[order[i]].motion[1]) / 2;
        frame[b] = sum / (block_start[b + 1] - block_start[b]);
        if (!frame[b].allFinite())
            frame[b] = Vec3::Zero();
        reach[b] = swept_in_frame(triangles[order[block_start[b]]], frame[b]);
        at_rest[b] = at_rest_each[order[block_start[b]]];
        for (int32_t i = block_start[b] + 1; i < block_start[b + 1]; ++i) {
            reach[b] = box_union(reach[b], swept_in_frame(triangles[order[i]], frame[b]));
            at_rest[b] = box_union(at_rest[b], at_rest_each[order[i]]);
        }
    }
    // Two triangles that can meet have overlapping boxes at rest, so their blocks have too.
    // A pair of different blocks is compared in the frame of the first (`after`: the
    // blocks after each one whose boxes at rest overlap its own).
    std::vector<std::pair<int32_t, int32_t>> near;
    if (blocks > 1) {
        std::vector<std::vector<std::pair<int32_t, int32_t>>> found(static_cast<size_t>(loop_threads()));
        for_each_overlapping_pair(at_rest, detail::mean_extent(at_rest), [&](int32_t a, int32_t b) {
            found[static_cast<size_t>(thread_index())].push_back({a, b});
        });
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
    // guests are not its pair). On `threads` threads; visit is told `thread` if that is 1.
    const auto compare_block = [&](int32_t b, std::vector<Box> &boxes, std::vector<int32_t> &index, int threads,
                                   int thread) {
        boxes.clear();
        index.clear();
        for (int32_t i = block_start[b]; i < block_start[b + 1]; ++i) {
            boxes.push_back(swept_in_frame(triangles[order[i]], frame[b]));
            index.push_back(order[i]);
        }
        const size_t own = boxes.size();
        for (size_t p = after_start[b]; p < after_start[b + 1]; ++p) {
            const int32_t other = near[p].second;
            for (int32_t i = block_start[other]; i < block_start[other + 1]; ++i)
                if (const Box box = swept_in_frame(triangles[order[i]], frame[b]); boxes_overlap(box, reach[b])) {
                    boxes.push_back(box);
                    index.push_back(order[i]);
                }
        }
        const double cell = detail::mean_extent(boxes);
        for_each_overlapping_pair(
            boxes, cell > 0 ? cell : edge,
            [&](int32_t i, int32_t j) {
                if (static_cast<size_t>(i) < own)
                    visit(std::min(index[i], index[j]), std::max(index[i], index[j]),
                          threads > 1 ? thread_index() : thread);
            },
            threads);
    };
    std::vector<Box> boxes;
    std::vector<int32_t> index;
    if (blocks == 1) { // a small surface: the threads share its one block
        compare_block(0, boxes, index, loop_threads(), 0);
        return;
    }
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 1) firstprivate(boxes, index)
    for (int32_t b = 0; b < blocks; ++b)
        compare_block(b, boxes, index, 1, thread_index()); // nested loops would number threads from 0
}

} // namespace sfa

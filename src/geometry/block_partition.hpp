// SPDX-License-Identifier: BSD-3-Clause
// What the broad phase of collision-safe motion (swept_pairs.hpp) may keep between searches.
#pragma once

#include <cstdint>
#include <vector>

namespace sfa {

// The triangles dealt into blocks, and each block into its eight parts, by the place of
// their start boxes: kept by a caller whose triangles stay the same from one search to the
// next (collision-safe motion between two adaptations), the next searches take it as it is
// instead of dealing the triangles anew. Any dealing finds every pair that may meet, for
// each block's frame, reach and boxes come from its triangles as they are at the search; one
// made a few steps before only compares a little more (on the Enright run's meshes at
// t = 0.75 and 1.5, reused over three steps, the search took 0.85 to 0.95 times as long:
// the keys, their numbering and the counting sort are a seventh of it).
struct BlockPartition {
    int32_t triangles = 0; // how many it deals (0: none made yet, or dropped)
    int32_t searches = 0;  // how many searches have used it
    int32_t blocks = 0;
    std::vector<int32_t> part_start, order; // part p of block b: order[part_start[8 b + p]] on
};

// A kept BlockPartition serves at most this many searches, so that one kept while the
// surface moves without being adapted is made again before it drifts far from its places.
constexpr int32_t block_partition_searches = 4;

} // namespace sfa

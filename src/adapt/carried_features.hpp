// The features of the surface as sfa_adapt found them, carried through its splits and
// contractions (which renumber half-edges and vertices) rather than detected again after
// every step: within one call a feature stays a feature. Otherwise refining a crease that
// is just sharp enough (a coarse model's) halves its dihedral angles, and the next analysis
// would lose it (spot lost 18 of its 30 corners that way). The next call detects afresh,
// so that features of a moving surface can still appear and vanish.
#pragma once

#include "geometry/features.hpp"

#include <array>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace sfa {

// Ridge edges as vertex pairs.
class RidgeSet {
public:
    explicit RidgeSet(const std::vector<std::array<int32_t, 2>> &edges);
    bool contains(int32_t a, int32_t b) const { return keys_.count(key(a, b)) != 0; }
    void add(int32_t a, int32_t b) { keys_.insert(key(a, b)); }
    void remove(int32_t a, int32_t b) { keys_.erase(key(a, b)); }
    // Every pair, smaller vertex first.
    std::vector<std::array<int32_t, 2>> edges() const;

private:
    static uint64_t key(int32_t a, int32_t b)
    {
        const uint32_t lo = static_cast<uint32_t>(a < b ? a : b), hi = static_cast<uint32_t>(a < b ? b : a);
        return uint64_t(lo) << 32 | hi;
    }
    std::unordered_set<uint64_t> keys_;
};

struct CarriedFeatures {
    explicit CarriedFeatures(const Features &detected);

    std::vector<int8_t> rank; // per vertex
    RidgeSet ridges;

    // The position of v's ridge neighbour other than `not_this`, or nullptr if v is not a
    // ridge vertex (rank 1: exactly two ridge neighbours) or has none.
    const Vec3 *next_along(const TriMesh &mesh, int32_t v, int32_t not_this) const;

    // After compaction: vertex v is vertex_map[v] now, or gone if that is -1.
    void renumber(const std::vector<int32_t> &vertex_map);

    // As the analysis presents features (ranks, ridge half-edge flags, sorted ridge edges).
    Features as_features(const TriMesh &mesh) const;
};

} // namespace sfa

// The ridge edges of a mesh whose connectivity is changing (splits, contractions), as
// vertex pairs: half-edge flags would have to follow every renumbered half-edge.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <array>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace sfa {

class RidgeSet {
public:
    explicit RidgeSet(const std::vector<std::array<int32_t, 2>> &edges)
    {
        for (const auto &e : edges)
            add(e[0], e[1]);
    }
    bool contains(int32_t a, int32_t b) const { return keys_.count(key(a, b)) != 0; }
    void add(int32_t a, int32_t b) { keys_.insert(key(a, b)); }
    void remove(int32_t a, int32_t b) { keys_.erase(key(a, b)); }

    // The position of v's ridge neighbour other than `not_this`, or nullptr if v is not a
    // ridge vertex (rank 1: exactly two ridge neighbours) or has none.
    const Vec3 *next_along(const TriMesh &mesh, const std::vector<int8_t> &rank, int32_t v, int32_t not_this) const
    {
        if (rank[v] != 1)
            return nullptr;
        const Vec3 *found = nullptr;
        mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
            if (w != not_this && contains(v, w))
                found = &mesh.pos[w];
        });
        return found;
    }

private:
    static uint64_t key(int32_t a, int32_t b)
    {
        const uint32_t lo = static_cast<uint32_t>(a < b ? a : b), hi = static_cast<uint32_t>(a < b ? b : a);
        return uint64_t(lo) << 32 | hi;
    }
    std::unordered_set<uint64_t> keys_;
};

} // namespace sfa

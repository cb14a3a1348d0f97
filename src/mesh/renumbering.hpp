// SPDX-License-Identifier: BSD-3-Clause
// A renumbering of a mesh's vertices and triangles (compaction, the locality order), as
// the data living on its elements must follow it.
#pragma once

#include "mesh/parallel.hpp"

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace sfa {

struct Renumbering {
    std::vector<int32_t> vertex_map;   // old vertex -> new number, or -1 if it is gone
    std::vector<int32_t> triangle_map; // old triangle -> new number, or -1 if it is gone
    // True if the survivors keep their order (compaction): new numbers never exceed old ones,
    // so per-element arrays can be renumbered in place, front to back.
    bool keeps_order = false;

    // Corners keep their order within each triangle, so half-edge 3 t + i goes to
    // 3 triangle_map[t] + i.
    int32_t new_halfedge(int32_t h) const { return h < 0 ? -1 : 3 * triangle_map[h / 3] + h % 3; }

    // Moves every element's entry of `values` (one per old element) to its new number; gone
    // elements' entries are dropped. `per_element` entries per element (3 for half-edges).
    // In parallel: each element writes its own entries.
    template <class T>
    void apply(std::vector<T> &values, const std::vector<int32_t> &map, size_t per_element = 1) const
    {
        static_assert(!std::is_same_v<T, bool>, "std::vector<bool> packs its entries: no parallel writes");
        const int64_t elements = static_cast<int64_t>(map.size());
        int64_t count = 0;
#pragma omp parallel for num_threads(loop_threads()) schedule(static) reduction(+ : count)
        for (int64_t old = 0; old < elements; ++old)
            count += map[old] >= 0;
        std::vector<T> out(per_element * static_cast<size_t>(count));
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int64_t old = 0; old < elements; ++old)
            if (map[old] >= 0)
                for (size_t k = 0; k < per_element; ++k)
                    out[per_element * static_cast<size_t>(map[old]) + k] = values[per_element * old + k];
        values.swap(out);
    }
    template <class T>
    void apply_to_vertices(std::vector<T> &values, size_t per_vertex = 1) const
    {
        apply(values, vertex_map, per_vertex);
    }
    // Per half-edge: three entries per triangle.
    template <class T>
    void apply_to_halfedges(std::vector<T> &values) const
    {
        apply(values, triangle_map, 3);
    }
};

} // namespace sfa

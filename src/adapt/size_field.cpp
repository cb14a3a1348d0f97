// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/size_field.hpp"

#include <functional>
#include <queue>
#include <utility>

namespace sfa {

std::vector<double> graded_sizes(const TriMesh &mesh, std::vector<double> size, double gradation)
{
    const double slope = gradation - 1;
    using Entry = std::pair<double, int32_t>; // (size, vertex): the smallest first
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        queue.push({size[v], v});
    std::vector<char> settled(size.size(), 0);
    // Each vertex is settled once, when its entry is the smallest left; an entry is pushed
    // only when a size is lowered, at most once per edge direction: the loop is bounded by
    // the number of vertices plus twice the number of edges.
    while (!queue.empty()) {
        const double l = queue.top().first; // not a structured binding: a lambda captures these
        const int32_t v = queue.top().second;
        queue.pop();
        if (settled[v] || l > size[v])
            continue;
        settled[v] = 1;
        mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
            const double reach = l + slope * (mesh.pos[w] - mesh.pos[v]).norm();
            if (!settled[w] && reach < size[w]) {
                size[w] = reach;
                queue.push({reach, w});
            }
        });
    }
    return size;
}

RepairSettings repair_at_length(const RepairSettings &s, double l)
{
    const double scale = l / s.desired_length;
    RepairSettings out = s;
    out.desired_length = l;
    out.split_length *= scale;
    out.split_shortest *= scale;
    out.contract_length *= scale;
    out.short_edge_length *= scale;
    return out;
}

} // namespace sfa

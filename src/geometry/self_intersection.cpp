// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/self_intersection.hpp"

#include "geometry/box_pairs.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/parallel.hpp"

#include <cstdint>
#include <vector>

namespace sfa {

int32_t self_intersection_count(const TriMesh &mesh)
{
    const int32_t n = mesh.num_triangles();
    if (n < 2)
        return 0;
    // Cells of twice the mean edge length (from the triangles' first edges): most
    // triangles' boxes then cover one to four cells.
    double cell = 0;
    std::vector<Box> boxes(static_cast<size_t>(n));
    for (int32_t t = 0; t < n; ++t) {
        const Triangle &c = mesh.tri[t];
        cell += (mesh.pos[c[1]] - mesh.pos[c[0]]).norm();
        boxes[t] = {mesh.pos[c[0]].cwiseMin(mesh.pos[c[1]]).cwiseMin(mesh.pos[c[2]]),
                    mesh.pos[c[0]].cwiseMax(mesh.pos[c[1]]).cwiseMax(mesh.pos[c[2]])};
    }
    cell = 2 * cell / n;
    if (!(cell > 0))
        return 0;
    std::vector<int32_t> per_thread(static_cast<size_t>(loop_threads()), 0);
    for_each_overlapping_pair(boxes, cell, [&](int32_t s, int32_t t) {
        const Triangle &p = mesh.tri[s], &q = mesh.tri[t];
        if (share_a_vertex(p, q))
            return; // neighbours touch by construction
        if (triangles_intersect(mesh.pos[p[0]], mesh.pos[p[1]], mesh.pos[p[2]], mesh.pos[q[0]], mesh.pos[q[1]],
                                mesh.pos[q[2]]))
            ++per_thread[static_cast<size_t>(thread_index())];
    });
    int32_t count = 0;
    for (int32_t c : per_thread)
        count += c;
    return count;
}

} // namespace sfa

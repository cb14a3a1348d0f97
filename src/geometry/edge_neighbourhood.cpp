// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/edge_neighbourhood.hpp"

#include <algorithm>
#include <cmath>

namespace sfa {

EdgeNeighbourhood edge_neighbourhood(const TriMesh &mesh, int32_t h)
{
    EdgeNeighbourhood n{};
    const Vec3 &a = mesh.pos[mesh.tail(h)], &b = mesh.pos[mesh.head(h)];
    n.length = (b - a).norm();
    n.longest = n.shortest = n.length;
    for (int32_t side : {h, mesh.opp[h]}) {
        if (side < 0)
            continue;
        const Vec3 &p = mesh.pos[mesh.head(TriMesh::next(side))];
        const Vec3 to_a = a - p, to_b = b - p;
        const double pa = to_a.norm(), pb = to_b.norm();
        // A corner on an end of the edge has the angle 0.
        n.opposite_cos[n.triangles] = pa * pb > 0 ? std::clamp(to_a.dot(to_b) / (pa * pb), -1.0, 1.0) : 1.0;
        n.triangle_longest[n.triangles] = std::max({n.length, pa, pb});
        n.longest = std::max({n.longest, pa, pb});
        n.shortest = std::min({n.shortest, pa, pb});
        ++n.triangles;
    }
    return n;
}

} // namespace sfa

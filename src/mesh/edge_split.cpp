// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/edge_split.hpp"

namespace sfa {
namespace {

void link(TriMesh &mesh, int32_t x, int32_t y)
{
    mesh.opp[x] = y;
    if (y >= 0)
        mesh.opp[y] = x;
}

} // namespace

SplitRecord split_edge(TriMesh &mesh, int32_t h, const Vec3 &position)
{
    const int32_t twin = mesh.opp[h];
    const int32_t t0 = TriMesh::face(h), i = h % 3;
    const int32_t a = mesh.tail(h), b = mesh.head(h), p = mesh.head(TriMesh::next(h));
    const int32_t m = mesh.num_vertices();
    const int32_t t2 = mesh.num_triangles(), t3 = t2 + 1;
    const auto at = [](int32_t t, int32_t corner) { return 3 * t + corner % 3; };

    mesh.pos.push_back(position);
    mesh.v2h.push_back(3 * t2); // m -> b: the boundary half-edge if the edge was one
    const int32_t outer_bp = mesh.opp[at(t0, i + 1)];
    mesh.tri.push_back({m, b, p});
    mesh.tri[t0][(i + 1) % 3] = m; // (a, m, p)
    mesh.opp.resize(3 * (t2 + 1), -1);
    link(mesh, 3 * t2 + 1, outer_bp);          // b -> p moved to t2
    link(mesh, at(t0, i + 1), 3 * t2 + 2);     // m -> p and p -> m
    if (mesh.v2h[b] == at(t0, i + 1))
        mesh.v2h[b] = 3 * t2 + 1;

    SplitRecord record{m, a, b, p, -1, {t0, -1}, {t2, -1}, {{h, 3 * t2}, {-1, -1}}, {at(t0, i + 1), -1},
                       {3 * t2 + 1, -1}, {at(t0, i + 1), 3 * t2 + 2, -1, -1}};
    if (twin < 0) {
        mesh.opp[h] = -1;      // a -> m
        mesh.opp[3 * t2] = -1; // m -> b
        return record;
    }
    const int32_t t1 = TriMesh::face(twin), j = twin % 3;
    const int32_t q = mesh.head(TriMesh::next(twin));
    const int32_t outer_aq = mesh.opp[at(t1, j + 1)];
    mesh.tri.push_back({m, a, q});
    mesh.tri[t1][(j + 1) % 3] = m; // (b, m, q)
    mesh.opp.resize(3 * (t3 + 1), -1);
    link(mesh, 3 * t3 + 1, outer_aq);      // a -> q moved to t3
    link(mesh, at(t1, j + 1), 3 * t3 + 2); // m -> q and q -> m
    link(mesh, h, 3 * t3);                 // a -> m and m -> a
    link(mesh, 3 * t2, twin);              // m -> b and b -> m
    if (mesh.v2h[a] == at(t1, j + 1))
        mesh.v2h[a] = 3 * t3 + 1;
    record.q = q;
    record.old_faces[1] = t1;
    record.new_faces[1] = t3;
    record.halves[1][0] = twin;
    record.halves[1][1] = 3 * t3;
    record.moved_from[1] = at(t1, j + 1);
    record.moved_to[1] = 3 * t3 + 1;
    record.fresh[2] = at(t1, j + 1);
    record.fresh[3] = 3 * t3 + 2;
    return record;
}

} // namespace sfa

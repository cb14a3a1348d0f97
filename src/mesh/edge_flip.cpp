// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/edge_flip.hpp"

namespace sfa {

FlipQuad flip_quad(const TriMesh &mesh, int32_t h)
{
    const int32_t twin = mesh.opp[h];
    return {mesh.tail(h), mesh.head(h), mesh.head(TriMesh::next(h)), mesh.head(TriMesh::next(twin))};
}

bool flip_keeps_manifold(const TriMesh &mesh, int32_t h)
{
    if (mesh.opp[h] < 0)
        return false;
    const FlipQuad quad = flip_quad(mesh, h);
    bool joined = false;
    mesh.for_each_neighbour(quad.p, [&](int32_t w, int32_t) { joined = joined || w == quad.q; });
    return !joined;
}

FlipMoves flip_edge(TriMesh &mesh, int32_t h)
{
    // Before: triangle t0 = (a, b, p) with h = a -> b at corner i, t1 = (b, a, q) with its
    // twin at corner j. After: t0 = (q, p, a), t1 = (p, q, b), corners starting at i and j,
    // so that h is q -> p and its twin p -> q; the four outer edges keep their direction.
    const int32_t twin = mesh.opp[h];
    const int32_t t0 = TriMesh::face(h), i = h % 3;
    const int32_t t1 = TriMesh::face(twin), j = twin % 3;
    const FlipQuad quad = flip_quad(mesh, h);
    const auto at = [](int32_t t, int32_t corner) { return 3 * t + corner % 3; };

    // Old half-edges b->p, p->a (in t0) and a->q, q->b (in t1), and their new places.
    const FlipMoves moves{{at(t0, i + 1), at(t0, i + 2), at(t1, j + 1), at(t1, j + 2)},
                          {at(t1, j + 2), at(t0, i + 1), at(t0, i + 2), at(t1, j + 1)}};
    std::array<int32_t, 4> outer_twin;
    for (int k = 0; k < 4; ++k)
        outer_twin[k] = mesh.opp[moves.from[k]];

    mesh.tri[t0][i] = quad.q;
    mesh.tri[t0][(i + 1) % 3] = quad.p;
    mesh.tri[t0][(i + 2) % 3] = quad.a;
    mesh.tri[t1][j] = quad.p;
    mesh.tri[t1][(j + 1) % 3] = quad.q;
    mesh.tri[t1][(j + 2) % 3] = quad.b;

    for (int k = 0; k < 4; ++k) {
        mesh.opp[moves.to[k]] = outer_twin[k];
        if (outer_twin[k] >= 0)
            mesh.opp[outer_twin[k]] = moves.to[k];
    }

    // Each corner's half-edge follows its edge; a and b lose the flipped edge and take
    // their outer edge in the quad instead (interior edges, so a boundary vertex's
    // boundary half-edge is never among the ones they lose).
    const int32_t corners[4] = {quad.b, quad.p, quad.a, quad.q}; // tails of moves.from
    for (int k = 0; k < 4; ++k)
        if (mesh.v2h[corners[k]] == moves.from[k])
            mesh.v2h[corners[k]] = moves.to[k];
    if (mesh.v2h[quad.a] == h)
        mesh.v2h[quad.a] = at(t0, i + 2); // a -> q
    if (mesh.v2h[quad.b] == twin)
        mesh.v2h[quad.b] = at(t1, j + 2); // b -> p
    return moves;
}

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/edge_collapse.hpp"

#include <algorithm>

namespace sfa {
namespace {

int32_t valence(const TriMesh &mesh, int32_t v)
{
    int32_t count = 0;
    mesh.for_each_neighbour(v, [&](int32_t, int32_t) { ++count; });
    return count;
}

// The outgoing half-edge of v to keep in v2h: for a boundary vertex the one without a
// twin, found by turning clockwise from any outgoing half-edge.
int32_t canonical_outgoing(const TriMesh &mesh, int32_t any)
{
    int32_t h = any;
    while (mesh.opp[h] >= 0) {
        h = TriMesh::next(mesh.opp[h]);
        if (h == any)
            return any; // an interior vertex: any will do
    }
    return h;
}

void link(TriMesh &mesh, int32_t x, int32_t y)
{
    if (x >= 0)
        mesh.opp[x] = y;
    if (y >= 0)
        mesh.opp[y] = x;
}

} // namespace

bool collapse_keeps_manifold(const TriMesh &mesh, int32_t h)
{
    const int32_t twin = mesh.opp[h];
    const int32_t gone = mesh.tail(h), keep = mesh.head(h);
    if (twin >= 0 && mesh.is_boundary_vertex(gone) && mesh.is_boundary_vertex(keep))
        return false;
    int32_t opposite[2] = {mesh.head(TriMesh::next(h)), twin >= 0 ? mesh.head(TriMesh::next(twin)) : -1};
    for (int32_t side : {h, twin}) {
        if (side < 0)
            continue;
        const int32_t p = mesh.head(TriMesh::next(side));
        // An ear (both other edges on the boundary) would leave p hanging; an interior p
        // of valence 3 would be left with two neighbours.
        if (mesh.opp[TriMesh::next(side)] < 0 && mesh.opp[TriMesh::prev(side)] < 0)
            return false;
        if (!mesh.is_boundary_vertex(p) && valence(mesh, p) < 4)
            return false;
    }
    bool ok = true;
    mesh.for_each_neighbour(gone, [&](int32_t w, int32_t) {
        if (w == keep || w == opposite[0] || w == opposite[1])
            return;
        mesh.for_each_neighbour(keep, [&](int32_t x, int32_t) { ok = ok && x != w; });
    });
    return ok;
}

CollapseRecord collapse_edge(TriMesh &mesh, int32_t h, const Vec3 &position)
{
    const int32_t twin = mesh.opp[h];
    const int32_t gone = mesh.tail(h), keep = mesh.head(h);

    // Every triangle around gone takes keep instead (the two dying ones too: harmless).
    mesh.for_each_outgoing(gone, [&](int32_t g) { mesh.tri[TriMesh::face(g)][g % 3] = keep; });

    // Each dying triangle (gone, keep, p) leaves its two other edges' outer twins joined:
    // keep -> p's twin (p -> keep) with p -> gone's twin (gone -> p, now keep -> p).
    int32_t survivors[4] = {-1, -1, -1, -1}; // outer twins: p->keep, keep->p, q->keep, keep->q
    CollapseRecord record{gone, keep, {-1, -1}, {-1, -1}, {{-1, -1}, {-1, -1}}, {{-1, -1}, {-1, -1}}};
    int k = 0;
    for (int32_t side : {h, twin}) {
        if (side < 0)
            continue;
        record.opposite[k / 2] = mesh.head(TriMesh::next(side));
        record.dead_faces[k / 2] = TriMesh::face(side);
        record.dead_halves[k / 2][0] = TriMesh::next(side);
        record.dead_halves[k / 2][1] = TriMesh::prev(side);
        const int32_t to_p = mesh.opp[TriMesh::next(side)], from_p = mesh.opp[TriMesh::prev(side)];
        // For the twin's triangle (keep, gone, q) the roles turn round: next is gone -> q,
        // prev is q -> keep.
        if (side == h) {
            survivors[0] = to_p;   // p -> keep
            survivors[1] = from_p; // keep -> p (was gone -> p)
        } else {
            survivors[2] = from_p; // keep -> q
            survivors[3] = to_p;   // q -> keep (was q -> gone)
        }
        link(mesh, to_p, from_p);
        record.joined[k / 2][0] = to_p;
        record.joined[k / 2][1] = from_p;
        k += 2;
    }
    for (int32_t side : {h, twin}) {
        if (side < 0)
            continue;
        const int32_t t = TriMesh::face(side);
        mesh.tri[t] = {-1, -1, -1};
        for (int c = 0; c < 3; ++c)
            mesh.opp[3 * t + c] = -1;
    }
    mesh.v2h[gone] = -1;
    mesh.pos[keep] = position;

    // The vertex half-edges of keep and of the opposite vertices may have died.
    // from_v leaves the vertex; into_v arrives at it (so its next leaves it).
    const auto outgoing_of = [](int32_t from_v, int32_t into_v) { return from_v >= 0 ? from_v : TriMesh::next(into_v); };
    int32_t any_keep = survivors[1] >= 0 ? survivors[1] : survivors[2];
    if (any_keep < 0)
        any_keep = survivors[0] >= 0 ? TriMesh::next(survivors[0]) : TriMesh::next(survivors[3]);
    mesh.v2h[keep] = canonical_outgoing(mesh, any_keep);
    if (record.opposite[0] >= 0)
        mesh.v2h[record.opposite[0]] = canonical_outgoing(mesh, outgoing_of(survivors[0], survivors[1]));
    if (record.opposite[1] >= 0)
        mesh.v2h[record.opposite[1]] = canonical_outgoing(mesh, outgoing_of(survivors[3], survivors[2]));
    return record;
}

} // namespace sfa

#include "adapt/split.hpp"

#include "fields/transfer.hpp"
#include "geometry/circle.hpp"
#include "geometry/crossing_guard.hpp"
#include "geometry/edge_neighbourhood.hpp"
#include "geometry/quadric_error.hpp"
#include "mesh/edge_split.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <tuple>

namespace sfa {
namespace {

bool wants_split(const EdgeNeighbourhood &n, const RepairSettings &settings)
{
    const bool absolutely_long = n.length >= n.longest && n.length > settings.split_length;
    const double cos_largest_angle = std::min(n.opposite_cos[0], n.triangles > 1 ? n.opposite_cos[1] : 1.0);
    const bool relatively_long = n.length > settings.desired_length && cos_largest_angle < settings.cos_large_angle &&
                                 n.shortest >= settings.split_shortest;
    return absolutely_long || relatively_long;
}

// The edge's one or two triangles.
template <class Fn>
void for_each_edge_face(const TriMesh &mesh, int32_t h, Fn &&fn)
{
    fn(TriMesh::face(h));
    if (mesh.opp[h] >= 0)
        fn(TriMesh::face(mesh.opp[h]));
}

// True if putting the new vertex at x turns no part of the edge's triangles over: each
// half of triangle (a, b, p) keeps the triangle's orientation.
bool halves_keep_orientation(const TriMesh &mesh, int32_t h, const Vec3 &x)
{
    bool ok = true;
    for_each_edge_face(mesh, h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        const Vec3 &p0 = mesh.pos[t[0]], &p1 = mesh.pos[t[1]], &p2 = mesh.pos[t[2]];
        const Vec3 normal = (p1 - p0).cross(p2 - p0);
        // The edge's ends are two of the corners; x replaces each of them in turn.
        for (int k = 0; k < 3; ++k) {
            if (t[k] != mesh.tail(h) && t[k] != mesh.head(h))
                continue;
            Vec3 q[3] = {p0, p1, p2};
            q[k] = x;
            ok = ok && (q[1] - q[0]).cross(q[2] - q[0]).dot(normal) > 0;
        }
    });
    return ok;
}

// §4.1: the centre, moved along the normal to the quadric error minimum of the faces
// around both ends; on a ridge or boundary edge, the midpoint of the curve through the
// ridge neighbours (the centre where the ridge is straight); the centre itself where a
// move would fold a half of the edge's triangles.
Vec3 new_vertex_position(const TriMesh &mesh, int32_t h, bool on_ridge, const CarriedFeatures &features)
{
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    const Vec3 centre = (mesh.pos[a] + mesh.pos[b]) / 2;
    if (on_ridge) {
        const Vec3 on_curve =
            curve_midpoint(features.next_along(mesh, a, b), mesh.pos[a], mesh.pos[b], features.next_along(mesh, b, a));
        return halves_keep_orientation(mesh, h, on_curve) ? on_curve : centre;
    }
    Vec3 normal = Vec3::Zero();
    for_each_edge_face(mesh, h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        normal += (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]);
    });
    // The faces around the smooth ends only (and the edge's own): a feature end's fan
    // reaches across its crease, and fitting both sides would round the crease off.
    const Vec3 placed = quadric_error_minimum_along(
        mesh,
        [&](auto &&visit) {
            for_each_edge_face(mesh, h, visit);
            for (int32_t end : {a, b})
                if (features.rank[end] == 0)
                    mesh.for_each_outgoing(end, [&](int32_t g) { visit(TriMesh::face(g)); });
        },
        centre, normal.normalized(), max_shift_ratio * (mesh.pos[b] - mesh.pos[a]).norm());
    return halves_keep_orientation(mesh, h, placed) ? placed : centre;
}

// True if a half of the edge's faces, with the new vertex at `position`, would pass
// through a watched face.
bool split_crosses(const TriMesh &mesh, int32_t h, const Vec3 &position, const CrossingGuard &guard)
{
    bool crosses = false;
    for_each_edge_face(mesh, h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        if (crosses || !guard.watches_any(t))
            return;
        // The edge's ends are two of the corners; the new vertex replaces each in turn (and
        // is none of the faces' vertices, -1 here).
        for (int k = 0; k < 3; ++k) {
            if (t[k] != mesh.tail(h) && t[k] != mesh.head(h))
                continue;
            Triangle half = t;
            half[k] = -1;
            Vec3 at[3] = {mesh.pos[t[0]], mesh.pos[t[1]], mesh.pos[t[2]]};
            at[k] = position;
            crosses = crosses || guard.crosses(mesh, mesh.pos, half, at);
        }
    });
    return crosses;
}

struct Candidate {
    double length;
    int32_t a, b;
};

} // namespace

int32_t splitting_pass(TriMesh &mesh, const RepairSettings &settings, CarriedFeatures &features,
                       std::vector<VertexField> &fields, std::vector<char> &changed, CrossingGuard *guard)
{
    // Judging is independent per edge (in parallel); collecting is in half-edge order.
    const int32_t halfedges = 3 * mesh.num_triangles();
    std::vector<char> wanted(halfedges, 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t h = 0; h < halfedges; ++h) {
        if (mesh.opp[h] >= 0 && mesh.opp[h] < h)
            continue; // each edge once
        // Both criteria need the edge longer than l or L: most edges are not, and their
        // neighbourhood need not be looked at.
        const double length = (mesh.pos[mesh.head(h)] - mesh.pos[mesh.tail(h)]).norm();
        if (length > settings.desired_length || length > settings.split_length)
            wanted[h] = wants_split(edge_neighbourhood(mesh, h), settings);
    }
    std::vector<Candidate> candidates;
    for (int32_t h = 0; h < halfedges; ++h)
        if (wanted[h])
            candidates.push_back({(mesh.pos[mesh.head(h)] - mesh.pos[mesh.tail(h)]).norm(), mesh.tail(h), mesh.head(h)});
    // Longest first (§4.1); ties in vertex order, so the result never depends on the order
    // the candidates were found in.
    std::sort(candidates.begin(), candidates.end(), [](const Candidate &x, const Candidate &y) {
        return std::tie(y.length, x.a, x.b) < std::tie(x.length, y.a, y.b);
    });

    if (guard)
        guard->index_faces(mesh, mesh.pos);
    int32_t splits = 0;
    for (const Candidate &c : candidates) {
        int32_t h = mesh.halfedge(c.a, c.b);
        if (h < 0)
            h = mesh.halfedge(c.b, c.a); // a boundary edge has one direction only
        if (h < 0 || !wants_split(edge_neighbourhood(mesh, h), settings))
            continue;
        const bool on_ridge = features.ridges.contains(c.a, c.b) || mesh.opp[h] < 0;
        const Vec3 position = new_vertex_position(mesh, h, on_ridge, features);
        if (guard && split_crosses(mesh, h, position, *guard))
            continue;
        const Stencil stencil = stencil_over(mesh, position, [&](auto &&visit) { for_each_edge_face(mesh, h, visit); });
        for_each_edge_face(mesh, h, [&](int32_t f) {
            for (int32_t v : mesh.tri[f])
                changed[v] = 1;
        });
        const int32_t m = split_edge(mesh, h, position);
        changed.push_back(1);
        if (guard) {
            guard->add_vertex(guard->watches(c.a) || guard->watches(c.b));
            mesh.for_each_outgoing(m, [&](int32_t g) { guard->refresh(mesh, mesh.pos, TriMesh::face(g)); });
        }
        append_interpolated(fields, stencil);
        features.rank.push_back(on_ridge ? 1 : 0);
        if (on_ridge) {
            features.ridges.remove(c.a, c.b);
            features.ridges.add(c.a, m);
            features.ridges.add(m, c.b);
        }
        ++splits;
    }
    return splits;
}

} // namespace sfa

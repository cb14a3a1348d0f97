// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/split.hpp"

#include "adapt/size_field.hpp"
#include "geometry/circle.hpp"
#include "geometry/edge_neighbourhood.hpp"
#include "geometry/local_fit.hpp"
#include "geometry/quadric_error.hpp"
#include "geometry/surface_side.hpp"

#include <algorithm>

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

// True if putting the new vertex at x turns no part of the edge's triangles over: each
// half of triangle (a, b, p) keeps the triangle's orientation, and faces the side the
// surface faces at its smooth corners where the triangle did (surface_side.hpp: the
// halves of a sliver can each turn by almost a right angle, and an earlier change may
// have tilted the sliver already). The centre, the fallback, keeps both.
bool halves_keep_orientation(const TriMesh &mesh, const SurfaceAnalysis &analysis, const CarriedFeatures &features,
                             int32_t h, const Vec3 &x)
{
    bool ok = true;
    mesh.for_each_face_of_edge(h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        const Vec3 &p0 = mesh.pos[t[0]], &p1 = mesh.pos[t[1]], &p2 = mesh.pos[t[2]];
        const Vec3 normal = (p1 - p0).cross(p2 - p0);
        // The edge's ends are two of the corners; x replaces each of them in turn.
        for (int k = 0; k < 3; ++k) {
            if (t[k] != mesh.tail(h) && t[k] != mesh.head(h))
                continue;
            Vec3 q[3] = {p0, p1, p2};
            q[k] = x;
            const Vec3 half = (q[1] - q[0]).cross(q[2] - q[0]);
            ok = ok && half.dot(normal) > 0;
            for (int j = 0; j < 3; ++j) // the half's other corners
                ok = ok && (j == k || !turns_at_corner(mesh, analysis.fan_area, features.rank(t[j]), t[j], normal, half));
        }
    });
    return ok;
}

// §4.1: the point over the centre on the surface fitted around the smooth ends (their
// frames are the pass's analysis, made before any split of the pass: a vertex made in it
// has none and is not fitted; a feature vertex's fan reaches across its crease); where no
// end can be fitted, the centre moved along the normal to the quadric error minimum of
// the faces around the smooth ends. On a ridge or boundary edge, the midpoint of the
// curve through the ridge neighbours (the centre where the ridge is straight). The centre
// itself where a move would fold a half of the edge's triangles. The quadric error
// minimum is the paper's placement; it leaves the vertex off the surface by a fraction of
// the sagitta, and over a period of the Enright flow those offsets piled up to half of
// the vertices' backtrace error (bench/fidelity.cpp).
Vec3 new_vertex_position(const TriMesh &mesh, const SurfaceAnalysis &analysis, int32_t h, bool on_ridge,
                         const CarriedFeatures &features)
{
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    const Vec3 centre = (mesh.pos[a] + mesh.pos[b]) / 2;
    if (on_ridge) {
        const Vec3 on_curve =
            curve_midpoint(features.next_along(mesh, a, b), mesh.pos[a], mesh.pos[b], features.next_along(mesh, b, a));
        return halves_keep_orientation(mesh, analysis, features, h, on_curve) ? on_curve : centre;
    }
    const double max_shift = max_shift_ratio * (mesh.pos[b] - mesh.pos[a]).norm();
    const auto fits = [&](int32_t end) {
        return features.rank(end) == 0 && end < static_cast<int32_t>(analysis.metric.size());
    };
    Vec3 fitted;
    if (onto_fitted_surface_of_ends(mesh, analysis.metric, a, fits(a), b, fits(b), centre, max_shift, fitted))
        return halves_keep_orientation(mesh, analysis, features, h, fitted) ? fitted : centre;
    Vec3 normal = Vec3::Zero();
    mesh.for_each_face_of_edge(h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        normal += (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]);
    });
    // The faces around the smooth ends only (and the edge's own): a feature end's fan
    // reaches across its crease, and fitting both sides would round the crease off.
    const Vec3 placed = quadric_error_minimum_along(
        mesh,
        [&](auto &&visit) {
            mesh.for_each_face_of_edge(h, visit);
            for (int32_t end : {a, b})
                if (features.rank(end) == 0)
                    mesh.for_each_outgoing(end, [&](int32_t g) { visit(TriMesh::face(g)); });
        },
        centre, normal.normalized(), max_shift);
    return halves_keep_orientation(mesh, analysis, features, h, placed) ? placed : centre;
}

// True if a half of the edge's faces, with the new vertex at `position`, would pass
// through a watched face.
bool split_crosses(const TriMesh &mesh, int32_t h, const Vec3 &position, const CrossingGuard &guard)
{
    bool crosses = false;
    mesh.for_each_face_of_edge(h, [&](int32_t f) {
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

class Splitting {
public:
    struct Plan {};
    // wants_split is the whole verdict, and it reads only the edge's triangles.
    static constexpr bool plans_ahead = false;

    Splitting(const PassContext &context, const SurfaceAnalysis &analysis, const RepairSettings &settings)
        : mesh_(context.edit.mesh()), analysis_(analysis), repair_(settings, context.size),
          features_(context.features), constraints_(context.constraints), guard_(context.guard)
    {
    }

    bool wanted(int32_t h, double &order) const
    {
        if (constraints_.required(h))
            return false;
        // Both criteria need the edge longer than l or L: most edges are not, and their
        // neighbourhood need not be looked at.
        const RepairSettings settings = repair_.at_edge(mesh_, h);
        const double length = (mesh_.pos[mesh_.head(h)] - mesh_.pos[mesh_.tail(h)]).norm();
        if (!(length > settings.desired_length || length > settings.split_length) ||
            !wants_split(edge_neighbourhood(mesh_, h), settings))
            return false;
        order = -length; // longest first (§4.1)
        return true;
    }
    int32_t locate(int32_t a, int32_t b) const
    {
        const int32_t h = mesh_.halfedge(a, b);
        return h >= 0 ? h : mesh_.halfedge(b, a); // a boundary edge has one direction only
    }
    bool plan(int32_t h, Plan &) const { return wants_split(edge_neighbourhood(mesh_, h), repair_.at_edge(mesh_, h)); }
    // An edge's triangles change only in a split of one of their edges, which marks their corners.
    bool may_have_changed(int32_t h, const ChangedVertices &changed) const
    {
        return changed[mesh_.tail(h)] || changed[mesh_.head(h)];
    }
    bool apply(MeshEdit &edit, int32_t h, const Plan &)
    {
        const bool on_ridge = features_.is_ridge(h) || mesh_.opp[h] < 0;
        const Vec3 position = new_vertex_position(mesh_, analysis_, h, on_ridge, features_);
        if (guard_ && split_crosses(mesh_, h, position, *guard_))
            return false;
        edit.split(h, position);
        return true;
    }

private:
    const TriMesh &mesh_;
    const SurfaceAnalysis &analysis_;
    const LocalRepair repair_;
    const CarriedFeatures &features_;
    const CarriedConstraints &constraints_;
    const CrossingGuard *guard_;
};

} // namespace

int32_t splitting_pass(const PassContext &context, const SurfaceAnalysis &analysis, const RepairSettings &settings)
{
    Splitting splitting(context, analysis, settings);
    return run_edge_pass(context.edit, splitting);
}

} // namespace sfa

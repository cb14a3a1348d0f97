// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/contract.hpp"

#include "adapt/size_field.hpp"
#include "geometry/circle.hpp"
#include "geometry/edge_neighbourhood.hpp"
#include "geometry/fan_sectors.hpp"
#include "geometry/local_fit.hpp"
#include "geometry/quadric_error.hpp"
#include "geometry/surface_side.hpp"
#include "geometry/triangle_intersection.hpp"

#include <algorithm>
#include <cmath>

namespace sfa {
namespace {

// A face may turn this much at most: more is a fold in the making.
const double cos_max_face_turn = 0.5; // 60 degrees
// A face whose height is below this fraction of its longest edge is nearly flat (an angle
// of about 0.06 degrees): it would spoil every normal computed from it.
constexpr double min_height_ratio = 1e-3;

// The metric (eq. 4) length of h's edge and the longest of its triangles' edges.
struct MetricLengths {
    double metric_length, metric_longest;
};

MetricLengths metric_lengths(const TriMesh &mesh, const SurfaceAnalysis &analysis, int32_t h)
{
    const auto length = [&](int32_t p, int32_t q) {
        return metric_edge_length(mesh.pos[p], analysis.metric[p], mesh.pos[q], analysis.metric[q]);
    };
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    MetricLengths out{length(a, b), length(a, b)};
    for (int32_t side : {h, mesh.opp[h]}) {
        if (side < 0)
            continue;
        const int32_t p = mesh.head(TriMesh::next(side));
        out.metric_longest = std::max({out.metric_longest, length(a, p), length(b, p)});
    }
    return out;
}

// Two feature vertices that a contraction of their edge would make one, joining two
// corners or two ridge curves (or a curve and a corner): two corners, or two feature
// vertices whose edge is no ridge edge.
bool joins_features(const TriMesh &mesh, int32_t h, const CarriedFeatures &features)
{
    const int8_t ra = features.rank(mesh.tail(h)), rb = features.rank(mesh.head(h));
    return ra > 0 && rb > 0 && ((ra == 2 && rb == 2) || !features.is_ridge(h));
}

// A cusp the flow squeezed: h's edge joins two feature vertices (joins_features) that are
// both near a facing sheet (CrossingGuard::near_sheet), as at the rim of a sheet thinner
// than an edge, where the detected features are the cusps of the unresolved rim rather
// than the surface's own.
bool at_cusp(const TriMesh &mesh, int32_t h, const CarriedFeatures &features, const CrossingGuard *guard)
{
    return guard && guard->near_sheet(mesh.tail(h)) && guard->near_sheet(mesh.head(h)) &&
           joins_features(mesh, h, features);
}

// The edge of a needle at a cusp (at_cusp): shorter than 2 r l, opposite an angle below
// theta_s. Its two ends count as one feature, as two feature vertices nearer than r l do
// anywhere (merged_position). In the vortex flow of T = 6 the sweeps slide a ridge vertex
// along its ridge towards a corner 0.12 to 0.18 l away across such an edge, which §4.2's
// relative shortness (r times the longest edge around, about 1.2 l there) does not reach:
// 1 to 7 triangles of 2.9 to 4.8 degrees at each checkpoint from t = 3, each where the
// sheets came nearest, and the largest backtrace error at its vertex.
bool needle_at_cusp(const EdgeNeighbourhood &n, const RepairSettings &s)
{
    if (!(n.length < 2 * s.contract_short_ratio * s.desired_length))
        return false;
    for (int k = 0; k < n.triangles; ++k)
        if (n.opposite_cos[k] > s.cos_small_angle)
            return true;
    return false;
}

// `coarsens`: absolute shortness may apply (shortness_applies); `cusp`: at_cusp.
bool wants_contraction(const TriMesh &mesh, const SurfaceAnalysis &analysis, int32_t h, const RepairSettings &s,
                       bool coarsens, bool cusp)
{
    const EdgeNeighbourhood n = edge_neighbourhood(mesh, h);
    if (cusp && needle_at_cusp(n, s))
        return true;
    for (int k = 0; k < n.triangles; ++k)
        if (n.opposite_cos[k] > s.cos_small_angle && n.triangle_longest[k] < s.desired_length)
            return true; // absolute small angle
    if (n.length < s.contract_short_ratio * n.longest)
        return true; // relative shortness
    if (n.longest < s.contract_length && n.length <= n.shortest)
        return true; // absolute small triangle
    if (coarsens && n.length < s.short_edge_length && n.length <= n.shortest &&
        metric_lengths(mesh, analysis, h).metric_length < s.short_edge_length)
        return true; // absolute shortness (not the paper's: it makes a mesh coarsen to l, not to S)
    if (n.longest < s.desired_length && n.length < s.contract_small_ratio * n.longest) {
        const MetricLengths metric = metric_lengths(mesh, analysis, h); // relative small triangle,
        return metric.metric_length < s.contract_small_ratio * metric.metric_longest; // in both spaces
    }
    return false;
}

// Absolute shortness (RepairSettings::short_edge_length) coarsens a smooth region only: it
// leaves an edge between two feature vertices (the paper's criteria keep ridge curves as
// they were; coarsened too, the fandisk's faded creases showed up as new curves), and an
// edge with an end near a facing sheet (crossing_guard.hpp), where the two sides are
// nearer than an edge and fewer vertices let a later step carry one through the other
// (the vortex flow of T = 6 crossed so).
bool shortness_applies(const TriMesh &mesh, int32_t h, const CarriedFeatures &features, const CrossingGuard *guard)
{
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    return !(features.rank(a) > 0 && features.rank(b) > 0) && !(guard && (guard->watches(a) || guard->watches(b)));
}

// True if moving both ends of h to `merged` keeps every surviving face's orientation
// (turned by at most 60 degrees, and facing the side the surface faces at each smooth
// corner where it did) and shape (not nearly flat). The 60 degrees are relative to the
// face as this contraction finds it: a chain of contractions (and the splits and sweeps
// between them) could turn a face over step by step, as on a shallow cone of 1000
// slivers (issue 18); the side the surface faces at the corners bounds the total
// (surface_side.hpp).
bool faces_survive(const TriMesh &mesh, const SurfaceAnalysis &analysis, const CarriedFeatures &features, int32_t h,
                   const Vec3 &merged)
{
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    bool ok = true;
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        const bool has_a = t[0] == a || t[1] == a || t[2] == a, has_b = t[0] == b || t[1] == b || t[2] == b;
        if (has_a && has_b)
            return; // dies with the edge
        Vec3 q[3];
        for (int k = 0; k < 3; ++k)
            q[k] = t[k] == a || t[k] == b ? merged : mesh.pos[t[k]];
        const Vec3 before = (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]);
        const Vec3 after = (q[1] - q[0]).cross(q[2] - q[0]);
        const double longest2 = std::max({(q[1] - q[0]).squaredNorm(), (q[2] - q[1]).squaredNorm(),
                                          (q[0] - q[2]).squaredNorm()});
        // height / longest = |after| / longest^2
        ok = ok && after.dot(before) >= cos_max_face_turn * after.norm() * before.norm() &&
             after.norm() >= min_height_ratio * longest2;
        for (int32_t c : t) // a and b by their own normals
            ok = ok && !turns_at_corner(mesh, analysis.fan_area, features.rank(c), c, before, after);
    });
    return ok;
}

// A vertex with at least this many faces has its fan indexed by angle (FanSectors) for
// stays_clear_of_neighbours: below it, reading the fan costs less than looking it up.
constexpr int32_t min_indexed_valence = 64;

// The fans of the vertices of high valence, indexed at the start of a contraction pass
// (issue 18: on a cone of n slivers, each of the O(n) contractions of the rim read the
// apex's whole fan, O(n^2)). A contraction changes the fans of the neighbours of the
// vertex it keeps: every changed face has that vertex as a corner, so each index keeps the
// list of such vertices and the faces around them are tested as they are now; the index
// is built anew when that list grows longer than about the square root of the fan (the
// rebuilds and the list's reads then cost O(sqrt n) per contraction).
struct HubFans {
    std::vector<int32_t> slot;     // per vertex: its index in `fans`, or -1
    std::vector<FanSectors> fans;
    std::vector<std::vector<int32_t>> changed; // per index: vertices whose faces changed since
};

// The list of changed vertices after which a fan of `faces` faces is indexed anew.
size_t changed_limit(size_t faces) { return 8 + static_cast<size_t>(2 * std::sqrt(static_cast<double>(faces))); }

// True if no face around the merged vertex would pass through a face around the ends'
// neighbours that it shares no vertex with. Where a sheet is thinner than an edge (the
// filaments of the vortex flow), the other side of the sheet is that close, and a merged
// vertex can land beyond it although every face keeps its own orientation. `nearby` is
// scratch space, kept by the caller so that the candidates of a pass allocate nothing.
//
// A face that shares a vertex with the moved face (one around a or b included: the merged
// vertex) is not tested, so the fan of a neighbour that is a corner of the moved face is
// skipped whole; the fans in `hubs` are read through their index, and only the faces in
// the moved face's sectors are tested (fan_sectors.hpp: none that could meet it is left
// out). The answer is that of testing every face around every neighbour. The exact
// triangle tests made are added to `tests`.
bool stays_clear_of_neighbours(const TriMesh &mesh, int32_t h, const Vec3 &merged, const HubFans &hubs,
                               std::vector<int32_t> &nearby, FanSectors &merged_fan, int64_t &tests)
{
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    const auto corner = [&](int32_t v) { return v == a || v == b ? merged : mesh.pos[v]; };
    const auto same = [&](int32_t v) { return v == a ? b : v; }; // a and b become one vertex
    const auto indexed = [&](int32_t w) { return hubs.slot.empty() ? -1 : hubs.slot[w]; };
    // The faces around the neighbours not indexed, each once (a face is around up to three
    // of them); the indexed neighbours apart.
    nearby.clear();
    for (int32_t end : {a, b})
        mesh.for_each_neighbour(end, [&](int32_t w, int32_t) {
            if (w != a && w != b && indexed(w) < 0) // a's and b's faces all have the merged vertex
                mesh.for_each_outgoing(w, [&](int32_t g) { nearby.push_back(TriMesh::face(g)); });
        });
    std::sort(nearby.begin(), nearby.end());
    nearby.erase(std::unique(nearby.begin(), nearby.end()), nearby.end());
    const int32_t first_hub = static_cast<int32_t>(nearby.size());
    for (int32_t end : {a, b})
        mesh.for_each_neighbour(end, [&](int32_t w, int32_t) {
            if (w != a && w != b && indexed(w) >= 0)
                nearby.push_back(w);
        });
    std::sort(nearby.begin() + first_hub, nearby.end());
    nearby.erase(std::unique(nearby.begin() + first_hub, nearby.end()), nearby.end());

    // The faces that move, after: the merged vertex's fan.
    const int32_t first_moved = static_cast<int32_t>(nearby.size());
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        const bool has_a = t[0] == a || t[1] == a || t[2] == a, has_b = t[0] == b || t[1] == b || t[2] == b;
        if (!(has_a && has_b)) // or it dies with the edge
            nearby.push_back(f);
    });
    const int32_t moved = static_cast<int32_t>(nearby.size()) - first_moved;

    // True if moved face f would meet face e (which does not move unless it shares a vertex).
    const auto meets = [&](int32_t f, int32_t e) {
        const Triangle &t = mesh.tri[f], &u = mesh.tri[e];
        bool shares = false; // a vertex with f (or is f itself)
        for (int32_t x : t)
            for (int32_t y : u)
                shares = shares || same(x) == same(y);
        if (shares)
            return false;
        ++tests;
        return triangles_intersect(corner(t[0]), corner(t[1]), corner(t[2]), corner(u[0]), corner(u[1]),
                                   corner(u[2]));
    };
    bool clear = true;
    // The faces around the neighbours not indexed. Where the merged vertex has many faces
    // (a vertex of high valence contracted), each face e is looked up in the merged fan's
    // sectors, as a moved face is in an indexed neighbour's below: a face that has a or b
    // shares the merged vertex with every moved face.
    const bool by_sectors = moved >= min_indexed_valence && merged_fan.build_merged(mesh, h, merged);
    for (int32_t k = 0; clear && k < first_hub; ++k) {
        const int32_t e = nearby[k];
        const Triangle &u = mesh.tri[e];
        if (u[0] == a || u[0] == b || u[1] == a || u[1] == b || u[2] == a || u[2] == b)
            continue;
        const Vec3 q[3] = {mesh.pos[u[0]], mesh.pos[u[1]], mesh.pos[u[2]]};
        if (!by_sectors) {
            // Most faces that move are neighbours of e or lie beside it: meets() for the
            // others, which share no vertex with e (e has neither a nor b) and whose box
            // reaches e's. (The nine comparisons through `same` were a tenth of Enright's
            // contraction passes.)
            const Vec3 lo = q[0].cwiseMin(q[1]).cwiseMin(q[2]), hi = q[0].cwiseMax(q[1]).cwiseMax(q[2]);
            for (int32_t m = first_moved; clear && m < first_moved + moved; ++m) {
                const Triangle &t = mesh.tri[nearby[m]];
                if (t[0] == u[0] || t[0] == u[1] || t[0] == u[2] || t[1] == u[0] || t[1] == u[1] || t[1] == u[2] ||
                    t[2] == u[0] || t[2] == u[1] || t[2] == u[2])
                    continue;
                const Vec3 p0 = corner(t[0]), p1 = corner(t[1]), p2 = corner(t[2]);
                if ((p0.cwiseMax(p1).cwiseMax(p2) - lo).minCoeff() < 0 ||
                    (hi - p0.cwiseMin(p1).cwiseMin(p2)).minCoeff() < 0)
                    continue; // boxes apart
                ++tests;
                clear = !triangles_intersect(p0, p1, p2, q[0], q[1], q[2]);
            }
            continue;
        }
        if (!merged_fan.for_each_candidate(q, [&](int32_t f) { clear = clear && !meets(f, e); }))
            for (int32_t m = first_moved; clear && m < first_moved + moved; ++m)
                clear = !meets(nearby[m], e);
    }
    // The indexed neighbours' fans, for each moved face by its sectors.
    for (int32_t m = first_moved; clear && m < first_moved + moved; ++m) {
        const int32_t f = nearby[m];
        const Triangle &t = mesh.tri[f];
        const Vec3 p[3] = {corner(t[0]), corner(t[1]), corner(t[2])};
        for (int32_t k = first_hub; clear && k < first_moved; ++k) {
            const int32_t w = nearby[k];
            if (t[0] == w || t[1] == w || t[2] == w)
                continue; // every face around w shares w with f
            const auto around_w = [&](int32_t e) {
                const Triangle &u = mesh.tri[e];
                if (clear && (u[0] == w || u[1] == w || u[2] == w) && meets(f, e))
                    clear = false;
            };
            const int32_t slot = indexed(w);
            // The faces around w no contraction changed, by their sectors (the index may
            // also list faces that are now elsewhere or dead: around_w passes them by) ...
            if (!hubs.fans[slot].for_each_candidate(p, around_w)) {
                mesh.for_each_outgoing(w, [&](int32_t g) { around_w(TriMesh::face(g)); });
                continue; // the filter could not tell: the whole fan
            }
            // ... and those that changed, around the vertices they have in common.
            for (int32_t v : hubs.changed[slot])
                if (!is_dead_vertex(mesh, v))
                    mesh.for_each_outgoing(v, [&](int32_t g) { around_w(TriMesh::face(g)); });
        }
    }
    return clear;
}

// True if a surviving face around the merged vertex would pass through a watched face:
// the check of stays_clear_of_neighbours, for the faces beyond the ends' neighbours.
bool merge_crosses(const TriMesh &mesh, int32_t h, const Vec3 &merged, const CrossingGuard &guard)
{
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    bool crosses = false;
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        Triangle t = mesh.tri[f];
        const bool has_a = t[0] == a || t[1] == a || t[2] == a, has_b = t[0] == b || t[1] == b || t[2] == b;
        if (crosses || (has_a && has_b) || !guard.watches_any(t))
            return; // done, dies with the edge, or nothing near
        Vec3 at[3];
        for (int k = 0; k < 3; ++k) {
            at[k] = t[k] == a || t[k] == b ? merged : mesh.pos[t[k]];
            if (t[k] == a)
                t[k] = b; // the merged vertex keeps b's number
        }
        crosses = guard.crosses(mesh, mesh.pos, t, at, a);
    });
    return crosses;
}

// Where the merged vertex goes (§4.2), or false if the contraction would spoil a feature.
// (The merged vertex takes the higher of the two ranks: carried_features.hpp.) Between two
// smooth vertices: over the centre, on the surface fitted around both ends (as a split's
// new vertex, split.cpp), or where they cannot be fitted, the quadric error minimum of
// the faces around the edge along their normal.
//
// Two feature vertices nearer than r l (an edge so short that §4.2 calls it relatively
// short next to any edge of length l), or the ends of a needle at a cusp (`cusp`: at_cusp;
// needle_at_cusp), are one feature: they merge (at the one of higher rank, or halfway)
// although that joins two corners or two ridge curves (joins_features). Detected
// features of an evolving surface include the cusps at the rims of sheets thinner than an
// edge, where the flow squeezes such vertices together: kept apart, they left needles of
// 0.1 degrees in the vortex flow of T = 6.
//
// A fixed vertex (constraints.hpp) is a corner that stays where it is: the pass keeps it
// (h's head) and never contracts two.
bool merged_position(const TriMesh &mesh, const SurfaceAnalysis &analysis, int32_t h, const CarriedFeatures &features,
                     const CarriedConstraints &constraints, const RepairSettings &settings, bool cusp, Vec3 &merged)
{
    const int32_t a = mesh.tail(h), b = mesh.head(h);
    const int8_t ra = features.rank(a), rb = features.rank(b);
    if (joins_features(mesh, h, features)) {
        const bool one_feature =
            (mesh.pos[b] - mesh.pos[a]).norm() < settings.contract_short_ratio * settings.desired_length ||
            (cusp && needle_at_cusp(edge_neighbourhood(mesh, h), settings));
        if (!one_feature)
            return false;
        merged = constraints.fixed(b) || ra != rb ? mesh.pos[ra > rb ? a : b] : Vec3((mesh.pos[a] + mesh.pos[b]) / 2);
        return true;
    }
    if (ra != rb) {
        merged = mesh.pos[ra > rb ? a : b]; // the feature vertex stays where it is
        return true;
    }
    if (ra > 0) { // on the ridge curve
        merged = curve_midpoint(features.next_along(mesh, a, b), mesh.pos[a], mesh.pos[b], features.next_along(mesh, b, a));
        return true;
    }
    const Vec3 centre = (mesh.pos[a] + mesh.pos[b]) / 2;
    const double max_shift = max_shift_ratio * (mesh.pos[b] - mesh.pos[a]).norm();
    if (onto_fitted_surface_of_ends(mesh, analysis.metric, a, true, b, true, centre, max_shift, merged))
        return true;
    Vec3 normal = Vec3::Zero();
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        normal += (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]);
    });
    merged = quadric_error_minimum_along(
        mesh, [&](auto &&visit) { mesh.for_each_face_around_edge(h, visit); }, centre, normal.normalized(), max_shift);
    return true;
}

// Every check of contracting h but the crossing guard's; the merged vertex's position if
// it passes. `coarsens`: shortness_applies; `cusp`: at_cusp. `nearby`: scratch for
// stays_clear_of_neighbours.
bool contraction_allowed(const TriMesh &mesh, const SurfaceAnalysis &analysis, int32_t h,
                         const RepairSettings &settings, const CarriedFeatures &features,
                         const CarriedConstraints &constraints, bool coarsens, bool cusp, const HubFans &hubs,
                         std::vector<int32_t> &nearby, FanSectors &merged_fan, int64_t &tests, Vec3 &merged)
{
    return wants_contraction(mesh, analysis, h, settings, coarsens, cusp) && collapse_keeps_manifold(mesh, h) &&
           merged_position(mesh, analysis, h, features, constraints, settings, cusp, merged) &&
           faces_survive(mesh, analysis, features, h, merged) &&
           stays_clear_of_neighbours(mesh, h, merged, hubs, nearby, merged_fan, tests);
}

// The edge between a and b, in either direction, or -1.
int32_t edge_between(const TriMesh &mesh, int32_t a, int32_t b)
{
    const int32_t h = mesh.halfedge(a, b);
    return h >= 0 ? h : mesh.halfedge(b, a);
}

// True if a vertex within two edges of a or b is marked.
bool near_marked(const TriMesh &mesh, int32_t a, int32_t b, const std::vector<char> &marked)
{
    bool found = false;
    for (int32_t end : {a, b})
        if (!found && !marked[end])
            mesh.for_each_neighbour(end, [&](int32_t w, int32_t) {
                if (!found && !marked[w])
                    mesh.for_each_neighbour(w, [&](int32_t x, int32_t) { found = found || marked[x]; });
                found = found || marked[w];
            });
        else
            found = true;
    return found;
}

class Contraction {
public:
    struct Plan {
        Vec3 merged = Vec3::Zero();
    };
    // The full check is costly (the faces around the ends' neighbours are tested for
    // crossings): made for every candidate in parallel first. It reads the positions within
    // two edges of the candidate's ends and the fans and features within one, so it stands
    // in the serial phase for every candidate whose ends are more than two edges from any
    // vertex an earlier contraction moved or gave a new fan.
    static constexpr bool plans_ahead = true;
    // A contraction marks its kept vertex and the neighbours (may_have_changed), which come
    // within two edges of a candidate's ends where the kept one is within three.
    static constexpr int32_t changes_reach = 3;

    Contraction(const PassContext &context, const SurfaceAnalysis &analysis, const RepairSettings &settings)
        : mesh_(context.edit.mesh()), analysis_(analysis), repair_(settings, context.size),
          features_(context.features), constraints_(context.constraints), guard_(context.guard),
          nearby_(loop_threads()), merged_fans_(loop_threads()), tests_(loop_threads(), 0)
    {
        // stays_clear_of_neighbours lists the fans of the neighbours of both ends that are
        // not indexed, those neighbours that are, and the moved faces: each thread's list is allocated for that here, so that none grows in
        // a parallel loop (but where a fan of high valence could not be indexed).
        const int32_t nv = mesh_.num_vertices();
        std::vector<int32_t> valence(nv, 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int32_t v = 0; v < nv; ++v)
            if (!is_dead_vertex(mesh_, v))
                mesh_.for_each_outgoing(v, [&](int32_t) { ++valence[v]; });
        const int32_t most_neighbours = nv > 0 ? *std::max_element(valence.begin(), valence.end()) + 1 : 0;
        for (std::vector<int32_t> &list : nearby_)
            list.reserve(2 * static_cast<size_t>(most_neighbours) *
                         (std::min(most_neighbours, min_indexed_valence) + 3));
        // The fans of high valence, indexed in parallel (each its own element).
        std::vector<int32_t> hubs;
        for (int32_t v = 0; v < nv; ++v)
            if (valence[v] >= min_indexed_valence)
                hubs.push_back(v);
        if (hubs.empty())
            return;
        std::vector<FanSectors> fans(hubs.size());
        std::vector<char> usable(hubs.size(), 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 1)
        for (size_t k = 0; k < hubs.size(); ++k)
            usable[k] = fans[k].build(mesh_, hubs[k]);
        hubs_.slot.assign(nv, -1);
        for (size_t k = 0; k < hubs.size(); ++k)
            if (usable[k]) {
                hubs_.slot[hubs[k]] = static_cast<int32_t>(hubs_.fans.size());
                hubs_.fans.push_back(std::move(fans[k]));
            }
        hubs_.changed.resize(hubs_.fans.size());
    }

    bool wanted(int32_t h, double &order) const
    {
        if (constraints_.fixed(mesh_.tail(h)) && constraints_.fixed(mesh_.head(h)))
            return false; // neither may go (a required edge's ends are both fixed)
        if (!wants_contraction(mesh_, analysis_, h, repair_.at_edge(mesh_, h),
                               shortness_applies(mesh_, h, features_, guard_), at_cusp(mesh_, h, features_, guard_)))
            return false;
        order = (mesh_.pos[mesh_.head(h)] - mesh_.pos[mesh_.tail(h)]).norm(); // shortest first (§4.2)
        return true;
    }
    // The edge as (gone -> keep), a fixed end kept (-1 where that is a boundary edge's
    // missing half).
    int32_t locate(int32_t a, int32_t b) const
    {
        if (is_dead_vertex(mesh_, a) || is_dead_vertex(mesh_, b))
            return -1;
        const int32_t h = edge_between(mesh_, a, b);
        return h >= 0 && constraints_.fixed(mesh_.tail(h)) ? mesh_.opp[h] : h;
    }
    bool plan(int32_t h, Plan &plan) const
    {
        return contraction_allowed(mesh_, analysis_, h, repair_.at_edge(mesh_, h), features_, constraints_,
                                   shortness_applies(mesh_, h, features_, guard_),
                                   at_cusp(mesh_, h, features_, guard_), hubs_, nearby_[thread_index()],
                                   merged_fans_[thread_index()], tests_[thread_index()], plan.merged);
    }
    // Each contraction marks the merged vertex and its neighbours.
    bool may_have_changed(int32_t h, const ChangedVertices &changed) const
    {
        return near_marked(mesh_, mesh_.tail(h), mesh_.head(h), changed.marks());
    }
    bool apply(MeshEdit &edit, int32_t h, const Plan &plan)
    {
        if (guard_ && merge_crosses(mesh_, h, plan.merged, *guard_))
            return false;
        const int32_t gone = mesh_.tail(h), keep = mesh_.head(h);
        edit.collapse(h, plan.merged);
        if (!hubs_.fans.empty())
            update_hubs(gone, keep);
        return true;
    }

private:
    // After gone was contracted into keep (serial): the faces that changed all have keep as
    // a corner. Keep's own fan is indexed anew, as is a neighbour's whose list grew long;
    // an index that could not be made again is dropped (its fan is then read whole).
    void update_hubs(int32_t gone, int32_t keep)
    {
        const auto rebuild = [&](int32_t v) {
            const int32_t slot = hubs_.slot[v];
            hubs_.changed[slot].clear();
            if (!hubs_.fans[slot].build(mesh_, v))
                hubs_.slot[v] = -1;
        };
        hubs_.slot[gone] = -1;
        if (hubs_.slot[keep] >= 0)
            rebuild(keep);
        mesh_.for_each_neighbour(keep, [&](int32_t w, int32_t) {
            const int32_t slot = hubs_.slot[w];
            if (slot < 0)
                return;
            std::vector<int32_t> &changed = hubs_.changed[slot];
            changed.push_back(keep);
            if (changed.size() > changed_limit(hubs_.fans[slot].size()))
                rebuild(w);
        });
    }

    const TriMesh &mesh_;
    const SurfaceAnalysis &analysis_;
    const LocalRepair repair_;
    const CarriedFeatures &features_;
    const CarriedConstraints &constraints_;
    const CrossingGuard *guard_;
    HubFans hubs_;
    mutable std::vector<std::vector<int32_t>> nearby_; // scratch per thread
    mutable std::vector<FanSectors> merged_fans_;     // scratch per thread

public:
    // The exact triangle tests the clearance checks made, per thread (a count of work).
    mutable std::vector<int64_t> tests_;
};

} // namespace

int32_t contraction_pass(const PassContext &context, const SurfaceAnalysis &analysis, const RepairSettings &settings,
                         int64_t &clearance_tests)
{
    Contraction contraction(context, analysis, settings);
    const int32_t made = run_edge_pass(context.edit, contraction);
    for (const int64_t tests : contraction.tests_)
        clearance_tests += tests;
    return made;
}

} // namespace sfa

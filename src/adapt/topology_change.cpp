// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/topology_change.hpp"

#include "geometry/box_pairs.hpp"
#include "geometry/direction_classes.hpp"
#include "geometry/distance.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/components.hpp"
#include "mesh/parallel.hpp"
#include "mesh/surgery.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

namespace sfa {
namespace {

// Two sheets face each other where their normals are within 60 degrees of opposite.
constexpr double facing_cosine = -0.5;
// A film of the inner phase (a bubble's two walls) tears when its walls are nearer than
// this fraction of the merge distance: a thin bubble stays whole, one pressed flat opens.
constexpr double film_tearing = 0.25;
// Events of one call are at least this many desired lengths apart (see the header).
constexpr double event_spacing = 2;
// How far a pinch's corners move towards the centre of their side's neighbours, as a
// fraction of the way: enough to part the two closing triangles by parted_by merge
// distances, so that the two ends do not merge again at once (at 1.25 they did). Where
// that would take more than most_parting of the way, the neck is not cut yet: the flow
// that thins it draws its ends apart.
constexpr double least_parting = 0.2, most_parting = 0.9, parted_by = 2;
// A closed component whose box is smaller than this many merge distances across is
// below what the mesh resolves there: it is removed (a drop smaller than that is a
// tetrahedron or two, and a flow that crushes it would stop the motion).
constexpr double tiny_drop = 2;

Vec3 unit_normal(const std::vector<Vec3> &pos, const Triangle &t)
{
    return (pos[t[1]] - pos[t[0]]).cross(pos[t[2]] - pos[t[0]]).normalized();
}

double area(const std::vector<Vec3> &pos, const Triangle &t)
{
    return 0.5 * (pos[t[1]] - pos[t[0]]).cross(pos[t[2]] - pos[t[0]]).norm();
}

// The signed volume of a triangle about `centre` (a.(b x c)/6).
double volume_about(const std::vector<Vec3> &pos, const Triangle &t, const Vec3 &centre)
{
    return (pos[t[0]] - centre).dot((pos[t[1]] - centre).cross(pos[t[2]] - centre)) / 6;
}

bool is_live(const Triangle &t) { return t[0] >= 0; }

// True if triangle t's height is below a trillionth of its longest edge: flat to round-off
// for the operations after the events, which read its normal (sfa_set_mesh refuses 4 eps,
// about 9e-16). The corners of two sheets that touch can line up so (a soak finding, seed
// 20261205010480: a tube triangle 3.6e-16 flat, which no later pass could shape).
bool flat(const std::vector<Vec3> &pos, const Triangle &t)
{
    const Vec3 &a = pos[t[0]], &b = pos[t[1]], &c = pos[t[2]];
    const double longest2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    return !((b - a).cross(c - a).norm() > 1e-12 * longest2);
}

struct MergeCandidate {
    double distance;
    int32_t h1, h2;
};

struct PinchCandidate {
    double perimeter;
    int32_t a, b, c;
};

// One event, as applied: enough to undo it and to carry the face fields over it.
struct Event {
    enum class Kind { merge, pinch, removal } kind;
    std::vector<std::pair<int32_t, Triangle>> replaced{}; // triangles changed or removed, as they were
    std::vector<int32_t> added{};                         // triangles appended
    std::vector<std::pair<int32_t, Vec3>> moved{};        // vertices moved, and where they were
    Vec3 centre = Vec3::Zero();
    bool live = true;
};

// The stage: the mesh as a list of triangles (removed ones {-1, -1, -1}) and positions,
// changed event by event; the adjacency of `mesh` stays as on entry, valid around every
// vertex no event has touched.
class Surgery {
public:
    Surgery(const TriMesh &mesh, SurfaceData &data, double merge_distance, double edge_length)
        : mesh_(mesh), data_(data), tri_(mesh.tri), pos_(mesh.pos), ratio_(merge_distance), l_(edge_length),
          used_(mesh.pos.size(), 0)
    {
        const std::vector<char> &fixed = data.constraints.fixed;
        for (size_t v = 0; v < fixed.size(); ++v)
            used_[v] = fixed[v];
        for (const auto &edge : data.constraints.required)
            used_[edge[0]] = used_[edge[1]] = 1;
    }

    void merge_facing_sheets();
    void pinch_thin_necks();
    void remove_tiny_drops(const Components &components);
    // Undoes every event that made or moved a triangle meeting one it shares no corner
    // with, or a flat one.
    void undo_unsound_events();
    // The mesh, the host's data and the hints as the live events left them; the counts.
    TopologyCounts finish(TriMesh &mesh, std::vector<int32_t> &hints);

private:
    double length_at(int32_t v) const { return data_.size.empty() ? l_ : data_.size[v]; }
    double merge_distance(int32_t a, int32_t b) const { return ratio_ * 0.5 * (length_at(a) + length_at(b)); }
    bool far_from_events(const Vec3 &x, double spacing) const
    {
        return std::all_of(events_.begin(), events_.end(),
                           [&](const Event &e) { return (e.centre - x).squaredNorm() >= spacing * spacing; });
    }
    void add_triangle(const Triangle &t, Event &event)
    {
        tri_.push_back(t);
        event.added.push_back(static_cast<int32_t>(tri_.size()) - 1);
    }
    void replace_triangle(int32_t f, const Triangle &t, Event &event)
    {
        event.replaced.emplace_back(f, tri_[f]);
        tri_[f] = t;
    }
    std::vector<MergeCandidate> merge_candidates() const;
    std::vector<PinchCandidate> pinch_candidates() const;
    void apply(const ZipperPlan &plan);
    // False (and nothing done) where the two sides cannot be parted enough.
    bool apply(const PinchPlan &plan);
    void pool_face_fields(const Event &event, const std::vector<Vec3> &old_pos);

    const TriMesh &mesh_;
    SurfaceData &data_;
    std::vector<Triangle> tri_;
    std::vector<Vec3> pos_;
    const double ratio_, l_;
    std::vector<char> used_; // per vertex: in an event already, or pinned by the host
    std::vector<Event> events_;
    std::vector<int32_t> copy_of_; // per vertex appended (a pinch's copy): its corner
    int32_t merges_ = 0, pinches_ = 0, removals_ = 0;
};

std::vector<MergeCandidate> Surgery::merge_candidates() const
{
    // Most overlapping pairs are two edges of one sheet, whose normals cannot face: the
    // search sorts the edges by the classes of their normals and passes over the pairs of
    // classes that cannot face unseen (box_pairs.hpp).
    static const DirectionClasses classes(facing_cosine);
    const int32_t faces = mesh_.num_triangles();
    std::vector<Vec3> face_normals(static_cast<size_t>(faces));
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t f = 0; f < faces; ++f)
        if (is_live(mesh_.tri[f]))
            face_normals[f] = unit_normal(pos_, mesh_.tri[f]);
    // Every interior edge once, by its half-edge h > twin, with the class of its normal,
    // the mean of its triangles' (the class of a sum is that of its direction), and its
    // box grown by d / 2 all round, so that two edges closer than d have overlapping boxes.
    std::vector<int32_t> edges;
    edges.reserve(mesh_.opp.size() / 2);
    for (int32_t h = 0; h < 3 * faces; ++h)
        if (const int32_t twin = mesh_.opp[h]; twin >= 0 && twin < h)
            edges.push_back(h);
    const int32_t edge_count = static_cast<int32_t>(edges.size());
    std::vector<int16_t> normal_class(edges.size());
    std::vector<Box> boxes(edges.size());
    std::vector<double> extent(edges.size()); // its length and d, for the grid's cells
    const bool uniform = data_.size.empty();
    const double uniform_distance = ratio_ * 0.5 * (l_ + l_); // merge_distance's, without a size field
    const auto distance_of = [&](int32_t a, int32_t b) { return uniform ? uniform_distance : merge_distance(a, b); };
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t e = 0; e < edge_count; ++e) {
        const int32_t h = edges[e], a = mesh_.tail(h), b = mesh_.head(h);
        const double d = distance_of(a, b);
        const Vec3 grow = Vec3::Constant(0.5 * d);
        normal_class[e] = static_cast<int16_t>(
            classes.of(face_normals[TriMesh::face(h)] + face_normals[TriMesh::face(mesh_.opp[h])]));
        boxes[e] = {pos_[a].cwiseMin(pos_[b]) - grow, pos_[a].cwiseMax(pos_[b]) + grow};
        extent[e] = (pos_[b] - pos_[a]).norm() + d;
    }
    double cell = ordered_sum(edge_count, 0.0, [&](int32_t e) { return extent[e]; });
    const size_t count = edges.size();
    if (count < 2 || !(cell > 0))
        return {};
    // Cells of twice the mean box: a box covers about 3 cells instead of 8, and with the
    // pairs of classes that cannot face passed over whole, the grid's entries are what
    // costs (bench_topology's sphere: 92-97 ms a call with cells of two boxes, 115-131 with
    // one, 90-93 with three, 115-127 with six).
    cell = 2 * cell / static_cast<double>(count);
    std::vector<std::vector<MergeCandidate>> found(static_cast<size_t>(loop_threads()));
    const auto normal_of = [&](int32_t h) {
        return (face_normals[TriMesh::face(h)] + face_normals[TriMesh::face(mesh_.opp[h])]).normalized();
    };
    const auto class_of = [&](int32_t s) { return normal_class[s]; };
    const auto may_face = [&](int a, int b) { return classes.may_pair(a, b); };
    for_each_overlapping_pair_across(boxes, DirectionClasses::count, class_of, may_face, cell, [&](int32_t s, int32_t t) {
        const int32_t h1 = edges[s], h2 = edges[t]; // h1 < h2: `edges` is in increasing order
        const Vec3 n1 = normal_of(h1), n2 = normal_of(h2);
        if (!(n1.dot(n2) < facing_cosine))
            return;
        const int32_t a1 = mesh_.tail(h1), b1 = mesh_.head(h1), a2 = mesh_.tail(h2), b2 = mesh_.head(h2);
        if (a1 == a2 || a1 == b2 || b1 == a2 || b1 == b2)
            return;
        const auto [c1, c2] = closest_points(pos_[a1], pos_[b1], pos_[a2], pos_[b2]);
        const double distance = (c2 - c1).norm();
        const double d = std::min(merge_distance(a1, b1), merge_distance(a2, b2));
        if (!(distance < d))
            return;
        // Each on the side of the other its normal points to: the outer phase between
        // them, two drops meet. Each on the side its normal points away from: a film of
        // the inner phase, a bubble's walls, which tears only when pressed together.
        // Where they already touch, facing is enough.
        const Vec3 gap = c2 - c1;
        const double outward = gap.dot(n1), inward = -gap.dot(n2);
        const bool outer_phase = outward >= 0 && inward >= 0, inner_film = outward <= 0 && inward <= 0;
        if (!outer_phase && !(inner_film && distance < film_tearing * d))
            return;
        found[static_cast<size_t>(thread_index())].push_back({distance, h1, h2});
    });
    std::vector<MergeCandidate> all;
    for (const auto &list : found)
        all.insert(all.end(), list.begin(), list.end());
    // Nearest first; ties by edge, so that the order does not depend on the threads.
    std::sort(all.begin(), all.end(), [](const MergeCandidate &x, const MergeCandidate &y) {
        return std::tie(x.distance, x.h1, x.h2) < std::tie(y.distance, y.h1, y.h2);
    });
    return all;
}

void Surgery::merge_facing_sheets()
{
    for (const MergeCandidate &candidate : merge_candidates()) {
        ZipperPlan plan;
        if (!plan_zipper(mesh_, candidate.h1, candidate.h2, plan))
            continue;
        bool free = true;
        for (const Triangle &t : plan.tube)
            for (int32_t v : t)
                free = free && !used_[v];
        const int32_t a = mesh_.tail(candidate.h1);
        if (!free || !far_from_events(pos_[a], event_spacing * length_at(a)))
            continue;
        apply(plan);
        ++merges_;
    }
}

void Surgery::apply(const ZipperPlan &plan)
{
    Event event{Event::Kind::merge};
    event.centre = Vec3::Zero();
    for (const Triangle &t : plan.tube) {
        add_triangle(t, event);
        event.centre += pos_[t[0]] / 8; // each corner is the first of two tube triangles
        for (int32_t v : t)
            used_[v] = 1;
    }
    for (int32_t f : plan.removed)
        replace_triangle(f, {-1, -1, -1}, event);
    events_.push_back(std::move(event));
}

std::vector<PinchCandidate> Surgery::pinch_candidates() const
{
    std::vector<PinchCandidate> all;
    std::vector<int32_t> short_neighbours;
    const auto is_short = [&](int32_t v, int32_t w) { return (pos_[w] - pos_[v]).norm() < merge_distance(v, w); };
    // A loop's first corner a has two short edges to higher corners: only such vertices
    // are searched around, found in one pass over the edges (most calls have none).
    std::vector<uint8_t> short_to_higher(mesh_.pos.size(), 0);
    for (int32_t f = 0; f < mesh_.num_triangles(); ++f) {
        const Triangle &t = mesh_.tri[f];
        for (int k = 0; k < 3; ++k) {
            const int32_t twin = mesh_.opp[3 * f + k], a = t[k], b = t[k == 2 ? 0 : k + 1];
            if ((twin < 0 || twin > 3 * f + k) && is_short(a, b)) {
                uint8_t &count = short_to_higher[std::min(a, b)];
                count = static_cast<uint8_t>(std::min(count + 1, 2));
            }
        }
    }
    for (int32_t a = 0; a < mesh_.num_vertices(); ++a) {
        if (short_to_higher[a] < 2 || mesh_.v2h[a] < 0 || mesh_.is_boundary_vertex(a))
            continue;
        short_neighbours.clear();
        mesh_.for_each_neighbour(a, [&](int32_t w, int32_t) {
            if (w > a && is_short(a, w))
                short_neighbours.push_back(w);
        });
        for (int32_t b : short_neighbours)
            for (int32_t c : short_neighbours)
                if (c > b && is_short(b, c) && mesh_.halfedge(b, c) >= 0)
                    all.push_back({(pos_[b] - pos_[a]).norm() + (pos_[c] - pos_[b]).norm() + (pos_[a] - pos_[c]).norm(),
                                   a, b, c});
    }
    std::sort(all.begin(), all.end(), [](const PinchCandidate &x, const PinchCandidate &y) {
        return std::tie(x.perimeter, x.a, x.b, x.c) < std::tie(y.perimeter, y.a, y.b, y.c);
    });
    return all;
}

void Surgery::pinch_thin_necks()
{
    PinchPlan plan;
    for (const PinchCandidate &candidate : pinch_candidates()) {
        // Most loops of three short edges are triangles: plan_pinch says which are not.
        if (used_[candidate.a] || used_[candidate.b] || used_[candidate.c] ||
            !plan_pinch(mesh_, candidate.a, candidate.b, candidate.c, plan))
            continue;
        // No other event within a ring of the loop: each event's triangles are its own.
        bool free = true;
        for (int32_t v : plan.loop)
            mesh_.for_each_neighbour(v, [&](int32_t w, int32_t) { free = free && !used_[w]; });
        if (free && apply(plan))
            ++pinches_;
    }
}

bool Surgery::apply(const PinchPlan &plan)
{
    Event event{Event::Kind::pinch};
    // The two sides' triangles around the loop, and the centres of their other corners.
    std::vector<int32_t> around;
    for (int32_t v : plan.loop)
        mesh_.for_each_outgoing(v, [&](int32_t h) { around.push_back(TriMesh::face(h)); });
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    Vec3 centre[2] = {Vec3::Zero(), Vec3::Zero()};
    int32_t count[2] = {0, 0};
    for (int32_t f : around) {
        const int side = std::binary_search(plan.left.begin(), plan.left.end(), f) ? 0 : 1;
        for (int32_t v : tri_[f])
            if (v != plan.loop[0] && v != plan.loop[1] && v != plan.loop[2]) {
                centre[side] += pos_[v];
                ++count[side];
            }
    }
    for (int side = 0; side < 2; ++side)
        centre[side] /= std::max(count[side], 1);
    const auto [a, b, c] = plan.loop;
    const double wanted = parted_by * std::max({merge_distance(a, b), merge_distance(b, c), merge_distance(c, a)});
    const double needed = wanted / (centre[0] - centre[1]).norm();
    if (!(needed <= most_parting))
        return false;
    const double parting = std::max(needed, least_parting);

    std::array<int32_t, 3> copies;
    for (int k = 0; k < 3; ++k) {
        const int32_t v = plan.loop[k];
        copies[k] = static_cast<int32_t>(pos_.size());
        pos_.push_back(pos_[v] + parting * (centre[0] - pos_[v]));
        copy_of_.push_back(v);
        used_.push_back(1);
        event.moved.emplace_back(v, pos_[v]);
        pos_[v] += parting * (centre[1] - pos_[v]);
        used_[v] = 1;
        mesh_.for_each_neighbour(v, [&](int32_t w, int32_t) { used_[w] = 1; });
    }
    for (int32_t f : around) {
        const bool left = std::binary_search(plan.left.begin(), plan.left.end(), f);
        replace_triangle(f, left ? with_copies(plan, tri_[f], copies) : tri_[f], event); // the right side's corners moved
    }
    for (const Triangle &cap : pinch_caps(plan, copies))
        add_triangle(cap, event);
    event.centre = (pos_[plan.loop[0]] + pos_[plan.loop[1]] + pos_[plan.loop[2]]) / 3;
    events_.push_back(std::move(event));
    return true;
}

void Surgery::remove_tiny_drops(const Components &components)
{
    // A drop is tiny where its box is narrower than tiny_drop times its corners' mean merge
    // distance, which is at most ratio_ times the longest length: a box wider than twice
    // that (room for the mean's rounding) is not, and the rest of its corners are not read
    // (a bubble of the whole surface costs a few hundred of them, not all).
    const double longest = data_.size.empty() ? l_ : *std::max_element(data_.size.begin(), data_.size.end());
    const double surely_wide = 2 * tiny_drop * ratio_ * longest;
    std::vector<std::pair<int32_t, Vec3>> tiny; // the components to remove, and their centres
    int32_t tiny_triangles = 0;
    for (int32_t c = 0; c < components.count; ++c) {
        if (!components.closed[c])
            continue;
        Vec3 lowest = Vec3::Constant(std::numeric_limits<double>::infinity()), highest = -lowest;
        double distance = 0;
        int32_t corners = 0;
        bool pinned = false, wide = false;
        const int32_t first = components.triangle_start[c], last = components.triangle_start[c + 1];
        for (int32_t k = first; k < last && !wide; ++k) {
            for (int32_t v : tri_[components.triangles[k]]) {
                lowest = lowest.cwiseMin(pos_[v]);
                highest = highest.cwiseMax(pos_[v]);
                distance += ratio_ * length_at(v);
                ++corners;
                pinned = pinned || used_[v];
            }
            if ((k - first) % 64 == 63)
                wide = (highest - lowest).norm() >= surely_wide;
        }
        if (wide || pinned || !((highest - lowest).norm() < tiny_drop * distance / corners))
            continue;
        tiny.push_back({c, 0.5 * (lowest + highest)});
        tiny_triangles += last - first;
    }
    // A surface that is all tiny drops stays: a call leaves a surface, never nothing (a
    // soak finding, seed 20261205015752: a box two edges across, its merge distance 1.17 l).
    if (tiny_triangles == static_cast<int32_t>(tri_.size()))
        return;
    for (const auto &[c, centre] : tiny) {
        Event event{Event::Kind::removal};
        event.centre = centre;
        for (int32_t k = components.triangle_start[c]; k < components.triangle_start[c + 1]; ++k) {
            for (int32_t v : tri_[components.triangles[k]])
                used_[v] = 1; // no pinch of what is gone
            replace_triangle(components.triangles[k], {-1, -1, -1}, event);
        }
        events_.push_back(std::move(event));
        ++removals_;
    }
}

void Surgery::undo_unsound_events()
{
    // Each round undoes at least one event, or ends. A removal makes no triangle.
    const auto makes_triangles = [](const Event &e) { return e.live && e.kind != Event::Kind::removal; };
    for (size_t round = 0; round <= events_.size(); ++round) {
        if (std::none_of(events_.begin(), events_.end(), makes_triangles))
            return;
        std::vector<int32_t> event_of(tri_.size(), -1);
        for (size_t e = 0; e < events_.size(); ++e) {
            if (!makes_triangles(events_[e]))
                continue;
            for (int32_t f : events_[e].added)
                event_of[f] = static_cast<int32_t>(e);
            for (const auto &[f, was] : events_[e].replaced)
                if (is_live(tri_[f]))
                    event_of[f] = static_cast<int32_t>(e);
        }
        const double nan = std::numeric_limits<double>::quiet_NaN();
        std::vector<Box> boxes(tri_.size());
        double cell = 0;
        int32_t live = 0;
        for (size_t f = 0; f < tri_.size(); ++f) {
            const Triangle &t = tri_[f];
            if (!is_live(t)) {
                boxes[f] = {Vec3::Constant(nan), Vec3::Constant(nan)}; // overlaps nothing
                continue;
            }
            boxes[f] = {pos_[t[0]].cwiseMin(pos_[t[1]]).cwiseMin(pos_[t[2]]),
                        pos_[t[0]].cwiseMax(pos_[t[1]]).cwiseMax(pos_[t[2]])};
            cell += (pos_[t[1]] - pos_[t[0]]).norm();
            ++live;
        }
        if (live < 2 || !(cell > 0))
            return;
        // Crossings the stage did not make are not its to undo: only the pairs with a
        // triangle an event made or moved are looked at.
        std::vector<int32_t> of_events;
        for (size_t f = 0; f < tri_.size(); ++f)
            if (event_of[f] >= 0)
                of_events.push_back(static_cast<int32_t>(f));
        std::vector<char> unsound(events_.size(), 0);
        for (const int32_t f : of_events)
            if (flat(pos_, tri_[f]))
                unsound[event_of[f]] = 1;
        for_each_overlapping_pair_with(boxes, of_events, 2 * cell / live, [&](int32_t s, int32_t t) {
            const Triangle &p = tri_[s], &q = tri_[t];
            if (share_a_vertex(p, q) ||
                !triangles_intersect(pos_[p[0]], pos_[p[1]], pos_[p[2]], pos_[q[0]], pos_[q[1]], pos_[q[2]]))
                return;
            for (int32_t e : {event_of[s], event_of[t]})
                if (e >= 0)
                    unsound[e] = 1; // a byte each: the race writes the same value
        });
        bool undone = false;
        for (size_t e = 0; e < events_.size(); ++e) {
            if (!unsound[e])
                continue;
            Event &event = events_[e];
            for (int32_t f : event.added)
                tri_[f] = {-1, -1, -1};
            for (auto it = event.replaced.rbegin(); it != event.replaced.rend(); ++it)
                tri_[it->first] = it->second;
            for (const auto &[v, was] : event.moved)
                pos_[v] = was;
            event.live = false;
            (event.kind == Event::Kind::merge ? merges_ : pinches_) -= 1; // a removal makes no triangle
            undone = true;
        }
        if (!undone)
            return;
    }
}

void Surgery::pool_face_fields(const Event &event, const std::vector<Vec3> &old_pos)
{
    // The event's triangles before (those it replaced) and after (the same, now, and those
    // it added) share one density per component: their integral, over their area now.
    double area_after = 0;
    for (const auto &[f, was] : event.replaced)
        if (is_live(tri_[f]))
            area_after += area(pos_, tri_[f]);
    for (int32_t f : event.added)
        area_after += area(pos_, tri_[f]);
    if (!(area_after > 0))
        return; // nothing to spread it over: the event made only flat triangles
    for (FaceField &field : data_.face_fields) {
        const size_t n = static_cast<size_t>(field.ncomp);
        field.values.resize(n * tri_.size(), 0);
        for (size_t c = 0; c < n; ++c) {
            double integral = 0;
            for (const auto &[f, was] : event.replaced)
                integral += field.values[n * f + c] * area(old_pos, was);
            const double density = integral / area_after;
            for (const auto &[f, was] : event.replaced)
                if (is_live(tri_[f]))
                    field.values[n * f + c] = density;
            for (int32_t f : event.added)
                field.values[n * f + c] = density;
        }
    }
}

TopologyCounts Surgery::finish(TriMesh &mesh, std::vector<int32_t> &hints)
{
    TopologyCounts counts{merges_, pinches_, removals_, 0};
    if (merges_ + pinches_ + removals_ == 0)
        return counts; // the mesh as it came (an undone pinch's copies are not in it)
    const std::vector<Vec3> &old_pos = mesh.pos;
    for (const Event &event : events_) {
        if (!event.live)
            continue;
        pool_face_fields(event, old_pos);
        // The change of volume: the event's triangles after, less those before, about a
        // point near them (the two sets have the same boundary, so the point is free).
        double change = 0;
        for (const auto &[f, was] : event.replaced) {
            change -= volume_about(old_pos, was, event.centre);
            if (is_live(tri_[f]))
                change += volume_about(pos_, tri_[f], event.centre);
        }
        for (int32_t f : event.added)
            change += volume_about(pos_, tri_[f], event.centre);
        counts.volume_change += std::abs(change);
    }

    // The vertices still in a triangle, in order (the copies of live pinches after those
    // on entry), each with the vertex on entry it takes its values from; the live triangles.
    const int32_t entry_vertices = mesh.num_vertices();
    std::vector<char> referenced(pos_.size(), 0);
    for (const Triangle &t : tri_)
        if (is_live(t))
            for (int32_t v : t)
                referenced[v] = 1;
    std::vector<int32_t> vertex_of(pos_.size(), -1), source;
    for (size_t v = 0; v < pos_.size(); ++v)
        if (referenced[v]) {
            vertex_of[v] = static_cast<int32_t>(source.size());
            source.push_back(v < static_cast<size_t>(entry_vertices) ? static_cast<int32_t>(v)
                                                                     : copy_of_[v - static_cast<size_t>(entry_vertices)]);
        }
    TriMesh out;
    out.pos.resize(source.size());
    for (size_t v = 0; v < pos_.size(); ++v)
        if (vertex_of[v] >= 0)
            out.pos[vertex_of[v]] = pos_[v];
    std::vector<size_t> kept_triangles;
    for (size_t f = 0; f < tri_.size(); ++f)
        if (is_live(tri_[f])) {
            out.tri.push_back({vertex_of[tri_[f][0]], vertex_of[tri_[f][1]], vertex_of[tri_[f][2]]});
            kept_triangles.push_back(f);
        }
    build_adjacency(out);

    // What lives on vertices goes with them; a copy takes its corner's values.
    const auto carry = [&](auto &values, size_t per_vertex) {
        if (values.empty())
            return;
        std::remove_reference_t<decltype(values)> out_values(per_vertex * source.size());
        for (size_t k = 0; k < source.size(); ++k)
            std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(per_vertex * static_cast<size_t>(source[k])),
                        per_vertex, out_values.begin() + static_cast<std::ptrdiff_t>(per_vertex * k));
        values.swap(out_values);
    };
    for (VertexField &field : data_.fields)
        carry(field.values, static_cast<size_t>(field.ncomp));
    carry(data_.size, 1);
    carry(hints, 1);
    carry(data_.constraints.fixed, 1);
    for (auto &edge : data_.constraints.required)
        edge = {vertex_of[edge[0]], vertex_of[edge[1]]}; // in no event: never removed, never after a copy
    for (FaceField &field : data_.face_fields) {
        const size_t n = static_cast<size_t>(field.ncomp);
        std::vector<double> kept(n * kept_triangles.size());
        for (size_t k = 0; k < kept_triangles.size(); ++k)
            std::copy_n(field.values.begin() + static_cast<std::ptrdiff_t>(n * kept_triangles[k]), n,
                        kept.begin() + static_cast<std::ptrdiff_t>(n * k));
        field.values.swap(kept);
    }
    mesh = std::move(out);
    return counts;
}

} // namespace

TopologyCounts change_topology(TriMesh &mesh, SurfaceData &data, Components &components, double merge_distance,
                               double edge_length, std::vector<int32_t> &origin_hints)
{
    TopologyCounts counts;
    // Merges first, on the mesh as it came; then pinches, on the mesh the merges left; then,
    // if a pinch cut off a drop below what the mesh resolves, its removal. (Left for the
    // next call, such a drop of a few triangles went through this call's remeshing, which
    // changed its volume by up to half, more than the correction could take back: a soak
    // finding, seed 20261207000573.)
    for (int stage = 0; stage < 3; ++stage) {
        if (stage == 2 && counts.pinches == 0)
            break;
        Surgery surgery(mesh, data, merge_distance, edge_length);
        if (stage == 0) {
            surgery.merge_facing_sheets();
        } else {
            surgery.remove_tiny_drops(components);
            if (stage == 1)
                surgery.pinch_thin_necks();
        }
        surgery.undo_unsound_events();
        const TopologyCounts made = surgery.finish(mesh, origin_hints);
        if (made.merges + made.pinches + made.removals > 0)
            components = connected_components(mesh);
        counts.merges += made.merges;
        counts.pinches += made.pinches;
        counts.removals += made.removals;
        counts.volume_change += made.volume_change;
    }
    return counts;
}

} // namespace sfa

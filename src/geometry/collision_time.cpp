// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/collision_time.hpp"

#include "geometry/swept_pairs.hpp"
#include "geometry/distance.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sfa {
namespace {

// The six corners of a pair, positions and velocities.
struct PairMotion {
    Vec3 x[6], v[6];
};

// For two triangles that touch along n within round-off (their corners' speeds w along n;
// `lower` as in time_across): there is no gap to share, and the pair may move only as long
// as no corner crosses the plane towards the other triangle by more than the round-off. A
// pair that slides along the plane or opens moves on; one that closes is held (a cone
// smoothed until two faces touched 8e-15 apart, then moved into each other, crossed).
double time_touching(const double (&w)[6], double plane_speed, int lower, double roundoff,
                     double &gap, double &closing)
{
    double time = std::numeric_limits<double>::infinity(), rise = 0, fall = 0;
    for (int k = 0; k < 6; ++k) {
        const double relative = w[k] - plane_speed;
        const bool below = (k < 3) == (lower == 0);
        if (below && relative > 0) {
            time = std::min(time, roundoff / relative);
            rise = std::max(rise, relative);
        } else if (!below && relative < 0) {
            time = std::min(time, -roundoff / relative);
            fall = std::max(fall, -relative);
        }
    }
    gap = 0;
    closing = rise + fall;
    return time;
}

// The time the pair may move while a plane of normal n, moving along n with the mean
// speed of the six corners, stays between them, each triangle's corners taking at most a
// quarter of the gap (the plane moving, a sheet carried along as a whole is not held
// back); if they touch along n within round-off, time_touching's time; 0 if n does not
// separate them at the start. `gap` and `closing` are set unless it returns 0.
double time_across(const PairMotion &m, const Vec3 &n, double &gap, double &closing)
{
    double p[6], w[6], scale = 0, plane_speed = 0;
    for (int k = 0; k < 6; ++k) {
        p[k] = n.dot(m.x[k]);
        w[k] = n.dot(m.v[k]);
        plane_speed += w[k] / 6;
        scale = std::max(scale, n.cwiseAbs().dot(m.x[k].cwiseAbs()));
    }
    const double lo_a = std::min({p[0], p[1], p[2]}), hi_a = std::max({p[0], p[1], p[2]});
    const double lo_b = std::min({p[3], p[4], p[5]}), hi_b = std::max({p[3], p[4], p[5]});
    // Each projection is within a few roundings of n.x; a gap not well above them is no proof.
    const double roundoff = 8 * 0x1p-53 * scale;
    int lower; // 0: a below b along n, 1: b below a
    if (hi_a + roundoff < lo_b) {
        lower = 0;
        gap = lo_b - hi_a;
    } else if (hi_b + roundoff < lo_a) {
        lower = 1;
        gap = lo_a - hi_b;
    } else if (std::max(lo_b - hi_a, lo_a - hi_b) >= -roundoff) {
        const double time =
            time_touching(w, plane_speed, lo_b - hi_a >= lo_a - hi_b ? 0 : 1, roundoff, gap, closing);
        closing /= n.norm();
        return time;
    } else {
        return 0;
    }
    // Relative to the plane, the lower triangle may rise to `top` and the upper fall to `bottom`.
    const double top = (lower == 0 ? hi_a : hi_b) + gap / 4, bottom = (lower == 0 ? lo_b : lo_a) - gap / 4;
    double time = std::numeric_limits<double>::infinity(), rise = 0, fall = 0;
    for (int k = 0; k < 6; ++k) {
        const double relative = w[k] - plane_speed;
        const bool below = (k < 3) == (lower == 0);
        if (below && relative > 0) {
            time = std::min(time, (top - p[k]) / relative);
            rise = std::max(rise, relative);
        } else if (!below && relative < 0) {
            time = std::min(time, (bottom - p[k]) / relative);
            fall = std::max(fall, -relative);
        }
    }
    const double length = n.norm();
    gap /= length;
    closing = (rise + fall) / length;
    return time;
}

// The line from the first triangle's centroid to the second's, three times as long.
Vec3 line_of_centres(const PairMotion &m) { return m.x[3] + m.x[4] + m.x[5] - m.x[0] - m.x[1] - m.x[2]; }

// A lower bound of the distance between the pair's triangles at the start: the gap between
// their projections on the line of centres (negative where they overlap), less a margin
// for its rounding, so that it never exceeds the distance triangle_distance measures.
double gap_along_centres(const PairMotion &m)
{
    const Vec3 n = line_of_centres(m);
    const double length = n.norm();
    if (!(length > 0))
        return -std::numeric_limits<double>::infinity();
    double scale = 0;
    for (const Vec3 &x : m.x)
        scale = std::max(scale, x.cwiseAbs().maxCoeff());
    const double high_a = std::max({n.dot(m.x[0]), n.dot(m.x[1]), n.dot(m.x[2])}),
                 low_b = std::min({n.dot(m.x[3]), n.dot(m.x[4]), n.dot(m.x[5])});
    return (low_b - high_a) / length - 1e-12 * scale;
}

// How long the pair may move: the longest of the times its separating planes allow, or
// some time beyond `limit` once one plane allows that much.
Approach pair_approach(const PairMotion &m, double limit)
{
    Approach best;
    best.time = 0;
    const auto consider = [&](const Vec3 &n) {
        if (best.time > limit || n == Vec3::Zero())
            return;
        double gap = 0, closing = 0;
        const double time = time_across(m, n, gap, closing);
        if (time > best.time) {
            best.time = time;
            best.gap = gap;
            best.closing = closing;
        }
    };
    // The plane square to the line of centres first: it separates nearly every pair that
    // the balls leave, whether side by side in one sheet or facing across two (on the first
    // 60 steps of collision-safe Enright, all but 1.3 % of them; the face normals first
    // needed 2.7 planes a pair), and the other planes are not even made. Then the face
    // normals, and the planes through an edge square to its face, which separate the two
    // where they are nearly coplanar.
    consider(line_of_centres(m));
    if (best.time > limit)
        return best;
    Vec3 edge_a[3], edge_b[3];
    for (int k = 0; k < 3; ++k) {
        edge_a[k] = m.x[(k + 1) % 3] - m.x[k];
        edge_b[k] = m.x[3 + (k + 1) % 3] - m.x[3 + k];
    }
    const Vec3 normal_a = edge_a[0].cross(edge_a[1]), normal_b = edge_b[0].cross(edge_b[1]);
    consider(normal_a);
    consider(normal_b);
    for (int k = 0; k < 3; ++k) {
        consider(normal_a.cross(edge_a[k]));
        consider(normal_b.cross(edge_b[k]));
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            consider(edge_a[i].cross(edge_b[j]));
    return best;
}

// How long the pair may move before it comes nearer than half its distance at the start,
// found by additive continuous collision detection (Li, Kaufman and Jiang, "Codimensional
// incremental potential contact", 2021): the distance between the two triangles shrinks
// no faster than the sum of the two largest corner speeds relative to the pair's mean
// motion, so a step of 0.9 times (distance - target) / that speed cannot reach the target;
// take it, measure the distance again, repeat. A pair that slides along itself keeps its
// distance and goes on, where a separating plane fixed at the start would soon be crossed
// by a turning pair (the layers at a cusp). Some time beyond `limit` once it gets there;
// 0 where the distance is too small to measure against the coordinates' rounding.
double additive_time(const PairMotion &m, double limit)
{
    Vec3 mean = Vec3::Zero();
    for (const Vec3 &v : m.v)
        mean += v / 6;
    double speed_a = 0, speed_b = 0, scale = 0;
    for (int k = 0; k < 3; ++k) {
        speed_a = std::max(speed_a, (m.v[k] - mean).norm());
        speed_b = std::max(speed_b, (m.v[3 + k] - mean).norm());
    }
    for (const Vec3 &x : m.x)
        scale = std::max(scale, x.cwiseAbs().maxCoeff());
    const double speed = speed_a + speed_b;
    Vec3 a[3], b[3];
    const auto distance_at = [&](double t) {
        for (int k = 0; k < 3; ++k) {
            a[k] = m.x[k] + t * (m.v[k] - mean);
            b[k] = m.x[3 + k] + t * (m.v[3 + k] - mean);
        }
        return triangle_distance(a, b);
    };
    double distance = distance_at(0);
    if (!(distance > 1e-9 * scale))
        return 0;
    if (!(speed > 0))
        return std::numeric_limits<double>::infinity();
    const double target = distance / 2;
    // Each step closes at most nine tenths of what is left to the target, so the steps
    // shrink geometrically only while the pair truly closes in: once it has used nearly
    // all of its allowance, that is its time. A bound on the number of steps keeps a pair
    // that turns fast a hair apart from costing much (it then limits the step to the time
    // reached, which is safe).
    constexpr int max_steps = 1000;
    const double nearly_used = target + 0.05 * (distance - target);
    double t = 0;
    for (int step = 0; step < max_steps && t <= limit && distance > nearly_used; ++step) {
        t += 0.9 * (distance - target) / speed;
        distance = distance_at(t);
    }
    return t;
}

// A triangle as a ball moving with its mean velocity: every point of it is within
// `radius` of the centre and moves within `spread` of the mean velocity.
struct Reach {
    Vec3 centre, velocity;
    double radius, spread;
};

Reach reach_of(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &va, const Vec3 &vb, const Vec3 &vc)
{
    Reach r;
    r.centre = (a + b + c) / 3;
    r.velocity = (va + vb + vc) / 3;
    r.radius = std::sqrt(std::max({(a - r.centre).squaredNorm(), (b - r.centre).squaredNorm(),
                                   (c - r.centre).squaredNorm()}));
    r.spread = std::sqrt(std::max({(va - r.velocity).squaredNorm(), (vb - r.velocity).squaredNorm(),
                                   (vc - r.velocity).squaredNorm()}));
    return r;
}

// True if the two cannot meet within dt: the gap between their balls is more than their
// points' relative motion can close (the ball of each moves with its mean velocity, and
// each point within its spread of it). The margins cover the rounding: of the speeds, of
// centres and radii, which are as exact as the coordinates are far from the origin, and of
// the positions at the end of the step (rounding_of_step's pairs are not out of reach).
bool out_of_reach(const Reach &s, const Reach &t, double dt)
{
    const double reach = dt * ((s.velocity - t.velocity).norm() + s.spread + t.spread);
    const double rounding = 1e-14 * (s.centre.cwiseAbs().maxCoeff() + t.centre.cwiseAbs().maxCoeff() + s.radius +
                                     t.radius + dt * (s.velocity.cwiseAbs().maxCoeff() + t.velocity.cwiseAbs().maxCoeff()));
    const double clear = s.radius + t.radius + (1 + 1e-6) * reach + rounding; // the centres' distance needed
    return (s.centre - t.centre).squaredNorm() > clear * clear;
}

bool earlier(const Approach &a, const Approach &b)
{
    if (a.time != b.time)
        return a.time < b.time;
    return a.first != b.first ? a.first < b.first : a.second < b.second;
}

// A gap below which a separating plane does not certify the pair in floating point, in
// units of 2^-53 of S, the largest coordinate of its corners at either end of the step: the
// step's positions x + t v, each coordinate rounded on its own (or a Runge-Kutta step's,
// whose velocity is its displacement over its time), move the corners relative to each
// other by up to some 14 of them, and the plane's own arithmetic (the projections, the gap,
// the corners' share of it) errs by up to some 42; the certificate keeps half the gap.
double rounding_of_step(const PairMotion &m, double dt)
{
    double scale = 0;
    for (int k = 0; k < 6; ++k)
        scale = std::max({scale, m.x[k].cwiseAbs().maxCoeff(), (m.x[k] + dt * m.v[k]).cwiseAbs().maxCoeff()});
    return 128 * 0x1p-53 * scale;
}

// first_approach and first_approach_with_contacts: `contacts`, `among` and
// `within_rounding` may be null.
Approach approach_of_pairs(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double contact_gap,
                           std::vector<Approach> *contacts, const std::vector<int32_t> *among, BlockPartition *kept,
                           TrianglePairs *within_rounding)
{
    Approach first;
    first.time = dt;
    const int32_t n = mesh.num_triangles();
    if (n < 2)
        return first;
    // Each triangle's box at the start and the box of its corners' displacements; and the
    // ball its points stay within.
    const auto swept_of = [&](int32_t t) {
        const Triangle &c = mesh.tri[t];
        const Vec3 x[3] = {mesh.pos[c[0]], mesh.pos[c[1]], mesh.pos[c[2]]};
        const Vec3 d[3] = {dt * velocity[c[0]], dt * velocity[c[1]], dt * velocity[c[2]]};
        return swept_triangle(c, x, d);
    };
    const auto reach_of_triangle = [&](int32_t t) {
        const Triangle &c = mesh.tri[t];
        return reach_of(mesh.pos[c[0]], mesh.pos[c[1]], mesh.pos[c[2]], velocity[c[0]], velocity[c[1]],
                        velocity[c[2]]);
    };

    std::vector<Approach> per_thread(static_cast<size_t>(loop_threads()), first);
    std::vector<std::vector<Approach>> touching(per_thread.size());
    std::vector<TrianglePairs> rounding_pairs(per_thread.size());
    // Triangles s < t. Their balls are made here, two for each pair the broad phase finds:
    // on vortex T = 2 half as many as one for every triangle, which took 0.81 G of its
    // collision-safe run's 76.9 G instructions.
    const auto look_at = [&](int32_t s, int32_t t, int thread) {
        Approach &mine = per_thread[static_cast<size_t>(thread)];
        const Triangle &p = mesh.tri[s], &q = mesh.tri[t];
        if (share_a_vertex(p, q))
            return; // neighbours, the fold control's concern (the blocks' sweep leaves them out already)
        const Reach reach_s = reach_of_triangle(s), reach_t = reach_of_triangle(t);
        if (out_of_reach(reach_s, reach_t, dt))
            return; // too far apart for how differently they move: most neighbours in a sheet
        PairMotion m;
        for (int k = 0; k < 3; ++k) {
            m.x[k] = mesh.pos[p[k]];
            m.v[k] = velocity[p[k]];
            m.x[3 + k] = mesh.pos[q[k]];
            m.v[3 + k] = velocity[q[k]];
        }
        const auto longest_edge = [&] {
            double size = 0;
            for (int k = 0; k < 3; ++k)
                size = std::max({size, (m.x[(k + 1) % 3] - m.x[k]).norm(), (m.x[3 + (k + 1) % 3] - m.x[3 + k]).norm()});
            return size;
        };
        // A pair nearer than contact_gap of its size (its longest edge) may be a contact: it
        // is sought over the whole step. Any other only matters if it comes before the first
        // approach yet. The balls' gap and the gap along the line of centres are lower
        // bounds of the distance that rule most pairs out cheaply (side by side in a sheet,
        // the balls overlap, and the gap along their centres is most of an edge): no edge
        // is longer than a ball's diameter, so the size is measured only for the rest.
        double size = -1; // not measured yet
        bool near = false;
        if (contacts) {
            const double balls_gap = (reach_s.centre - reach_t.centre).norm() - reach_s.radius - reach_t.radius;
            // The larger diameter, with room for the radii's rounding.
            const double most = contact_gap * 2.000001 * std::max(reach_s.radius, reach_t.radius);
            if (balls_gap < most) {
                if (const double along = gap_along_centres(m); along < most) {
                    size = longest_edge();
                    const double touch = contact_gap * size;
                    near = balls_gap < touch && along < touch && triangle_distance(m.x, m.x + 3) < touch;
                }
            }
        }
        const double limit = near ? dt : mine.time;
        Approach pair = pair_approach(m, limit);
        if (within_rounding && (pair.time == 0 || pair.gap <= rounding_of_step(m, dt)))
            rounding_pairs[static_cast<size_t>(thread)].emplace_back(s, t);
        if (pair.time == 0)
            return; // they meet or touch already: no plane separates them
        if (pair.time < limit) // the pair would limit the step: measure it more closely
            pair.time = std::max(pair.time, additive_time(m, limit));
        pair.first = s;
        pair.second = t;
        if (near && pair.time < dt) {
            pair.size = size;
            touching[static_cast<size_t>(thread)].push_back(pair);
        } else if (earlier(pair, mine)) {
            pair.size = size < 0 ? longest_edge() : size;
            mine = pair;
        }
    };
    if (among) {
        // Few (the later rounds of contact: a few dozen triangles of a mesh of 100k). Only
        // a triangle whose box at rest meets the union of theirs can meet one of them: the
        // others cost a box each. The near ones' boxes at rest go into a grid of their own
        // (box_pairs.hpp), `among` among them. (Before, every triangle's swept box and ball
        // were made and looked up in the grid, 33 ms a round on vortex T = 6 at t = 4.5.)
        const Vec3 none = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
        Box around = {none, none};
        for (int32_t t : *among)
            around = detail::box_union(around, swept_in_frame(swept_of(t), Vec3::Zero()));
        std::vector<char> is_near(static_cast<size_t>(n));
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int32_t t = 0; t < n; ++t)
            is_near[t] = boxes_overlap(swept_in_frame(swept_of(t), Vec3::Zero()), around);
        std::vector<int32_t> near; // increasing, so that a pair's local order is its order
        for (int32_t t = 0; t < n; ++t)
            if (is_near[t])
                near.push_back(t);
        const int32_t count = static_cast<int32_t>(near.size());
        std::vector<Box> boxes(near.size());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int32_t k = 0; k < count; ++k)
            boxes[k] = swept_in_frame(swept_of(near[k]), Vec3::Zero());
        double extent = 0;
        for (const Box &box : boxes)
            extent += (box[1] - box[0]).maxCoeff();
        std::vector<int32_t> some; // `among` by its place in `near` (a NaN box is in neither)
        for (int32_t t : *among)
            if (const auto at = std::lower_bound(near.begin(), near.end(), t); at != near.end() && *at == t)
                some.push_back(static_cast<int32_t>(at - near.begin()));
        LoopFailure failure; // look_at lists the contacts as it finds them
        if (const double cell = extent / count; cell > 0)
            for_each_overlapping_pair_with(boxes, some, cell, [&](int32_t s, int32_t t) {
                failure.run([&] { look_at(near[s], near[t], thread_index()); });
            });
        failure.rethrow();
    } else {
        FillBuffer<SweptTriangle> swept(static_cast<size_t>(n));
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int32_t t = 0; t < n; ++t)
            swept[t] = swept_of(t);
        for_each_pair_that_may_meet(swept, look_at, kept);
    }
    for (const Approach &a : per_thread)
        if (earlier(a, first))
            first = a;
    if (within_rounding)
        for (const auto &list : rounding_pairs)
            within_rounding->insert(within_rounding->end(), list.begin(), list.end());
    if (contacts) {
        contacts->clear();
        for (const auto &list : touching)
            contacts->insert(contacts->end(), list.begin(), list.end());
        std::sort(contacts->begin(), contacts->end(), [](const Approach &a, const Approach &b) {
            return a.first != b.first ? a.first < b.first : a.second < b.second;
        });
    }
    return first;
}

} // namespace

Approach first_approach(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt,
                        const std::vector<int32_t> *among, BlockPartition *kept, TrianglePairs *within_rounding)
{
    return approach_of_pairs(mesh, velocity, dt, 0, nullptr, among, kept, within_rounding);
}

Approach first_approach_with_contacts(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt,
                                      double contact_gap, std::vector<Approach> &contacts,
                                      const std::vector<int32_t> *among, BlockPartition *kept,
                                      TrianglePairs *within_rounding)
{
    return approach_of_pairs(mesh, velocity, dt, contact_gap, &contacts, among, kept, within_rounding);
}

} // namespace sfa

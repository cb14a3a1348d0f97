// SPDX-License-Identifier: BSD-3-Clause
#include "motion/safe_motion.hpp"

#include "mesh/error.hpp"
#include "geometry/box_pairs.hpp"
#include "geometry/collision_time.hpp"
#include "geometry/triangle_intersection.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace sfa {
namespace {

// Throws if the pair that limits the step is too close to let it approach any further.
// `when` says when the step starts.
void require_room(const Approach &a, const char *when, int32_t index_base)
{
    if (!(a.gap < stuck_gap_ratio * a.size))
        return;
    char message[300];
    std::snprintf(message, sizeof message,
                  "triangles %d and %d are %.3g apart (%.2g of their size) and closing at %.3g %s: the surface "
                  "would touch itself within %.3g, and the step cannot advance without that",
                  a.first + index_base, a.second + index_base, a.gap, a.gap / a.size, a.closing, when,
                  a.closing > 0 ? a.gap / a.closing : 0.0);
    throw Error(Status::numeric, message);
}

// True if triangles p and q meet at `moved` but not where they are now. Decided exactly.
bool meet_only_after(const TriMesh &mesh, const Triangle &p, const Triangle &q, const std::vector<Vec3> &moved)
{
    return triangles_intersect(moved[p[0]], moved[p[1]], moved[p[2]], moved[q[0]], moved[q[1]], moved[q[2]]) &&
           !triangles_intersect(mesh.pos[p[0]], mesh.pos[p[1]], mesh.pos[p[2]], mesh.pos[q[0]], mesh.pos[q[1]],
                                mesh.pos[q[2]]);
}

// Throws if the step's positions carry one triangle of a pair the searches found within
// rounding of each other at the start (`within_rounding`) through the other, which it did
// not meet at the start. In real numbers the pair slides along its contact
// or opens; but each corner's x + t v is rounded on its own, and a pair that close can end
// up through each other whatever the step (a soak finding: a uniform translation, which
// moves no triangle relative to another, carried two triangles 1e-14 apart through each
// other).
void require_no_crossing_by_rounding(const TriMesh &mesh, TrianglePairs within_rounding,
                                     const std::vector<Vec3> &moved, int32_t index_base)
{
    std::sort(within_rounding.begin(), within_rounding.end()); // the pair named is the same on any threads
    within_rounding.erase(std::unique(within_rounding.begin(), within_rounding.end()), within_rounding.end());
    for (const auto &[a, b] : within_rounding) {
        if (!meet_only_after(mesh, mesh.tri[a], mesh.tri[b], moved))
            continue;
        char message[300];
        std::snprintf(message, sizeof message,
                      "triangles %d and %d touch at the start of the step, within the rounding of their coordinates, "
                      "and the step's positions, each coordinate rounded on its own, would carry one through the "
                      "other; nothing moved",
                      a + index_base, b + index_base);
        throw Error(Status::numeric, message);
    }
}

std::vector<Vec3> mean_velocity(const TriMesh &mesh, const Step &step)
{
    std::vector<Vec3> velocity(step.positions.size());
    for (size_t v = 0; v < velocity.size(); ++v)
        velocity[v] = (step.positions[v] - mesh.pos[v]) / step.dt_taken;
    return velocity;
}

int32_t zone_of(std::vector<int32_t> &parent, int32_t v)
{
    while (parent[v] != v)
        v = parent[v] = parent[parent[v]];
    return v;
}

// The triangles with a corner whose velocity differs between `a` and `b`: those a zone retimed.
std::vector<int32_t> retimed_triangles(const TriMesh &mesh, const std::vector<Vec3> &a, const std::vector<Vec3> &b)
{
    std::vector<int32_t> retimed;
    for (int32_t f = 0; f < mesh.num_triangles(); ++f) {
        const Triangle &t = mesh.tri[f];
        if (a[t[0]] != b[t[0]] || a[t[1]] != b[t[1]] || a[t[2]] != b[t[2]])
            retimed.push_back(f);
    }
    return retimed;
}

// Joins the corners of every pair in contact over dt into zones, each moving with the mean
// velocity of its corners, until no pair is in contact (at most max_contact_rounds rounds;
// every round joins two zones at least, for a pair within one zone does not move relative
// to itself). A pair none of whose corners changed velocity in the last round is what it
// was, so a later round looks only at the triangles around the changed corners. Returns
// the first approach of the rest, the contacts left after the last round among them: of
// the pairs with a retimed corner alone where the first round found nothing but contacts
// limiting the step. Adds every round's pairs within rounding to `within_rounding`.
Approach move_contacts_together(const TriMesh &mesh, std::vector<Vec3> &velocity, double dt, BlockPartition *blocks,
                                TrianglePairs &within_rounding)
{
    const std::vector<Vec3> own = velocity;
    std::vector<int32_t> parent(own.size());
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<Approach> contacts;
    std::vector<int32_t> changed; // the triangles with a corner whose velocity changed
    bool only_contacts_limit = false; // in the first round, only contacts would limit the step
    for (int round = 0; round < max_contact_rounds; ++round) {
        const Approach first =
            first_approach_with_contacts(mesh, velocity, dt, contact_gap_ratio, contacts, round ? &changed : nullptr,
                                         blocks, &within_rounding);
        if (round == 0)
            only_contacts_limit = !(first.time < dt);
        if (contacts.empty()) {
            if (round == 0)
                return first;
            if (!only_contacts_limit)
                return first_approach(mesh, velocity, dt, nullptr, blocks, &within_rounding);
            // No pair that kept its velocities limits the step: in the first round no pair
            // but the contacts did, and a contact whose corners all kept their velocities
            // moves as one. So only the pairs with a retimed corner are looked at again
            // (on vortex T = 6 after t = 4.5 this was always so, and looking at every pair
            // again took a third of the advection).
            const std::vector<int32_t> retimed = retimed_triangles(mesh, velocity, own);
            return first_approach(mesh, velocity, dt, &retimed, nullptr, &within_rounding);
        }
        for (const Approach &c : contacts) {
            const Triangle &p = mesh.tri[c.first], &q = mesh.tri[c.second];
            const int32_t root = zone_of(parent, p[0]);
            for (int32_t v : {p[1], p[2], q[0], q[1], q[2]})
                parent[zone_of(parent, v)] = root;
        }
        // The sums in vertex order: the same zones give the same velocities on any threads.
        std::vector<Vec3> sum(own.size(), Vec3::Zero());
        std::vector<int32_t> count(own.size(), 0);
        for (size_t v = 0; v < own.size(); ++v) {
            const int32_t z = zone_of(parent, static_cast<int32_t>(v));
            sum[z] += own[v];
            ++count[z];
        }
        std::vector<char> retimed(own.size(), 0); // the corners whose velocity changed
        for (size_t v = 0; v < own.size(); ++v) {
            const int32_t z = zone_of(parent, static_cast<int32_t>(v));
            const Vec3 zone_velocity = sum[z] / count[z];
            retimed[v] = zone_velocity != velocity[v];
            velocity[v] = zone_velocity;
        }
        changed.clear();
        for (int32_t f = 0; f < mesh.num_triangles(); ++f) {
            const Triangle &t = mesh.tri[f];
            if (retimed[t[0]] || retimed[t[1]] || retimed[t[2]])
                changed.push_back(f);
        }
    }
    return first_approach(mesh, velocity, dt, nullptr, blocks, &within_rounding);
}

// True if the step to `moved` made two triangles meet that did not before, one of them with
// a corner whose velocity a zone changed. A zone moving as one keeps its triangles apart in
// real numbers, but each corner's x + dt v is rounded on its own, and two triangles that
// touch within round-off can end up through each other (a soak finding: a thin ellipsoid's
// two sheets, a distance 0 apart, moved as one zone, crossed). Decided exactly.
bool zones_made_a_crossing(const TriMesh &mesh, const std::vector<Vec3> &velocity, const std::vector<Vec3> &moving,
                           const std::vector<Vec3> &moved)
{
    const std::vector<int32_t> zoned = retimed_triangles(mesh, moving, velocity);
    std::vector<Box> boxes(mesh.tri.size());
    double extent = 0;
    for (size_t f = 0; f < boxes.size(); ++f) {
        const Triangle &t = mesh.tri[f];
        boxes[f] = {moved[t[0]].cwiseMin(moved[t[1]]).cwiseMin(moved[t[2]]),
                    moved[t[0]].cwiseMax(moved[t[1]]).cwiseMax(moved[t[2]])};
        extent += (boxes[f][1] - boxes[f][0]).maxCoeff();
    }
    char crossed = 0;
    for_each_overlapping_pair_with(boxes, zoned, extent / static_cast<double>(boxes.size()), [&](int32_t a, int32_t b) {
        const Triangle &p = mesh.tri[a], &q = mesh.tri[b];
        if (!share_a_vertex(p, q) && meet_only_after(mesh, p, q, moved))
            crossed = 1; // a byte: the race writes the same value
    });
    return crossed != 0;
}

} // namespace

Step collision_safe_explicit_step(const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt, double safety,
                                  int32_t index_base, bool contact, BlockPartition *blocks)
{
    Step step = explicit_step(mesh, velocity, dt, safety, index_base);
    std::vector<Vec3> moving = velocity;
    TrianglePairs within_rounding;
    const Approach a = contact ? move_contacts_together(mesh, moving, step.dt_taken, blocks, within_rounding)
                               : first_approach(mesh, moving, step.dt_taken, nullptr, blocks, &within_rounding);
    const bool zoned = moving != velocity;
    if (zoned) // zones moving as one may fold a triangle between them and the rest
        step = explicit_step(mesh, moving, step.dt_taken, safety, index_base);
    if (a.time < step.dt_taken) {
        require_room(a, "at the start of the step", index_base);
        step.dt_taken = a.time;
        step.positions = displaced(mesh.pos, moving, step.dt_taken);
        require_valid_step(mesh, step.positions, step.dt_taken, index_base);
    }
    if (zoned && zones_made_a_crossing(mesh, velocity, moving, step.positions))
        return collision_safe_explicit_step(mesh, velocity, dt, safety, index_base, false, blocks); // without contact
    require_no_crossing_by_rounding(mesh, std::move(within_rounding), step.positions, index_base);
    return step;
}

Step collision_safe_rk4_step(const TriMesh &mesh, const VelocityField &field, double t, double dt, double safety,
                             int32_t index_base, bool contact, BlockPartition *blocks)
{
    // The RK4 mean velocity changes with the step only at higher order, so a step a little
    // shorter than the collision-free time of the last try is nearly always free.
    constexpr int max_tries = 40;
    double h = dt;
    for (int attempt = 0; attempt < max_tries; ++attempt) {
        Step step = rk4_step(mesh, field, t, h, safety, index_base);
        const std::vector<Vec3> velocity = mean_velocity(mesh, step);
        std::vector<Vec3> moving = velocity;
        TrianglePairs within_rounding;
        const Approach a = contact ? move_contacts_together(mesh, moving, step.dt_taken, blocks, within_rounding)
                                   : first_approach(mesh, moving, step.dt_taken, nullptr, blocks, &within_rounding);
        if (moving != velocity) {
            // Zones moving as one may fold a triangle sooner: then a shorter Runge-Kutta step.
            const Step held = explicit_step(mesh, moving, step.dt_taken, safety, index_base);
            if (held.dt_taken < step.dt_taken) {
                h = held.dt_taken;
                continue;
            }
            step.positions = held.positions;
        }
        if (a.time >= step.dt_taken) {
            if (moving != velocity && zones_made_a_crossing(mesh, velocity, moving, step.positions))
                return collision_safe_rk4_step(mesh, field, t, dt, safety, index_base, false, blocks); // without contact
            require_no_crossing_by_rounding(mesh, std::move(within_rounding), step.positions, index_base);
            return step;
        }
        char when[40];
        std::snprintf(when, sizeof when, "at t = %g", t);
        require_room(a, when, index_base);
        h = std::min(a.time, 0.9 * step.dt_taken);
    }
    char message[200];
    std::snprintf(message, sizeof message,
                  "no Runge-Kutta step from t = %g keeps the surface from touching itself (tried down to dt = %g)", t, h);
    throw Error(Status::numeric, message);
}

} // namespace sfa

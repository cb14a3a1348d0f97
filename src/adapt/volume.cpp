// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/volume.hpp"

#include "geometry/collision_time.hpp"
#include "geometry/measures.hpp"
#include "geometry/overlap.hpp"
#include "mesh/parallel.hpp"
#include "motion/fold_time.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sfa {
namespace {

constexpr int max_newton_steps = 8;

double det(const Vec3 &x, const Vec3 &y, const Vec3 &z) { return x.dot(y.cross(z)); }

// The offset o that makes the six-fold volume c0 + o (c1 + o (c2 + o c3)) equal `six_volume`.
double offset_for(const Eigen::Vector4d &c, double six_volume)
{
    const auto volume_at = [&](double o) { return c[0] + o * (c[1] + o * (c[2] + o * c[3])); };
    const auto slope = [&](double o) { return c[1] + o * (2 * c[2] + o * 3 * c[3]); };
    double offset = 0, last_missing = std::numeric_limits<double>::infinity();
    for (int step = 0; step < max_newton_steps; ++step) {
        const double missing = six_volume - volume_at(offset);
        if (!(std::abs(missing) < last_missing))
            break; // at round-off
        last_missing = std::abs(missing);
        offset += missing / slope(offset);
    }
    return offset;
}

} // namespace

std::vector<double> component_volumes(const TriMesh &mesh, const std::vector<int32_t> &label, int32_t count)
{
    // About each component's centre: about the origin, a unit sphere at 1e5 kept 1 digit of
    // its volume, and the correction then moved its vertices to match that (-24 % through
    // one sfa_adapt). An open component's volume is not used.
    const std::vector<Vec3> about = component_centres(mesh.pos, label, count);
    std::vector<double> volume = ordered_group_sums(
        mesh.num_triangles(), count, 0.0, [&](int32_t t) { return label[mesh.tri[t][0]]; },
        [&](int32_t t) {
            const Triangle &c = mesh.tri[t];
            const Vec3 &o = about[label[c[0]]];
            return det(mesh.pos[c[0]] - o, mesh.pos[c[1]] - o, mesh.pos[c[2]] - o);
        });
    for (double &v : volume)
        v /= 6;
    return volume;
}

namespace {

// An offset moves every smooth vertex of a component by the same distance along its
// normal. Where the component is thinner than twice that (a sheet squashed flat, a drop
// pressed against another), that carries one side through the other without folding any
// face. An offset of more than a hundredth of the component's mean thickness (its volume
// over half its area) is therefore certified, as collision-safe motion is
// (geometry/collision_time.hpp): every pair of triangles that share no vertex must keep
// half its gap over the offset. Returns the triangles of every pair that does not. The
// usual offsets (some 1e-5 of the thickness on the paper's flows) stay below that and cost
// nothing; where the surface nearly touches itself, the crossing guard looks at them
// (faces_carried_through).
std::vector<int32_t> triangles_brought_together(const TriMesh &mesh, const std::vector<int32_t> &label,
                                                const std::vector<double> &volume, const std::vector<Vec3> &moved)
{
    const int32_t n = mesh.num_vertices(), count = static_cast<int32_t>(volume.size());
    const std::vector<double> area = ordered_group_sums(
        mesh.num_triangles(), count, 0.0, [&](int32_t t) { return label[mesh.tri[t][0]]; },
        [&](int32_t t) {
            const Triangle &c = mesh.tri[t];
            return triangle_area(mesh.pos[c[0]], mesh.pos[c[1]], mesh.pos[c[2]]);
        });
    const std::vector<double> largest = ordered_group_reduce(
        n, count, 0.0, [&](int32_t v) { return label[v]; }, [&](int32_t v) { return (moved[v] - mesh.pos[v]).norm(); },
        [](double a, double b) { return std::max(a, b); });
    bool any = false;
    for (int32_t c = 0; c < count; ++c)
        any = any || largest[c] > 1e-2 * 2 * std::abs(volume[c]) / area[c];
    if (!any)
        return {};
    std::vector<Vec3> offset(n);
    for (int32_t v = 0; v < n; ++v)
        offset[v] = moved[v] - mesh.pos[v];
    // Every pair that would limit the offset, as a contact at any distance.
    std::vector<Approach> pairs;
    first_approach_with_contacts(mesh, offset, 1, std::numeric_limits<double>::infinity(), pairs);
    std::vector<int32_t> triangles;
    for (const Approach &a : pairs)
        triangles.insert(triangles.end(), {a.first, a.second});
    return triangles;
}

// Every triangle the offsets fold (move_folded): the first found in parallel, the rest
// listed from there only where there is one.
std::vector<int32_t> triangles_folded(const TriMesh &mesh, const std::vector<Vec3> &moved)
{
    const int32_t first = first_folded_moved_triangle(mesh, moved);
    if (first < 0)
        return {};
    std::vector<int32_t> folded;
    for (int32_t t = first; t < mesh.num_triangles(); ++t)
        if (move_folded(mesh, moved, t))
            folded.push_back(t);
    return folded;
}

// Each closed component's offset along its movable vertices' unit volume gradients, and
// how far the operations had moved its volume.
struct ComponentOffsets {
    std::vector<Vec3> normal;   // per vertex: zero where the vertex does not move
    std::vector<double> offset; // per component: zero where nothing can move
    std::vector<double> change; // per component: |V - volume[c]| / |volume[c]| before the offset
};

ComponentOffsets component_offsets(const TriMesh &mesh, const std::vector<char> &movable,
                                   const std::vector<int32_t> &label, const std::vector<double> &volume,
                                   const std::vector<char> &closed)
{
    // Every movable vertex moves by its component's offset o along its unit volume gradient
    // n_v; the six-fold volume of a component is then the cubic sum over its triangles of
    // det(p_0 + o n_0, p_1 + o n_1, p_2 + o n_2). One pass gathers the four coefficients of
    // every component, and Newton's method on each cubic finds its offset to round-off
    // without touching the mesh again.
    const int32_t n = mesh.num_vertices(), count = static_cast<int32_t>(volume.size());
    ComponentOffsets result{std::vector<Vec3>(n, Vec3::Zero()), std::vector<double>(count, 0),
                            std::vector<double>(count, 0)};
    std::vector<Vec3> &normal = result.normal;
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v)
        if (movable[v])
            normal[v] = volume_gradient(mesh, v).normalized();
    // About each component's centre (as component_volumes): the cubic's coefficients then
    // keep the digits the coordinates give the shape, wherever the component lies.
    const std::vector<Vec3> about = component_centres(mesh.pos, label, count);
    const std::vector<Eigen::Vector4d> coefficients = ordered_group_sums(
        mesh.num_triangles(), count, Eigen::Vector4d::Zero().eval(), [&](int32_t t) { return label[mesh.tri[t][0]]; },
        [&](int32_t k) {
            const Triangle &t = mesh.tri[k];
            const Vec3 &o = about[label[t[0]]];
            const Vec3 p0 = mesh.pos[t[0]] - o, p1 = mesh.pos[t[1]] - o, p2 = mesh.pos[t[2]] - o;
            const Vec3 &n0 = normal[t[0]], &n1 = normal[t[1]], &n2 = normal[t[2]];
            // The eight determinants from four cross products: with m = n1 x p2 + p1 x n2,
            // det(n0, p1, p2) + det(p0, n1, p2) + det(p0, p1, n2) = n0 . (p1 x p2) + p0 . m
            // and det(p0, n1, n2) + det(n0, p1, n2) + det(n0, n1, p2) = p0 . (n1 x n2) + n0 . m.
            const Vec3 pp = p1.cross(p2), nn = n1.cross(n2), m = n1.cross(p2) + p1.cross(n2);
            return Eigen::Vector4d(p0.dot(pp), n0.dot(pp) + p0.dot(m), p0.dot(nn) + n0.dot(m), n0.dot(nn));
        });
    for (int32_t c = 0; c < count; ++c) {
        if (!closed[c])
            continue;
        const Eigen::Vector4d &k = coefficients[c];
        result.change[c] = std::abs(6 * volume[c] - k[0]) / std::abs(6 * volume[c]);
        if (k[1] > 0) // else nothing can move: every vertex is a feature or held
            result.offset[c] = offset_for(k, 6 * volume[c]);
    }
    return result;
}

// The faces with a moved corner that the crossing guard sees meet another watched face at
// `moved`: where the surface nearly touches itself (a fold sharper than the offsets are
// small), even a tiny offset carries one side through the other.
std::vector<int32_t> faces_carried_through(const TriMesh &mesh, CrossingGuard &guard, const std::vector<Vec3> &moved)
{
    const std::vector<int32_t> &watched = guard.list_faces(mesh, moved);
    std::vector<char> moves(watched.size());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (size_t i = 0; i < watched.size(); ++i) {
        const Triangle &t = mesh.tri[watched[i]];
        moves[i] = moved[t[0]] != mesh.pos[t[0]] || moved[t[1]] != mesh.pos[t[1]] || moved[t[2]] != mesh.pos[t[2]];
    }
    // An offset moves nearly every watched face: each pair compared once.
    const std::vector<char> crossing = guard.faces_meeting(mesh, moved, moves);
    std::vector<int32_t> faces;
    for (size_t i = 0; i < watched.size(); ++i)
        if (crossing[i])
            faces.push_back(watched[i]);
    return faces;
}

// How many times the corners of the triangles an offset would fold, bring together or
// carry through each other are held before their whole components are left as they were.
constexpr int32_t max_holding_rounds = 4;

} // namespace

VolumeRestoration restore_enclosed_volumes(MeshEdit &edit, const std::vector<int8_t> &rank,
                                           const std::vector<int32_t> &label, const std::vector<double> &volume,
                                           const std::vector<char> &closed, bool correct, CrossingGuard *guard)
{
    const TriMesh &mesh = edit.mesh();
    const int32_t n = mesh.num_vertices(), count = static_cast<int32_t>(volume.size());
    // The smooth vertices of closed components move; features do not.
    std::vector<char> movable(n);
    for (int32_t v = 0; v < n; ++v)
        movable[v] = rank[v] == 0 && closed[label[v]];
    const auto leave_as_it_was = [&](int32_t c) {
        for (int32_t v = 0; v < n; ++v)
            if (label[v] == c)
                movable[v] = 0;
    };
    VolumeRestoration result;
    std::vector<double> change;
    std::vector<Vec3> moved;
    // An offset that would fold a triangle, bring two sheets together or carry a face the
    // guard watches through another is not applied: the corners of those triangles are
    // held and the rest of the component takes the volume back. Folds and approaches come
    // where few vertices carry a large correction (coarse cones, thin slabs, strong
    // denoising): a component left as it was there kept a change of up to a third of its
    // volume. After max_holding_rounds rounds the components still concerned are left as
    // they were. Each round ends, holds at least one more moving vertex (the first rounds)
    // or leaves one more component as it was (the later ones): at most
    // max_holding_rounds + count + 1 rounds.
    const auto hold_or_leave = [&](int32_t round, const std::vector<int32_t> &triangles) {
        for (const int32_t t : triangles)
            if (round < max_holding_rounds)
                for (const int32_t v : mesh.tri[t])
                    movable[v] = 0;
            else
                leave_as_it_was(label[mesh.tri[t][0]]);
    };
    for (int32_t round = 0;; ++round) {
        ComponentOffsets offsets = component_offsets(mesh, movable, label, volume, closed);
        if (round == 0)
            change = offsets.change; // what the operations did
        if (!correct || round > max_holding_rounds + count) {
            moved = mesh.pos;
            break;
        }
        moved.resize(n);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int32_t v = 0; v < n; ++v)
            moved[v] = offsets.offset[label[v]] != 0 ? Vec3(mesh.pos[v] + offsets.offset[label[v]] * offsets.normal[v])
                                                     : mesh.pos[v];
        // Only triangles with a corner the offsets move count as folded: one that was flat
        // before them is no fold of theirs.
        if (const std::vector<int32_t> folded = triangles_folded(mesh, moved); !folded.empty()) {
            hold_or_leave(round, folded);
            continue;
        }
        if (const std::vector<int32_t> near = triangles_brought_together(mesh, label, volume, moved); !near.empty()) {
            hold_or_leave(round, near);
            continue;
        }
        if (!guard)
            break;
        const std::vector<int32_t> through = faces_carried_through(mesh, *guard, moved);
        if (through.empty())
            break;
        hold_or_leave(round, through);
    }
    // What the correction left: everything without it, and the components the safeguards
    // above left as they were (or where nothing could move).
    std::vector<char> corrected(count, 0);
    for (int32_t v = 0; v < n; ++v)
        if (moved[v] != mesh.pos[v])
            corrected[label[v]] = 1;
    for (int32_t c = 0; c < count; ++c)
        if (closed[c]) {
            result.largest_change = std::max(result.largest_change, change[c]);
            if (!corrected[c])
                result.largest_left = std::max(result.largest_left, change[c]);
        }
    edit.offset(moved);
    return result;
}

} // namespace sfa

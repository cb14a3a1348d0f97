// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/smooth.hpp"

#include "geometry/circle.hpp"
#include "geometry/crossing_guard.hpp"
#include "geometry/local_fit.hpp"
#include "geometry/surface_side.hpp"
#include "mesh/error.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace sfa {
namespace {

// Smooth vertex (§3.2): each neighbour's edge midpoint m_q is mapped into the metric space
// of its edge, u_q = sqrt(M_half) T^T (m_q - p) with M_half = (M_p + M_q seen from p) / 2,
// the images are averaged, and the average is mapped back through the mean edge metric.
// At equilibrium the edges have equal metric lengths (eq. 4): a neighbour across a metric
// k times stronger ends up sqrt(k) times closer, not k times as a plain metric-weighted
// average of midpoints would make it. With the identity metric this is the average of the
// midpoints: half a Laplacian step, which keeps the Jacobi iteration stable undamped.
//
// `imbalance` is how far the fan is from that equilibrium: the length of the mean image
// over the mean length of the images, that is the step's metric length over the mean
// metric half-edge (0 at equilibrium).
Vec3 tangent_target(const TriMesh &mesh, const SurfaceAnalysis &analysis, int32_t v, double &imbalance)
{
    const VertexMetric &mp = analysis.metric[v];
    const Eigen::Matrix2d own = mp.tensor();
    Eigen::Matrix2d sum_metric = Eigen::Matrix2d::Zero();
    Eigen::Vector2d sum_image = Eigen::Vector2d::Zero();
    double sum_image_length = 0;
    int count = 0;
    // Between two isotropic vertices (most of a smooth surface) the metric is exactly the
    // identity, and so are its roots: no square roots there. (Compared entry by entry:
    // Eigen's isIdentity(0) means the same, through a loop of relative comparisons that cost
    // 2.3 % of a plain vortex T = 2 run's instructions.)
    const auto identity = [](const Eigen::Matrix2d &m) {
        return m(0, 0) == 1 && m(1, 1) == 1 && m(0, 1) == 0 && m(1, 0) == 0;
    };
    const auto root = [&](const Eigen::Matrix2d &m) { return identity(m) ? m : tensor_sqrt(m); };
    const auto inverse_root = [&](const Eigen::Matrix2d &m) { return identity(m) ? m : tensor_inverse_sqrt(m); };
    // Where both ends are isotropic (their tensors exactly the identity), so is the edge's
    // metric, and the image is the midpoint's own coordinates: the same numbers without the
    // tensor's arithmetic (every smooth vertex is tested in every sweep).
    const bool own_isotropic = mp.m_major == 1 && mp.m_minor == 1;
    mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
        const VertexMetric &mw = analysis.metric[w];
        const Vec3 to_midpoint = 0.5 * (mesh.pos[w] - mesh.pos[v]);
        const Eigen::Vector2d local(mp.major.dot(to_midpoint), mp.minor.dot(to_midpoint));
        Eigen::Vector2d image;
        if (own_isotropic && mw.m_major == 1 && mw.m_minor == 1) {
            sum_metric += Eigen::Matrix2d::Identity();
            image = local;
        } else {
            const Eigen::Matrix2d half = 0.5 * (own + tensor_in_frame(mw, mp));
            sum_metric += half;
            image = root(half) * local;
        }
        sum_image += image;
        sum_image_length += image.norm();
        ++count;
    });
    imbalance = sum_image.norm() / sum_image_length;
    const Eigen::Vector2d t = inverse_root(sum_metric / count) * (sum_image / count);
    return t.x() * mp.major + t.y() * mp.minor;
}

// A smooth vertex whose fan is this near the equilibrium (imbalance of tangent_target: its
// step is shorter than 2.5 % of its mean metric edge) stays where it is. On a moving surface
// most fans are that near after every step; moving them anyway costs the local fit, the
// fold check and the crossing guard's query of each of their faces, and lifts a vertex that
// the advection had put on the surface onto a fitted quadric, a little off it, at every
// step. A fan that drifts further moves back the whole way, so the mesh stays that near its
// equilibrium. Measured (medians of alternating runs, against moving every vertex and
// before three smaller changes worth about 0.93x): the Enright and vortex runs take 0.81x
// the time on one thread and on two; at t = T the
// largest backtrace error fell from 1.4e-3 to 1.0e-3 (Enright) and from 1.1e-3 to 5.5e-4
// (vortex T = 2), the RMS a little. 0.1 (5 %) was no faster and left the needles of
// test_adapt's blade (min angle 2.6 degrees instead of 30): after merges a static mesh
// needs its sweeps; 0.02 saved half as much.
constexpr double settled_imbalance = 0.05;

// Ridge (or boundary) vertex: moves only along its ridge, with the same equal-metric-length
// balance as tangent_target in one dimension: the signed distance s along the chord of its
// two ridge neighbours (the midpoints weighted by the square root of the edge metric along
// the chord), taken along the circle through the vertex and those two neighbours. A straight
// ridge stays exactly straight, and a vertex of a circular ridge (a cylinder's rim) stays on
// its circle; moving along the chord instead would cut inside a curved ridge.
Vec3 ridge_motion(const TriMesh &mesh, const SurfaceAnalysis &analysis, int32_t v)
{
    int32_t ends[2] = {-1, -1}, found = 0;
    mesh.for_each_neighbour(v, [&](int32_t w, int32_t h) {
        if (analysis.features.ridge_halfedge[h] && found < 2)
            ends[found++] = w;
    });
    const Vec3 &p = mesh.pos[v];
    const Vec3 direction = (mesh.pos[ends[1]] - mesh.pos[ends[0]]).normalized();
    const VertexMetric &mp = analysis.metric[v];
    const Eigen::Vector2d d(mp.major.dot(direction), mp.minor.dot(direction));
    double sum_weight = 0, sum_moment = 0;
    for (int32_t w : ends) {
        const Eigen::Matrix2d half = 0.5 * (mp.tensor() + tensor_in_frame(analysis.metric[w], mp));
        // Along a line the frame may not see (a ridge leaving the tangent plane), fall back
        // to the physical length.
        const double weight = std::sqrt(std::max(d.dot(half * d), 1e-12));
        sum_weight += weight;
        sum_moment += weight * direction.dot(0.5 * (mesh.pos[w] - p));
    }
    const double distance = sum_moment / sum_weight;

    Circle circle;
    if (!circle_through(mesh.pos[ends[0]], p, mesh.pos[ends[1]], circle))
        return distance * direction; // a straight ridge: the chord is the ridge
    return along_circle(circle, p, direction, distance) - p;
}

// Umbrella vectors: the mean of each vertex's neighbours minus the vertex.
std::vector<Vec3> umbrella_vectors(const TriMesh &mesh)
{
    std::vector<Vec3> umbrella(mesh.pos.size(), Vec3::Zero());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        Vec3 sum = Vec3::Zero();
        int count = 0;
        mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
            sum += mesh.pos[w];
            ++count;
        });
        umbrella[v] = sum / count - mesh.pos[v];
    }
    return umbrella;
}

// The denoising motion of a smooth vertex (smooth.hpp): along the normal only.
Vec3 denoising_motion(const TriMesh &mesh, const std::vector<Vec3> &umbrella, const Vec3 &normal, int32_t v,
                      double weight)
{
    Vec3 mean = Vec3::Zero();
    int count = 0;
    mesh.for_each_neighbour(v, [&](int32_t w, int32_t) {
        mean += umbrella[w];
        ++count;
    });
    return weight / 4 * normal.dot(umbrella[v] - mean / count) * normal;
}

// The first triangle (or -1) that the sweep folds or turns from the surface: one whose
// normal at `moved` no longer points along its normal before the sweep (flat or turned
// over, as first_folded_triangle of fold_time.hpp), or one that faced the side the surface
// faces at one of its smooth corners and no longer does (surface_side.hpp). The first
// bounds each face's turn within one sweep by a right angle, relative to the face as the
// sweep found it; a sliver that splits, contractions or earlier sweeps had tilted steeply
// could be turned the rest of the way over (issue 18: a shallow cone of 200 slivers was
// left with faces upside down around its apex after one pass). One loop for both: the
// check runs again after every round of stopped vertices.
int32_t first_folded_or_turned(const TriMesh &mesh, const SurfaceAnalysis &analysis, const std::vector<Vec3> &moved)
{
    const int32_t first = first_where(mesh.num_triangles(), [&](int32_t f) {
        const Triangle &t = mesh.tri[f];
        if (moved[t[0]] == mesh.pos[t[0]] && moved[t[1]] == mesh.pos[t[1]] && moved[t[2]] == mesh.pos[t[2]])
            return false; // as it was: whatever it is, not this move's doing
        const Vec3 before = (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]);
        const Vec3 after = (moved[t[1]] - moved[t[0]]).cross(moved[t[2]] - moved[t[0]]);
        if (!(before.dot(after) > 0))
            return true;
        // The face's lengths once for its three corners (this check runs on every face).
        double before_length = -1, after_length = -1;
        for (int32_t c : t) {
            if (analysis.features.rank[c] != 0)
                continue;
            if (before_length < 0) {
                before_length = before.norm();
                after_length = after.norm();
            }
            if (turns_from_surface(before, after, surface_side(mesh, analysis.fan_area, c), before_length,
                                   after_length))
                return true;
        }
        return false;
    });
    return first < mesh.num_triangles() ? first : -1;
}

} // namespace

std::vector<Vec3> smoothing_sweep(const TriMesh &mesh, const SurfaceAnalysis &analysis, double denoise,
                                  CrossingGuard *guard)
{
    const int32_t n = mesh.num_vertices();
    std::vector<Vec3> motion(n, Vec3::Zero());
    const std::vector<Vec3> umbrella = denoise > 0 ? umbrella_vectors(mesh) : std::vector<Vec3>();
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v) {
        const int rank = analysis.features.rank[v];
        if (rank == 2)
            continue; // corners never move
        if (rank == 0) {
            double imbalance = 0;
            const Vec3 step = tangent_target(mesh, analysis, v, imbalance);
            if (!(imbalance < settled_imbalance)) // NaN: as before, for the checks to see
                motion[v] = onto_fitted_surface(mesh, v, analysis.metric[v], mesh.pos[v] + step) - mesh.pos[v];
            if (denoise > 0)
                motion[v] += denoising_motion(mesh, umbrella, analysis.metric[v].normal, v, denoise);
        } else {
            motion[v] = ridge_motion(mesh, analysis, v);
        }
    }

    // Jacobi moves can still fold a triangle where neighbours move towards each other, turn
    // one over against the surface, or carry a face through the other side of a sheet
    // thinner than an edge: the vertices of such a face stay where they were in this sweep.
    // Only faces with a corner that moves count: a face flat before the sweep (a collapsed
    // bubble, round-off) is no fold of this move, and stopping its corners would not unfold
    // it. So each round that goes on stops at least one vertex that moved, and there are at
    // most n + 1 rounds.
    std::vector<Vec3> moved(n);
    const auto moves = [&](const Triangle &t) {
        return motion[t[0]] != Vec3::Zero() || motion[t[1]] != Vec3::Zero() || motion[t[2]] != Vec3::Zero();
    };
    // The guard's first round asks every watched face that moves, where the sweep would put
    // it, at once: each pair of overlapping boxes among the watched faces is compared once
    // (faces_meeting). (Asking each moving face of the grid instead looked at some fifty
    // entries a face; on Enright a third of the watched faces move in a sweep.) Only if
    // that stops a vertex are the faces indexed, as they were in that round, and a later
    // round asks only the faces with a corner stopped since, entered again where they now
    // are: a pair of faces neither of which changed did not meet before and does not now.
    // (Asking all of them again, a fuzz input took 50 rounds over 52,000 watched faces per
    // sweep: 56 s in the sanitizer build.) A face whose corners have all been stopped is
    // asked too: back where it was, it may meet a face that moved and was asked only
    // against where it would have gone (vortex T = 6 with topology change, t = 5.895: four
    // crossing pairs); then the other face's corners stop, and it is asked again in the
    // next round, for the guard names one face it meets at a time (a fuzz input: a large
    // face, back where it was, met six faces that moved; the corners of the first stopped,
    // and the other five were left through it).
    std::vector<int32_t> stopped_since, asked_in_round, ask_again;
    const auto stop = [&](int32_t v) {
        if (motion[v] != Vec3::Zero()) {
            motion[v] = Vec3::Zero();
            stopped_since.push_back(v);
        }
    };
    std::vector<int32_t> asked;
    for (int32_t round = 0;; ++round) {
        if (round > n + 1) // cannot happen (see above); a bound all the same, not a hang
            throw Error(Status::internal, "the smoothing sweep's fold re-check did not settle");
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int32_t v = 0; v < n; ++v)
            moved[v] = mesh.pos[v] + motion[v];
        const int32_t folded = first_folded_or_turned(mesh, analysis, moved);
        if (folded >= 0) {
            for (int32_t v : mesh.tri[folded])
                stop(v);
            continue;
        }
        if (!guard)
            return moved;
        if (asked_in_round.empty()) { // the first round
            stopped_since.clear(); // by the fold checks: their faces are asked with the others
            const std::vector<int32_t> &watched = guard->list_faces(mesh, moved);
            std::vector<char> asking(watched.size());
            for (size_t i = 0; i < watched.size(); ++i)
                asking[i] = moves(mesh.tri[watched[i]]);
            const std::vector<char> met = guard->faces_meeting(mesh, moved, asking);
            for (size_t i = 0; i < watched.size(); ++i)
                if (met[i])
                    for (int32_t v : mesh.tri[watched[i]])
                        stop(v);
            if (stopped_since.empty())
                return moved;
            guard->index_faces(mesh, moved);
            asked_in_round.assign(mesh.num_triangles(), -1);
            continue;
        }
        asked.clear();
        const auto ask = [&](int32_t f) {
            if (asked_in_round[f] == round || !guard->watches_any(mesh.tri[f]))
                return;
            asked_in_round[f] = round;
            guard->refresh(mesh, moved, f);
            asked.push_back(f);
        };
        for (const int32_t v : stopped_since)
            mesh.for_each_outgoing(v, [&](int32_t h) { ask(TriMesh::face(h)); });
        for (const int32_t f : ask_again)
            ask(f);
        stopped_since.clear();
        ask_again.clear();
        std::vector<int32_t> crossed(asked.size(), -1);
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 256)
        for (size_t i = 0; i < asked.size(); ++i) {
            const Triangle &t = mesh.tri[asked[i]];
            const Vec3 at[3] = {moved[t[0]], moved[t[1]], moved[t[2]]};
            crossed[i] = guard->face_crossed(mesh, moved, t, at);
        }
        for (size_t i = 0; i < asked.size(); ++i) {
            if (crossed[i] < 0)
                continue;
            const bool asker_moves = moves(mesh.tri[asked[i]]);
            for (int32_t v : mesh.tri[asker_moves ? asked[i] : crossed[i]])
                stop(v);
            if (!asker_moves)
                ask_again.push_back(asked[i]);
        }
        if (stopped_since.empty())
            return moved;
    }
}

} // namespace sfa

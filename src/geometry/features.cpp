// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/features.hpp"

#include "mesh/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace sfa {
namespace {

// f(chi) = 2 atan(sqrt(chi)) inverted: the eigenvalue ratio of a fold of this angle (§2.2).
double ratio_of_angle(double angle) { return std::pow(std::tan(angle / 2), 2); }

double angle_between(const Vec3 &u, const Vec3 &w) { return std::atan2(u.cross(w).norm(), u.dot(w)); }

// Stage 1: the rank the quadric alone suggests. Boundary vertices are at least ridges.
std::vector<int8_t> candidate_ranks(const TriMesh &mesh, const std::vector<QuadricEigen> &eigen,
                                    const FeatureThresholds &thresholds)
{
    const double chi_c = ratio_of_angle(thresholds.ridge_angle), chi_r = ratio_of_angle(thresholds.corner_angle);
    std::vector<int8_t> rank(mesh.pos.size(), 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        const Eigen::Vector3d &lambda = eigen[v].values;
        if (lambda[2] >= chi_r * lambda[0])
            rank[v] = 2;
        else if (lambda[1] >= chi_c * lambda[0])
            rank[v] = 1;
        if (mesh.is_boundary_vertex(v))
            rank[v] = std::max<int8_t>(rank[v], 1);
    }
    return rank;
}

// Each edge is judged through its lower half-edge, so that both halves (and the vertices
// at either end) see the same answer to the last bit.
int32_t canonical_halfedge(const TriMesh &mesh, int32_t h)
{
    const int32_t g = mesh.opp[h];
    return g >= 0 && g < h ? g : h;
}

// The eigenvalue ratios weigh the two sides of a ridge by area: a vertex whose fan has a
// sliver on one side (a jittered or graded mesh) can fall below chi_c although it sits on
// a sharp edge. So the edges vote too: a vertex on two edges whose dihedral angle reaches
// the ridge angle is a ridge candidate, on three or more a corner candidate (curves meet).
std::vector<int8_t> promoted_by_edges(const TriMesh &mesh, std::vector<int8_t> candidate,
                                      const std::vector<Vec3> &area_vectors, const std::vector<double> &length,
                                      const FeatureThresholds &thresholds)
{
    // Every edge is looked at once, through its canonical half-edge, in parallel: compare
    // cosines (no arc tangent). The angle between u and w reaches the ridge angle where
    // u.w <= cos(ridge angle) |u| |w|. Then the few sharp edges are counted at their ends.
    // (Looking at each edge from both ends, through each vertex's fan, cost 2.5 % of an
    // Enright run.)
    const double cos_ridge = std::cos(thresholds.ridge_angle);
    const int32_t halfedges = static_cast<int32_t>(mesh.opp.size());
    std::vector<char> sharp(static_cast<size_t>(halfedges), 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t h = 0; h < halfedges; ++h) {
        if (canonical_halfedge(mesh, h) != h)
            continue;
        const int32_t g = mesh.opp[h];
        sharp[h] = g < 0 || area_vectors[TriMesh::face(h)].dot(area_vectors[TriMesh::face(g)]) <=
                                cos_ridge * length[TriMesh::face(h)] * length[TriMesh::face(g)];
    }
    std::vector<int32_t> sharp_edges(mesh.pos.size(), 0);
    for (int32_t h = 0; h < halfedges; ++h)
        if (sharp[h]) {
            ++sharp_edges[mesh.tail(h)];
            ++sharp_edges[mesh.head(h)];
        }
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < mesh.num_vertices(); ++v)
        candidate[v] = std::max<int8_t>(candidate[v], sharp_edges[v] >= 3 ? 2 : sharp_edges[v] == 2 ? 1 : 0);
    return candidate;
}

// A boundary edge outranks every dihedral angle (at most pi).
constexpr double boundary_strength = 4;

// Stage 2: candidate ridge edges, with a strength (dihedral angle between the two faces'
// normals, or boundary_strength), indexed by half-edge; 0 where an edge is no candidate.
std::vector<double> candidate_edges(const TriMesh &mesh, const std::vector<int8_t> &candidate,
                                    const std::vector<Vec3> &area_vectors, const std::vector<double> &length,
                                    const FeatureThresholds &thresholds)
{
    // The arc tangent only where the cosine leaves doubt: an angle whose cosine exceeds
    // cos(ridge angle) by more than round-off is certainly below it.
    const double cos_below = std::cos(thresholds.ridge_angle) + 1e-9;
    std::vector<double> strength(mesh.opp.size(), 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t h = 0; h < static_cast<int32_t>(mesh.opp.size()); ++h) {
        const int32_t c = canonical_halfedge(mesh, h), g = mesh.opp[c];
        if (g < 0) {
            strength[h] = boundary_strength;
            continue;
        }
        if (candidate[mesh.tail(c)] == 0 || candidate[mesh.head(c)] == 0)
            continue;
        const int32_t f = TriMesh::face(c), e = TriMesh::face(g);
        const Vec3 &u = area_vectors[f], &w = area_vectors[e];
        if (u.dot(w) > cos_below * length[f] * length[e])
            continue;
        const double dihedral = angle_between(u, w);
        if (dihedral >= thresholds.ridge_angle)
            strength[h] = dihedral;
    }
    return strength;
}

// Stage 3: one ridge curve passes through a vertex that is no corner candidate, so such a
// vertex keeps only its two strongest candidate edges. Ties are broken by the position of
// the other end, so that the answer does not depend on the numbering.
std::vector<char> pruned_edges(const TriMesh &mesh, const std::vector<int8_t> &candidate,
                               const std::vector<double> &strength)
{
    // Few vertices have more than two candidate edges: count each candidate edge at its
    // ends (both halves of an edge have its strength; counted through the canonical one),
    // and prune those vertices one by one.
    const int32_t halfedges = static_cast<int32_t>(strength.size());
    std::vector<char> keep(strength.size(), 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t h = 0; h < halfedges; ++h)
        keep[h] = strength[h] > 0;
    std::vector<int32_t> edges_at(mesh.pos.size(), 0);
    for (int32_t h = 0; h < halfedges; ++h)
        if (keep[h] && canonical_halfedge(mesh, h) == h) {
            ++edges_at[mesh.tail(h)];
            ++edges_at[mesh.head(h)];
        }
    std::vector<int32_t> edges;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        if (candidate[v] == 2 || edges_at[v] <= 2)
            continue;
        edges.clear();
        // Every edge at v once: the half-edges leaving v, and the boundary one arriving.
        mesh.for_each_neighbour(v, [&](int32_t, int32_t h) {
            if (strength[h] > 0)
                edges.push_back(h);
        });
        const auto far_end = [&](int32_t h) { return mesh.pos[mesh.tail(h) == v ? mesh.head(h) : mesh.tail(h)]; };
        std::sort(edges.begin(), edges.end(), [&](int32_t x, int32_t y) {
            if (strength[x] != strength[y])
                return strength[x] > strength[y];
            const Vec3 &px = far_end(x), &py = far_end(y);
            return std::lexicographical_compare(px.data(), px.data() + 3, py.data(), py.data() + 3);
        });
        for (size_t k = 2; k < edges.size(); ++k) {
            const int32_t h = edges[k];
            keep[h] = 0;
            if (mesh.opp[h] >= 0)
                keep[mesh.opp[h]] = 0;
        }
    }
    return keep;
}

} // namespace

Features detect_features(const TriMesh &mesh, const std::vector<QuadricEigen> &eigen,
                         const std::vector<Vec3> &area_vectors, const FeatureThresholds &thresholds)
{
    // Each face's area once, for both edge stages (not at every edge end).
    std::vector<double> length(area_vectors.size());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t t = 0; t < static_cast<int32_t>(area_vectors.size()); ++t)
        length[t] = area_vectors[t].norm();
    const std::vector<int8_t> candidate = promoted_by_edges(mesh, candidate_ranks(mesh, eigen, thresholds),
                                                            area_vectors, length, thresholds);
    const double chi_c = ratio_of_angle(thresholds.ridge_angle);
    const std::vector<double> strength = candidate_edges(mesh, candidate, area_vectors, length, thresholds);

    Features features;
    features.ridge_halfedge = pruned_edges(mesh, candidate, strength);

    // Stage 4: ranks follow the ridge curves.
    std::vector<int32_t> count(mesh.pos.size(), 0);
    std::vector<std::array<int32_t, 2>> ends(mesh.pos.size(), {-1, -1});
    for (int32_t h = 0; h < static_cast<int32_t>(mesh.opp.size()); ++h) {
        if (!features.ridge_halfedge[h] || (mesh.opp[h] >= 0 && mesh.opp[h] < h))
            continue; // each ridge edge once
        const int32_t a = mesh.tail(h), b = mesh.head(h);
        features.ridge_edges.push_back({std::min(a, b), std::max(a, b)});
        for (auto [v, w] : {std::pair{a, b}, std::pair{b, a}}) {
            if (count[v] < 2)
                ends[v][count[v]] = w;
            ++count[v];
        }
    }
    std::sort(features.ridge_edges.begin(), features.ridge_edges.end());

    features.rank.assign(mesh.pos.size(), 0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        if (count[v] == 0)
            // An isolated corner, like a cone's tip: its normals spread in every direction
            // as much as across a ridge (lambda3/lambda1 >= chi_c), not merely as much as the
            // corner threshold that ridge curves' corners need; otherwise coarse but smooth
            // bumps (the ears and horns of a coarse model) would pin vertices as corners.
            features.rank[v] = candidate[v] == 2 && eigen[v].values[2] >= chi_c * eigen[v].values[0] ? 2 : 0;
        else if (count[v] == 2) {
            const Vec3 in = mesh.pos[v] - mesh.pos[ends[v][0]], out = mesh.pos[ends[v][1]] - mesh.pos[v];
            features.rank[v] = angle_between(in, out) > thresholds.turn_angle ? 2 : 1;
        } else
            features.rank[v] = 2; // a curve ends (1) or curves meet (3 or more)
    }
    return features;
}

} // namespace sfa

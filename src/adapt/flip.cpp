#include "adapt/flip.hpp"

#include "mesh/edge_flip.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace sfa {
namespace {

constexpr double pi = 3.14159265358979323846;

// A flip must gain at least this much opposite angle (radians, 0.06 degrees). Nearly
// cocircular quads (the rectangles of CAD meshes, a square split either way) would
// otherwise flip on round-off, and back again in the next pass, because neighbouring quads'
// frames differ slightly (seen on fandisk: cycles of 1-3 edges with gains of 1e-5 to 2e-4).
constexpr double delaunay_slack = 1e-3;

struct Verdict {
    bool flip;
    double max_opposite_angle;
};

double angle_at(const Eigen::Vector2d &apex, const Eigen::Vector2d &x, const Eigen::Vector2d &y)
{
    const Eigen::Vector2d u = x - apex, w = y - apex;
    return std::atan2(std::abs(u.x() * w.y() - u.y() * w.x()), u.dot(w));
}

double cross2(const Eigen::Vector2d &u, const Eigen::Vector2d &w) { return u.x() * w.y() - u.y() * w.x(); }

bool within_dihedral(const Vec3 &n0, const Vec3 &n1, double cos_max_dihedral)
{
    return n0.dot(n1) >= cos_max_dihedral * n0.norm() * n1.norm();
}

// Should interior, unlocked half-edge h be flipped? The §3.3 test: the frame and metric of
// the summed quadrics of the quad's four vertices (no vertex is favoured), the points mapped
// into that metric space about their centroid, and the Delaunay criterion there: flip when
// the angles opposite the edge sum to more than pi.
Verdict judge(const TriMesh &mesh, int32_t h, const std::vector<Mat3> &quadric, const FlipSettings &settings,
              double cos_max_dihedral)
{
    const Verdict keep{false, 0};
    const FlipQuad quad = flip_quad(mesh, h);
    const Vec3 &a = mesh.pos[quad.a], &b = mesh.pos[quad.b], &p = mesh.pos[quad.p], &q = mesh.pos[quad.q];

    // The surface must stay nearly as it is: both the old triangles (a, b, p), (b, a, q)
    // and the new ones (q, p, a), (p, q, b) nearly coplanar. A folded or degenerate new
    // triangle fails this too (its normal is opposite or zero).
    const Vec3 old0 = (b - a).cross(p - a), old1 = (a - b).cross(q - b);
    const Vec3 new0 = (p - q).cross(a - q), new1 = (q - p).cross(b - p);
    if (new0.squaredNorm() == 0 || new1.squaredNorm() == 0 || !within_dihedral(old0, old1, cos_max_dihedral) ||
        !within_dihedral(new0, new1, cos_max_dihedral) || new0.dot(old0 + old1) <= 0 || new1.dot(old0 + old1) <= 0)
        return keep;

    // The quad's own two triangles count in three of the four vertex quadrics each. They
    // are replaced by the average of both diagonals' triangles, so that the frame is the
    // same whichever diagonal is present: otherwise the test can favour the new diagonal
    // in its own frame and the old one in the next pass's, and a pass never settles
    // (seen on fandisk: a cycle of three edges flipping back and forth).
    const Mat3 old_terms = face_quadric(old0 / 2) + face_quadric(old1 / 2);
    const Mat3 both_diagonals = 1.5 * (old_terms + face_quadric(new0 / 2) + face_quadric(new1 / 2));
    const Mat3 summed = quadric[quad.a] + quadric[quad.b] + quadric[quad.p] + quadric[quad.q] - 3 * old_terms + both_diagonals;
    const VertexMetric metric = vertex_metric(decompose(summed), old0 + old1, settings.bounds);
    const Eigen::Matrix<double, 2, 3> to_metric_space =
        Eigen::Vector2d(std::sqrt(metric.m_major), std::sqrt(metric.m_minor)).asDiagonal() * metric.frame().transpose();
    const Vec3 centroid = (a + b + p + q) / 4;
    const Eigen::Vector2d ma = to_metric_space * (a - centroid), mb = to_metric_space * (b - centroid),
                          mp = to_metric_space * (p - centroid), mq = to_metric_space * (q - centroid);
    // The criterion means something only where the projection keeps both triangles'
    // orientation (near a ridge the summed frame can be steep to the quad).
    if (cross2(mb - ma, mp - ma) <= 0 || cross2(ma - mb, mq - mb) <= 0)
        return keep;
    // Two acute opposite angles sum to less than pi: most edges are settled without an arc
    // tangent.
    if ((ma - mp).dot(mb - mp) > 0 && (mb - mq).dot(ma - mq) > 0)
        return keep;
    const double angle_p = angle_at(mp, ma, mb), angle_q = angle_at(mq, mb, ma);
    return {angle_p + angle_q > pi + delaunay_slack, std::max(angle_p, angle_q)};
}

// Keeps the quadrics exact through a flip: the two triangles' terms leave their old
// corners and enter their new ones.
void update_quadrics(std::vector<Mat3> &quadric, const TriMesh &mesh, int32_t t0, int32_t t1, int sign)
{
    for (int32_t t : {t0, t1}) {
        const Triangle &c = mesh.tri[t];
        const Mat3 term = face_quadric(0.5 * (mesh.pos[c[1]] - mesh.pos[c[0]]).cross(mesh.pos[c[2]] - mesh.pos[c[0]]));
        for (int32_t v : c)
            quadric[v] += sign * term;
    }
}

// True if either new face of the flip, (q, p, a) or (p, q, b), would pass through a
// watched face.
bool flip_crosses(const TriMesh &mesh, const FlipQuad &quad, const CrossingGuard &guard)
{
    for (const Triangle &t : {Triangle{quad.q, quad.p, quad.a}, Triangle{quad.p, quad.q, quad.b}}) {
        const Vec3 at[3] = {mesh.pos[t[0]], mesh.pos[t[1]], mesh.pos[t[2]]};
        if (guard.watches_any(t) && guard.crosses(mesh, mesh.pos, t, at))
            return true;
    }
    return false;
}

struct Candidate {
    double max_opposite_angle;
    int32_t a, b;
};

} // namespace

int32_t flipping_pass(TriMesh &mesh, const SurfaceAnalysis &analysis, const FlipSettings &settings,
                      std::vector<char> *changed, CrossingGuard *guard)
{
    const double cos_max_dihedral = std::cos(settings.max_dihedral);
    std::vector<Mat3> quadric = analysis.quadric;
    std::vector<char> locked = analysis.features.ridge_halfedge;
    const int32_t halfedges = 3 * mesh.num_triangles();
    const auto may_flip = [&](int32_t h) { return !locked[h] && flip_keeps_manifold(mesh, h); };

    // Judging is independent per edge (in parallel); collecting is in half-edge order. The
    // manifold test walks a fan through memory far apart: only for the few edges that
    // would flip.
    std::vector<Verdict> verdict(halfedges, Verdict{false, 0});
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 1024)
    for (int32_t h = 0; h < halfedges; ++h)
        if (mesh.opp[h] > h && !locked[h]) { // each interior edge once, from its lower half
            const Verdict v = judge(mesh, h, quadric, settings, cos_max_dihedral);
            if (v.flip && flip_keeps_manifold(mesh, h))
                verdict[h] = v;
        }
    std::vector<Candidate> candidates;
    for (int32_t h = 0; h < halfedges; ++h)
        if (verdict[h].flip)
            candidates.push_back({verdict[h].max_opposite_angle, mesh.tail(h), mesh.head(h)});
    // Greedy, largest opposite angle first; ties in vertex order, so the result is the same
    // however the candidates were found.
    std::sort(candidates.begin(), candidates.end(), [](const Candidate &x, const Candidate &y) {
        return std::tie(y.max_opposite_angle, x.a, x.b) < std::tie(x.max_opposite_angle, y.a, y.b);
    });

    if (guard)
        guard->index_faces(mesh, mesh.pos);
    int32_t flips = 0;
    // The corners of the quads flipped so far. A candidate's verdict reads its quad's
    // corners (positions, quadrics, fans): while none of them is marked, it stands.
    std::vector<char> flipped(mesh.pos.size(), 0);
    for (const Candidate &candidate : candidates) {
        const int32_t h = mesh.halfedge(candidate.a, candidate.b);
        if (h < 0)
            continue;
        const FlipQuad quad = flip_quad(mesh, h);
        // Earlier flips may have changed this edge's quad: then judge it again.
        if ((flipped[quad.a] || flipped[quad.b] || flipped[quad.p] || flipped[quad.q]) &&
            (!may_flip(h) || !judge(mesh, h, quadric, settings, cos_max_dihedral).flip))
            continue;
        if (guard && flip_crosses(mesh, quad, *guard))
            continue;
        const int32_t t0 = TriMesh::face(h), t1 = TriMesh::face(mesh.opp[h]);
        for (int32_t v : {quad.a, quad.b, quad.p, quad.q}) {
            flipped[v] = 1;
            if (changed)
                (*changed)[v] = 1;
        }
        update_quadrics(quadric, mesh, t0, t1, -1);
        const FlipMoves moves = flip_edge(mesh, h);
        update_quadrics(quadric, mesh, t0, t1, +1);
        if (guard) {
            guard->refresh(mesh, mesh.pos, t0);
            guard->refresh(mesh, mesh.pos, t1);
        }
        char moved[4];
        for (int k = 0; k < 4; ++k)
            moved[k] = locked[moves.from[k]];
        for (int k = 0; k < 4; ++k)
            locked[moves.to[k]] = moved[k];
        ++flips;
    }
    return flips;
}

} // namespace sfa

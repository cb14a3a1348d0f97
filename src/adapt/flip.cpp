// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/flip.hpp"

#include "geometry/angles.hpp"
#include "geometry/surface_side.hpp"

#include <algorithm>
#include <cmath>

namespace sfa {
namespace {

// A flip must gain at least this much opposite angle (radians, 0.06 degrees). Nearly
// cocircular quads (the rectangles of CAD meshes, a square split either way) would
// otherwise flip on round-off, and back again in the next pass, because neighbouring quads'
// frames differ slightly (seen on fandisk: cycles of 1-3 edges with gains of 1e-5 to 2e-4).
constexpr double delaunay_slack = 1e-3;

// The least ratio of a triangle's area in the metric's plane to its area times the metric's
// area scale (the cosine of the tilt between the frame and the triangle) for the flip
// criterion to be read in that plane: a tilt of up to 75 degrees.
constexpr double min_projected_share = 0.25;

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

// True if a new face of the flip turns away from the side the surface faces at one of the
// quad's smooth corners where an old face with that corner faced it (surface_side.hpp).
// The dihedral bounds of judge are relative to the quad as the flip finds it: over
// slivers, whose normals an earlier change may have tilted steeply, they leave room to
// turn a face the rest of the way over.
bool flip_turns_from_surface(const TriMesh &mesh, const FlipQuad &quad, const Vec3 &old0, const Vec3 &old1,
                             const Vec3 &new0, const Vec3 &new1, const std::vector<Vec3> &fan_area,
                             const CarriedFeatures &features)
{
    const auto turns = [&](int32_t c, const Vec3 &before, const Vec3 &after) {
        return turns_at_corner(mesh, fan_area, features.rank(c), c, before, after);
    };
    // old0 = (a, b, p), old1 = (b, a, q); new0 = (q, p, a), new1 = (p, q, b).
    return turns(quad.a, old0, new0) || turns(quad.a, old1, new0) || turns(quad.b, old0, new1) ||
           turns(quad.b, old1, new1) || turns(quad.p, old0, new0) || turns(quad.p, old0, new1) ||
           turns(quad.q, old1, new0) || turns(quad.q, old1, new1);
}

// Should interior, unlocked half-edge h be flipped? The §3.3 test: the frame and metric of
// the summed quadrics of the quad's four vertices (no vertex is favoured), the points mapped
// into that metric space about their centroid, and the Delaunay criterion there: flip when
// the angles opposite the edge sum to more than pi.
Verdict judge(const TriMesh &mesh, int32_t h, const std::vector<Mat3> &quadric, const std::vector<Vec3> &fan_area,
              const CarriedFeatures &features, const FlipSettings &settings, double cos_max_dihedral)
{
    const Verdict keep{false, 0};
    const FlipQuad quad = flip_quad(mesh, h);
    const Vec3 &a = mesh.pos[quad.a], &b = mesh.pos[quad.b], &p = mesh.pos[quad.p], &q = mesh.pos[quad.q];

    // The surface must stay nearly as it is: both the old triangles (a, b, p), (b, a, q)
    // and the new ones (q, p, a), (p, q, b) nearly coplanar. A folded or degenerate new
    // triangle fails this too (its normal is opposite or zero).
    const Vec3 old0 = (b - a).cross(p - a), old1 = (a - b).cross(q - b);
    const Vec3 new0 = (p - q).cross(a - q), new1 = (q - p).cross(b - p);
    if (!(new0.squaredNorm() > 0) || !(new1.squaredNorm() > 0) || !within_dihedral(old0, old1, cos_max_dihedral) ||
        !within_dihedral(new0, new1, cos_max_dihedral) || !(new0.dot(old0 + old1) > 0) || !(new1.dot(old0 + old1) > 0))
        return keep;

    // The quad's own two triangles count in three of the four vertex quadrics each. They
    // are replaced by the average of both diagonals' triangles, so that the frame is the
    // same whichever diagonal is present: otherwise the test can favour the new diagonal
    // in its own frame and the old one in the next pass's, and a pass never settles
    // (seen on fandisk: a cycle of three edges flipping back and forth).
    const Mat3 old_terms = face_quadric(old0 / 2) + face_quadric(old1 / 2);
    const Mat3 both_diagonals = 1.5 * (old_terms + face_quadric(new0 / 2) + face_quadric(new1 / 2));
    const Mat3 summed = quadric[quad.a] + quadric[quad.b] + quadric[quad.p] + quadric[quad.q] - 3 * old_terms + both_diagonals;
    // Most edges keep their diagonal for sure: no decomposition for them (88 % of the
    // edges judged on the paper's flows).
    if (surely_acute_opposite(summed, a, b, p, q, old0, old1, settings.bounds))
        return keep;
    const VertexMetric metric = vertex_metric(decompose(summed), old0 + old1, settings.bounds);
    const Eigen::Matrix<double, 2, 3> to_metric_space =
        Eigen::Vector2d(std::sqrt(metric.m_major), std::sqrt(metric.m_minor)).asDiagonal() * metric.frame().transpose();
    const Vec3 centroid = (a + b + p + q) / 4;
    const Eigen::Vector2d ma = to_metric_space * (a - centroid), mb = to_metric_space * (b - centroid),
                          mp = to_metric_space * (p - centroid), mq = to_metric_space * (q - centroid);
    // The criterion means something only where the projection keeps both triangles'
    // orientation and a fair share of their area (near a ridge the summed frame can be
    // steep to the quad). A frame nearly square to it maps the corners almost onto a line,
    // where the angles are round-off: a split's midpoint a of an edge pq then looked like
    // a Delaunay flip back to pq, which made (q, p, a) of zero area (a soak finding).
    const double metric_area = std::sqrt(metric.m_major * metric.m_minor);
    if (!(cross2(mb - ma, mp - ma) > min_projected_share * metric_area * old0.norm()) ||
        !(cross2(ma - mb, mq - mb) > min_projected_share * metric_area * old1.norm()))
        return keep;
    // Two acute opposite angles sum to less than pi: most edges are settled without an arc
    // tangent.
    if ((ma - mp).dot(mb - mp) > 0 && (mb - mq).dot(ma - mq) > 0)
        return keep;
    const double angle_p = angle_at(mp, ma, mb), angle_q = angle_at(mq, mb, ma);
    if (!(angle_p + angle_q > pi + delaunay_slack))
        return keep;
    // Checked last: only for the few edges that would flip.
    if (flip_turns_from_surface(mesh, quad, old0, old1, new0, new1, fan_area, features))
        return keep;
    return {true, std::max(angle_p, angle_q)};
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

class Flipping {
public:
    struct Plan {};
    // judge is the whole verdict; it reads the quad's corners (positions, quadrics, fans).
    static constexpr bool plans_ahead = false;

    Flipping(const PassContext &context, const SurfaceAnalysis &analysis, const FlipSettings &settings)
        : mesh_(context.edit.mesh()), features_(context.features), constraints_(context.constraints),
          guard_(context.guard), settings_(settings),
          cos_max_dihedral_(std::cos(settings.max_dihedral)), quadric_(analysis.quadric), fan_area_(analysis.fan_area)
    {
    }

    bool wanted(int32_t h, double &order) const
    {
        if (mesh_.opp[h] < 0 || features_.is_ridge(h) || constraints_.required(h))
            return false;
        // The manifold test walks a fan through memory far apart: only for the few edges
        // that would flip.
        const Verdict verdict = judge(mesh_, h, quadric_, fan_area_, features_, settings_, cos_max_dihedral_);
        if (!verdict.flip || !flip_keeps_manifold(mesh_, h))
            return false;
        order = -verdict.max_opposite_angle; // largest first
        return true;
    }
    int32_t locate(int32_t a, int32_t b) const { return mesh_.halfedge(a, b); }
    bool plan(int32_t h, Plan &) const
    {
        return !features_.is_ridge(h) && !constraints_.required(h) && flip_keeps_manifold(mesh_, h) &&
               judge(mesh_, h, quadric_, fan_area_, features_, settings_, cos_max_dihedral_).flip;
    }
    bool may_have_changed(int32_t h, const ChangedVertices &changed) const
    {
        const FlipQuad quad = flip_quad(mesh_, h);
        return changed[quad.a] || changed[quad.b] || changed[quad.p] || changed[quad.q];
    }
    bool apply(MeshEdit &edit, int32_t h, const Plan &)
    {
        if (guard_ && flip_crosses(mesh_, flip_quad(mesh_, h), *guard_))
            return false;
        const int32_t t0 = TriMesh::face(h), t1 = TriMesh::face(mesh_.opp[h]);
        update_quadrics(quadric_, mesh_, t0, t1, -1);
        edit.flip(h);
        update_quadrics(quadric_, mesh_, t0, t1, +1);
        return true;
    }

private:
    const TriMesh &mesh_;
    const CarriedFeatures &features_;
    const CarriedConstraints &constraints_;
    const CrossingGuard *guard_;
    const FlipSettings &settings_;
    const double cos_max_dihedral_;
    std::vector<Mat3> quadric_; // the analysis's, kept exact through the pass's flips
    const std::vector<Vec3> &fan_area_; // the analysis's, as the pass found it
};

} // namespace

// (flip.hpp) Bounds that hold for any unit n (here the quad's normal) give the certificate
// without the decomposition. lambda1 >= n.A n, and lambda2 <= lambda2 + lambda3 = trace(A) -
// lambda1 <= trace(A) - n.A n (= rest); so m_major / m_minor is at most rest / (psi_l's
// ratio times n.A n) (eq. 12: where lambda2 is below psi_l, both clamp to 1), and e1 leans
// from n by beta with sin^2 beta <= rest / (n.A n - rest), for lambda1 - n.A n >= (lambda1 -
// lambda2) sin^2 beta. A triangle's map into metric space, the projection onto the plane
// normal to e1 followed by the metric's scaling, stretches one direction at most K =
// sqrt(m_major / m_minor) / cos(gamma) times another, gamma the angle between the triangle's
// normal and e1 (at most its angle to n plus beta), and an angle theta then becomes at most
// 2 atan(K tan(theta / 2)). The margin keeps the certified angles a tenth of a degree from
// square, far beyond the round-off of either test. Only a quadric whose e1 leans less than
// 35 degrees from n (rest < n.A n / 4) is looked at.
bool surely_acute_opposite(const Mat3 &summed, const Vec3 &a, const Vec3 &b, const Vec3 &p, const Vec3 &q,
                           const Vec3 &old0, const Vec3 &old1, const MetricBounds &bounds)
{
    const Vec3 n = (old0 + old1).normalized();
    const double along = n.dot(summed * n), rest = summed.trace() - along;
    if (!(along > 0 && rest >= 0 && rest < 0.25 * along))
        return false;
    const double most_anisotropy = // of m_major / m_minor
        bounds.anisotropic ? std::max(1.0, std::min(rest / (bounds.lower_ratio * along), bounds.upper_ratio / bounds.lower_ratio))
                           : 1.0;
    const double sin2_lean = rest / (along - rest), sin_lean = std::sqrt(sin2_lean), cos_lean = std::sqrt(1 - sin2_lean);
    const auto acute = [&](const Vec3 &apex, const Vec3 &face_area) {
        const double c = n.dot(face_area) / face_area.norm(), s = std::sqrt(std::max(0.0, 1 - c * c));
        const double cos_gamma = c * cos_lean - s * sin_lean; // cos(angle to n + lean)
        if (!(c > 0 && cos_gamma > 0.5))
            return false;
        const double stretch = std::sqrt(most_anisotropy) / cos_gamma;
        const Vec3 u = a - apex, w = b - apex;
        // tan(theta / 2) = |u x w| / (|u| |w| + u.w)
        return stretch * u.cross(w).norm() < 0.998 * (u.norm() * w.norm() + u.dot(w));
    };
    return acute(p, old0) && acute(q, old1);
}

int32_t flipping_pass(const PassContext &context, const SurfaceAnalysis &analysis, const FlipSettings &settings)
{
    Flipping flipping(context, analysis, settings);
    return run_edge_pass(context.edit, flipping);
}

int32_t flipping_pass(TriMesh &mesh, const SurfaceAnalysis &analysis, const FlipSettings &settings)
{
    MeshEdit edit(mesh);
    CarriedFeatures features(analysis.features);
    edit.attach(features);
    const CarriedConstraints none;
    return flipping_pass(PassContext{edit, features, nullptr, none, nullptr}, analysis, settings);
}

} // namespace sfa

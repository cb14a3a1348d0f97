// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/fan_sectors.hpp"

#include <cmath>
#include <limits>

namespace sfa {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double eps = std::numeric_limits<double>::epsilon();
// A link vertex (or a triangle's corner) nearer the axis than this fraction of its distance
// from w has no angle to speak of.
constexpr double min_axis_ratio = 1e-6;

// The angle of d - rounded from a d of length `length` projected to (x, y) - and an upper
// bound on its rounding error: each of x and y is off by a few eps |d|.
double padded_angle(double x, double y, double length, double &pad)
{
    pad = 1e-12 + 64 * eps * length / std::hypot(x, y);
    return std::atan2(y, x);
}

} // namespace

bool FanSectors::build(const TriMesh &mesh, int32_t w)
{
    usable_ = false;
    hub_ = w;
    faces_.clear();
    links_.clear();
    bool closed = true;
    mesh.for_each_outgoing(w, [&](int32_t h) {
        faces_.push_back(TriMesh::face(h));
        links_.push_back(mesh.pos[mesh.head(h)]);
        closed = closed && mesh.rotate_ccw(h) >= 0;
    });
    return closed && index(mesh.pos[w]);
}

bool FanSectors::build_merged(const TriMesh &mesh, int32_t h, const Vec3 &merged)
{
    usable_ = false;
    hub_ = -1;
    faces_.clear();
    links_.clear();
    // Around each end from the edge on, counter-clockwise: the first and the last face have
    // both ends and die; the last link vertex of one end's fan is the first of the other's.
    bool closed = true;
    for (const int32_t end : {mesh.tail(h), mesh.head(h)}) {
        const int32_t other = end == mesh.tail(h) ? mesh.head(h) : mesh.tail(h);
        int32_t g = mesh.halfedge(end, other);
        if (g < 0)
            return false;
        for (g = mesh.rotate_ccw(g); closed && g >= 0 && mesh.head(g) != other; g = mesh.rotate_ccw(g)) {
            const int32_t next = mesh.rotate_ccw(g);
            closed = next >= 0;
            if (closed && mesh.head(next) != other) {
                faces_.push_back(TriMesh::face(g));
                links_.push_back(mesh.pos[mesh.head(g)]);
            }
        }
        closed = closed && g >= 0;
    }
    return closed && index(merged);
}

bool FanSectors::index(const Vec3 &centre)
{
    centre_ = centre;
    phi_.clear();
    const size_t m = faces_.size();
    if (m < 3)
        return false;
    Vec3 axis = Vec3::Zero();
    for (size_t k = 0; k < m; ++k)
        axis += (links_[k] - centre_).cross(links_[(k + 1) % m] - centre_);
    if (!(axis.norm() > 0))
        return false;
    axis.normalize();
    e1_ = std::abs(axis.x()) < 0.6 ? Vec3(1, 0, 0).cross(axis) : Vec3(0, 1, 0).cross(axis);
    e1_.normalize();
    e2_ = axis.cross(e1_);
    // The link vertices in the order of the faces: face i = (w, v_i, v_i+1).
    std::vector<double> length(m + 1), radius(m + 1);
    double pad = 0;
    for (size_t i = 0; i < m; ++i) {
        const Vec3 d = links_[i] - centre_;
        const double x = d.dot(e1_), y = d.dot(e2_), r = std::hypot(x, y);
        length[i] = d.norm();
        radius[i] = r;
        if (!(r > min_axis_ratio * length[i])) {
            phi_.push_back(0);
            pad = pi; // unusable below
        } else {
            double p;
            phi_.push_back(padded_angle(x, y, length[i], p));
            pad = std::max(pad, p);
        }
    }
    if (!(pad < 1e-6))
        return false;
    pad_ = 2 * pad;
    length[m] = length[0];
    radius[m] = radius[0];
    // Unwrapped, each step in [0, pi - 0.1]: star-shaped, every sector convex and the bound
    // below finite. A step the rounding made barely negative is refused, as is a fold.
    double stretch = 0;
    const double first = phi_[0];
    for (size_t k = 0; k < m; ++k) {
        const double step = std::remainder((k + 1 < m ? phi_[k + 1] : first) - phi_[k], 2 * pi);
        if (!(step >= 0 && step <= pi - 0.1))
            return false;
        if (k + 1 < m)
            phi_[k + 1] = phi_[k] + step;
        else
            phi_.push_back(phi_[k] + step);
        // A point s u_k + t u_k+1 (s, t >= 0) of the wedge: both projected edges lie within
        // half the step of its bisector, so |L(s u_k + t u_k+1)| >= (s r_k + t r_k+1)
        // cos(step / 2), while |s u_k + t u_k+1| <= s |u_k| + t |u_k+1|.
        const double c = std::cos((step + 2 * pad_) / 2);
        stretch = std::max(stretch, std::max(length[k] / radius[k], length[k + 1] / radius[k + 1]) / c);
    }
    if (!(std::abs(phi_[m] - phi_[0] - 2 * pi) < 1e-6))
        return false; // winds more than once (or the fan is not closed around the axis)
    stretch_ = 1.01 * stretch;
    usable_ = true;
    return true;
}

bool FanSectors::query_range(const Vec3 (&p)[3], double &from, double &to) const
{
    double x[3], y[3], r[3], len[3];
    int near = -1, nears = 0;
    for (int k = 0; k < 3; ++k) {
        const Vec3 d = p[k] - centre_;
        x[k] = d.dot(e1_), y[k] = d.dot(e2_), r[k] = std::hypot(x[k], y[k]), len[k] = d.norm();
        if (!(r[k] > min_axis_ratio * len[k]))
            near = k, ++nears;
    }
    if (nears > 1)
        return false;
    if (nears == 0) {
        // The corners' angles within less than pi: the projected triangle lies in the
        // convex wedge from L(w) they span. The wedge is the complement of the widest gap.
        double a[3], pad = 0;
        for (int k = 0; k < 3; ++k) {
            double pk;
            a[k] = padded_angle(x[k], y[k], len[k], pk);
            pad = std::max(pad, pk);
        }
        std::sort(a, a + 3);
        const double gaps[3] = {a[1] - a[0], a[2] - a[1], a[0] + 2 * pi - a[2]};
        const int widest = static_cast<int>(std::max_element(gaps, gaps + 3) - gaps);
        if (!(gaps[widest] > pi + 1e-6))
            return false; // L(w) in (or near) the projected triangle
        from = a[(widest + 1) % 3];
        to = from + (2 * pi - gaps[widest]);
        from -= 2 * pad;
        to += 2 * pad;
        return true;
    }
    // One corner (k) on or near the axis. A common point x of the triangle and the fan is
    // at least the distance D of w from the triangle's plane away from w, so |L(x - w)| >=
    // D / stretch = 2 rho; a point of the triangle so far from the axis is, within the angle
    // asin(r_k / (rho - r_k)), in line with a point of the opposite edge: the sector of
    // that edge, widened by that angle, holds every common point.
    const int j = (near + 1) % 3, l = (near + 2) % 3;
    const Vec3 normal = (p[1] - p[0]).cross(p[2] - p[0]);
    if (!(normal.norm() > 0))
        return false;
    const double distance = std::abs((centre_ - p[0]).dot(normal)) / normal.norm() * (1 - 1e-9);
    const double rho = distance / (2 * stretch_);
    const double rk = r[near] + 8 * eps * len[near];
    if (!(rk < rho / 4))
        return false;
    double pj, pl;
    const double aj = padded_angle(x[j], y[j], len[j], pj), al = padded_angle(x[l], y[l], len[l], pl);
    const double step = std::remainder(al - aj, 2 * pi);
    if (!(std::abs(step) < pi - 1e-3))
        return false; // the opposite edge passes (near) L(w)
    const double widen = 2 * pi * rk / (rho - rk) + 2 * std::max(pj, pl);
    from = std::min(aj, aj + step) - widen;
    to = std::max(aj, aj + step) + widen;
    return true;
}

} // namespace sfa

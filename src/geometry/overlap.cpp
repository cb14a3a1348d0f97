// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/overlap.hpp"

#include <algorithm>
#include <cmath>

namespace sfa {
namespace {

// Twice the signed area of (o, a, b): positive when counter-clockwise. As a function of b
// it is the signed distance from the line o -> a, scaled by |a - o|: positive to its left.
double cross(const ChartPoint &o, const ChartPoint &a, const ChartPoint &b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Each clip emits at most two points per point it is given (a crossing and the point), so
// three clips of a triangle need at most 3 -> 6 -> 12 -> 24 points. A convex polygon
// clipped by a half-plane gains at most one point; the doubling bound also holds when
// round-off makes nearly collinear points disagree about their side, so no input can
// overrun the buffers.
constexpr int32_t clip_capacity = 24;

// The part of polygon in[0..n) to the left of the line a -> b (on it counts as inside):
// one Sutherland-Hodgman step. The crossing parameter t = dp / (dp - dq) is only formed
// when dp and dq have opposite signs, so its denominator is never zero and t lies in
// [0, 1]: no NaN, and every point stays between the points it came from.
int32_t clip(const ChartPoint *in, int32_t n, const ChartPoint &a, const ChartPoint &b, ChartPoint *out)
{
    int32_t m = 0;
    ChartPoint p = in[n - 1];
    double dp = cross(a, b, p);
    for (int32_t k = 0; k < n; ++k) {
        const ChartPoint q = in[k];
        const double dq = cross(a, b, q);
        if ((dp < 0) != (dq < 0)) {
            const double t = dp / (dp - dq);
            out[m++] = {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
        }
        if (dq >= 0)
            out[m++] = q;
        p = q;
        dp = dq;
    }
    return m;
}

double area(const Corners &t) { return triangle_area(t[0], t[1], t[2]); }

// The fallback: every new triangle gets the region's mean density, the old integral over
// the new area, which keeps the total exactly and a constant uniform. Where the new
// triangles have no area at all nothing can carry the integral; they then take the old
// mean, so that at least a constant stays what it was.
RemapPath share_by_area(const Corners *old_faces, const double *old_values, int32_t n_old, const Corners *new_faces,
                        double *new_values, int32_t n_new, int32_t ncomp)
{
    double old_area = 0, new_area = 0;
    for (int32_t i = 0; i < n_old; ++i)
        old_area += area(old_faces[i]);
    for (int32_t j = 0; j < n_new; ++j)
        new_area += area(new_faces[j]);
    const double spread = new_area > 0 ? new_area : old_area;
    for (int32_t c = 0; c < ncomp; ++c) {
        double total = 0;
        for (int32_t i = 0; i < n_old; ++i)
            total += old_values[static_cast<size_t>(ncomp) * i + c] * area(old_faces[i]);
        const double mean = spread > 0 ? total / spread : 0;
        for (int32_t j = 0; j < n_new; ++j)
            new_values[static_cast<size_t>(ncomp) * j + c] = mean;
    }
    return RemapPath::shared;
}

// A triangle in the chart with what the remap needs of it.
struct ChartTriangle {
    ChartPoint p[3];               // counter-clockwise
    double lo_x, hi_x, lo_y, hi_y; // bounding box
    double twice_signed_area;      // as the corners were: negative when turned over
    double area;                   // in space
};

ChartTriangle chart_triangle(const Corners &t, double area, const Vec3 &origin, const Vec3 &u, const Vec3 &w)
{
    ChartTriangle c;
    for (int k = 0; k < 3; ++k) {
        const Vec3 d = t[k] - origin; // from a nearby point: small coordinates, little cancellation
        c.p[k] = {d.dot(u), d.dot(w)};
    }
    c.lo_x = std::min({c.p[0].x, c.p[1].x, c.p[2].x});
    c.hi_x = std::max({c.p[0].x, c.p[1].x, c.p[2].x});
    c.lo_y = std::min({c.p[0].y, c.p[1].y, c.p[2].y});
    c.hi_y = std::max({c.p[0].y, c.p[1].y, c.p[2].y});
    c.twice_signed_area = cross(c.p[0], c.p[1], c.p[2]);
    if (c.twice_signed_area < 0) // a sliver turned over by round-off only (the remap checks)
        std::swap(c.p[1], c.p[2]);
    c.area = area;
    return c;
}

// The chart's normal: the one given, unless a triangle (beyond round-off on a degenerate
// one) is turned over seen along it; then tilted towards the normals of those turned over,
// a batch perceptron (unit normals added to an unnormalized direction), which finds a
// direction every triangle faces where one exists with some margin, in a few rounds on a
// fan: a steep fan whose area-weighted normal is not inside its cone of normals, such as
// a valence-3 cap whose apex leans out past its base. A triangle turned over in the chart
// means that one set covers part of the region twice, and the overlaps would count it
// twice: false where no direction is found in a few rounds (a folded fan). `vectors` are
// the triangles' areas times their unit normals, `scale` the sum of their lengths.
bool facing_normal(const Vec3 *vectors, int32_t count, double scale, Vec3 &n)
{
    for (int round = 0; round < 32; ++round) {
        const double turned = -1e-12 * scale * n.norm();
        Vec3 tilt = Vec3::Zero();
        for (int32_t k = 0; k < count; ++k)
            if (vectors[k].dot(n) < turned)
                tilt += vectors[k].normalized();
        if (tilt == Vec3::Zero()) {
            n.normalize();
            return n.allFinite();
        }
        n += tilt;
    }
    return false;
}

bool boxes_apart(const ChartTriangle &a, const ChartTriangle &b)
{
    return a.hi_x < b.lo_x || b.hi_x < a.lo_x || a.hi_y < b.lo_y || b.hi_y < a.lo_y;
}

} // namespace

double triangle_area(const Vec3 &a, const Vec3 &b, const Vec3 &c) { return 0.5 * (b - a).cross(c - a).norm(); }

namespace {

// overlap_area of a and b, both counter-clockwise with these twice areas, both positive.
double overlap_ccw(const ChartPoint a[3], double twice_a, const ChartPoint b[3], double twice_b)
{
    const double smaller = 0.5 * std::min(twice_a, twice_b);
    // Where a's corners lie against each edge of b, as the clip would see them. An edge
    // with every corner outside separates the two; one with every corner inside cuts
    // nothing (what the other clips make lies in a's hull) and is not clipped by. Most
    // pairs of a fan's triangles are apart, or cross one or two edges of each other.
    bool cuts[3];
    for (int k = 0; k < 3; ++k) {
        int outside = 0;
        for (int m = 0; m < 3; ++m)
            outside += cross(b[k], b[(k + 1) % 3], a[m]) < 0;
        if (outside == 3)
            return 0;
        cuts[k] = outside > 0;
    }
    if (!cuts[0] && !cuts[1] && !cuts[2]) // a inside b
        return std::min(0.5 * twice_a, smaller);
    ChartPoint buffers[2][clip_capacity];
    std::copy(a, a + 3, buffers[0]);
    int32_t n = 3, current = 0;
    for (int k = 0; k < 3; ++k) {
        if (!cuts[k])
            continue;
        n = clip(buffers[current], n, b[k], b[(k + 1) % 3], buffers[1 - current]);
        current = 1 - current;
        if (n < 3)
            return 0;
    }
    // The clipped polygon's area by the shoelace about its first point. Round-off on
    // slivers can leave it a little off either way: it is clamped to what an intersection
    // can be.
    const ChartPoint *polygon = buffers[current];
    double twice = 0;
    for (int32_t k = 1; k + 1 < n; ++k)
        twice += cross(polygon[0], polygon[k], polygon[k + 1]);
    return std::clamp(0.5 * twice, 0.0, smaller);
}

} // namespace

double overlap_area(const ChartPoint a[3], const ChartPoint b[3])
{
    const double twice_a = cross(a[0], a[1], a[2]), twice_b = cross(b[0], b[1], b[2]);
    if (!(twice_a != 0 && twice_b != 0)) // degenerate (or not finite): no area to share
        return 0;
    // Both counter-clockwise, so that the inside of each is to the left of its edges.
    const ChartPoint ccw_a[3] = {a[0], twice_a > 0 ? a[1] : a[2], twice_a > 0 ? a[2] : a[1]};
    const ChartPoint ccw_b[3] = {b[0], twice_b > 0 ? b[1] : b[2], twice_b > 0 ? b[2] : b[1]};
    return overlap_ccw(ccw_a, std::abs(twice_a), ccw_b, std::abs(twice_b));
}

RemapPath remap_by_overlap(const Corners *old_faces, const double *old_values, int32_t n_old,
                           const Corners *new_faces, double *new_values, int32_t n_new, int32_t ncomp,
                           const Vec3 &normal)
{
    const double length = normal.norm();
    if (n_old < 1 || n_new < 1 || n_old > max_overlap_faces || n_new > max_overlap_faces || !(length > 0))
        return share_by_area(old_faces, old_values, n_old, new_faces, new_values, n_new, ncomp);
    Vec3 vectors[2 * max_overlap_faces]; // area times unit normal: old triangles, then new
    double scale = 0;
    for (int32_t k = 0; k < n_old + n_new; ++k) {
        const Corners &t = k < n_old ? old_faces[k] : new_faces[k - n_old];
        vectors[k] = 0.5 * (t[1] - t[0]).cross(t[2] - t[0]); // its length is triangle_area's
        scale += vectors[k].norm();
    }
    Vec3 n = normal / length;
    if (!facing_normal(vectors, n_old + n_new, scale, n))
        return share_by_area(old_faces, old_values, n_old, new_faces, new_values, n_new, ncomp);
    // The chart: a right-handed frame (u, w, n), so that triangles counter-clockwise about
    // n are counter-clockwise in the chart; u from whichever axis is far from n.
    const Vec3 u = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    const Vec3 w = n.cross(u);
    const Vec3 origin = old_faces[0][0];
    ChartTriangle olds[max_overlap_faces], news[max_overlap_faces];
    double old_area = 0, new_area = 0, chart_area = 0;
    for (int32_t i = 0; i < n_old; ++i) {
        olds[i] = chart_triangle(old_faces[i], vectors[i].norm(), origin, u, w);
        old_area += olds[i].area;
        chart_area += std::abs(olds[i].twice_signed_area);
    }
    for (int32_t j = 0; j < n_new; ++j) {
        news[j] = chart_triangle(new_faces[j], vectors[n_old + j].norm(), origin, u, w);
        new_area += news[j].area;
        chart_area += std::abs(news[j].twice_signed_area);
    }
    // Round-off of the projection could still turn a sliver over that facing_normal saw
    // facing the chart.
    const double turned = -1e-12 * chart_area;
    for (int32_t i = 0; i < n_old; ++i)
        if (olds[i].twice_signed_area < turned)
            return share_by_area(old_faces, old_values, n_old, new_faces, new_values, n_new, ncomp);
    for (int32_t j = 0; j < n_new; ++j)
        if (news[j].twice_signed_area < turned)
            return share_by_area(old_faces, old_values, n_old, new_faces, new_values, n_new, ncomp);
    if (!(chart_area > 0))
        return share_by_area(old_faces, old_values, n_old, new_faces, new_values, n_new, ncomp);

    // Each new triangle: the overlap-weighted mean of the old densities over it.
    bool covered[max_overlap_faces];
    for (int32_t j = 0; j < n_new; ++j) {
        double *out = new_values + static_cast<size_t>(ncomp) * j;
        std::fill(out, out + ncomp, 0.0);
        double weight = 0;
        for (int32_t i = 0; i < n_old; ++i) {
            const double twice_new = std::abs(news[j].twice_signed_area);
            const double twice_old = std::abs(olds[i].twice_signed_area);
            if (boxes_apart(news[j], olds[i]) || !(twice_new > 0) || !(twice_old > 0))
                continue;
            const double o = overlap_ccw(news[j].p, twice_new, olds[i].p, twice_old);
            if (!(o > 0))
                continue;
            weight += o;
            const double *in = old_values + static_cast<size_t>(ncomp) * i;
            for (int32_t c = 0; c < ncomp; ++c)
                out[c] += o * in[c];
        }
        covered[j] = weight > 0;
        if (covered[j])
            for (int32_t c = 0; c < ncomp; ++c)
                out[c] /= weight;
    }
    // Then each component's total made exact.
    for (int32_t c = 0; c < ncomp; ++c) {
        double total = 0;
        for (int32_t i = 0; i < n_old; ++i)
            total += old_values[static_cast<size_t>(ncomp) * i + c] * olds[i].area;
        const double mean = old_area > 0 ? total / old_area : 0;
        double sum = 0;
        bool negative = false, positive = false;
        for (int32_t j = 0; j < n_new; ++j) {
            double &d = new_values[static_cast<size_t>(ncomp) * j + c];
            if (!covered[j]) // a degenerate triangle, over nothing
                d = mean;
            sum += d * news[j].area;
            negative = negative || d < 0;
            positive = positive || d > 0;
        }
        const double ratio = sum != 0 ? total / sum : -1;
        if (!(negative && positive) && ratio >= 0 && std::isfinite(ratio)) {
            for (int32_t j = 0; j < n_new; ++j)
                new_values[static_cast<size_t>(ncomp) * j + c] *= ratio;
        } else if (new_area > 0) {
            const double spread = (total - sum) / new_area;
            for (int32_t j = 0; j < n_new; ++j)
                new_values[static_cast<size_t>(ncomp) * j + c] += spread;
        }
    }
    return RemapPath::overlap;
}

} // namespace sfa

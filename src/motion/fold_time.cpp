// SPDX-License-Identifier: BSD-3-Clause
#include "motion/fold_time.hpp"

#include "mesh/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace sfa {
namespace {

// frexp's exponent of x and 2^by (ldexp(1, by)), read from and written into the bits of a
// normal double: the library's calls cost more than the rest of a triangle's fold time
// (3 % of a plain vortex T = 2 run's instructions), and this runs for every triangle at every
// stage of every step. The library's own for what is not normal.
int binary_exponent(double x)
{
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = static_cast<int>(bits >> 52) & 0x7ff;
    if (biased == 0 || biased == 0x7ff) {
        int k = 0;
        std::frexp(x, &k);
        return k;
    }
    return biased - 1022; // x = 1.f 2^(biased - 1023) = 0.1f 2^(biased - 1022)
}

double power_of_two(int by)
{
    if (by < -1022 || by > 1023)
        return std::ldexp(1.0, by);
    const uint64_t bits = static_cast<uint64_t>(by + 1023) << 52;
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}

} // namespace

double first_positive_root(double c0, double c1, double c2)
{
    const double none = std::numeric_limits<double>::infinity();
    // Treat the quadratic term as absent when it cannot matter before the linear root.
    if (c2 == 0 || std::abs(c2) * c0 <= 1e-15 * c1 * c1)
        return c1 < 0 ? -c0 / c1 : none;
    const double discriminant = c1 * c1 - 4 * c2 * c0;
    if (discriminant < 0)
        return none; // c2 > 0 here: the parabola stays above zero
    // Numerically stable pair of roots: q / c2 and c0 / q.
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(discriminant), c1));
    double first = none;
    for (double root : {q / c2, c0 / q})
        if (root > 0)
            first = std::min(first, root);
    return first;
}

bool turned_over(const TriMesh &mesh, const std::vector<Vec3> &moved, int32_t t)
{
    const Triangle &c = mesh.tri[t];
    const Vec3 before = (mesh.pos[c[1]] - mesh.pos[c[0]]).cross(mesh.pos[c[2]] - mesh.pos[c[0]]);
    const Vec3 after = (moved[c[1]] - moved[c[0]]).cross(moved[c[2]] - moved[c[0]]);
    return !(before.dot(after) > 0); // NaN counts as turned over
}

int32_t first_folded_triangle(const TriMesh &mesh, const std::vector<Vec3> &moved)
{
    const int32_t first = first_where(mesh.num_triangles(), [&](int32_t t) { return turned_over(mesh, moved, t); });
    return first < mesh.num_triangles() ? first : -1;
}

bool move_folded(const TriMesh &mesh, const std::vector<Vec3> &moved, int32_t t)
{
    const Triangle &c = mesh.tri[t];
    const bool any_moved =
        moved[c[0]] != mesh.pos[c[0]] || moved[c[1]] != mesh.pos[c[1]] || moved[c[2]] != mesh.pos[c[2]];
    return any_moved && turned_over(mesh, moved, t);
}

int32_t first_folded_moved_triangle(const TriMesh &mesh, const std::vector<Vec3> &moved)
{
    const int32_t first = first_where(mesh.num_triangles(), [&](int32_t t) { return move_folded(mesh, moved, t); });
    return first < mesh.num_triangles() ? first : -1;
}

double triangle_fold_time(const Vec3 &e1, const Vec3 &e2, const Vec3 &d1, const Vec3 &d2)
{
    // n(t) = n0 + t (e1 x d2 + d1 x e2) + t^2 (d1 x d2); fold where n0.n(t) = 0, a quartic
    // in the lengths. With |x| <= 1e50 it would not overflow, but a sliver's or a fast
    // vertex's would underflow or overflow (a collapsing bubble's c0 went to 0 and its
    // "safe step" with it). Scaled, e = 2^k e' and d = 2^j d', the quadratic in tau =
    // t 2^(j-k) has the coefficients c0 2^-4k, c1 2^-(3k+j), c2 2^-(2k+2j), each exactly,
    // and so its root is exactly t 2^(j-k).
    const double none = std::numeric_limits<double>::infinity();
    const double edge = std::max(e1.cwiseAbs().maxCoeff(), e2.cwiseAbs().maxCoeff());
    const double speed = std::max(d1.cwiseAbs().maxCoeff(), d2.cwiseAbs().maxCoeff());
    if (speed == 0)
        return none; // moved rigidly by a translation
    if (!(edge > 0) || !std::isfinite(speed))
        return 0;
    const int k = binary_exponent(edge), j = binary_exponent(speed);
    // A product with 2^-k is ldexp(x, -k), rounded the same where it underflows, and one
    // ldexp per vector instead of one per coordinate (this runs for every triangle at every
    // stage of every step). 2^by is a double for by <= 1023; above that (coordinates under
    // 1e-308) each coordinate is scaled on its own.
    const auto scaled = [](const Vec3 &v, int by) {
        if (by <= 1023)
            return Vec3(v * power_of_two(by));
        return Vec3(std::ldexp(v.x(), by), std::ldexp(v.y(), by), std::ldexp(v.z(), by));
    };
    const Vec3 f1 = scaled(e1, -k), f2 = scaled(e2, -k), g1 = scaled(d1, -j), g2 = scaled(d2, -j);
    const Vec3 n0 = f1.cross(f2);
    const double c0 = n0.squaredNorm();
    if (!(c0 > 0))
        return 0; // flat (to within 1e-154 of its edges' size): no direction to keep
    const double c1 = n0.dot(f1.cross(g2) + g1.cross(f2));
    const double c2 = n0.dot(g1.cross(g2));
    const double tau = first_positive_root(c0, c1, c2);
    return tau == none ? none : std::ldexp(tau, k - j);
}

Fold first_fold(const TriMesh &mesh, const std::vector<Vec3> &velocity)
{
    // Each triangle's time, and the earliest in triangle order (the first of equal ones),
    // block by block in parallel and then the blocks in order: the same answer for any
    // number of threads.
    const Fold none{std::numeric_limits<double>::infinity(), -1};
    return ordered_group_reduce(
        mesh.num_triangles(), 1, none, [](int32_t) { return 0; },
        [&](int32_t k) {
            const Triangle &t = mesh.tri[k];
            return Fold{triangle_fold_time(mesh.pos[t[1]] - mesh.pos[t[0]], mesh.pos[t[2]] - mesh.pos[t[0]],
                                           velocity[t[1]] - velocity[t[0]], velocity[t[2]] - velocity[t[0]]),
                        k};
        },
        [](const Fold &first, const Fold &next) { return next.time < first.time ? next : first; })[0];
}

double first_fold_time(const TriMesh &mesh, const std::vector<Vec3> &velocity) { return first_fold(mesh, velocity).time; }

} // namespace sfa

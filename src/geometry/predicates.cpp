// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/predicates.hpp"

#include "geometry/expansion.hpp"

#include <cmath>

namespace sfa {
namespace {

namespace ex = expansion;

constexpr double epsilon = 0x1p-53; // half an ulp of 1: the relative rounding error
// Shewchuk's first error bounds (§4.3): when the floating-point determinant exceeds this
// factor times its permanent (the same sum with every term made positive), its sign is right.
constexpr double orient2d_bound = (3 + 16 * epsilon) * epsilon;
constexpr double orient3d_bound = (7 + 56 * epsilon) * epsilon;

int sign_of(double x) { return (x > 0) - (x < 0); }

// x - y as an expansion of at most two terms; returns its length.
int difference(double x, double y, double *h)
{
    double d, error;
    ex::two_diff(x, y, d, error);
    if (error == 0) {
        h[0] = d;
        return 1;
    }
    h[0] = error;
    h[1] = d;
    return 2;
}

// p q - r s for expansions of at most two terms each: at most 16 terms in h.
int two_by_two(const double *p, int np, const double *q, int nq, const double *r, int nr, const double *s, int ns,
               double *h)
{
    double pq[8], rs[8], scratch[12];
    const int npq = ex::product(p, np, q, nq, pq, scratch);
    int nrs = ex::product(r, nr, s, ns, rs, scratch);
    for (int i = 0; i < nrs; ++i)
        rs[i] = -rs[i];
    return ex::sum(pq, npq, rs, nrs, h);
}

int orient3d_exact(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    double u[3][2], v[3][2], w[3][2];
    int nu[3], nv[3], nw[3];
    for (int k = 0; k < 3; ++k) {
        nu[k] = difference(b[k], a[k], u[k]);
        nv[k] = difference(c[k], a[k], v[k]);
        nw[k] = difference(d[k], a[k], w[k]);
    }
    // u . (v x w), one cofactor of u at a time.
    double det[192], next[192], minor[16], term[64], scratch[96];
    int n = 0;
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const int nm = two_by_two(v[i], nv[i], w[j], nw[j], v[j], nv[j], w[i], nw[i], minor);
        const int nt = ex::product(minor, nm, u[k], nu[k], term, scratch);
        if (n == 0) {
            for (int m = 0; m < nt; ++m)
                det[m] = term[m];
            n = nt;
        } else {
            n = ex::sum(term, nt, det, n, next);
            for (int m = 0; m < n; ++m)
                det[m] = next[m];
        }
    }
    return ex::sign(det, n);
}

int orient2d_exact(const double a[2], const double b[2], const double c[2])
{
    double u[2][2], v[2][2];
    int nu[2], nv[2];
    for (int k = 0; k < 2; ++k) {
        nu[k] = difference(b[k], a[k], u[k]);
        nv[k] = difference(c[k], a[k], v[k]);
    }
    double det[16];
    return ex::sign(det, two_by_two(u[0], nu[0], v[1], nv[1], u[1], nu[1], v[0], nv[0], det));
}

} // namespace

int orient3d(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    const Vec3 u = b - a, v = c - a, w = d - a;
    const double m0 = v[1] * w[2], m0r = v[2] * w[1], m1 = v[2] * w[0], m1r = v[0] * w[2], m2 = v[0] * w[1],
                 m2r = v[1] * w[0];
    const double det = u[0] * (m0 - m0r) + u[1] * (m1 - m1r) + u[2] * (m2 - m2r);
    const double permanent = std::abs(u[0]) * (std::abs(m0) + std::abs(m0r)) +
                             std::abs(u[1]) * (std::abs(m1) + std::abs(m1r)) +
                             std::abs(u[2]) * (std::abs(m2) + std::abs(m2r));
    if (std::abs(det) > orient3d_bound * permanent)
        return sign_of(det);
    if (permanent == 0) // every product zero: with no underflow, every exact product too
        return 0;
    return orient3d_exact(a, b, c, d);
}

int orient2d(const double a[2], const double b[2], const double c[2])
{
    const double left = (b[0] - a[0]) * (c[1] - a[1]), right = (b[1] - a[1]) * (c[0] - a[0]);
    const double det = left - right;
    if (std::abs(det) > orient2d_bound * (std::abs(left) + std::abs(right)))
        return sign_of(det);
    if (left == 0 && right == 0)
        return 0;
    return orient2d_exact(a, b, c);
}

} // namespace sfa

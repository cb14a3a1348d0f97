// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the exact predicates (orient2d, orient3d) and of the triangle-triangle
// test built on them, against exact rational arithmetic (GMP): every double is a rational,
// so the reference answers are the true ones. The cases are the hard ones: nearly coplanar
// points (made by rounding points of a plane), points on or next to an edge, triangles
// touching at a corner or sharing an edge, crossings 1e-15 thin, degenerate triangles,
// and all of it at huge and tiny scales and far from the origin.
#include "geometry/predicates.hpp"
#include "geometry/triangle_intersection.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <setjmp.h>

extern "C" {
#include <cmocka.h>
}

#include "numbers.hpp"

using namespace sfa;

namespace {

// ---- exact references ----

using Q = mpq_class;
struct QVec {
    Q x[3];
};

QVec exact(const Vec3 &v) { return QVec{{Q(v[0]), Q(v[1]), Q(v[2])}}; }
QVec minus(const QVec &a, const QVec &b) { return QVec{{a.x[0] - b.x[0], a.x[1] - b.x[1], a.x[2] - b.x[2]}}; }
QVec cross(const QVec &a, const QVec &b)
{
    return QVec{{a.x[1] * b.x[2] - a.x[2] * b.x[1], a.x[2] * b.x[0] - a.x[0] * b.x[2],
                 a.x[0] * b.x[1] - a.x[1] * b.x[0]}};
}
Q dot(const QVec &a, const QVec &b) { return a.x[0] * b.x[0] + a.x[1] * b.x[1] + a.x[2] * b.x[2]; }

int exact_orient3d(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
{
    const QVec qa = exact(a);
    return sgn(dot(cross(minus(exact(b), qa), minus(exact(c), qa)), minus(exact(d), qa)));
}

int exact_orient2d(const double a[2], const double b[2], const double c[2])
{
    const Q ux = Q(b[0]) - Q(a[0]), uy = Q(b[1]) - Q(a[1]), vx = Q(c[0]) - Q(a[0]), vy = Q(c[1]) - Q(a[1]);
    return sgn(ux * vy - uy * vx);
}

// Whether two non-degenerate closed triangles meet, by another route than the library's:
// Moller's intervals on the line where the planes meet, in exact arithmetic, and the
// separating axes of the edges' normals when the triangles are coplanar.
bool exact_triangles_meet(const Vec3 (&a)[3], const Vec3 (&b)[3])
{
    const QVec qa[3] = {exact(a[0]), exact(a[1]), exact(a[2])}, qb[3] = {exact(b[0]), exact(b[1]), exact(b[2])};
    const QVec na = cross(minus(qa[1], qa[0]), minus(qa[2], qa[0]));
    const QVec nb = cross(minus(qb[1], qb[0]), minus(qb[2], qb[0]));
    Q db[3], da[3];
    int sb[3], sa[3];
    for (int k = 0; k < 3; ++k) {
        db[k] = dot(na, minus(qb[k], qa[0]));
        da[k] = dot(nb, minus(qa[k], qb[0]));
        sb[k] = sgn(db[k]);
        sa[k] = sgn(da[k]);
    }
    if ((sb[0] == sb[1] && sb[1] == sb[2] && sb[0] != 0) || (sa[0] == sa[1] && sa[1] == sa[2] && sa[0] != 0))
        return false;
    if (sb[0] == 0 && sb[1] == 0 && sb[2] == 0) {
        int drop = 0; // a coordinate plane the triangles' plane projects onto one to one
        while (sgn(na.x[drop]) == 0)
            ++drop;
        const int x = (drop + 1) % 3, y = (drop + 2) % 3;
        const QVec *tri[2] = {qa, qb};
        for (int owner = 0; owner < 2; ++owner)
            for (int k = 0; k < 3; ++k) {
                const QVec &p = tri[owner][k], &q = tri[owner][(k + 1) % 3];
                const Q axis_x = -(q.x[y] - p.x[y]), axis_y = q.x[x] - p.x[x];
                Q lo[2], hi[2];
                for (int t = 0; t < 2; ++t)
                    for (int m = 0; m < 3; ++m) {
                        const Q s = axis_x * tri[t][m].x[x] + axis_y * tri[t][m].x[y];
                        if (m == 0 || s < lo[t])
                            lo[t] = s;
                        if (m == 0 || s > hi[t])
                            hi[t] = s;
                    }
                if (hi[0] < lo[1] || hi[1] < lo[0])
                    return false;
            }
        return true;
    }
    const QVec line = cross(na, nb);
    const auto interval = [&](const QVec (&t)[3], const Q (&d)[3], Q &lo, Q &hi) {
        bool any = false;
        const auto take = [&](const QVec &p) {
            const Q s = dot(line, p);
            if (!any || s < lo)
                lo = s;
            if (!any || s > hi)
                hi = s;
            any = true;
        };
        for (int k = 0; k < 3; ++k) {
            const int l = (k + 1) % 3;
            if (sgn(d[k]) == 0)
                take(t[k]);
            if (sgn(d[k]) * sgn(d[l]) < 0) {
                const Q f = d[k] / (d[k] - d[l]);
                const QVec e = minus(t[l], t[k]);
                take(QVec{{t[k].x[0] + f * e.x[0], t[k].x[1] + f * e.x[1], t[k].x[2] + f * e.x[2]}});
            }
        }
    };
    Q lo_a, hi_a, lo_b, hi_b;
    interval(qa, da, lo_a, hi_a);
    interval(qb, db, lo_b, hi_b);
    return !(hi_a < lo_b || hi_b < lo_a);
}

bool exact_degenerate(const Vec3 (&t)[3])
{
    const QVec n = cross(minus(exact(t[1]), exact(t[0])), minus(exact(t[2]), exact(t[0])));
    return sgn(n.x[0]) == 0 && sgn(n.x[1]) == 0 && sgn(n.x[2]) == 0;
}

// ---- cases ----


// A point of the plane of t, rounded: within an ulp or so of the plane, on either side or on it.
Vec3 in_plane(const Vec3 (&t)[3], double s, double r) { return t[0] + s * (t[1] - t[0]) + r * (t[2] - t[0]); }

// A pair of triangles of one of the hard kinds.
void hard_pair(Numbers &rng, Vec3 (&a)[3], Vec3 (&b)[3])
{
    for (Vec3 &p : a)
        p = rng.point(1);
    const double thin = std::ldexp(1.0, -50 + rng.pick(8)); // about 1e-15 of the size
    const Vec3 normal = (a[1] - a[0]).cross(a[2] - a[0]).normalized();
    switch (rng.pick(6)) {
    case 0: // nearly coplanar, overlapping or not
        for (Vec3 &p : b)
            p = in_plane(a, rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5));
        break;
    case 1: // a corner on (or next to) an edge of a, the others off on either side
        b[0] = in_plane(a, rng.uniform(0, 1), 0);
        b[1] = b[0] + rng.point(0.5);
        b[2] = b[0] + rng.point(0.5);
        break;
    case 2: // touching at (or missing by an ulp) a corner
        b[0] = a[rng.pick(3)] + thin * rng.point(1) * (rng.pick(2) ? 1 : 0);
        b[1] = b[0] + rng.point(0.5);
        b[2] = b[0] + rng.point(0.5);
        break;
    case 3: // crossing a's plane by about 1e-15
        b[0] = in_plane(a, rng.uniform(-0.2, 1), rng.uniform(-0.2, 1)) + thin * normal * rng.uniform(-1, 1);
        b[1] = in_plane(a, rng.uniform(-0.2, 1), rng.uniform(-0.2, 1)) - thin * normal * rng.uniform(-1, 1);
        b[2] = b[0] + rng.uniform(-1, 1) * normal;
        break;
    case 4: // sharing an edge (or nearly), folded a little either way
        b[0] = a[0];
        b[1] = a[1] + thin * rng.point(1) * rng.pick(2);
        b[2] = in_plane(a, rng.uniform(-1, 1), rng.uniform(-1, 0.2)) + thin * normal * rng.uniform(-1, 1);
        break;
    default: // parallel planes 1e-15 apart, boxes overlapping in the plane
        for (Vec3 &p : b)
            p = in_plane(a, rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5)) + thin * normal;
        break;
    }
    // Far from the origin (rounding again) or at a huge or tiny scale (exactly, powers of 2).
    const int move = rng.pick(4);
    const Vec3 offset = move == 1 ? rng.point(1e6) : Vec3::Zero();
    const int exponent = move == 2 ? rng.pick(301) - 150 : 0;
    for (Vec3 *t : {a, b})
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c)
                t[k][c] = std::ldexp(t[k][c] + offset[c], exponent);
}

// orient3d and orient2d agree with exact arithmetic on hard quadruples and triples.
void orientations_agree_with_exact_arithmetic(void **)
{
    Numbers rng{1};
    const int pairs = 250000; // four orient3d (and four orient2d) each: 10^6 of each
    int zeros = 0, mismatches = 0;
    for (int i = 0; i < pairs; ++i) {
        Vec3 a[3], b[3];
        hard_pair(rng, a, b);
        for (int k = 0; k < 4; ++k) {
            const Vec3 &d = k < 3 ? b[k] : in_plane(a, rng.uniform(-1, 2), rng.uniform(-1, 2));
            const int got = orient3d(a[0], a[1], a[2], d), want = exact_orient3d(a[0], a[1], a[2], d);
            zeros += want == 0;
            if (got != want && ++mismatches < 5)
                print_error("orient3d gave %d, exactly %d\n", got, want);
            const int axis = k % 3, x = (axis + 1) % 3, y = (axis + 2) % 3;
            const double p[2] = {a[0][x], a[0][y]}, q[2] = {a[1][x], a[1][y]}, r[2] = {d[x], d[y]};
            if (orient2d(p, q, r) != exact_orient2d(p, q, r) && ++mismatches < 5)
                print_error("orient2d gave %d, exactly %d\n", orient2d(p, q, r), exact_orient2d(p, q, r));
        }
    }
    print_message("10^6 hard orientations: %d exactly coplanar, %d mismatches\n", zeros, mismatches);
    assert_int_equal(mismatches, 0);
    assert_true(zeros > 1000); // the hard cases include exact zeros, which need the fallback
}

// The triangle test agrees with an exact intersection by another method on hard pairs.
void triangle_test_agrees_with_exact_arithmetic(void **)
{
    Numbers rng{2};
    int meet = 0, apart = 0, mismatches = 0;
    for (int i = 0; i < 200000; ++i) {
        Vec3 a[3], b[3];
        hard_pair(rng, a, b);
        if (exact_degenerate(a) || exact_degenerate(b))
            continue;
        const bool want = exact_triangles_meet(a, b);
        const bool got = triangles_intersect(a[0], a[1], a[2], b[0], b[1], b[2]);
        const bool swapped = triangles_intersect(b[2], b[0], b[1], a[1], a[2], a[0]);
        (want ? meet : apart) += 1;
        if ((got != want || swapped != want) && ++mismatches < 5)
            print_error("pair %d: the test says %d (swapped %d), exactly %d\n", i, got, swapped, want);
    }
    print_message("200k hard triangle pairs: %d meet, %d apart, %d mismatches\n", meet, apart, mismatches);
    assert_int_equal(mismatches, 0);
    assert_true(meet > 20000 && apart > 20000);
}

// Hand-made cases: touching, sharing, degenerate, and the same at every scale.
void triangles_that_touch_share_or_degenerate(void **)
{
    for (const int exponent : {0, -150, 150}) {
        const auto s = [&](double x, double y, double z) {
            return Vec3(std::ldexp(x, exponent), std::ldexp(y, exponent), std::ldexp(z, exponent));
        };
        const Vec3 A0 = s(0, 0, 0), A1 = s(1, 0, 0), A2 = s(0, 1, 0);
        const auto meet = [&](const Vec3 &b0, const Vec3 &b1, const Vec3 &b2) {
            return triangles_intersect(A0, A1, A2, b0, b1, b2);
        };
        assert_true(meet(s(0.2, 0.2, -1), s(0.2, 0.2, 1), s(0.3, 0.5, 1)));      // through the interior
        assert_false(meet(s(2, 2, -1), s(2, 2, 1), s(2, 3, 1)));                  // beside
        assert_false(meet(s(0, 0, 0x1p-40), s(1, 0, 0x1p-40), s(0, 1, 0x1p-40))); // just above
        assert_true(meet(s(1, 0, 0), s(2, 0, 1), s(2, 1, -1)));                   // at a corner
        assert_true(meet(A0, A1, s(0.3, -1, 0.5)));                               // a shared edge
        assert_true(meet(A0, s(-1, -1, 1), s(-1, 1, 1)));                         // a shared corner only
        assert_true(meet(s(0.5, 0.5, 0), s(2, 0.5, 1), s(0.5, 2, 1)));            // a corner on the edge
        assert_false(meet(s(0.5, 0.5 + 0x1p-52, 0), s(2, 2, 1), s(2, 2, -1)));   // an ulp beyond it
        assert_true(meet(s(0.1, 0.1, 0), s(0.3, 0.1, 0), s(0.1, 0.3, 0)));        // inside, coplanar
        assert_false(meet(s(0.6, 0.6, 0), s(2, 0.6, 0), s(0.6, 2, 0)));           // beside, coplanar
        // Degenerate: a segment through the interior, a segment above, a point on the face,
        // a point just off it, a point on another point.
        assert_true(meet(s(0.2, 0.2, -1), s(0.2, 0.2, 1), s(0.2, 0.2, 1)));
        assert_false(meet(s(0.2, 0.2, 0x1p-50), s(0.4, 0.2, 0x1p-50), s(0.3, 0.2, 0x1p-50)));
        assert_true(meet(s(0.25, 0.25, 0), s(0.25, 0.25, 0), s(0.25, 0.25, 0)));
        assert_false(meet(s(0.25, 0.25, 0x1p-60), s(0.25, 0.25, 0x1p-60), s(0.25, 0.25, 0x1p-60)));
        assert_true(triangles_intersect(s(1, 1, 1), s(1, 1, 1), s(1, 1, 1), s(1, 1, 1), s(1, 1, 1), s(1, 1, 1)));
        // Two segments (degenerate triangles) crossing in space, and skew by an ulp.
        assert_true(triangles_intersect(A0, A1, A1, s(0.5, -1, 0), s(0.5, 1, 0), s(0.5, 1, 0)));
        assert_false(triangles_intersect(A0, A1, A1, s(0.5, -1, 0x1p-60), s(0.5, 1, 0x1p-60), s(0.5, 1, 0x1p-60)));
    }
}

// The case the old interval test got wrong: nearly coplanar triangles whose boxes are 1e-9
// apart, so that they cannot meet.
void nearly_coplanar_triangles_with_boxes_apart_do_not_meet(void **)
{
    Numbers rng{3};
    for (int i = 0; i < 10000; ++i) {
        const Vec3 a0 = rng.point(1), a1 = rng.point(1);
        const Vec3 a2 = a0 + (a1 - a0) * 0.5 + Vec3(0, 0, 1e-3) + rng.point(1e-6);
        Vec3 b0 = a0 + (a1 - a0) * 1.5, b1 = a0 + (a1 - a0) * 2.0, b2 = a0 + (a1 - a0) * 1.7 + Vec3(0, 0, 1e-3);
        // Beyond a's box by 1e-9 along the line: b's box is apart from a's.
        const Vec3 gap = (a1 - a0).cwiseSign() * 1e-9;
        const Vec3 a_hi = a0.cwiseMax(a1).cwiseMax(a2);
        const Vec3 a_lo = a0.cwiseMin(a1).cwiseMin(a2);
        for (Vec3 *p : {&b0, &b1, &b2})
            for (int c = 0; c < 3; ++c)
                (*p)[c] = (a1 - a0)[c] > 0 ? std::max((*p)[c], a_hi[c] + gap[c]) : std::min((*p)[c], a_lo[c] + gap[c]);
        assert_false(triangles_intersect(a0, a1, a2, b0, b1, b2));
    }
}

} // namespace

int main()
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(orientations_agree_with_exact_arithmetic),
        cmocka_unit_test(triangle_test_agrees_with_exact_arithmetic),
        cmocka_unit_test(triangles_that_touch_share_or_degenerate),
        cmocka_unit_test(nearly_coplanar_triangles_with_boxes_apart_do_not_meet),
    };
    return cmocka_run_group_tests_name("unit_predicates", tests, nullptr, nullptr);
}

// SPDX-License-Identifier: BSD-3-Clause
// Exact arithmetic on floating-point expansions, after J. R. Shewchuk, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates" (Discrete Comput. Geom.
// 18, 1997), §2. An expansion is a sum of doubles, stored from the smallest magnitude to
// the largest, no two of which overlap in their bits: its value is the exact sum, and its
// sign is the sign of its last (largest) term. The exact predicates (predicates.cpp) use
// it only when the floating-point filter cannot decide.
//
// Exact as long as no product underflows or overflows and the arithmetic rounds to
// nearest: the library's coordinate range (surfadapt.h) keeps the first; the second is
// IEEE 754's default, and this file must not be built with -ffast-math, which reorders
// the sums the error terms depend on.
#pragma once

#include <cmath>

namespace sfa::expansion {

// a + b = sum + error exactly (Knuth's two-sum, §2.5 Theorem 7).
inline void two_sum(double a, double b, double &sum, double &error)
{
    sum = a + b;
    const double b_virtual = sum - a, a_virtual = sum - b_virtual;
    error = (a - a_virtual) + (b - b_virtual);
}

// a - b = difference + error exactly.
inline void two_diff(double a, double b, double &difference, double &error)
{
    difference = a - b;
    const double b_virtual = a - difference, a_virtual = difference + b_virtual;
    error = (a - a_virtual) + (b_virtual - b);
}

// a * b = product + error exactly: the fused multiply-add rounds once, so it returns the
// product's rounding error itself (the role of Dekker's splitting in §2.6).
inline void two_product(double a, double b, double &product, double &error)
{
    product = a * b;
    error = std::fma(a, b, -product);
}

// h = e + b (GROW-EXPANSION with zero elimination, §2.7 Theorem 10); h has room for
// e_length + 1 terms and may be e. Returns h's length.
inline int grow(const double *e, int e_length, double b, double *h)
{
    double q = b;
    int n = 0;
    for (int i = 0; i < e_length; ++i) {
        double sum, error;
        two_sum(q, e[i], sum, error);
        q = sum;
        if (error != 0)
            h[n++] = error;
    }
    if (q != 0 || n == 0)
        h[n++] = q;
    return n;
}

// h = e + f (EXPANSION-SUM, §2.7 Theorem 12: e grown by each term of f); h has room for
// e_length + f_length terms and must not be f. Returns h's length.
inline int sum(const double *e, int e_length, const double *f, int f_length, double *h)
{
    for (int i = 0; i < e_length; ++i)
        h[i] = e[i];
    int n = e_length;
    for (int j = 0; j < f_length; ++j)
        n = grow(h, n, f[j], h);
    return n;
}

// h = b e (SCALE-EXPANSION with zero elimination, §2.8 Theorem 19); h has room for
// 2 e_length terms and must not be e. Returns h's length.
inline int scale(const double *e, int e_length, double b, double *h)
{
    double q, error;
    two_product(e[0], b, q, error);
    int n = 0;
    if (error != 0)
        h[n++] = error;
    for (int i = 1; i < e_length; ++i) {
        double product, product_error, partial, partial_error;
        two_product(e[i], b, product, product_error);
        two_sum(q, product_error, partial, partial_error);
        if (partial_error != 0)
            h[n++] = partial_error;
        two_sum(product, partial, q, error);
        if (error != 0)
            h[n++] = error;
    }
    if (q != 0 || n == 0)
        h[n++] = q;
    return n;
}

// h = e f: the sum of e scaled by each term of f. h has room for 2 e_length f_length
// terms, `scratch` for 2 e_length (f_length + 1). Returns h's length.
inline int product(const double *e, int e_length, const double *f, int f_length, double *h, double *scratch)
{
    int n = scale(e, e_length, f[0], h);
    for (int j = 1; j < f_length; ++j) {
        const int m = scale(e, e_length, f[j], scratch);
        double *term = scratch + m; // the rest of scratch holds the running sum
        n = sum(scratch, m, h, n, term);
        for (int i = 0; i < n; ++i)
            h[i] = term[i];
    }
    return n;
}

// The sign of an expansion: that of its largest term.
inline int sign(const double *e, int e_length)
{
    const double top = e[e_length - 1];
    return (top > 0) - (top < 0);
}

} // namespace sfa::expansion

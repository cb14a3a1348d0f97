// SPDX-License-Identifier: BSD-3-Clause
// |a - b| <= tol in double precision, with both values in the failure message. CMocka's
// assert_float_equal converts its arguments to float, which cannot tell a difference of
// 1e-12 from one of 1e-8. (tests/c/support/testing.h has the same for the C tests.)
#pragma once

#include <cmath>

#define assert_near(a, b, tol)                                                                                         \
    do {                                                                                                               \
        const double a_ = (a), b_ = (b), t_ = (tol);                                                                   \
        if (!(std::abs(a_ - b_) <= t_))                                                                                \
            fail_msg("%s:%d: %s = %.17g, expected %.17g within %.3g (off by %.3g)", __FILE__, __LINE__, #a, a_, b_,     \
                     t_, a_ - b_);                                                                                     \
    } while (0)

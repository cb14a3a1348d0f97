// SPDX-License-Identifier: BSD-3-Clause
// The analytic flows of the paper's §5.2, as sfa_velocity_fn callbacks. Both are
// time-modulated by cos(pi t / T), so the exact solution returns to its start at t = T.
#pragma once

#include <cstdint>

struct FlowPeriod {
    double period; // T
};

// Enright's deformation field (§5.2.2). The paper's eq. 18 has a typesetting error; this
// is the standard field: w = -sin(2 pi x) sin(2 pi y) sin^2(pi z).
extern "C" void enright_velocity(void *period, int32_t n, const double *xyz, double t, double *vel);

// The vortex flow of §5.2.1 and §5.2.3, eqs. 13-15.
extern "C" void vortex_velocity(void *period, int32_t n, const double *xyz, double t, double *vel);

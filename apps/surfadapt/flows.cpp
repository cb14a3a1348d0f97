// SPDX-License-Identifier: BSD-3-Clause
#include "flows.hpp"

#include <cmath>

namespace {
constexpr double pi = 3.14159265358979323846;

double modulation(void *period, double t) { return std::cos(pi * t / static_cast<FlowPeriod *>(period)->period); }
double sq(double x) { return x * x; }
} // namespace

// The host's loops over the vertices are its own: these run in parallel like a solver's
// would. sin(2 pi x) = 2 sin(pi x) cos(pi x): one sine and cosine per coordinate.
extern "C" void enright_velocity(void *period, int32_t n, const double *xyz, double t, double *vel)
{
    const double m = modulation(period, t);
#pragma omp parallel for schedule(static)
    for (int32_t i = 0; i < n; ++i) {
        const double sx = std::sin(pi * xyz[3 * i]), sy = std::sin(pi * xyz[3 * i + 1]), sz = std::sin(pi * xyz[3 * i + 2]);
        const double s2x = 2 * sx * std::cos(pi * xyz[3 * i]), s2y = 2 * sy * std::cos(pi * xyz[3 * i + 1]),
                     s2z = 2 * sz * std::cos(pi * xyz[3 * i + 2]);
        vel[3 * i] = m * 2 * sq(sx) * s2y * s2z;
        vel[3 * i + 1] = -m * s2x * sq(sy) * s2z;
        vel[3 * i + 2] = -m * s2x * s2y * sq(sz);
    }
}

extern "C" void vortex_velocity(void *period, int32_t n, const double *xyz, double t, double *vel)
{
    const double m = modulation(period, t);
#pragma omp parallel for schedule(static)
    for (int32_t i = 0; i < n; ++i) {
        const double sx = std::sin(pi * xyz[3 * i]), sy = std::sin(pi * xyz[3 * i + 1]), sz = std::sin(pi * xyz[3 * i + 2]);
        const double s2x = 2 * sx * std::cos(pi * xyz[3 * i]), s2y = 2 * sy * std::cos(pi * xyz[3 * i + 1]),
                     s2z = 2 * sz * std::cos(pi * xyz[3 * i + 2]);
        vel[3 * i] = m * sq(sx) * (s2z - s2y);
        vel[3 * i + 1] = m * sq(sy) * (s2x - s2z);
        vel[3 * i + 2] = m * sq(sz) * (s2y - s2x);
    }
}

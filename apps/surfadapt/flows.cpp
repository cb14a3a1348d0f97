#include "flows.hpp"

#include <cmath>

namespace {
constexpr double pi = 3.14159265358979323846;

double modulation(void *period, double t) { return std::cos(pi * t / static_cast<FlowPeriod *>(period)->period); }
double sq(double x) { return x * x; }
} // namespace

extern "C" void enright_velocity(void *period, int32_t n, const double *xyz, double t, double *vel)
{
    const double m = modulation(period, t);
    for (int32_t i = 0; i < n; ++i) {
        const double x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
        vel[3 * i] = m * 2 * sq(std::sin(pi * x)) * std::sin(2 * pi * y) * std::sin(2 * pi * z);
        vel[3 * i + 1] = -m * std::sin(2 * pi * x) * sq(std::sin(pi * y)) * std::sin(2 * pi * z);
        vel[3 * i + 2] = -m * std::sin(2 * pi * x) * std::sin(2 * pi * y) * sq(std::sin(pi * z));
    }
}

extern "C" void vortex_velocity(void *period, int32_t n, const double *xyz, double t, double *vel)
{
    const double m = modulation(period, t);
    for (int32_t i = 0; i < n; ++i) {
        const double x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
        vel[3 * i] = m * sq(std::sin(pi * x)) * (std::sin(2 * pi * z) - std::sin(2 * pi * y));
        vel[3 * i + 1] = m * sq(std::sin(pi * y)) * (std::sin(2 * pi * x) - std::sin(2 * pi * z));
        vel[3 * i + 2] = m * sq(std::sin(pi * z)) * (std::sin(2 * pi * y) - std::sin(2 * pi * x));
    }
}

// SPDX-License-Identifier: BSD-3-Clause
#include "motion/rk4_step.hpp"

#include "mesh/error.hpp"
#include "mesh/parallel.hpp"
#include "motion/fold_time.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sfa {
namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are passed to the host as a flat array");

std::vector<Vec3> evaluate(const VelocityField &field, const std::vector<Vec3> &points, double t, int32_t index_base)
{
    const int32_t n = static_cast<int32_t>(points.size());
    std::vector<Vec3> velocity(n);
    if (n == 0)
        return velocity; // a surface all of whose drops an adaptation removed: nothing to ask
    // Zero where the host leaves a vertex unwritten; in parallel, as four evaluations a step
    // of 10^5 vertices each would otherwise leave the other threads waiting.
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v)
        velocity[v] = Vec3::Zero();
    field(n, points.data()->data(), t, velocity.data()->data());
    const int32_t first_bad = first_where(n, [&](int32_t v) { return !velocity[v].allFinite(); });
    if (first_bad < n) {
        const Vec3 &bad = velocity[first_bad];
        char message[200];
        std::snprintf(message, sizeof message,
                      "the velocity callback gave vertex %d a non-finite velocity (%g, %g, %g) at t = %g",
                      first_bad + index_base, bad.x(), bad.y(), bad.z(), t);
        throw Error(Status::numeric, message);
    }
    return velocity;
}

// The RK4 mean velocity (k1 + 2 k2 + 2 k3 + k4) / 6 over a step h.
std::vector<Vec3> rk4_velocity(const std::vector<Vec3> &pos, const VelocityField &field, double t, double h,
                               int32_t index_base)
{
    const std::vector<Vec3> k1 = evaluate(field, pos, t, index_base);
    const std::vector<Vec3> k2 = evaluate(field, displaced(pos, k1, h / 2), t + h / 2, index_base);
    const std::vector<Vec3> k3 = evaluate(field, displaced(pos, k2, h / 2), t + h / 2, index_base);
    const std::vector<Vec3> k4 = evaluate(field, displaced(pos, k3, h), t + h, index_base);
    const int32_t n = static_cast<int32_t>(pos.size());
    std::vector<Vec3> mean(n);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v)
        mean[v] = (k1[v] + 2 * k2[v] + 2 * k3[v] + k4[v]) / 6;
    return mean;
}

} // namespace

Step rk4_step(const TriMesh &mesh, const VelocityField &field, double t, double dt, double safety, int32_t index_base)
{
    // Each retry shrinks h to what the fold control allows for the last velocity; the
    // velocity changes with h only at higher order, so this settles in a few tries.
    constexpr int max_tries = 40;
    double h = dt;
    for (int attempt = 0; attempt < max_tries; ++attempt) {
        const std::vector<Vec3> velocity = rk4_velocity(mesh.pos, field, t, h, index_base);
        const Fold fold = first_fold(mesh, velocity);
        const double allowed = safety * fold.time;
        if (h <= allowed) {
            Step step{displaced(mesh.pos, velocity, h), h};
            require_valid_step(mesh, step.positions, h, index_base);
            return step;
        }
        require_step_at_least(fold, allowed, dt, index_base);
        h = std::min(allowed, 0.9 * h); // a little below, so that the retries do not creep
    }
    char message[200];
    std::snprintf(message, sizeof message,
                  "no Runge-Kutta step from t = %g avoids folding a triangle (tried down to dt = %g)", t, h);
    throw Error(Status::numeric, message);
}

} // namespace sfa

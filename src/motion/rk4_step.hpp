// SPDX-License-Identifier: BSD-3-Clause
// One classic fourth-order Runge-Kutta step through a velocity field the host evaluates
// in batches (sfa_advect, paper §5.2), with the fold control of explicit_step.
#pragma once

#include "motion/explicit_step.hpp"

#include <functional>

namespace sfa {

// Writes 3n velocities at the n points xyz (3n coordinates) at time t.
using VelocityField = std::function<void(int32_t n, const double *xyz, double t, double *vel)>;

// Takes the RK4 step of length h <= dt whose displacement, seen as linear motion over h,
// reaches no fold before h / safety; shorter h are tried as needed. Throws
// Error(Status::numeric) if the field gives a non-finite value or no step avoids folding.
// Messages count vertices and triangles from index_base.
Step rk4_step(const TriMesh &mesh, const VelocityField &field, double t, double dt, double safety, int32_t index_base);

} // namespace sfa

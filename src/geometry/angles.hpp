// SPDX-License-Identifier: BSD-3-Clause
// Angles: the public parameters and measures are in degrees, the computations in radians.
#pragma once

namespace sfa {

inline constexpr double pi = 3.14159265358979323846;
inline constexpr double radians_per_degree = pi / 180;
inline constexpr double degrees_per_radian = 180.0 / pi;

} // namespace sfa

// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/coordinate_range.hpp"

#include <cstdio>
#include <string>

namespace sfa {

double extent_of(const std::vector<Vec3> &points)
{
    if (points.empty())
        return 0;
    Vec3 low = points[0], high = points[0];
    for (const Vec3 &p : points) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    return (high - low).norm();
}

int32_t first_out_of_range(const std::vector<Vec3> &points)
{
    const int32_t n = static_cast<int32_t>(points.size());
    for (int32_t v = 0; v < n; ++v)
        if (!coordinate_in_range(points[v]))
            return v;
    // In range, the extent cannot overflow: the diagonal is at most 3.5e50.
    return extent_of(points) >= min_extent ? -1 : n;
}

const char *coordinate_range_text()
{
    static const std::string text = [] {
        char buffer[100];
        std::snprintf(buffer, sizeof buffer, "every |coordinate| at most %g, the mesh spanning at least %g",
                      max_abs_coordinate, min_extent);
        return std::string(buffer);
    }();
    return text.c_str();
}

} // namespace sfa

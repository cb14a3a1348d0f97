// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/settings.hpp"

#include "geometry/angles.hpp"
#include "mesh/error.hpp"

#include <cmath>
#include <cstdio>

namespace sfa {
namespace {
// Smoothing sweeps per pass of sfa_adapt: two let the vertices settle around what repair changed.
constexpr int smoothing_sweeps_per_pass = 2;
} // namespace

FeatureThresholds feature_thresholds(const Parameters &p)
{
    return {p.get(Param::ridge_angle) * radians_per_degree, p.get(Param::corner_angle) * radians_per_degree,
            p.get(Param::ridge_turn_angle) * radians_per_degree};
}

MetricBounds metric_bounds(const Parameters &p)
{
    const MetricBounds bounds{p.get(Param::metric_min_angle) * radians_per_degree,
                              p.get(Param::metric_max_angle) * radians_per_degree, p.get(Param::anisotropic) != 0};
    if (bounds.anisotropic && !(bounds.lower_ratio < bounds.upper_ratio)) {
        char message[200];
        std::snprintf(message, sizeof message,
                      "SFA_PARAM_METRIC_MIN_ANGLE (%g) must be smaller than SFA_PARAM_METRIC_MAX_ANGLE (%g)",
                      p.get(Param::metric_min_angle), p.get(Param::metric_max_angle));
        throw Error(Status::argument, message);
    }
    return bounds;
}

RepairSettings repair_settings(const Parameters &p, double l)
{
    return {l,
            p.get(Param::split_length_ratio) * l,
            p.get(Param::split_shortest_ratio) * l,
            p.get(Param::contract_length_ratio) * l,
            p.get(Param::short_edge_ratio) * l,
            p.get(Param::contract_short_ratio),
            p.get(Param::contract_small_ratio),
            std::cos(p.get(Param::small_angle) * radians_per_degree),
            std::cos(p.get(Param::large_angle) * radians_per_degree)};
}

FlipSettings flip_settings(const Parameters &p)
{
    return {metric_bounds(p), p.get(Param::flip_dihedral_angle) * radians_per_degree};
}

SmoothSettings smooth_settings(const Parameters &p)
{
    return {feature_thresholds(p), metric_bounds(p), p.get(Param::denoise), p.get(Param::crossing_guard) != 0,
            p.get(Param::volume_correction) != 0};
}

AdaptSettings adapt_settings(const Parameters &p, double default_edge_length)
{
    const double l = p.get(Param::edge_length) > 0 ? p.get(Param::edge_length) : default_edge_length;
    return {feature_thresholds(p),
            metric_bounds(p),
            flip_settings(p),
            repair_settings(p, l),
            static_cast<int>(p.get(Param::adapt_passes)),
            smoothing_sweeps_per_pass,
            p.get(Param::denoise),
            p.get(Param::crossing_guard) != 0,
            p.get(Param::volume_correction) != 0,
            p.get(Param::size_gradation),
            p.get(Param::topology_change) != 0,
            p.get(Param::merge_distance),
            p.get(Param::thin_sheet_edge_ratio)};
}

} // namespace sfa

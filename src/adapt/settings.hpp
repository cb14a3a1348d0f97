// SPDX-License-Identifier: BSD-3-Clause
// The settings of each operation, made from the public parameters (enum sfa_param) in one
// place: degrees become radians, ratios of l become lengths, and the defaults of §3.1 and
// §4.3 reach the operations only through here.
#pragma once

#include "adapt/parameters.hpp"
#include "geometry/analysis.hpp"

namespace sfa {

// The thresholds of mesh repair (§4.1-§4.3), all derived from the desired edge length l.
struct RepairSettings {
    double desired_length;       // l
    double split_length;         // L: absolute longness
    double split_shortest;       // s: relative longness needs every nearby edge at least this long
    double contract_length;      // S: absolute small triangle
    double short_edge_length;    // absolute shortness, in metric space (not the paper's)
    double contract_short_ratio; // r: relative shortness
    double contract_small_ratio; // R: relative small triangle
    double cos_small_angle;      // cos theta_s
    double cos_large_angle;      // cos theta_l
};

struct FlipSettings {
    MetricBounds bounds;  // the metric of eq. 12 (or the identity in isotropic mode)
    double max_dihedral;  // radians: flips only where the quad is this close to flat
};

// sfa_smooth.
struct SmoothSettings {
    FeatureThresholds features;
    MetricBounds metric;
    double denoise;      // weight in every sweep (smoothing_sweep)
    bool crossing_guard; // no sweep passes the surface through itself (crossing_guard.hpp)
    bool volume_correction; // closed components get their volumes back (restore_enclosed_volumes)
};

// sfa_adapt.
struct AdaptSettings {
    FeatureThresholds features;
    MetricBounds metric;
    FlipSettings flip;
    RepairSettings repair;
    int max_passes;       // iterations at most
    int smoothing_sweeps; // per iteration
    double denoise;       // weight in every sweep (smoothing_sweep)
    bool crossing_guard;  // no step passes the surface through itself (crossing_guard.hpp)
    bool volume_correction; // closed components get their volumes back (restore_enclosed_volumes)
    double size_gradation;  // of a host's size field (size_field.hpp)
    bool topology_change;   // merges and pinches first (topology_change.hpp)
    double merge_distance;  // their distance, a ratio of l
    double thin_sheet_edge_ratio; // the desired length where a sheet is thinner than an edge, a ratio of l
};

FeatureThresholds feature_thresholds(const Parameters &parameters);
// Throws Error(Status::argument) if the two metric angles are the wrong way round.
MetricBounds metric_bounds(const Parameters &parameters);
// For the desired edge length l.
RepairSettings repair_settings(const Parameters &parameters, double desired_length);
FlipSettings flip_settings(const Parameters &parameters);
SmoothSettings smooth_settings(const Parameters &parameters);
// l is SFA_PARAM_EDGE_LENGTH, or `default_edge_length` where that is 0.
AdaptSettings adapt_settings(const Parameters &parameters, double default_edge_length);

} // namespace sfa

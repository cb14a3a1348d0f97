// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/parameters.hpp"

#include "geometry/angles.hpp"
#include "mesh/error.hpp"

#include <cmath>
#include <cstdio>

namespace sfa {
namespace {

// Indexed by Param. The angles of §3.1 are given as f(chi) = 2 atan(sqrt(chi)). These are
// the checks of sfa_set_param and the answers of sfa_get_param_bounds.
const ParamSpec specs[] = {
    {"SFA_PARAM_EDGE_LENGTH", "length units", 0, RangeKind::at_least, 0, INFINITY},
    {"SFA_PARAM_ANISOTROPIC", "a flag", 1, RangeKind::flag, 0, 1},
    {"SFA_PARAM_RIDGE_ANGLE", "degrees", 45, RangeKind::open_interval, 0, 180},
    {"SFA_PARAM_CORNER_ANGLE", "degrees", 20, RangeKind::open_interval, 0, 180},
    {"SFA_PARAM_METRIC_MIN_ANGLE", "degrees", 8, RangeKind::open_interval, 0, 180},
    {"SFA_PARAM_METRIC_MAX_ANGLE", "degrees", 30, RangeKind::open_interval, 0, 180},
    {"SFA_PARAM_SPLIT_LENGTH_RATIO", "a ratio to l", 1.5, RangeKind::open_interval, 0, INFINITY},
    // §4.3: s = l sqrt(psi_l / psi_u) with psi = lambda1 tan^2(theta/2), theta = 8 and 30
    // degrees; the constructor computes it.
    {"SFA_PARAM_SPLIT_SHORTEST_RATIO", "a ratio to l", NAN, RangeKind::open_interval, 0, INFINITY},
    {"SFA_PARAM_CONTRACT_LENGTH_RATIO", "a ratio to l", 0.5, RangeKind::open_interval, 0, INFINITY},
    {"SFA_PARAM_CONTRACT_SHORT_RATIO", "a ratio", 0.1, RangeKind::open_interval, 0, 1},
    {"SFA_PARAM_CONTRACT_SMALL_RATIO", "a ratio", 0.5, RangeKind::open_interval, 0, 1},
    {"SFA_PARAM_SMALL_ANGLE", "degrees", 15, RangeKind::left_open, 0, 60},
    {"SFA_PARAM_LARGE_ANGLE", "degrees", 160, RangeKind::right_open, 60, 180},
    {"SFA_PARAM_FOLD_SAFETY", "a fraction", 0.5, RangeKind::left_open, 0, 1},
    {"SFA_PARAM_DROP_UNREFERENCED", "a flag", 0, RangeKind::flag, 0, 1},
    {"SFA_PARAM_RIDGE_TURN_ANGLE", "degrees", 40, RangeKind::open_interval, 0, 180},
    {"SFA_PARAM_FLIP_DIHEDRAL_ANGLE", "degrees", 20, RangeKind::open_interval, 0, 180},
    {"SFA_PARAM_THREADS", "threads", 0, RangeKind::whole_number, 0, 4096},
    {"SFA_PARAM_DENOISE", "a weight", 0, RangeKind::closed_interval, 0, 1},
    {"SFA_PARAM_ADAPT_PASSES", "passes", 8, RangeKind::whole_number, 1, 100},
    {"SFA_PARAM_CROSSING_GUARD", "a flag", 1, RangeKind::flag, 0, 1},
    {"SFA_PARAM_VOLUME_CORRECTION", "a flag", 1, RangeKind::flag, 0, 1},
    {"SFA_PARAM_SIZE_GRADATION", "a ratio", 1.5, RangeKind::open_interval, 1, INFINITY},
    {"SFA_PARAM_SHORT_EDGE_RATIO", "a ratio to l", 0.6, RangeKind::right_open, 0, 1},
    {"SFA_PARAM_COLLISION_SAFE_MOTION", "a flag", 0, RangeKind::flag, 0, 1},
    {"SFA_PARAM_TOPOLOGY_CHANGE", "a flag", 0, RangeKind::flag, 0, 1},
    {"SFA_PARAM_MERGE_DISTANCE", "a ratio to l", 0.5, RangeKind::left_open, 0, 10},
    {"SFA_PARAM_THIN_SHEET_EDGE_RATIO", "a ratio to l", 1, RangeKind::left_open, 0, 1},
};
static_assert(sizeof specs / sizeof specs[0] == static_cast<size_t>(Param::count), "one spec per key");

} // namespace

Parameters::Parameters()
{
    for (int k = 0; k < static_cast<int>(Param::count); ++k)
        value_[k] = specs[k].default_value;
    value_[static_cast<int>(Param::split_shortest_ratio)] = std::tan(4 * radians_per_degree) / std::tan(15 * radians_per_degree);
}

bool Parameters::is_key(int key) { return key >= 0 && key < static_cast<int>(Param::count); }

void Parameters::require_key(int key)
{
    if (is_key(key))
        return;
    char message[120];
    std::snprintf(message, sizeof message, "unknown parameter key %d (keys are 0 to %d, enum sfa_param)", key,
                  static_cast<int>(Param::count) - 1);
    throw Error(Status::argument, message);
}

const ParamSpec &Parameters::spec(int key) { return specs[key]; }

bool Parameters::accepts(const ParamSpec &spec, double v)
{
    if (!std::isfinite(v))
        return false;
    const double lo = spec.lowest, hi = spec.highest;
    switch (spec.kind) {
    case RangeKind::at_least: return v >= lo;
    case RangeKind::open_interval: return v > lo && v < hi;
    case RangeKind::left_open: return v > lo && v <= hi;
    case RangeKind::right_open: return v >= lo && v < hi;
    case RangeKind::closed_interval: return v >= lo && v <= hi;
    case RangeKind::flag: return v == 0 || v == 1;
    case RangeKind::whole_number: return v >= lo && v <= hi && v == std::floor(v);
    }
    return false;
}

std::string Parameters::describe_range(const ParamSpec &spec)
{
    char text[80];
    const double lo = spec.lowest, hi = spec.highest;
    switch (spec.kind) {
    case RangeKind::at_least: std::snprintf(text, sizeof text, ">= %g", lo); break;
    case RangeKind::open_interval:
        if (std::isinf(hi))
            std::snprintf(text, sizeof text, "> %g", lo);
        else
            std::snprintf(text, sizeof text, "in (%g, %g)", lo, hi);
        break;
    case RangeKind::left_open: std::snprintf(text, sizeof text, "in (%g, %g]", lo, hi); break;
    case RangeKind::right_open: std::snprintf(text, sizeof text, "in [%g, %g)", lo, hi); break;
    case RangeKind::closed_interval: std::snprintf(text, sizeof text, "in [%g, %g]", lo, hi); break;
    case RangeKind::flag: std::snprintf(text, sizeof text, "0 or 1"); break;
    case RangeKind::whole_number: std::snprintf(text, sizeof text, "a whole number in [%g, %g]", lo, hi); break;
    }
    return text;
}

void Parameters::set(int key, double value)
{
    require_key(key);
    const ParamSpec &s = specs[key];
    if (!accepts(s, value)) {
        char message[256];
        std::snprintf(message, sizeof message, "%s (%s) must be %s, got %g", s.name, s.unit,
                      describe_range(s).c_str(), value);
        throw Error(Status::argument, message);
    }
    value_[key] = value;
}

} // namespace sfa

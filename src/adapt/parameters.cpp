#include "adapt/parameters.hpp"

#include "mesh/error.hpp"

#include <cmath>
#include <cstdio>

namespace sfa {
namespace {

enum class Kind { at_least, open_interval, left_open, right_open, closed_interval, flag, whole_number };

struct Spec {
    const char *name;
    double default_value;
    Kind kind;
    double lo, hi;
};

constexpr double pi = 3.14159265358979323846;
constexpr double degrees = pi / 180;

// Indexed by Param. The angles of §3.1 are given as f(chi) = 2 atan(sqrt(chi)).
const Spec specs[] = {
    {"SFA_PARAM_EDGE_LENGTH", 0, Kind::at_least, 0, 0},
    {"SFA_PARAM_ANISOTROPIC", 1, Kind::flag, 0, 1},
    {"SFA_PARAM_RIDGE_ANGLE", 45, Kind::open_interval, 0, 180},
    {"SFA_PARAM_CORNER_ANGLE", 20, Kind::open_interval, 0, 180},
    {"SFA_PARAM_METRIC_MIN_ANGLE", 8, Kind::open_interval, 0, 180},
    {"SFA_PARAM_METRIC_MAX_ANGLE", 30, Kind::open_interval, 0, 180},
    {"SFA_PARAM_SPLIT_LENGTH_RATIO", 1.5, Kind::open_interval, 0, INFINITY},
    // §4.3: s = l sqrt(psi_l / psi_u) with psi = lambda1 tan^2(theta/2), theta = 8 and 30 degrees.
    {"SFA_PARAM_SPLIT_SHORTEST_RATIO", 0, Kind::open_interval, 0, INFINITY},
    {"SFA_PARAM_CONTRACT_LENGTH_RATIO", 0.5, Kind::open_interval, 0, INFINITY},
    {"SFA_PARAM_CONTRACT_SHORT_RATIO", 0.1, Kind::open_interval, 0, 1},
    {"SFA_PARAM_CONTRACT_SMALL_RATIO", 0.5, Kind::open_interval, 0, 1},
    {"SFA_PARAM_SMALL_ANGLE", 15, Kind::left_open, 0, 60},
    {"SFA_PARAM_LARGE_ANGLE", 160, Kind::right_open, 60, 180},
    {"SFA_PARAM_FOLD_SAFETY", 0.5, Kind::left_open, 0, 1},
    {"SFA_PARAM_DROP_UNREFERENCED", 0, Kind::flag, 0, 1},
    {"SFA_PARAM_RIDGE_TURN_ANGLE", 40, Kind::open_interval, 0, 180},
    {"SFA_PARAM_FLIP_DIHEDRAL_ANGLE", 20, Kind::open_interval, 0, 180},
    {"SFA_PARAM_THREADS", 0, Kind::whole_number, 0, 4096},
    {"SFA_PARAM_DENOISE", 0, Kind::closed_interval, 0, 1},
    {"SFA_PARAM_ADAPT_PASSES", 8, Kind::whole_number, 1, 100},
    {"SFA_PARAM_CROSSING_GUARD", 1, Kind::flag, 0, 1},
};
static_assert(sizeof specs / sizeof specs[0] == static_cast<size_t>(Param::count), "one spec per key");

bool in_range(const Spec &spec, double v)
{
    switch (spec.kind) {
    case Kind::at_least: return v >= spec.lo;
    case Kind::open_interval: return v > spec.lo && v < spec.hi;
    case Kind::left_open: return v > spec.lo && v <= spec.hi;
    case Kind::right_open: return v >= spec.lo && v < spec.hi;
    case Kind::closed_interval: return v >= spec.lo && v <= spec.hi;
    case Kind::flag: return v == 0 || v == 1;
    case Kind::whole_number: return v >= spec.lo && v <= spec.hi && v == std::floor(v);
    }
    return false;
}

void describe_range(const Spec &spec, char *out, size_t size)
{
    switch (spec.kind) {
    case Kind::at_least: std::snprintf(out, size, ">= %g", spec.lo); break;
    case Kind::open_interval:
        if (std::isinf(spec.hi))
            std::snprintf(out, size, "> %g", spec.lo);
        else
            std::snprintf(out, size, "in (%g, %g)", spec.lo, spec.hi);
        break;
    case Kind::left_open: std::snprintf(out, size, "in (%g, %g]", spec.lo, spec.hi); break;
    case Kind::right_open: std::snprintf(out, size, "in [%g, %g)", spec.lo, spec.hi); break;
    case Kind::closed_interval: std::snprintf(out, size, "in [%g, %g]", spec.lo, spec.hi); break;
    case Kind::flag: std::snprintf(out, size, "0 or 1"); break;
    case Kind::whole_number: std::snprintf(out, size, "a whole number in [%g, %g]", spec.lo, spec.hi); break;
    }
}

} // namespace

Parameters::Parameters()
{
    for (int k = 0; k < static_cast<int>(Param::count); ++k)
        value_[k] = specs[k].default_value;
    value_[static_cast<int>(Param::split_shortest_ratio)] = std::tan(4 * degrees) / std::tan(15 * degrees);
}

void Parameters::require_key(int key)
{
    if (key >= 0 && key < static_cast<int>(Param::count))
        return;
    char message[120];
    std::snprintf(message, sizeof message, "unknown parameter key %d (keys are 0 to %d, enum sfa_param)", key,
                  static_cast<int>(Param::count) - 1);
    throw Error(Status::argument, message);
}

void Parameters::set(int key, double value)
{
    require_key(key);
    char message[256];
    const Spec &spec = specs[key];
    if (!std::isfinite(value) || !in_range(spec, value)) {
        char range[64];
        describe_range(spec, range, sizeof range);
        std::snprintf(message, sizeof message, "%s must be %s, got %g", spec.name, range, value);
        throw Error(Status::argument, message);
    }
    value_[key] = value;
}

} // namespace sfa

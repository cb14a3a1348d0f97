// SPDX-License-Identifier: BSD-3-Clause
// Every tunable of the adaptation, one double per key of enum sfa_param (same numbers),
// with the paper's defaults (§3.1, §4.3), the range each may take and its unit.
#pragma once

#include <array>
#include <string>

namespace sfa {

enum class Param : int {
    edge_length = 0,
    anisotropic,
    ridge_angle,
    corner_angle,
    metric_min_angle,
    metric_max_angle,
    split_length_ratio,
    split_shortest_ratio,
    contract_length_ratio,
    contract_short_ratio,
    contract_small_ratio,
    small_angle,
    large_angle,
    fold_safety,
    drop_unreferenced,
    ridge_turn_angle,
    flip_dihedral_angle,
    threads,
    denoise,
    adapt_passes,
    crossing_guard,
    volume_correction,
    size_gradation,
    short_edge_ratio,
    collision_safe_motion,
    topology_change,
    merge_distance,
    thin_sheet_edge_ratio,
    count
};

// The shape of a key's range, whose ends are ParamSpec::lowest and ParamSpec::highest.
enum class RangeKind {
    at_least,        // [lowest, infinity)
    open_interval,   // (lowest, highest); "> lowest" when highest is infinite
    left_open,       // (lowest, highest]
    right_open,      // [lowest, highest)
    closed_interval, // [lowest, highest]
    flag,            // 0 or 1
    whole_number,    // the whole numbers in [lowest, highest]
};

// One key as the library checks it. surfadapt.h ends each key's documentation with the
// sentence "Unit, range; default value." in these words (unit, Parameters::describe_range),
// and a unit test (unit_constant_lists) holds the two together.
struct ParamSpec {
    const char *name;       // the header's enumerator, e.g. "SFA_PARAM_RIDGE_ANGLE"
    const char *unit;       // e.g. "degrees", "a ratio to l", "a flag"
    double default_value;   // NaN where the constructor computes the default
    RangeKind kind;
    double lowest, highest; // the closed hull of the accepted values; infinite where unbounded
};

class Parameters {
public:
    Parameters();

    static bool is_key(int key);
    // Throws Error(Status::argument) unless is_key(key).
    static void require_key(int key);
    // The spec of a key for which is_key holds.
    static const ParamSpec &spec(int key);
    // Whether sfa_set_param accepts `value` for the key of `spec`.
    static bool accepts(const ParamSpec &spec, double value);
    // The accepted values in words, as messages and the header state them, e.g. "in (0, 180)".
    static std::string describe_range(const ParamSpec &spec);

    double get(Param key) const { return value_[static_cast<int>(key)]; }
    // Throws Error(Status::argument) naming the key, its unit and its range.
    void set(int key, double value);

private:
    std::array<double, static_cast<int>(Param::count)> value_;
};

} // namespace sfa
